// Tests for core/analytic/damped_mode.cpp
#include "damped_mode.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace pb::internal {
namespace {

// x'' + 2 sigma x' + w0^2 x = 0 by RK4 with n steps over t: the independent truth
std::array<double, 2> integrate(double sigma, double w0sq, double x0, double v0, double t, int n) {
  std::array<double, 2> y{x0, v0};
  auto f = [&](const std::array<double, 2>& s) {
    return std::array<double, 2>{s[1], -2.0 * sigma * s[1] - w0sq * s[0]};
  };
  const double h = t / n;
  for (int i = 0; i < n; ++i) {
    const auto k1 = f(y);
    const auto k2 = f({y[0] + 0.5 * h * k1[0], y[1] + 0.5 * h * k1[1]});
    const auto k3 = f({y[0] + 0.5 * h * k2[0], y[1] + 0.5 * h * k2[1]});
    const auto k4 = f({y[0] + h * k3[0], y[1] + h * k3[1]});
    y[0] += h / 6.0 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]);
    y[1] += h / 6.0 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1]);
  }
  return y;
}

struct Damping {
  const char* name;
  double sigma;  // 1/s
};

// w0 = 100 rad/s (the cases' K = 1e4 N/m, m = 1 kg); sigma from zeta = 0,
// 0.05 (the cases), 1 - 1e-9 (just under critical), 1 (critical), 1 + 1e-9,
// 3 and 300 (strongly over-damped: the fast exponential underflows early)
class DampedModeRegimes : public ::testing::TestWithParam<Damping> {};

// The closed form against RK4 at 1e-5 s steps (w0 h = 1e-3: RK4's global
// error ~ (w0 h)^4 ~ 1e-12 relative) over 0.3 s, a few periods.
TEST_P(DampedModeRegimes, MatchesNumericalIntegration) {
  const double w0sq = 1e4;
  const double sigma = GetParam().sigma;
  const double x0 = 1e-3;  // m
  const double v0 = -0.7;  // m/s
  const DampedMode x(sigma, w0sq, x0, v0);
  for (double t : {0.0, 0.001, 0.0123, 0.05, 0.1, 0.3}) {
    const int n = std::max(1, static_cast<int>(t / 1e-5));
    const auto y = integrate(sigma, w0sq, x0, v0, t, n);
    // scales: x0 + v0 / w0 and v0 + w0 x0; RK4 error well below 1e-10 of them
    EXPECT_NEAR(x.value(t), y[0], 1e-10 * (x0 + 0.7 / 100.0)) << GetParam().name << " t=" << t;
    EXPECT_NEAR(x.rate(t), y[1], 1e-10 * (0.7 + 100.0 * x0)) << GetParam().name << " t=" << t;
  }
}

// derivative() is the mode of x': its value is x's rate everywhere.
TEST_P(DampedModeRegimes, DerivativeIsTheRate) {
  const DampedMode x(GetParam().sigma, 1e4, 1e-3, 0.4);
  const DampedMode dx = x.derivative();
  for (double t : {0.0, 0.002, 0.02, 0.2}) {
    // rounding of the two evaluations, relative to the rate scale 0.5 m/s
    EXPECT_NEAR(dx.value(t), x.rate(t), 1e-14) << GetParam().name;
  }
}

// Stationary points are roots of x' (to rounding of the rate scale) and
// ascend; x is monotone between them (checked by sampling). Only those in the
// first 0.5 s: near critical damping the next one lies hundreds of seconds
// on, where the motion has underflowed to zero and has no sign to check.
TEST_P(DampedModeRegimes, StationaryPointsAreRootsOfTheRate) {
  const DampedMode x(GetParam().sigma, 1e4, 1e-3, 0.4);
  double previous = 0.0;
  for (int k = 0; k < 6; ++k) {
    const double s = x.stationary_point(k);
    if (!(s < 0.5)) break;
    EXPECT_GT(s, previous);
    // x' ~ (rate scale 0.5 m/s) * (rounding of the phase w_d s, a few 1e-16)
    EXPECT_NEAR(x.rate(s), 0.0, 1e-14 * std::max(1.0, s * 100.0)) << GetParam().name << " k=" << k;
    // monotone between previous and s: the sign of x' does not change
    const double mid_sign = std::copysign(1.0, x.rate(0.5 * (previous + s)));
    for (int i = 1; i < 32; ++i) {
      const double t = previous + (s - previous) * i / 32.0;
      EXPECT_EQ(std::copysign(1.0, x.rate(t)), mid_sign) << GetParam().name;
    }
    previous = s;
  }
}

// |x(t)| <= A e^(-r t) at every sample.
TEST_P(DampedModeRegimes, EnvelopeBoundsTheMotion) {
  const DampedMode x(GetParam().sigma, 1e4, 1e-3, -0.7);
  for (int i = 0; i <= 3000; ++i) {
    const double t = 1e-4 * i;
    const double bound = x.envelope_amplitude() * std::exp(-x.envelope_rate() * t);
    EXPECT_LE(std::abs(x.value(t)), bound * (1.0 + 1e-12)) << GetParam().name << " t=" << t;
  }
}

INSTANTIATE_TEST_SUITE_P(Regimes, DampedModeRegimes,
                         ::testing::Values(Damping{"undamped", 0.0}, Damping{"zeta_0_05", 5.0},
                                           Damping{"near_critical_under", 100.0 * (1.0 - 1e-9)},
                                           Damping{"critical", 100.0},
                                           Damping{"near_critical_over", 100.0 * (1.0 + 1e-9)},
                                           Damping{"over_3", 300.0}, Damping{"over_300", 30000.0}),
                         [](const auto& p) { return std::string(p.param.name); });

// The textbook under-damped response from rest at x0 (Meirovitch §2.5):
// x = x0 e^(-sigma t) (cos w_d t + sigma / w_d sin w_d t); its stationary
// points are at w_d t = k pi, k >= 1.
TEST(DampedMode, UnderDampedFromRestIsTheTextbookForm) {
  const double sigma = 5.0;
  const double wd = std::sqrt(1e4 - 25.0);
  const DampedMode x(sigma, 1e4, 2e-3, 0.0);
  for (double t : {0.01, 0.1, 0.5}) {
    const double expect =
        2e-3 * std::exp(-sigma * t) * (std::cos(wd * t) + sigma / wd * std::sin(wd * t));
    EXPECT_NEAR(x.value(t), expect, 1e-17);  // rounding of a 2e-3 m amplitude
  }
  // k pi / w_d: one ulp of 0.03 s is 3.5e-18; 1e-16 and 4e-16 allow a few roundings
  EXPECT_NEAR(x.stationary_point(0), std::numbers::pi / wd, 1e-16);
  EXPECT_NEAR(x.stationary_point(3), 4.0 * std::numbers::pi / wd, 4e-16);
}

// Over-damped motion that starts toward zero but never crosses has no
// stationary point; one that is thrown away from zero has exactly one.
TEST(DampedMode, OverDampedHasAtMostOneStationaryPoint) {
  const DampedMode creeping(300.0, 1e4, 1e-3, -0.01);
  EXPECT_TRUE(std::isinf(creeping.stationary_point(0)));
  const DampedMode thrown(300.0, 1e4, 1e-3, 1.0);
  const double s = thrown.stationary_point(0);
  EXPECT_GT(s, 0.0);
  EXPECT_TRUE(std::isinf(thrown.stationary_point(1)));
  // rate of a 1 m/s motion at its root: rounding of O(1 m/s) terms
  EXPECT_NEAR(thrown.rate(s), 0.0, 1e-15);
}

// Zero motion stays zero and has no stationary points.
TEST(DampedMode, ZeroMotion) {
  const DampedMode x(5.0, 1e4, 0.0, 0.0);
  EXPECT_EQ(x.value(1.0), 0.0);
  EXPECT_TRUE(std::isinf(x.stationary_point(0)));
}

}  // namespace
}  // namespace pb::internal
