// Native mode's rule for MuJoCo's contact parameters (SPEC §5b: the engine as
// its users run it, parameters from the state at the time, no look-ahead).
//
// MuJoCo's soft contact follows the reference acceleration a_ref = -b v - k r
// in constraint space (ENGINES.md; engine_core_constraint.c mj_makeImpedance:
// K = -solref[0] / dmax^2, B = -solref[1] / dmax for a direct, negative
// solref), so a force law in N/m needs k and c divided by the effective mass
// along the normal, and that mass changes with the configuration and the
// contact point. At every evaluation of the dynamics, after mj_collision has
// found the contacts of the current state and before mj_makeConstraint turns
// them into constraint rows, this rule sets the solref of each case pair's
// contacts (and the pair's m->pair_solref, which the RK4 stages of the same
// step reuse) from:
//   - the case's law at the pair's current penetration delta (the deepest of
//     its contacts), as a linear spring-damper (k, c) (linearize_law: a
//     Kelvin-Voigt law is itself; Hertz and Lankarani-Nikravesh their secant
//     stiffness and eq. 7's damping coefficient at this delta, with the
//     approach speed latched at the pair's first step in contact);
//   - the effective mass of the pair's pressed contacts from MuJoCo's own
//     Jacobians and mass matrix, A = J M^-1 J^T (mj_jac, mj_solveM), and the
//     spread of one solref over several rows: solref = (-sigma k, -c) / m_set
//     with m_set = 1^T A^+ 1 and sigma = delta / delta_w
//     (planarbench/contact_set_mass.hpp), so that the rows' springs sum to
//     k delta (one force per pair, SPEC §1), the dampers to c times the
//     rows' mean normal speed (weighted by w = A^+ 1), and a uniform
//     penetration gives the law's force with every contact point
//     accelerated alike.
// Before that, a contact repeated at one point by two convex pieces of one
// body is fused into the first (mujoco_shared_vertex.hpp): one row a point.
// Per evaluation the contacts are grouped by pair once (mujoco_contact_buckets:
// a scene's group pairs are registered as MuJoCo's broad phase reports them),
// and only pairs with contacts are visited; the rows live on the two bodies'
// DOFs only (mujoco_sparse_jacobian: at most 6 numbers, the dense rows' own
// bits), so an evaluation costs O(contacts), not O(pairs x contacts x nv).
// Nothing is taken from the future: the rule sees the state the step starts
// from, as a user's code between mj_collision and mj_makeConstraint would.
#pragma once

#include <mujoco/mujoco.h>

#include <nlohmann/json.hpp>
#include <array>
#include <vector>

#include "mujoco_contact_buckets.hpp"
#include "mujoco_model.hpp"
#include "mujoco_pair_state.hpp"
#include "planarbench/case.hpp"
#include "planarbench/contact_set_mass.hpp"

namespace pb::internal::mujoco {

class SolrefRule {
 public:
  // `model` is the run's own model, whose pair_solref the rule writes;
  // `layout` gains the group pairs MuJoCo's collider reports
  SolrefRule(const Case& c, mjModel* model, ModelLayout& layout);

  // the hook of forward_checked (mujoco_stepping.hpp): `self` is a SolrefRule
  static void hook(void* self, const mjModel* m, mjData* d);

  // what the rule set last for pair k: solref (1/s^2, 1/s), m_set (kg), sigma
  struct Last {
    double solref_k = 0.0;
    double solref_b = 0.0;
    double mass_kg = 0.0;
    double scale = 1.0;
    int rows = 0;
  };
  [[nodiscard]] const Last& last(std::size_t k) const {
    static const Last kNone{};
    return k < last_.size() ? last_[k] : kNone;
  }
  // the largest sigma and the most pressed contacts of one pair seen so far
  [[nodiscard]] double largest_scale() const { return largest_scale_; }
  [[nodiscard]] int most_rows() const { return most_rows_; }
  // the most contacts fused into another in one evaluation (a vertex shared
  // by two convex pieces, mujoco_shared_vertex.hpp)
  [[nodiscard]] int most_fused() const { return fused_; }
  // the three above, as a run's mapping states them ("solref_rule_seen")
  [[nodiscard]] nlohmann::json seen_json() const;

 private:
  void apply(const mjModel* m, mjData* d);
  // A = J M^-1 J^T of rows_'s first n contacts of pair p, into a
  void set_matrix(const mjModel* m, mjData* d, const PairLayout& p, int k, int n,
                  ContactSetMatrix& a, std::array<double, kMaxContactSetPoints>& depth);

  mjModel* model_;
  ModelLayout& layout_;
  Scratch scratch_;
  ContactBuckets buckets_;
  std::vector<int> rows_;            // contact indices of one pair, deepest first
  // the rows' normal Jacobians and M^-1 of each: kMaxContactSetPoints x nv
  // (dense), or x the pair's DOFs (scratch_.sparse)
  std::vector<double> jrows_;
  std::vector<double> minv_rows_;
  // per pair: the approach speed latched at its first step pressed (NaN:
  // none), and the evaluation it was last pressed in (a pair not pressed in
  // the evaluation before is a new contact: it latches anew)
  std::vector<double> approach_mps_;
  std::vector<long> pressed_at_;
  long evaluation_ = 0;
  std::vector<Last> last_;
  double largest_scale_ = 1.0;
  int most_rows_ = 0;
  int fused_ = 0;
};

}  // namespace pb::internal::mujoco
