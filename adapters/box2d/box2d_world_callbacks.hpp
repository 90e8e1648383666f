// The adapter's hooks into b2World: which fixtures may collide (only the
// case's contact pairs), the restitution of each contact as it begins, and
// the normal impulses the solver applied (b2ContactListener::PostSolve).
#pragma once

#include <box2d/b2_world_callbacks.h>

#include <vector>

#include "box2d_restitution.hpp"
#include "planarbench/case.hpp"

namespace pb::internal::box2d {

// index of the case contact pair of two bodies (either order), -1 if none
class PairTable {
 public:
  void reset(int bodies);
  void set(int body_a, int body_b, int pair);
  [[nodiscard]] int pair(int body_a, int body_b) const;

 private:
  [[nodiscard]] std::size_t index(int body_a, int body_b) const;
  int bodies_ = 0;
  std::vector<int> table_;  // bodies_ x bodies_
};

// case body index stored in b2FixtureUserData::pointer (+1; 0 = none)
[[nodiscard]] int body_index(b2Fixture& fixture);

// Only fixtures of bodies that form a case contact pair collide, and none in
// the force-injection mode (the adapter applies the contact force itself).
class PairContactFilter final : public b2ContactFilter {
 public:
  PairContactFilter(const PairTable& pairs, const bool& enabled)
      : pairs_(pairs), enabled_(enabled) {}
  bool ShouldCollide(b2Fixture* fixture_a, b2Fixture* fixture_b) override;

 private:
  const PairTable& pairs_;
  const bool& enabled_;
};

// per contact pair, what the listener needs and what it found
struct PairState {
  ContactLaw law;
  bool per_onset = false;      // restitution recomputed at each onset (depends on m_eff)
  double restitution = 0.0;    // the value set on the pair's contacts (last computed)
  double threshold_mps = 1.0;  // m/s, restitution velocity threshold
  float friction = 0.0f;       // the pair's Coulomb coefficient (SPEC §7), set per contact
  double step_impulse_ns =
      0.0;  // N s, normal impulses of the current step (all points, TOI included)
  // N s, the step's tangent impulses on the case's body_b along t = n rotated
  // by +90 deg (issue 32): Box2D's tangent is b2Cross(normal, 1) = (n.y, -n.x)
  // for its normal from fixture A to B, its impulse acts on B; whichever
  // fixture is body_b, that is minus the sum of tangentImpulses
  double step_tangent_impulse_ns = 0.0;
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
// goes to every touching contact of the pair. Sums the solver's normal
// impulses per pair.
class PairContactListener final : public b2ContactListener {
 public:
  PairContactListener(const PairTable& pairs, std::vector<PairState>& states,
                      const std::vector<BodyInertia>& inertia, const double& time_s)
      : pairs_(pairs), states_(states), inertia_(inertia), time_s_(time_s) {}

  void PreSolve(b2Contact* contact, const b2Manifold* old_manifold) override;
  void PostSolve(b2Contact* contact, const b2ContactImpulse* impulse) override;

  void reserve_log(std::size_t capacity) { log_.reserve(capacity); }
  [[nodiscard]] const std::vector<OnsetRecord>& log() const { return log_; }
  [[nodiscard]] long unlogged() const { return unlogged_; }

 private:
  const PairTable& pairs_;
  std::vector<PairState>& states_;
  const std::vector<BodyInertia>& inertia_;  // per case body; centre and pivot are t = 0 values

  const double& time_s_;
  std::vector<OnsetRecord> log_;  // bounded by its reserved capacity
  long unlogged_ = 0;
};

}  // namespace pb::internal::box2d
