// ODE's narrow phase for the case's contact pairs only: dCollide on every geom
// pair of each listed pair (no space traversal), and every contact dCollide
// reports for it (a body may be several convex
// pieces, each its own geom), mapped to the case's conventions (normal from
// body_a to body_b). One pair's contacts are one contact of the case (SPEC
// §1, one force per pair): its penetration is the deepest contact's depth,
// its point the depth-weighted centroid of the contacts' points.
#pragma once

#include <ode/ode.h>

#include <vector>

#include "ode_world.hpp"
#include "planarbench/case.hpp"

namespace pb::internal::ode {

struct PairContact {
  bool touching = false;            // dCollide reported a contact (depth >= 0)
  double depth_m = 0.0;             // m, delta: the deepest contact's depth
  double depth_sum_m = 0.0;         // m, the sum of every contact's depth
  Vec2 normal_ab = Vec2::Zero();    // unit, from body_a to body_b, of the deepest contact
  Vec2 point_m = Vec2::Zero();      // m, depth-weighted centroid of the contacts' midpoints
  double approach_speed_mps = 0.0;  // m/s, relative normal speed at point_m, > 0 approaching
  int deepest = -1;                 // index into geoms of the deepest contact
  // every contact of the pair for ODE: g1 is a geom with a body (body_a's
  // when body_a moves); normal points into g1 (ODE convention, contact.h);
  // pos and normal lie in z = 0. Capacity fixed at construction.
  std::vector<dContactGeom> geoms;
  int count = 0;              // contacts in geoms
  int contacts_reported = 0;  // contacts dCollide gave (before dropping out-of-plane ones)
};

// The most contacts one case pair keeps in a step: 2 (V_a + V_b) + 16, V the
// vertices of a body's geoms (a prism of n outline points has 2 n, a sphere
// or a plane 1). ODE's colliders report, for a prism against a plane, the
// prism's vertices below it (at most 2 n: V_a + V_b already); for a sphere,
// one point; for two prisms, the corners of a side face clipped by the other
// (at most 8, and only where the two overlap: in the plane, a piece touches
// only pieces its edges cross, each edge counted in V). The factor 2 is the
// margin over one contact per vertex. The buffers of a pair (contacts and
// joint feedback, 88 + 128 bytes each in double precision) hold that many,
// so an ODE run's contact memory is linear in the outline points:
// (2 (V_a + V_b) + 16) x 216 bytes per pair, 3.5 MB for a 2000-point star on
// the ground. More contacts is an EngineError (the run diverged, saying so),
// never a silent drop. It replaced (2 n + 4) x pieces^2 per pair, the cube
// of the points: 5.2 GB for a 300-point star (issue 24).
[[nodiscard]] long pair_contact_bound(int vertices_a, int vertices_b);

class PairCollider {
 public:
  PairCollider(const Case& c, const OdeWorld& world);

  // dCollide over the case's pairs; out[p] is pair p's contact
  // (touching = false when its geoms do not overlap). Allocation-free after
  // the first call.
  void collide(std::vector<PairContact>& out);
  // the most contacts one pair can hold
  [[nodiscard]] int capacity() const { return capacity_; }

 private:
  void collide_geoms(int pair, dGeomID g, dGeomID h, PairContact& out);
  void summarise(int pair, PairContact& out) const;

  const Case* case_;
  const OdeWorld* world_;
  std::vector<dContactGeom> buffer_;
  int capacity_ = 0;
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
