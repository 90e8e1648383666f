// Tests for adapters/ode/ode_probe.cpp
#include "ode_probe.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "ode_test_cases.hpp"

namespace pb::internal::ode {
namespace {

// The reference drop: the ball's lowest point starts 1.5 m above the line.
// Free fall reaches it at t = sqrt(2 * 1.5 / g) = 0.55311 s at v = 5.4240
// m/s. ODE's semi-implicit Euler falls g h t / 2 further than the exact
// parabola by time t, so it touches a little early, and the probe reports
// the first step at which dCollide sees the touch: within 2 steps of the
// closed form, at the closed-form speed within g * 2h. The centre is within
// one step's travel v h of y = 0.5 (+ rounding). The normal and the contact
// point's x are copied from the horizontal plane and the x = 0 drop: 1e-15.
TEST(OdeProbe, FirstTouchOfAFallingBall) {
  const Case c = ode_test::kelvin_voigt_drop(1.5, 1.0);
  const double h = 1e-4;
  long steps = -1;
  const auto touches = probe_first_touches(c, h, steps);
  ASSERT_EQ(touches.size(), 1u);
  const FirstTouch& t = touches[0];
  ASSERT_TRUE(t.found);
  // a look-ahead run (oracle mode only): it stepped up to the touch
  EXPECT_EQ(steps, std::lround(t.time_s / h));
  const double g = 9.8066;
  const double t_exact = std::sqrt(2.0 * 1.5 / g);
  EXPECT_NEAR(t.time_s, t_exact, 2.0 * h);
  EXPECT_NEAR(t.approach_speed_mps, g * t_exact, 2.0 * g * h);
  EXPECT_NEAR(t.normal_ab.y(), 1.0, 1e-15);
  EXPECT_NEAR(t.point_m.x(), 0.0, 1e-15);
  EXPECT_NEAR(t.centres_m[1].y(), 0.5, h * g * t_exact + 1e-12);
}

// No pair can touch within the duration: nothing found
TEST(OdeProbe, NoTouch) {
  const Case c = ode_test::kelvin_voigt_drop(1.5, 0.1);
  long steps = -1;
  const auto touches = probe_first_touches(c, 1e-4, steps);
  EXPECT_FALSE(touches[0].found);
  EXPECT_EQ(steps, 1000);  // the whole 0.1 s
}

}  // namespace
}  // namespace pb::internal::ode
