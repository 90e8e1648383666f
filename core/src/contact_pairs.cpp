#include "planarbench/contact_pairs.hpp"

#include <algorithm>
#include <stdexcept>

namespace pb {

ContactPairs::ContactPairs(const Case& c)
    : groups_(c.contact_groups), pairs_(c.contacts),
      body_groups_(c.bodies.size()), declared_(static_cast<int>(c.contacts.size())) {
  fixed_.reserve(c.bodies.size());
  names_.reserve(c.bodies.size());
  for (const Body& b : c.bodies) {
    fixed_.push_back(b.fixed);
    names_.push_back(b.name);
  }
  for (int k = 0; k < declared_; ++k) index_.emplace(key(pairs_[static_cast<std::size_t>(k)].body_a,
                                                         pairs_[static_cast<std::size_t>(k)].body_b),
                                                     k);
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    for (const int i : groups_[g].bodies) body_groups_[static_cast<std::size_t>(i)].push_back(static_cast<int>(g));
  }
}

std::uint64_t ContactPairs::key(int i, int j) const {
  const auto lo = static_cast<std::uint64_t>(std::min(i, j));
  const auto hi = static_cast<std::uint64_t>(std::max(i, j));
  return (lo << 32) | hi;
}

int ContactPairs::find(int i, int j) const {
  const auto it = index_.find(key(i, j));
  return it == index_.end() ? -1 : it->second;
}

int ContactPairs::group_of(int i, int j) const {
  if (i == j) return -1;
  const auto ui = static_cast<std::size_t>(i);
  const auto uj = static_cast<std::size_t>(j);
  if (fixed_[ui] && fixed_[uj]) return -1;
  // each body is in few groups, and the loader refuses a pair covered by two
  for (const int g : body_groups_[ui]) {
    const auto& other = body_groups_[uj];
    if (std::find(other.begin(), other.end(), g) != other.end()) return g;
  }
  return -1;
}

int ContactPairs::find_or_add(int i, int j) {
  if (const int k = find(i, j); k >= 0) return k;
  const int g = group_of(i, j);
  if (g < 0) return -1;
  const ContactGroup& group = groups_[static_cast<std::size_t>(g)];
  // the fixed body first (the normal from a to b, as a declared pair), else
  // the body listed first
  int a = std::min(i, j);
  int b = std::max(i, j);
  if (fixed_[static_cast<std::size_t>(b)]) std::swap(a, b);
  ContactPair p;
  p.name = group.name + ":" + names_[static_cast<std::size_t>(a)] + "-" + names_[static_cast<std::size_t>(b)];
  p.body_a = a;
  p.body_b = b;
  p.law = group.law;
  p.threshold_m = group.threshold_m;
  p.friction = group.friction;
  const int k = static_cast<int>(pairs_.size());
  pairs_.push_back(std::move(p));
  group_index_.push_back(g);
  index_.emplace(key(a, b), k);
  return k;
}

const ContactLaw* ContactPairs::law_between(int i, int j) const {
  if (const int k = find(i, j); k >= 0) return &pairs_[static_cast<std::size_t>(k)].law;
  const int g = group_of(i, j);
  return g >= 0 ? &groups_[static_cast<std::size_t>(g)].law : nullptr;
}

std::string ContactPairs::rule_name(int i, int j) const {
  if (const int k = find(i, j); k >= 0 && k < declared_) return pairs_[static_cast<std::size_t>(k)].name;
  const int g = group_of(i, j);
  return g >= 0 ? "group " + groups_[static_cast<std::size_t>(g)].name : std::string();
}

bool case_has_friction(const Case& c) {
  for (const ContactPair& p : c.contacts) {
    if (p.has_friction()) return true;
  }
  for (const ContactGroup& g : c.contact_groups) {
    if (g.has_friction()) return true;
  }
  return false;
}

}  // namespace pb
