// The run's contact pairs as the adapter's Box2D callbacks see them: the
// case's ContactPairs (declared pairs, then a group's pairs as Box2D's broad
// phase pairs their fixtures, SPEC §11) and, indexed like them, what each
// pair's contacts are given (restitution, friction) and what the solver gave
// it (impulses). A group pair's entry is made from its group's when Box2D
// first pairs the two bodies, so the list grows with the contacts that exist,
// never with the pairs that could.
#pragma once

#include <optional>
#include <vector>

#include "box2d_restitution.hpp"
#include "planarbench/case.hpp"
#include "planarbench/contact_pairs.hpp"

namespace pb::internal::box2d {

// per contact pair, what the listener needs and what it found
struct PairState {
  ContactLaw law;
  bool per_onset = false;      // restitution recomputed at each onset (depends on m_eff)
  double restitution = 0.0;    // the value set on the pair's contacts (last computed)
  double threshold_mps = 1.0;  // m/s, restitution velocity threshold
  float friction = 0.0f;       // the pair's Coulomb coefficient (SPEC §7), set per contact
  // the b2World::Step the impulses below belong to (PairBook::step); a pair
  // the solver did not touch in a step keeps an older one and had none then,
  // so no step clears every pair's sums
  long impulse_step = -1;
  double step_impulse_ns = 0.0;  // N s, normal impulses of that step (all points, TOI included)
  // N s, the step's tangent impulses on the case's body_b along t = n rotated
  // by +90 deg (issue 32): Box2D's tangent is b2Cross(normal, 1) = (n.y, -n.x)
  // for its normal from fixture A to B, its impulse acts on B; whichever
  // fixture is body_b, that is minus the sum of tangentImpulses
  double step_tangent_impulse_ns = 0.0;

  // N s, the normal and tangent impulses of step `step` (0 when the solver
  // gave the pair none then)
  [[nodiscard]] double impulse_ns(long step) const {
    return impulse_step == step ? step_impulse_ns : 0.0;
  }
  [[nodiscard]] double tangent_impulse_ns(long step) const {
    return impulse_step == step ? step_tangent_impulse_ns : 0.0;
  }
};

class PairBook {
 public:
  // The pairs of `c`: `declared[k]` for Case::contacts[k], `groups[g]` the
  // state every pair of Case::contact_groups[g] starts from.
  void reset(const Case& c, std::vector<PairState> declared, std::vector<PairState> groups);

  // whether some rule lets case bodies i and j touch (false for a fixture
  // without a body index, -1)
  [[nodiscard]] bool may_touch(int i, int j) const;
  // the pair of bodies i and j, added (with its group's state) when it has
  // none yet; -1 when no rule lets them touch
  int find_or_add(int i, int j);
  // ... without adding: -1 when it has no index yet
  [[nodiscard]] int find(int i, int j) const;

  [[nodiscard]] int size() const { return static_cast<int>(states_.size()); }
  [[nodiscard]] const ContactPair& pair(int k) const { return (*pairs_)[k]; }
  [[nodiscard]] const ContactPairs& pairs() const { return *pairs_; }
  [[nodiscard]] PairState& state(int k) { return states_[static_cast<std::size_t>(k)]; }
  [[nodiscard]] const PairState& state(int k) const { return states_[static_cast<std::size_t>(k)]; }

  // the b2World::Step being taken (1 for the first): the stamp of the
  // impulses PostSolve sums
  long step = 0;

 private:
  std::optional<ContactPairs> pairs_;  // ContactPairs is made from a case
  std::vector<PairState> states_;      // indexed like *pairs_
  std::vector<PairState> groups_;      // per contact group, its pairs' first state
  // per body, its pairs (other body, pair index): a lookup scans the shorter
  // list of the two (a disk's dozen, not the ground's thousand), which in a
  // pile costs a third of ContactPairs' hash lookup (called for each of
  // Box2D's contacts each step)
  std::vector<std::vector<std::pair<int, int>>> adjacent_;
  int bodies_ = 0;
};

}  // namespace pb::internal::box2d
