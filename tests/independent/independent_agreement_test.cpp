// Tests for core/independent/independent_truth.cpp: its agreement with the
// converged reference (the reference solver at exact geometry, rk45 at rtol
// 1e-12, atol 1e-14: core/analytic/converged_reference.cpp's truth settings)
// on the three cases whose truth it replaces. The two share no code (issue 25):
// what they agree on is not an artefact of either.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "planarbench/case_loader.hpp"
#include "planarbench/independent/independent_truth.hpp"
#include "planarbench/reference/reference_solver.hpp"

namespace pb {
namespace {

// Each solver's error controller admits per step and per state component a
// local error of at most atol + rtol |y|: this truth abs = rel = 1e-12, the
// converged reference atol 1e-14, rtol 1e-12. Summed over both solvers' steps
// with no cancellation, their difference in a component of size <= Y is at
// most  n_i (1e-12 + 1e-12 Y) + n_r (1e-14 + 1e-12 Y)  (the bound each
// tolerance below is built on; the impacts could amplify it, the measured
// figures, printed, are 2-4 decades below it).
double summed_local_error(long n_i, long n_r, double y) {
  return static_cast<double>(n_i) * (1e-12 + 1e-12 * y) +
         static_cast<double>(n_r) * (1e-14 + 1e-12 * y);
}

// the reference counts a pair as touching from a distance of 1e-10 m
// (ContactPair::threshold_m, paper §2.1.1); this truth from 0
constexpr double kThresholdM = 1e-10;  // m
// |d^2 delta / dt^2| before the touch, m/s^2: gravity plus the centripetal
// terms omega^2 r of the three cases (ellipse_incline 4^2 x 0.3 = 4.8,
// pendulum_wall (2.5 / 0.6)^2 x 0.7 = 12, dual_pendulum (1.8 / 0.7071)^2 x
// 0.96 = 6.2): <= 9.8 + 12 = 22
constexpr double kDeltaAccelMps2 = 22.0;

void expect_agreement(const std::string& name) {
  const Case c = load_case(std::string(PB_CASES_DIR) + "/" + name + ".toml");
  ReferenceSettings s;
  s.geometry = "exact";
  s.integrator = "rk45";
  s.rtol = 1e-12;
  s.atol = 1e-14;
  ReferenceSolver ref(c, s);
  independent::IndependentTruth ind(c);
  double position = 0.0;  // m, largest difference on the output grid
  double angle = 0.0;     // rad
  double size_x = 0.0;    // m, largest |x| of a centre
  double size_a = 0.0;    // rad, largest |theta|
  double size_v = 0.0;    // m/s, largest |v|
  std::vector<BodyState> states;
  for (int k = 0; k < c.output_samples(); ++k) {
    const double t = c.output_time(k);
    ref.advance_to(t);
    ind.advance_to(t);
    ind.body_states(states);
    for (std::size_t i = 0; i < c.bodies.size(); ++i) {
      if (c.bodies[i].fixed) continue;
      const BodyState r = ref.body_state(static_cast<int>(i));
      position = std::max(position, (r.position_m - states[i].position_m).norm());
      angle = std::max(angle, std::abs(r.angle_rad - states[i].angle_rad));
      size_x = std::max(size_x, states[i].position_m.norm());
      size_a = std::max(size_a, std::abs(states[i].angle_rad));
      size_v = std::max(size_v, states[i].velocity_mps.norm());
    }
  }
  const long n_i = ind.steps();
  const long n_r = ref.stats().steps;
  const double position_tol = summed_local_error(n_i, n_r, size_x);  // m
  const double angle_tol = summed_local_error(n_i, n_r, size_a);     // rad
  const double speed_tol = summed_local_error(n_i, n_r, size_v);     // m/s
  EXPECT_LE(position, position_tol) << name;
  EXPECT_LE(angle, angle_tol) << name;
  std::printf(
      "%s over %g s: position %.3g m (tolerance %.3g), angle %.3g rad (tolerance %.3g); "
      "steps %ld / %ld\n",
      name.c_str(), c.duration_s, position, position_tol, angle, angle_tol, n_i, n_r);

  const auto er = ref.episodes();
  const auto ei = ind.episodes();
  ASSERT_EQ(ei.size(), er.size()) << name;
  double cumulative_ns = 0.0;  // N s
  for (std::size_t k = 0; k < ei.size(); ++k) {
    const double app = ei[k].approach_speed_mps;  // m/s
    // onset: the reference's threshold crossed threshold / approach earlier,
    // plus the positions' error over the approach speed
    const double onset_tol = (kThresholdM + position_tol) / app;
    // restitution: each speed errs by the velocities' bound, and the
    // reference reads its approach speed threshold / approach earlier, when
    // delta_dot differed by up to kDeltaAccelMps2 times that: over e's
    // denominator, (1 + e) times each
    const double early_mps = kDeltaAccelMps2 * kThresholdM / app;
    const double restitution_tol = (1.0 + ei[k].restitution) * (speed_tol + early_mps) / app;
    // impulse: the impulse state's bound (the force is 0 in the threshold's
    // gap: no share of it), relative to the episode's impulse; the state is
    // the pair's impulse so far, episodes 0..k (one pair in these cases)
    cumulative_ns += ei[k].impulse_ns;
    const double impulse_tol = summed_local_error(n_i, n_r, cumulative_ns) / ei[k].impulse_ns;
    const double d_onset = std::abs(ei[k].onset_time_s - er[k].onset_time_s);
    const double d_e = std::abs(ei[k].restitution - er[k].restitution);
    const double d_j = std::abs(er[k].impulse_ns / ei[k].impulse_ns - 1.0);
    EXPECT_LE(d_onset, onset_tol) << name << " episode " << k;
    EXPECT_LE(d_e, restitution_tol) << name << " episode " << k;
    EXPECT_LE(d_j, impulse_tol) << name << " episode " << k;
    std::printf(
        "%s episode %zu: onset %.3g s (tolerance %.3g), restitution %.12g vs %.12g: %.3g "
        "(tolerance %.3g), impulse %.12g vs %.12g N s: %.3g relative (tolerance %.3g), "
        "peak force %.10g vs %.10g N: %.3g relative\n",
        name.c_str(), k, d_onset, onset_tol, ei[k].restitution, er[k].restitution, d_e,
        restitution_tol, ei[k].impulse_ns, er[k].impulse_ns, d_j, impulse_tol, ei[k].peak_force_n,
        er[k].peak_force_n, std::abs(er[k].peak_force_n / ei[k].peak_force_n - 1.0));
  }
}

// the whole duration of each case: the four together take ~50 ms (release)
TEST(IndependentAgreement, EllipseIncline) {
  expect_agreement("ellipse_incline");
}
TEST(IndependentAgreement, DualPendulum) {
  expect_agreement("dual_pendulum");
}
TEST(IndependentAgreement, PendulumWall) {
  expect_agreement("pendulum_wall");
}
// issue 25's concave corner (truth = converged): a polygon's single vertex on
// the line; released at rest, its delta_ddot before the touch is g (<= 22)
TEST(IndependentAgreement, ConcaveCorner) {
  expect_agreement("concave_corner");
}

}  // namespace
}  // namespace pb
