// ODE's broad phase for a scene (a case with contact groups, SPEC §11), as
// ODE's users collide a world of many bodies: the geoms live in a
// dSweepAndPruneSpace (OdeWorld::scene_space), dSpaceCollide hands every
// pair of geoms whose bounding boxes overlap (and whose category and collide
// bits match) to a near callback, and the callback asks ContactPairs for
// the pair's rule, calls dCollide, and registers the pair
// (ContactPairs::find_or_add) once ODE reports a contact for it. Pairs no rule lets touch are never collided; the work of a
// step follows the bodies and their near neighbours, not the N (N - 1) / 2
// pairs of the group.
#pragma once

#include <ode/ode.h>

#include <utility>
#include <vector>

#include "ode_pair_contact.hpp"
#include "ode_world.hpp"
#include "planarbench/case.hpp"
#include "planarbench/contact_pairs.hpp"

namespace pb::internal::ode {

// The category bits of a body's geoms (collide bits the same): bit g % 63 for
// each contact group g it belongs to, bit 63 when it is in a declared pair.
// ODE calls the near callback only for two geoms that share a bit; bodies
// of two groups that cannot touch are culled there, and the callback's
// ContactPairs::may_touch decides the rest (bits shared by groups g and
// g + 63, or two bodies each in some declared pair).
[[nodiscard]] unsigned long rule_bits(const ContactPairs& pairs, const Case& c, int body);

class SpaceCollider final : public Collider {
 public:
  // `world` holds its geoms in a scene's space; `pairs` is the run's pair list,
  // which the collider grows
  SpaceCollider(const Case& c, const OdeWorld& world, ContactPairs& pairs);
  // out.pairs: every pair ODE reported a contact for, ascending pair index
  void collide(StepContacts& out) override;

 private:
  static void near_callback(void* data, dGeomID o1, dGeomID o2);
  void near(dGeomID o1, dGeomID o2);
  // ContactPairs::find_or_add(i, j) behind a per-body list of the pairs met
  // (a hash lookup per touching pair and step was 5 % of pile_1000)
  int pair_index(int i, int j);

  // one contact of the near callback's pass, before it is grouped by pair
  struct Found {
    int pair = -1;
    bool planar = false;  // lies in the plane (flatten_to_plane): kept
    dContactGeom geom{};
  };

  const OdeWorld* world_;
  ContactPairs* pairs_;
  std::vector<dContactGeom> buffer_;  // one dCollide call's contacts
  std::vector<Found> found_;          // the callback's contacts, in the order ODE met them
  std::vector<std::pair<int, int>> order_;  // (pair, index into found_), sorted
  // per moving body: (other body, pair index) of each pair it has touched
  std::vector<std::vector<std::pair<int, int>>> known_;
  // the bits alone decide (no declared pairs, at most 63 groups): two geoms
  // ODE hands over share a group
  bool bits_decide_ = false;
};

}  // namespace pb::internal::ode
