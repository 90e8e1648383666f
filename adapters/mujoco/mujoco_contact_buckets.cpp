#include "mujoco_contact_buckets.hpp"

#include <algorithm>

namespace pb::internal::mujoco {

void ContactBuckets::build(const mjData* d, ModelLayout& layout) {
  pair_of_.resize(static_cast<std::size_t>(d->ncon));
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& c = d->contact[i];
    pair_of_[static_cast<std::size_t>(i)] = layout.find_or_add_pair(c.geom1, c.geom2);
  }
  group(d->ncon, layout.pairs.size());
}

void ContactBuckets::build(const mjData* d, const ModelLayout& layout) {
  pair_of_.resize(static_cast<std::size_t>(d->ncon));
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& c = d->contact[i];
    pair_of_[static_cast<std::size_t>(i)] = layout.pair_of(c.geom1, c.geom2);
  }
  group(d->ncon, layout.pairs.size());
}

void ContactBuckets::group(int ncon, std::size_t npairs) {
  // slot_ is -1 everywhere between builds: only this build's pairs are reset
  if (slot_.size() < npairs) slot_.resize(npairs, -1);
  pairs_.clear();
  for (int i = 0; i < ncon; ++i) {
    const int k = pair_of_[static_cast<std::size_t>(i)];
    if (k < 0 || slot_[static_cast<std::size_t>(k)] >= 0) continue;
    slot_[static_cast<std::size_t>(k)] = 0;
    pairs_.push_back(k);
  }
  std::sort(pairs_.begin(), pairs_.end());
  // counts, then offsets (a counting sort of the contacts by bucket)
  start_.assign(pairs_.size() + 1, 0);
  for (std::size_t b = 0; b < pairs_.size(); ++b) {
    slot_[static_cast<std::size_t>(pairs_[b])] = static_cast<int>(b);
  }
  for (int i = 0; i < ncon; ++i) {
    const int k = pair_of_[static_cast<std::size_t>(i)];
    if (k >= 0) ++start_[static_cast<std::size_t>(slot_[static_cast<std::size_t>(k)]) + 1];
  }
  for (std::size_t b = 0; b < pairs_.size(); ++b) start_[b + 1] += start_[b];
  items_.resize(static_cast<std::size_t>(start_.back()));
  fill_.assign(start_.begin(), start_.end() - 1);
  for (int i = 0; i < ncon; ++i) {
    const int k = pair_of_[static_cast<std::size_t>(i)];
    if (k < 0) continue;
    const auto b = static_cast<std::size_t>(slot_[static_cast<std::size_t>(k)]);
    items_[static_cast<std::size_t>(fill_[b]++)] = i;
  }
  for (const int k : pairs_) slot_[static_cast<std::size_t>(k)] = -1;
}

}  // namespace pb::internal::mujoco
