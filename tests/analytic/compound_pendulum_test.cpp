// Tests for core/analytic/compound_pendulum.cpp
#include "compound_pendulum.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "independent_integrators.hpp"

namespace pb::internal {
namespace {

const Vec2 kGravity(0.0, -9.8066);  // m/s^2

// The dual pendulum's ellipse: m = 1 kg, I = m (a^2 + b^2) / 4 with
// a = 0.7071, b = 0.25, centre 45 degrees to the -x side of the pivot at the
// origin, released from rest. Compound pendulum: I_p = I + m d^2,
// w0^2 = m g d / I_p, phi'' = -w0^2 sin(phi) (e.g. Meriam & Kraige,
// Dynamics, §6/4); phi measured from straight down, counter-clockwise.
Body ellipse_body() {
  Body b;
  b.name = "ellipse";
  b.shape = Ellipse{0.7071, 0.25};
  b.mass_kg = 1.0;
  b.inertia_kgm2 = (0.7071 * 0.7071 + 0.25 * 0.25) / 4.0;
  b.position_m = Vec2(-0.5, -0.5);
  b.angle_rad = std::numbers::pi / 4.0;
  return b;
}

double omega0_sq_of(const Body& b, const Vec2& pivot) {
  const double d = (b.position_m - pivot).norm();
  return b.mass_kg * 9.8066 * d / (b.inertia_kgm2 + b.mass_kg * d * d);
}

// phi of the state: angle of pivot -> centre from straight down
double arm_angle_of(const BodyState& s, const Vec2& pivot) {
  const Vec2 r = s.position_m - pivot;
  return std::atan2(r.x(), -r.y());
}

// The swing against RK4 (h = 1e-5 s: w0 h = 3e-5, global error ~1e-17 per
// unit time) over two periods.
TEST(CompoundPendulum, LibrationMatchesNumericalIntegration) {
  const Body b = ellipse_body();
  const CompoundPendulum p(Vec2::Zero(), b, kGravity);
  EXPECT_EQ(p.regime(), PendulumRegime::libration);
  // k = sin(phi0 / 2) from the release angle: one rounding of a ~0.38 result
  EXPECT_NEAR(p.modulus(), std::sin(std::numbers::pi / 8.0), 1e-16);
  const double w0sq = omega0_sq_of(b, Vec2::Zero());
  for (double t : {0.1, 0.4965, 0.77, 1.3, 2.5, 4.0}) {
    const auto y = testing::pendulum_rk4(-std::numbers::pi / 4.0, 0.0, w0sq, t, 1e-5);
    const BodyState s = p.state_at(t);
    // 1e-12 rad: RK4 and closed form agree to ~1e-14 over 4 s
    EXPECT_NEAR(arm_angle_of(s, Vec2::Zero()), y[0], 1e-12) << "t=" << t;
    EXPECT_NEAR(s.angular_velocity_radps, y[1], 1e-12) << "t=" << t;
  }
}

// The period: the time RK4 takes from the release to the far turning point
// (phi' back to zero, located by bisection on the last step) is half of the
// closed form's period 4 K(k) / w0, and there the closed form is at +phi0.
TEST(CompoundPendulum, PeriodMatchesNumericalIntegration) {
  const Body b = ellipse_body();
  const CompoundPendulum p(Vec2::Zero(), b, kGravity);
  const double w0sq = omega0_sq_of(b, Vec2::Zero());
  const double phi0 = -std::numbers::pi / 4.0;
  // march RK4 in 1 ms pieces until phi' changes sign, then bisect the piece
  double t = 0.0;
  std::array<double, 2> y{phi0, 0.0};
  for (;;) {
    const auto next = testing::pendulum_rk4(y[0], y[1], w0sq, 1e-3, 1e-5);
    if (!(next[1] > 0.0) && t > 0.0) break;
    y = next;
    t += 1e-3;
  }
  double lo = 0.0;
  double hi = 1e-3;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (testing::pendulum_rk4(y[0], y[1], w0sq, mid, 1e-5)[1] > 0.0 ? lo : hi) = mid;
  }
  const double half_period_rk4 = t + 0.5 * (lo + hi);
  // the bisection ends at ~1e-15 s; RK4's phase error at h = 1e-5 is below that
  EXPECT_NEAR(0.5 * p.period_s(), half_period_rk4, 1e-11);
  // the complete elliptic integral by the test's own AGM
  const double k2 = std::pow(std::sin(std::numbers::pi / 8.0), 2);
  // two AGMs both converge to rounding: a few ulps of a ~2 s period
  EXPECT_NEAR(p.period_s(), 4.0 * testing::complete_elliptic_k_by_agm(k2) / std::sqrt(w0sq), 1e-15);
  const BodyState at_half = p.state_at(0.5 * p.period_s());
  // sn/cn at u = 2K: rounding of K times a few ulps (~1e-15); 1e-14 rad, 1e-14 rad/s
  EXPECT_NEAR(arm_angle_of(at_half, Vec2::Zero()), -phi0, 1e-14);
  EXPECT_NEAR(at_half.angular_velocity_radps, 0.0, 1e-14);
}

// Energy 1/2 m v^2 + 1/2 I w^2 - m g . c is constant (relative 1e-14), the
// centre stays at the pivot distance, the body turns with its arm and the
// centre's velocity is w x (c - pivot).
TEST(CompoundPendulum, InvariantsOfTheSwing) {
  const Body b = ellipse_body();
  const CompoundPendulum p(Vec2::Zero(), b, kGravity);
  const double d = b.position_m.norm();
  auto energy = [&](const BodyState& s) {
    return 0.5 * b.mass_kg * s.velocity_mps.squaredNorm() +
           0.5 * b.inertia_kgm2 * s.angular_velocity_radps * s.angular_velocity_radps -
           b.mass_kg * kGravity.dot(s.position_m);
  };
  const double e0 = energy(p.state_at(0.0));
  const double scale = b.mass_kg * 9.8066 * d;  // J, the size of the potential
  for (int i = 0; i <= 400; ++i) {
    const double t = 0.01 * i;
    const BodyState s = p.state_at(t);
    EXPECT_NEAR(energy(s), e0, 1e-14 * scale) << "t=" << t;
    // rigid arm: d (cos, sin) to rounding, a few ulps of 0.7 m; angles and
    // velocities below likewise to rounding of O(1) quantities
    EXPECT_NEAR(s.position_m.norm(), d, 1e-15) << "t=" << t;
    const double phi = arm_angle_of(s, Vec2::Zero());
    EXPECT_NEAR(std::remainder(s.angle_rad - b.angle_rad - (phi + std::numbers::pi / 4.0),
                               2.0 * std::numbers::pi),
                0.0, 1e-14);
    const Vec2 r = s.position_m;
    EXPECT_NEAR((s.velocity_mps - s.angular_velocity_radps * Vec2(-r.y(), r.x())).norm(), 0.0,
                1e-15);
  }
}

// A body hanging at rest straight below its pivot stays put, bit for bit.
TEST(CompoundPendulum, RestStaysPut) {
  Body disk;
  disk.shape = Circle{0.5};
  disk.mass_kg = 1.0;
  disk.inertia_kgm2 = 0.125;
  disk.position_m = Vec2(0.75, -0.7071);
  disk.angle_rad = 0.3;
  const CompoundPendulum p(Vec2(0.75, 0.0), disk, kGravity);
  EXPECT_EQ(p.regime(), PendulumRegime::rest);
  EXPECT_TRUE(std::isinf(p.time_scale_s()));
  const BodyState s = p.state_at(1.7);
  EXPECT_EQ(s.position_m, disk.position_m);
  EXPECT_EQ(s.angle_rad, 0.3);
  EXPECT_EQ(s.velocity_mps, Vec2::Zero());
  EXPECT_EQ(s.angular_velocity_radps, 0.0);
}

// Thrown backwards (negative rate) while swinging, over the top (rotation,
// k > 1) and exactly on the separatrix (k = 1): against RK4.
struct Throw {
  const char* name;
  double phi0;     // rad
  double rate0;    // in units of w0
  double horizon;  // s
  double tol;      // rad
};
class CompoundPendulumThrows : public ::testing::TestWithParam<Throw> {};

TEST_P(CompoundPendulumThrows, MatchesNumericalIntegration) {
  const Throw& th = GetParam();
  Body b;
  b.shape = Circle{0.2};
  b.mass_kg = 2.0;
  b.inertia_kgm2 = 0.04;
  const Vec2 pivot(0.3, 1.0);
  const double d = 0.8;
  b.position_m = pivot + d * Vec2(std::sin(th.phi0), -std::cos(th.phi0));
  const double w0sq = omega0_sq_of(b, pivot);
  b.angular_velocity_radps = th.rate0 * std::sqrt(w0sq);
  b.velocity_mps =
      b.angular_velocity_radps * Vec2(-(b.position_m - pivot).y(), (b.position_m - pivot).x());
  const CompoundPendulum p(pivot, b, kGravity);
  for (int i = 1; i <= 20; ++i) {
    const double t = th.horizon * i / 20.0;
    const auto y = testing::pendulum_rk4(th.phi0, b.angular_velocity_radps, w0sq, t, 1e-5);
    const BodyState s = p.state_at(t);
    // continuous phi from the body angle (the body turns with its arm)
    const double phi = th.phi0 + s.angle_rad - b.angle_rad;
    EXPECT_NEAR(phi, y[0], th.tol) << th.name << " t=" << t;
    EXPECT_NEAR(s.angular_velocity_radps, y[1], th.tol * std::sqrt(w0sq)) << th.name << " t=" << t;
  }
}

// tolerances: RK4 at h = 1e-5 s agrees to ~1e-13 rad except on the separatrix,
// where any error grows like e^(w0 t): 1e-9 rad over 2.5 s
INSTANTIATE_TEST_SUITE_P(Throws, CompoundPendulumThrows,
                         ::testing::Values(Throw{"backwards", 0.5, -1.2, 3.0, 1e-11},
                                           Throw{"over_the_top", -0.3, 2.4, 3.0, 1e-11},
                                           Throw{"over_the_top_backwards", 2.0, -2.1, 3.0, 1e-11},
                                           Throw{"separatrix", 0.0, 2.0, 2.5, 1e-9}),
                         [](const auto& p) { return std::string(p.param.name); });

// Without gravity the body turns uniformly about its pivot.
TEST(CompoundPendulum, SpinWithoutGravity) {
  Body b;
  b.mass_kg = 1.0;
  b.inertia_kgm2 = 0.1;
  b.position_m = Vec2(1.0, 0.0);
  b.angular_velocity_radps = 2.0;
  const CompoundPendulum p(Vec2::Zero(), b, Vec2::Zero());
  EXPECT_EQ(p.regime(), PendulumRegime::spin);
  const BodyState s = p.state_at(0.5);
  // uniform rotation by w t = 1 rad exactly: rounding of cos/sin only
  EXPECT_NEAR(s.position_m.x(), std::cos(1.0), 1e-15);
  EXPECT_NEAR(s.position_m.y(), std::sin(1.0), 1e-15);
  EXPECT_NEAR(s.angle_rad, 1.0, 1e-15);
}

}  // namespace
}  // namespace pb::internal
