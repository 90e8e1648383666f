// The adapter's hooks into b2World: which fixtures may collide (those of
// bodies some rule of the case lets touch: a declared pair or a contact
// group), the restitution of each contact as it begins, and the normal
// impulses the solver applied (b2ContactListener::PostSolve).
#pragma once

#include <box2d/b2_world_callbacks.h>

#include <vector>

#include "box2d_pair_book.hpp"
#include "box2d_restitution.hpp"
#include "planarbench/case.hpp"

namespace pb::internal::box2d {

// case body index stored in b2FixtureUserData::pointer (+1; 0 = none)
[[nodiscard]] int body_index(b2Fixture& fixture);

// Only fixtures of bodies that some rule lets touch collide (ContactPairs::
// may_touch: a declared pair, or two bodies of one contact group), and none
// in the force-injection mode (the adapter applies the contact force
// itself). Box2D asks when its broad phase first finds two fixtures' fat
// AABBs overlapping (b2ContactManager::AddPair), so the filter costs what
// Box2D's new proxy pairs cost, never a pass over the pairs that could touch.
class PairContactFilter final : public b2ContactFilter {
 public:
  PairContactFilter(const PairBook& pairs, const bool& enabled)
      : pairs_(pairs), enabled_(enabled) {}
  bool ShouldCollide(b2Fixture* fixture_a, b2Fixture* fixture_b) override;

 private:
  const PairBook& pairs_;
  const bool& enabled_;
};

// the restitution a pair's contacts took at an onset (one per pair and step)
struct OnsetRecord {
  double time_s = 0.0;  // s, start of the step in which the contact began
  int pair = -1;
  double m_eff_kg = 0.0;      // kg, at the depth-weighted centroid of the pair's contact region
  int points = 0;             // those points
  double approach_mps = 0.0;  // m/s, normal approach speed at that point
  double restitution = 0.0;
};

// Sets each contact's restitution (and the pair's friction) when it begins, in its first PreSolve
// (b2Contact::SetRestitution persists for the contact's life, so Box2D's
// max-mixing of fixture values never applies), from the state Box2D has then:
// the pair's touching manifold points (every touching contact of the two
// bodies: a face on a face, the pieces of a concave body) are one contact
// at the depth-weighted centroid of their region (SPEC §1: the depth-weighted
// mean of its two end points along the surface), whose effective mass
// 1 / (J M^-1 J^T) along the deepest point's normal and the largest normal
// approach speed among the points give the law's restitution; the value
// goes to every touching contact of the pair. A group pair gets its index
// (PairBook::find_or_add) at its first onset. The pair's other contacts are
// read from the contact list of its body that is not static (a ground's
// list holds every body resting on it: O(N) per onset in a pile), which
// holds them in the same order (b2ContactManager::AddPair prepends each
// contact to both bodies' lists). Sums the solver's normal impulses per pair
// and step.
class PairContactListener final : public b2ContactListener {
 public:
  PairContactListener(PairBook& pairs, const std::vector<BodyInertia>& inertia,
                      const double& time_s)
      : pairs_(pairs), inertia_(inertia), time_s_(time_s) {}

  void PreSolve(b2Contact* contact, const b2Manifold* old_manifold) override;
  void PostSolve(b2Contact* contact, const b2ContactImpulse* impulse) override;

  void reserve_log(std::size_t capacity) { log_.reserve(capacity); }
  [[nodiscard]] const std::vector<OnsetRecord>& log() const { return log_; }
  [[nodiscard]] long unlogged() const { return unlogged_; }

 private:
  PairBook& pairs_;
  const std::vector<BodyInertia>& inertia_;  // per case body; centre and pivot are t = 0 values

  const double& time_s_;
  std::vector<OnsetRecord> log_;  // bounded by its reserved capacity
  long unlogged_ = 0;
};

}  // namespace pb::internal::box2d
