// ODE's contacts of one state, pair by pair: every contact dCollide reports
// for a contact pair (a body may be several convex pieces, each its own geom)
// in the planar conventions of the case (normal from body_a to body_b), kept
// in one pool per state, and one summary per touching pair. One pair's
// contacts are one contact of the case (SPEC §1, one force per pair): its
// penetration is the deepest contact's depth, its point the depth-weighted
// centroid of the contacts' points. PairCollider collides the case's
// declared pairs directly (dCollide on each pair's geoms, no space
// traversal); SpaceCollider (ode_space_collider.hpp) lets ODE's broad phase
// find a scene's pairs.
#pragma once

#include <ode/ode.h>

#include <string>
#include <vector>

#include "ode_world.hpp"
#include "planarbench/case.hpp"

namespace pb::internal::ode {

// one touching pair at one state
struct PairContact {
  int pair = -1;                    // index into the run's ContactPairs (declared pairs first)
  double depth_m = 0.0;             // m, delta: the deepest contact's depth
  double depth_sum_m = 0.0;         // m, the sum of every contact's depth
  Vec2 normal_ab = Vec2::Zero();    // unit, from body_a to body_b, of the deepest contact
  Vec2 point_m = Vec2::Zero();      // m, depth-weighted centroid of the contacts' midpoints
  double approach_speed_mps = 0.0;  // m/s, relative normal speed at point_m, > 0 approaching
  // the pair's contacts in StepContacts::geoms: [first, first + count). For
  // ODE, g1 is a geom with a body (body_a's when g1_is_a); the normal points
  // into g1 (ODE convention, contact.h); pos and normal lie in z = 0.
  int first = 0;
  int count = 0;
  int deepest = -1;           // index (from first) of the deepest contact
  int contacts_reported = 0;  // contacts dCollide gave (before dropping out-of-plane ones)
  bool g1_is_a = true;        // g1 of the pair's contacts is body_a's geom
};

// ODE's contacts at one state: a pool of every kept contact, and one entry
// per touching pair (dCollide reported a contact, depth >= 0) in ascending
// pair index. Reused from state to state: no allocation once it has grown.
struct StepContacts {
  std::vector<dContactGeom> geoms;
  std::vector<PairContact> pairs;
  void clear() {
    geoms.clear();
    pairs.clear();
  }
  [[nodiscard]] const dContactGeom& geom(const PairContact& pc, int k) const {
    return geoms[static_cast<std::size_t>(pc.first + k)];
  }
};

// The most contacts one case pair keeps in a step: 2 (V_a + V_b) + 16, V the
// vertices of a body's geoms (a prism of n outline points has 2 n, a sphere
// or a plane 1). ODE's colliders report, for a prism against a plane, the
// prism's vertices below it (at most 2 n: V_a + V_b already); for a sphere,
// one point; for two prisms, the corners of a side face clipped by the other
// (at most 8, and only where the two overlap: in the plane, a piece touches
// only pieces its edges cross, each edge counted in V). The factor 2 is the
// margin over one contact per vertex. A pair's contacts live in the state's
// pool (StepContacts), which grows with the contacts of the state, not with
// the pairs times this bound; more contacts than the bound is an EngineError
// (the run diverged, saying so), never a silent drop. It replaced buffers of
// (2 n + 4) x pieces^2 per pair, the cube of the points: 5.2 GB for a
// 300-point star (issue 24).
[[nodiscard]] long pair_contact_bound(int vertices_a, int vertices_b);

// the dCollide buffer of one geom pair: a prism of n outline points reports
// at most 2 n + 4 contacts; the largest over the case's bodies
[[nodiscard]] int geom_pair_capacity(const Case& c);

// Moves an ODE contact into the plane z = 0 (pos and normal, the normal
// renormalised); false for a normal along z (not a planar contact).
[[nodiscard]] bool flatten_to_plane(dContactGeom& c);

// Appends the planar contact c to pair pc's contacts (the last ones of
// out.geoms, from pc.first), unless one already kept lies at the same point
// of the plane (ode_pair_contact.cpp, in_plane_duplicate: why). Throws
// EngineError past `bound` contacts (pair_contact_bound), naming the pair.
void keep_contact(const dContactGeom& c, long bound, const std::string& pair_name,
                  StepContacts& out, PairContact& pc);

// The pair's depth, depth sum, normal (from body_a to body_b), point and
// approach speed from its kept contacts (pc.count > 0).
void summarise_pair(const OdeWorld& world, const ContactPair& pair, const StepContacts& out,
                    PairContact& pc);

// ODE's narrow phase of one state, into `out` (cleared first)
class Collider {
 public:
  virtual ~Collider() = default;
  virtual void collide(StepContacts& out) = 0;
};

// The case's declared pairs only (a case without contact groups): dCollide
// on every geom pair of each listed pair, in the case's order, every piece
// of one body against every piece of the other (ODE's manual: dCollide may
// be called directly on two geoms). dSpaceCollide would also find them,
// after recomputing every moved geom's bounding box (dxConvex::computeAABB
// walks all vertices of a prism: a third of dual_pendulum x ode) to test
// pairs the case does not list; and these runs' bits were pinned this way.
class PairCollider final : public Collider {
 public:
  PairCollider(const Case& c, const OdeWorld& world);
  // out.pairs: the touching declared pairs, index = Case::contacts index
  void collide(StepContacts& out) override;

 private:
  void collide_geoms(int pair, dGeomID g, dGeomID h, StepContacts& out, PairContact& pc);

  const Case* case_;
  const OdeWorld* world_;
  std::vector<dContactGeom> buffer_;
  std::vector<long> bounds_;  // per declared pair, pair_contact_bound
};

// Normal relative speed of body_b's and body_a's material points at `point`
// along `normal_ab`, > 0 approaching: -(v_b(p) - v_a(p)) . n.
[[nodiscard]] double approach_speed_mps(const OdeWorld& world, const ContactPair& pair,
                                        const Vec2& point_m, const Vec2& normal_ab);

// For one ODE contact: the point midway between the two geoms' deepest
// points. ODE's colliders put `pos` on one geom: sphere-sphere at the
// midpoint already; sphere-plane and sphere-convex on the sphere's deepest
// point; convex-plane and box-plane on the convex's or the box's deepest
// vertex (collision_sphere.cpp, collision_convex.cpp, box.cpp); other pairs
// (box-box: a point of whichever face dBoxBox clipped, within depth / 2 of
// the midpoint) are reported as ODE gives them.
[[nodiscard]] Vec2 contact_midpoint(const dContactGeom& g);

}  // namespace pb::internal::ode
