#include "box2d_pair_book.hpp"

#include <utility>

namespace pb::internal::box2d {

void PairBook::reset(const Case& c, std::vector<PairState> declared,
                     std::vector<PairState> groups) {
  pairs_.emplace(c);
  states_ = std::move(declared);
  groups_ = std::move(groups);
  bodies_ = static_cast<int>(c.bodies.size());
  step = 0;
  adjacent_.assign(c.bodies.size(), {});
  for (int k = 0; k < pairs_->size(); ++k) {
    const ContactPair& p = (*pairs_)[k];
    adjacent_[static_cast<std::size_t>(p.body_a)].emplace_back(p.body_b, k);
    adjacent_[static_cast<std::size_t>(p.body_b)].emplace_back(p.body_a, k);
  }
}

bool PairBook::may_touch(int i, int j) const {
  if (i < 0 || j < 0 || i >= bodies_ || j >= bodies_) return false;
  return pairs_->may_touch(i, j);
}

int PairBook::find(int i, int j) const {
  if (i < 0 || j < 0 || i >= bodies_ || j >= bodies_) return -1;
  const auto& ai = adjacent_[static_cast<std::size_t>(i)];
  const auto& aj = adjacent_[static_cast<std::size_t>(j)];
  const bool by_i = ai.size() <= aj.size();
  const int other = by_i ? j : i;
  for (const auto& [body, k] : by_i ? ai : aj) {
    if (body == other) return k;
  }
  return -1;
}

int PairBook::find_or_add(int i, int j) {
  if (const int k = find(i, j); k >= 0 || i < 0 || j < 0 || i >= bodies_ || j >= bodies_) {
    return k;
  }
  const int k = pairs_->find_or_add(i, j);
  if (k < 0) return k;
  // a group pair seen for the first time: ContactPairs gives the next index
  states_.push_back(groups_[static_cast<std::size_t>(pairs_->group_of_pair(k))]);
  adjacent_[static_cast<std::size_t>(i)].emplace_back(j, k);
  adjacent_[static_cast<std::size_t>(j)].emplace_back(i, k);
  return k;
}

}  // namespace pb::internal::box2d
