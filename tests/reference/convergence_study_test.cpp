// Tests for core/reference/src/convergence_study.cpp
//
// The observed orders of accuracy of the reference solver on falling_ball's
// first impact: 4 in the step of fixed RK4 (events located, so the impact's
// non-smooth force does not lower the order), 2 in the outline point count
// (the inscribed polygon's sag R (1 - cos(pi/N)) ~ pi^2 R / (2 N^2)).
#include "planarbench/reference/convergence_study.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "planarbench/case_loader.hpp"

namespace pb {
namespace {

Case falling_ball() { return load_case(std::string(PB_CASES_DIR) + "/falling_ball.toml"); }

TEST(ConvergenceStudy, FixedRk4IsFourthOrderInTheStep) {
  // through the first impact (t = 1.0 s) against rk45 at rtol 1e-12
  const ConvergenceTable t = step_size_convergence(falling_ball(), 1, 1.0, {5e-4, 2.5e-4, 1.25e-4});
  ASSERT_EQ(t.rows.size(), 3u);
  for (std::size_t i = 1; i < 3; ++i) {
    SCOPED_TRACE(i);
    // position and restitution: 3.6 .. 4.4 (the approach to 4 from below is
    // the impact's higher-order terms; measured 3.78 and 3.88)
    EXPECT_GT(t.rows[i].orders[0], 3.6);
    EXPECT_LT(t.rows[i].orders[0], 4.4);
    EXPECT_GT(t.rows[i].orders[4], 3.6);
    EXPECT_LT(t.rows[i].orders[4], 4.4);
  }
  // the finest step is already accurate to 1e-9 m: RK4's error on the
  // contact oscillator (w = sqrt(K/m) = 100 rad/s) scales as (w h)^4 times
  // its 0.058 m amplitude, 2.4e-8 * 0.058 m = 1.4e-9 m at h = 1.25e-4 s (the
  // free flights are quadratic, exact); measured 1.3e-10 m. A third-order
  // scheme, (w h)^3 * 0.058 m = 1.1e-7 m, fails it.
  EXPECT_LT(t.rows[2].errors[0], 1e-9);
}

TEST(ConvergenceStudy, OutlineIsSecondOrderInThePointCount) {
  // The disk turned by a third of the 45-point spacing: no outline point
  // lies on the contact normal for N = 45 * 2^k, so the outline's error is
  // the same fraction of its sag at every N. rk45 at rtol 1e-10 is far below
  // the outline errors (>= 1e-6 s, 1e-5 m at N = 360).
  Case c = falling_ball();
  c.bodies[1].angle_rad += 2.0 * std::numbers::pi / (3.0 * 45.0);
  const ConvergenceTable t = outline_convergence(c, 1, 0.8, {90, 180, 360}, 1e-10);
  ASSERT_EQ(t.rows.size(), 3u);
  // acceptance: order in N between 1.8 and 2.2 for the trajectory, the onset,
  // the peak force and the peak penetration (measured 1.88 .. 2.13)
  for (std::size_t i = 1; i < 3; ++i) {
    for (std::size_t q = 0; q < 4; ++q) {
      SCOPED_TRACE(t.quantities[q] + " row " + std::to_string(i));
      EXPECT_GT(t.rows[i].orders[q], 1.8);
      EXPECT_LT(t.rows[i].orders[q], 2.2);
    }
  }
  // the onset error is the gap error over the approach speed: the outline
  // point nearest the normal is a third of the spacing 2 pi / N off it,
  // so the gap is R (1 - cos(2 pi / (3N))) too large
  const double n = 180.0;
  // (6.1573 m/s: SPEC §2 normal approach speed, 5 digits)
  const double expect = 0.5 * (1.0 - std::cos(2.0 * std::numbers::pi / (3.0 * n))) / 6.1573;
  // relative 1e-3: the gap error is closed by an accelerating fall, not a
  // uniform one (a g t / v = 1e-5 s * 8.5 m/s^2 / 6.16 m/s ~ 1e-5 relative),
  // the speed is printed to 1e-5, rk45 at rtol 1e-10 errs by 1e-10 s against
  // 1.2e-6 s: all far below 1e-3, while a gap off by the wrong angle
  // (pi/N instead of 2 pi / 3N) would be 2.25x
  EXPECT_NEAR(t.rows[1].errors[1] / expect, 1.0, 1e-3);
}

TEST(ConvergenceStudy, TableFormatting) {
  ConvergenceTable t;
  t.title = "demo";
  t.parameter_name = "dt [s]";
  t.quantities = {"x [m]"};
  t.rows = {ConvergenceRow{0.1, {1e-3}, {std::nan("")}, 10}, ConvergenceRow{0.05, {6.25e-5}, {4.0}, 20}};
  const std::string s = format_table(t);
  EXPECT_NE(s.find("demo"), std::string::npos);
  EXPECT_NE(s.find("4.00"), std::string::npos);
  EXPECT_NE(s.find("6.250e-05"), std::string::npos);
}

}  // namespace
}  // namespace pb
