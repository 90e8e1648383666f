#include "ode_space_collider.hpp"

#include <algorithm>

namespace pb::internal::ode {

unsigned long rule_bits(const ContactPairs& pairs, const Case& c, int body) {
  unsigned long bits = 0;
  for (const int g : pairs.groups_of_body(body)) bits |= 1UL << (static_cast<unsigned>(g) % 63U);
  for (const ContactPair& p : c.contacts) {
    if (p.body_a == body || p.body_b == body) bits |= 1UL << 63U;
  }
  return bits;
}

SpaceCollider::SpaceCollider(const Case& c, const OdeWorld& world, ContactPairs& pairs)
    : world_(&world),
      pairs_(&pairs),
      buffer_(static_cast<std::size_t>(geom_pair_capacity(c))),
      bits_decide_(c.contacts.empty() && c.contact_groups.size() <= 63) {
  known_.resize(static_cast<std::size_t>(world.body_count()));
  for (int i = 0; i < world.body_count(); ++i) {
    const unsigned long bits = rule_bits(pairs, c, i);
    for (const dGeomID g : world.geoms(i)) {
      dGeomSetCategoryBits(g, bits);
      dGeomSetCollideBits(g, bits);
    }
  }
}

void SpaceCollider::near_callback(void* data, dGeomID o1, dGeomID o2) {
  static_cast<SpaceCollider*>(data)->near(o1, o2);
}

// One candidate pair of geoms from ODE's broad phase. Nothing here throws:
// the callback runs inside ODE's own frames.
void SpaceCollider::near(dGeomID o1, dGeomID o2) {
  const int i = OdeWorld::body_index_of(o1);
  const int j = OdeWorld::body_index_of(o2);
  if (i == j) return;  // two pieces of one body
  const dBodyID bi = world_->body(i);
  const dBodyID bj = world_->body(j);
  if (bi == nullptr && bj == nullptr) return;  // two fixed bodies never touch
  // shared bits already prove a shared group when no declared pair and no
  // second use of a bit exists (bits_decide_); else ask the rules
  if (!bits_decide_ && !pairs_->may_touch(i, j)) return;
  // g1 must have a body (a contact joint attached to (0, body) is stored
  // reversed, and its feedback f1 would belong to the other side); of two
  // moving bodies the lower index first, as ContactPairs orders a group pair
  const bool swap = bi == nullptr || (bj != nullptr && j < i);
  const dGeomID g1 = swap ? o2 : o1;
  const dGeomID g2 = swap ? o1 : o2;
  const int count = dCollide(g1, g2, static_cast<int>(buffer_.size()), buffer_.data(),
                             static_cast<int>(sizeof(dContactGeom)));
  if (count <= 0) return;
  const int k = pair_index(i, j);
  for (int n = 0; n < count; ++n) {
    Found f;
    f.pair = k;
    f.geom = buffer_[static_cast<std::size_t>(n)];
    f.planar = flatten_to_plane(f.geom);
    found_.push_back(f);
  }
}

int SpaceCollider::pair_index(int i, int j) {
  // keyed on the moving body (the lower one of two moving bodies): its list
  // holds the few pairs it has touched, while a fixed ground touches them all
  const bool i_key = world_->body(i) != nullptr && (world_->body(j) == nullptr || i < j);
  const int key = i_key ? i : j;
  const int other = i_key ? j : i;
  std::vector<std::pair<int, int>>& known = known_[static_cast<std::size_t>(key)];
  for (const auto& [o, k] : known) {
    if (o == other) return k;
  }
  const int k = pairs_->find_or_add(i, j);
  known.emplace_back(other, k);
  return k;
}

void SpaceCollider::collide(StepContacts& out) {
  out.clear();
  found_.clear();
  dSpaceCollide(world_->space(), this, &SpaceCollider::near_callback);
  // the pairs in ascending index, each pair's contacts in the order ODE gave
  // them: the same joints in the same order for the same state (std::sort on
  // (pair, arrival): no allocation, unlike std::stable_sort)
  order_.clear();
  for (std::size_t n = 0; n < found_.size(); ++n) {
    order_.emplace_back(found_[n].pair, static_cast<int>(n));
  }
  std::sort(order_.begin(), order_.end());
  for (std::size_t n = 0; n < order_.size();) {
    const int k = order_[n].first;
    const ContactPair& cp = (*pairs_)[k];
    PairContact pc;
    pc.pair = k;
    pc.first = static_cast<int>(out.geoms.size());
    pc.g1_is_a = OdeWorld::body_index_of(found_[static_cast<std::size_t>(order_[n].second)].geom.g1) ==
                 cp.body_a;
    const long bound =
        pair_contact_bound(world_->vertex_count(cp.body_a), world_->vertex_count(cp.body_b));
    for (; n < order_.size() && order_[n].first == k; ++n) {
      const Found& f = found_[static_cast<std::size_t>(order_[n].second)];
      ++pc.contacts_reported;
      if (f.planar) keep_contact(f.geom, bound, cp.name, out, pc);
    }
    if (pc.count == 0) continue;
    summarise_pair(*world_, cp, out, pc);
    out.pairs.push_back(pc);
  }
}

}  // namespace pb::internal::ode
