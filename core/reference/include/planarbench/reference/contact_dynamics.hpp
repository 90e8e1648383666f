// The equations of motion of a case with its contact forces, as a first-order
// ODE y' = f(y) for the integrators:
//   y = [q (n), u (n), J (one per contact pair)],
//   q' = u,  M u' = Q_gravity + Q_contact(q, u),  J_k' = F_k,
// where J_k, the running normal impulse of pair k (N s), is integrated with
// the motion so that episode impulses are as accurate as the trajectory.
// A case with friction on any pair (SPEC §7) appends, per pair, its running
// tangential impulse Jt_k' = f_k (N s) and the energy its friction has
// dissipated, W_k' = -f_k v_k >= 0 (J): y = [q, u, J, Jt, W]. A frictionless
// case keeps y = [q, u, J] and the arithmetic it always had.
// A case with contact groups (SPEC §11) appends each group pair's slots, [J]
// or [J, Jt, W], after the declared pairs' when its broad phase
// (near_pairs.hpp) first finds the pair: y grows between steps, and a
// declared-only case keeps the layout above bit for bit. Only the active
// pairs (every declared pair, the group pairs near now) are evaluated.
//
// Contact forces (paper §2.1.2). For each pair the geometry gives the signed
// gap s, the normal n (a -> b) and the contact points p_a, p_b (pair_geometry).
// delta = -s, and delta_dot = -n . (v_b(p_b) - v_a(p_a)) from the velocities of
// the two material points (the rate of the signed distance, exact for the
// closest / deepest point pair). The normal force F n acts on b at p_b and
// -F n on a at p_a, so it produces torques. F depends on the pair's discrete
// phase, which changes only at located events (reference_solver.hpp):
//   apart     s > threshold: no force;
//   touching  contact declared (s <= threshold once), no force: before delta
//             turns positive, or after the law's clamp released it;
//   pressing  F = the law without its clamp (unclamped_force.hpp).
// Inside each phase f is smooth, which is what an order-p integrator needs.
// Friction (coulomb_friction.hpp) acts while a pair presses, in the pair's
// slip or stick phase, which also change only at located events.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/contact_pairs.hpp"
#include "planarbench/reference/coulomb_friction.hpp"
#include "planarbench/reference/near_pairs.hpp"
#include "planarbench/reference/ode_system.hpp"
#include "planarbench/reference/pair_geometry.hpp"
#include "planarbench/reference/planar_model.hpp"
#include "planarbench/reference/sparse_stick_solve.hpp"

namespace pb {

enum class ContactPhase { apart, touching, pressing };

struct PairMode {
  ContactPhase phase = ContactPhase::apart;
  double approach_speed_mps = 0.0;  // m/s, delta_dot latched when the contact was declared
  // friction (pairs with friction > 0): the tangential phase while pressing,
  // and in slip the direction s = +-1 of the tangential speed it opposes
  SlipPhase slip = SlipPhase::slip;
  double slip_sign = 1.0;
};

struct PairEvaluation {
  ContactGeometry geometry;
  double gap_rate_mps = 0.0;        // m/s, d(gap)/dt, > 0 separating
  double unclamped_force_n = 0.0;   // N, the law without the clamp at 0
  double force_n = 0.0;             // N, applied (phase pressing: unclamped; else 0)
  // friction: unit tangent t = (n.y, -n.x), the tangential speed of b's
  // contact point relative to a's along it, and the tangential force on b
  // along t (0 unless the pair has friction and presses). Set by derivative().
  Vec2 tangent = Vec2(1.0, 0.0);
  double slip_rate_mps = 0.0;       // m/s
  double friction_n = 0.0;          // N
};

class ContactDynamics final : public OdeSystem {
 public:
  // throws std::invalid_argument for what the model or the geometry cannot do
  ContactDynamics(const Case& c, GeometryMode mode, DetectionMode detection = DetectionMode::fast);

  [[nodiscard]] int coordinates() const { return model_.coordinates(); }
  [[nodiscard]] int pair_count() const { return pairs_.size(); }
  [[nodiscard]] bool has_friction() const { return has_friction_; }
  [[nodiscard]] bool has_groups() const { return !near_.empty(); }
  [[nodiscard]] int state_size() const { return 2 * coordinates() + slots() * pair_count(); }
  [[nodiscard]] const PlanarModel& model() const { return model_; }
  [[nodiscard]] const ContactPair& pair(int k) const { return pairs_[k]; }
  // the pairs evaluated now, ascending: every declared pair and the group
  // pairs the broad phase found near (all pairs of a case without groups)
  [[nodiscard]] const std::vector<int>& active() const { return active_; }
  // index of pair k's impulse in y
  [[nodiscard]] int impulse_index(int k) const {
    return k < declared_ ? 2 * coordinates() + k : group_slot(k);
  }
  // with friction: index of pair k's tangential impulse and friction dissipation in y
  [[nodiscard]] int tangential_impulse_index(int k) const {
    return k < declared_ ? 2 * coordinates() + declared_ + k : group_slot(k) + 1;
  }
  [[nodiscard]] int dissipation_index(int k) const {
    return k < declared_ ? 2 * coordinates() + 2 * declared_ + k : group_slot(k) + 2;
  }

  // Groups: rebuilds the list of near group pairs at y when due
  // (near_pairs.hpp); new pairs get their slots at the end of y (the caller
  // grows its vectors to state_size(), the new slots 0). Returns whether the
  // active pairs changed.
  bool update_near(const Eigen::VectorXd& y);
  // the largest fraction of its broad-phase margin a group body moved at y
  // since the last rebuild; 0 without groups
  [[nodiscard]] double near_excursion(const Eigen::VectorXd& y) const;
  [[nodiscard]] long near_rebuilds() const { return near_.rebuilds(); }

  // the discrete phase of every pair; f uses it, the solver changes it
  [[nodiscard]] std::vector<PairMode>& modes() { return modes_; }
  [[nodiscard]] const std::vector<PairMode>& modes() const { return modes_; }

  void initial_state(Eigen::VectorXd& y) const;

  // dy = f(y) under the current modes; the pair evaluations at y are kept
  // (last_pairs) for event detection. No allocation.
  void derivative(const Eigen::VectorXd& y, Eigen::VectorXd& dy) override;
  [[nodiscard]] const std::vector<PairEvaluation>& last_pairs() const { return last_; }
  [[nodiscard]] long evaluations() const { return evaluations_; }

  // pair k at y under `mode`, without the derivative (friction_n: 0)
  [[nodiscard]] PairEvaluation evaluate_pair(int k, const Eigen::VectorXd& y, const PairMode& mode);

  // Every pair at y under `modes` with its friction force (the derivative's
  // evaluation: a stick force needs every other force), for output between
  // steps (issue 32); the phases and the evaluation count are left as they were.
  void evaluate_with_friction(const Eigen::VectorXd& y, const std::vector<PairMode>& modes,
                              std::vector<PairEvaluation>& out);

  // Chooses pair k's tangential phase at y now that it presses (at its
  // onset, when its slip speed crossed zero, or when its stick force reached
  // the cone): stick if it can hold (|v| <= kStickSpeed_mps and the stick
  // force within friction x F), else slip in the direction the load drives
  // it. Evaluates f at y (last_pairs then holds the result).
  void choose_slip_phase(int k, const Eigen::VectorXd& y);

  [[nodiscard]] BodyState body_state(int body, const Eigen::VectorXd& y) const;
  [[nodiscard]] double energy_j(const Eigen::VectorXd& y) const;
  [[nodiscard]] double joint_violation_m(const Eigen::VectorXd& y) const;

  // Why state y is past what the contact geometry can represent, or "" when
  // it is not: the centre of mass of a convex moving body of a pair lies
  // inside the other body. Its penetration is then deeper than the body's own
  // extent from its centre, no contact law of the case is meant for that,
  // and the outline search, which finds crossings of the two outlines, loses
  // the contact altogether once one outline is wholly past the other (issue
  // 15: a ball dropped at 1e4 m/s went on through the ground as `ok`).
  // Concave bodies are not checked: their centre may lie outside their
  // material.
  [[nodiscard]] std::string beyond_geometry(const Eigen::VectorXd& y) const;

 private:
  PairEvaluation evaluate(int k, const PairMode& mode);  // on q_, u_
  // the friction forces of every pair that has friction and presses, added
  // to gen_force_ (slip first, then the stick solve on top of them)
  void add_friction();
  // the couple of pair k's damping over a face (ContactGeometry::spread_m2),
  // added to gen_force_; pairs with friction only (coulomb_friction.hpp)
  void add_damping_couple(int k, const PairEvaluation& e);

  // slots per pair in y: J, or J, Jt, W with friction
  [[nodiscard]] int slots() const { return has_friction_ ? 3 : 1; }
  [[nodiscard]] int group_slot(int k) const {
    return 2 * coordinates() + slots() * k;  // k >= declared_: after every declared slot
  }
  // per-pair state for pairs added to pairs_ since the last call
  void add_pair_state();

  PlanarModel model_;
  ContactPairs pairs_;
  int declared_ = 0;
  std::vector<int> active_;
  NearPairs near_;
  std::vector<int> near_scratch_;
  DetectionMode detection_;
  GeometryMode mode_;
  std::vector<bool> face_;  // per pair: friction on a face (contact_dynamics.cpp)
  std::vector<std::unique_ptr<PairGeometry>> geometry_;
  std::vector<PairMode> modes_;
  std::vector<PairEvaluation> last_;
  std::vector<Body> bodies_;            // the case's, for beyond_geometry
  std::vector<double> reach_m_;         // m, farthest material point from each centre
  std::vector<bool> convex_;            // body is convex (its centre in its material)
  Eigen::VectorXd q_, u_, gen_force_;  // scratch
  long evaluations_ = 0;
  // friction
  bool has_friction_ = false;
  StickSolve stick_;
  SparseStickSolve sparse_stick_;        // scenes (has_groups)
  std::vector<StickRow> stick_rows_;     // scratch: the sticking pairs' rows
  std::vector<int> stick_pairs_;         // scratch: their pair indices
  std::vector<double> stick_force_n_;    // scratch: their forces
  Eigen::VectorXd u_dot_;                // scratch
  Eigen::VectorXd output_dy_;            // scratch: evaluate_with_friction's derivative
  std::vector<PairMode> kept_modes_;     // scratch: the phases it leaves as they were
};

}  // namespace pb
