// Coulomb friction of the reference solver (SPEC §7): the tangential force of
// a contact pair with friction mu > 0, while its normal force presses.
//
// The stick model: rigid stick with located stick / slip events, the limit
// of an elastic tangential spring capped by Coulomb as its stiffness grows
// without bound. Why this one:
//   - it holds a body truly still while the load is inside the cone (what a
//     truth-grade reference must do): no stiction speed to creep at, as a
//     regularised law mu F tanh(v / v_s) would (its creep is v_s times the
//     load ratio, and its time constant m v_s / (mu F) is 2e-7 s at v_s =
//     1e-6 m/s for the 1 kg cases: ~1e7 rk45 steps per second of contact);
//   - it adds no tangential stiffness: no new fast mode for the step rule
//     (an elastic spring stiff enough to hold a 4 N load within 1e-6 m needs
//     k_t = 4e6 N/m, a 2000 rad/s mode, and its stored energy flips the
//     tangential velocity at the end of an impact, Maw, Barber & Fawcett
//     1976, which the rigid closed forms of SPEC §7 do not have);
//   - the closed forms of SPEC §7 (blocks holding and sliding, disks rolling
//     and slipping, slip ending at t* = v0 / (3 mu g)) are its own solutions.
//
// Per pair k, with t_k = (n.y, -n.x) (the normal turned clockwise by 90 deg)
// and the tangential speed v_k = t_k . (v_b(p_b) - v_a(p_a)) of b's contact
// point relative to a's, the force f_k t_k acts on b at p_b and -f_k t_k on
// a at p_a, in one of two phases that change only at located events:
//   slip   f = -mu F s, s = +-1 the direction of v latched when the phase
//          began (smooth inside the phase: no sign() to integrate across);
//   stick  f from the constraint that the contact points' relative
//          tangential acceleration is -beta v (beta = kStickRate_per_s):
//          J_j M^-1 J_k^T f_k summed over the sticking pairs k, plus
//          J_j u_dot_free + t_j . (c_b - c_a) (c: the points' centripetal
//          accelerations) = -beta v_j. With v = 0 at the event that began
//          the stick, v stays 0 up to the integrator's error, which beta
//          damps (so the stuck points drift by at most v / beta).
// Events (the solver's): slip -> stick candidate when s v falls below 0,
// stick -> slip when |f| rises above mu F; at each, and when a pair starts
// pressing, the new phase is stick if it can hold (|v| <= kStickSpeed_mps,
// the stick force within mu F), else slip in the direction the load drives.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <vector>

#include "planarbench/reference/contact_geometry.hpp"
#include "planarbench/reference/planar_model.hpp"

namespace pb {

// 1/s, the rate at which a stuck pair's residual tangential speed is damped:
// the stick constraint's stabilisation. The classic RK4 and Dormand-Prince
// stability regions reach -2.78 and -3.3 on the real axis, so it is stable for
// steps up to 2.78 / 100 = 0.028 s, above the largest default step (h_max 1e-2 s).
constexpr double kStickRate_per_s = 100.0;

// m/s, the tangential speed counted as none when a pair starts pressing or
// its slip reverses: a stuck pair is then held to it, and a point moving this
// fast moves 1e-13 m in one 1e-4 s output interval
constexpr double kStickSpeed_mps = 1e-9;

enum class SlipPhase { slip, stick };

// one pair's contribution to the stick solve
struct StickRow {
  int body_a = -1;
  int body_b = -1;
  Vec2 point_a_m = Vec2::Zero();   // m, world
  Vec2 point_b_m = Vec2::Zero();   // m, world
  Vec2 tangent = Vec2::Zero();     // unit
  double slip_rate_mps = 0.0;      // m/s, v
};

// The forces that keep the sticking pairs stuck, solved together (pairs that
// share a body couple). Sized once for a case's pair count; no allocation
// per solve.
class StickSolve {
 public:
  StickSolve(int coordinates, int max_rows);

  // the tangential force (N, on b along t) of each row, given the bodies'
  // generalised accelerations without them (u_dot_free); rows.size() <= max_rows
  void solve(const PlanarModel& model, const Eigen::VectorXd& q, const Eigen::VectorXd& u,
             const Eigen::VectorXd& u_dot_free, const std::vector<StickRow>& rows,
             std::vector<double>& force_n);

  // J^T of a row into g (overwritten): the generalised force of a unit
  // tangential force on the pair (t on b at p_b, -t on a at p_a)
  static void jacobian_transpose(const PlanarModel& model, const Eigen::VectorXd& q,
                                 const StickRow& row, Eigen::VectorXd& g);

 private:
  Eigen::VectorXd g_;      // coordinates
  Eigen::MatrixXd jt_;     // coordinates x max_rows: J^T of each row
  Eigen::MatrixXd a_;      // max_rows x max_rows, J M^-1 J^T (identity past the rows)
  Eigen::VectorXd rhs_, f_;
  Eigen::LDLT<Eigen::MatrixXd> ldlt_;
};

}  // namespace pb
