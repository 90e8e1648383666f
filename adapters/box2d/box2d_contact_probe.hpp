// The contact state of two Box2D bodies as Box2D's own narrow phase sees it
// at their current transforms: the same b2Collide* functions and
// b2WorldManifold the solver uses at the start of the next step, and
// b2Distance (GJK) for the gap while they are apart.
#pragma once

#include <box2d/b2_body.h>
#include <box2d/b2_contact.h>

#include "planarbench/case.hpp"

namespace pb::internal::box2d {

struct ContactGeometry {
  bool valid = false;           // some fixture pair of the two bodies was measured
  bool touching = false;        // some manifold has points: Box2D's solver sees a contact
  double penetration_m = 0.0;   // m, > 0 overlap of the skinned surfaces, < 0 gap
  Vec2 normal = Vec2::Zero();   // unit, from body a to body b
  Vec2 point_m = Vec2::Zero();  // m, midpoint of the two bodies' surface points
};

// Over the fixture (and chain child) pairs of a and b that Box2D's broad
// phase holds (fat AABBs overlapping; none: valid = false): the deepest point while
// some manifold has points (penetration = -b2WorldManifold::separations, the
// radii included); otherwise the closest pair (b2Distance without radii, the
// radii subtracted), so the penetration is continuous through touch-down.
// Which fixture-child pairs are measured: Box2D's broad-phase pairs (after
// a step, when Box2D has found them), or every pair (before the first step,
// when the broad phase has not run yet; tests).
enum class ProbeScope { broad_phase, every_child };
[[nodiscard]] ContactGeometry probe_contact(const b2Body& a, const b2Body& b,
                                            ProbeScope scope = ProbeScope::broad_phase);
// ... over the given contacts of a and b (b2World::GetContactList, gathered
// by the caller per pair): the broad-phase pairs without a walk over a's
// contact list, which for a ground holds every body resting on it
[[nodiscard]] ContactGeometry probe_contact(const b2Body& a, const b2Body& b,
                                            const b2Contact* const* contacts, int count);

// Whether Box2D's broad phase holds some fixture-child pair of a and b (their
// fat AABBs overlap): what probe_contact's `valid` is with
// ProbeScope::broad_phase when the two are apart.
[[nodiscard]] bool broad_phase_pair(const b2Body& a, const b2Body& b);

}  // namespace pb::internal::box2d
