// ODE's narrow phase for the case's contact pairs only: dSpaceCollide with a
// near callback that skips every pair the case does not list, and dCollide's
// contact geoms reduced to the one deepest contact per pair, mapped to the
// case's conventions (normal from body_a to body_b).
#pragma once

#include <ode/ode.h>

#include <vector>

#include "ode_world.hpp"
#include "planarbench/case.hpp"

namespace pb::internal::ode {

struct PairContact {
  bool touching = false;            // dCollide reported a contact (depth >= 0)
  double depth_m = 0.0;             // m, ODE's depth of the deepest contact
  Vec2 normal_ab = Vec2::Zero();    // unit, from body_a to body_b
  Vec2 point_m = Vec2::Zero();      // m, midpoint of the two bodies' deepest points
  double approach_speed_mps = 0.0;  // m/s, relative normal speed, > 0 approaching
  // the contact for ODE: g1 is the geom with a body; normal points into g1
  // (ODE convention, contact.h); pos and normal lie in z = 0
  dContactGeom geom{};
  int contacts_reported = 0;  // how many contact geoms dCollide gave
};

class PairCollider {
 public:
  PairCollider(const Case& c, const OdeWorld& world);

  // dSpaceCollide over the world's space; out[p] is pair p's contact
  // (touching = false when its geoms do not overlap). Allocation-free.
  void collide(std::vector<PairContact>& out);

 private:
  static void near_callback(void* data, dGeomID o1, dGeomID o2);
  void collide_pair(int pair, PairContact& out);

  const Case* case_;
  const OdeWorld* world_;
  std::vector<int> pair_of_;  // n x n body indices -> pair index, -1 = no pair
  std::vector<dContactGeom> buffer_;
  std::vector<PairContact>* out_ = nullptr;
};

// Normal relative speed of body_b's and body_a's material points at `point`
// along `normal_ab`, > 0 approaching: -(v_b(p) - v_a(p)) . n.
[[nodiscard]] double approach_speed_mps(const OdeWorld& world, const ContactPair& pair,
                                        const Vec2& point_m, const Vec2& normal_ab);

// For one ODE contact: the point midway between the two geoms' deepest
// points. ODE's colliders put `pos` on one geom: sphere-sphere at the
// midpoint already; sphere-plane and sphere-convex on the sphere's deepest
// point; convex-plane on the convex's deepest vertex (collision_sphere.cpp,
// collision_convex.cpp); other pairs are reported as ODE gives them.
[[nodiscard]] Vec2 contact_midpoint(const dContactGeom& g);

}  // namespace pb::internal::ode
