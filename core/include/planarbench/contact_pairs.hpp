// The contact pairs of one run (SPEC §11): the case's declared pairs, and the
// pairs of its contact groups as a broad phase finds them. A declared pair
// keeps its index in Case::contacts; a group pair gets the next index when it
// is first added and keeps it for the run, so that every per-pair state an
// engine keeps (a phase, a latched approach speed, an episode) can live in a
// vector indexed like this list. A case without groups is its declared
// pairs, in their order, and nothing is ever added.
#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "planarbench/case.hpp"

namespace pb {

class ContactPairs {
 public:
  explicit ContactPairs(const Case& c);

  [[nodiscard]] int size() const { return static_cast<int>(pairs_.size()); }
  [[nodiscard]] const ContactPair& operator[](int k) const {
    return pairs_[static_cast<std::size_t>(k)];
  }
  [[nodiscard]] const std::vector<ContactPair>& all() const { return pairs_; }
  // declared pairs: indices 0 .. declared() - 1, as in Case::contacts
  [[nodiscard]] int declared() const { return declared_; }

  // the index of the pair of bodies i and j (either order), -1 if it has none yet
  [[nodiscard]] int find(int i, int j) const;
  // ... adding it from its group when it has none yet; -1 if no rule lets
  // the two bodies touch
  int find_or_add(int i, int j);
  // whether any rule (a declared pair or a group) lets bodies i and j touch
  [[nodiscard]] bool may_touch(int i, int j) const { return group_of(i, j) >= 0 || find(i, j) >= 0; }
  // the group whose rule covers bodies i and j, -1 if none (or both fixed)
  [[nodiscard]] int group_of(int i, int j) const;
  // the group pair k came from, -1 for a declared pair
  [[nodiscard]] int group_of_pair(int k) const {
    return k < declared_ ? -1 : group_index_[static_cast<std::size_t>(k - declared_)];
  }
  // the groups body i belongs to
  [[nodiscard]] const std::vector<int>& groups_of_body(int i) const {
    return body_groups_[static_cast<std::size_t>(i)];
  }
  [[nodiscard]] bool has_groups() const { return !groups_.empty(); }
  // the law of bodies i and j (a declared pair's, else their group's), nullptr if none
  [[nodiscard]] const ContactLaw* law_between(int i, int j) const;
  // the name of the rule that lets i and j touch (a pair's or a group's), "" if none
  [[nodiscard]] std::string rule_name(int i, int j) const;

 private:
  [[nodiscard]] std::uint64_t key(int i, int j) const;

  std::vector<bool> fixed_;           // per body
  std::vector<std::string> names_;    // per body, for the group pairs' names
  std::vector<ContactGroup> groups_;  // copies: the list does not hold on to the case
  std::vector<ContactPair> pairs_;
  std::vector<int> group_index_;      // per group pair (k - declared_), its group
  std::vector<std::vector<int>> body_groups_;
  std::unordered_map<std::uint64_t, int> index_;
  int declared_ = 0;
};

// whether any pair of the case has friction (declared or group)
[[nodiscard]] bool case_has_friction(const Case& c);

}  // namespace pb
