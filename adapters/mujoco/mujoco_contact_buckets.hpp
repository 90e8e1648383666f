// The contacts of one evaluation grouped by the run's pair (ModelLayout), so
// that every per-pair pass reads its own contacts instead of scanning all of
// d->contact once per pair (O(pairs x contacts) before: a 1000-disk pile has
// thousands of each). Built once per evaluation from d->contact, in
// O(ncon + k log k) for k pairs with contacts; a contact group's pair is
// registered (ModelLayout::find_or_add_pair) the first time MuJoCo's
// collider reports it. Each pair's contacts keep d->contact's order, and the
// pairs come in ascending index, so a pass over them does what a pass over
// every pair did, in the same order (the same bits).
#pragma once

#include <mujoco/mujoco.h>

#include <span>
#include <vector>

#include "mujoco_model.hpp"

namespace pb::internal::mujoco {

class ContactBuckets {
 public:
  // every contact of d (fused ones too, exclude = 2: passes skip them),
  // registering group pairs not seen before
  void build(const mjData* d, ModelLayout& layout);
  // the same for a layout that must not grow (declared pairs only)
  void build(const mjData* d, const ModelLayout& layout);

  // the pairs with at least one contact, ascending
  [[nodiscard]] const std::vector<int>& pairs() const { return pairs_; }
  // the contacts (indices into d->contact, ascending) of pairs()[b]
  [[nodiscard]] std::span<const int> contacts(std::size_t b) const {
    return {items_.data() + start_[b], items_.data() + start_[b + 1]};
  }
  // the pair of contact i of the last build, -1 if none of the run's
  [[nodiscard]] int pair_of_contact(int i) const {
    return pair_of_[static_cast<std::size_t>(i)];
  }

 private:
  void group(int ncon, std::size_t npairs);

  std::vector<int> pair_of_;  // per contact
  std::vector<int> pairs_;    // ascending
  std::vector<int> start_;    // per bucket, into items_ (size pairs_ + 1)
  std::vector<int> items_;    // contact indices, bucket by bucket
  std::vector<int> slot_;     // per pair: its bucket in this build, -1 none
  std::vector<int> fill_;     // per bucket: the next free item (scratch)
};

}  // namespace pb::internal::mujoco
