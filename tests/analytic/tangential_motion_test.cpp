// Tests for core/analytic/tangential_motion.cpp
//
// A body pressed onto a line at its static penetration has a constant normal
// force F = m g cos(theta), so the rigid-body closed forms of SPEC §7 hold
// exactly; each test states its formula (textbook: e.g. Marion & Thornton,
// Classical Dynamics, the rolling and sliding of a disk on an incline) and
// the tangential motion must reproduce it to rounding.
#include "tangential_motion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace pb::internal {
namespace {

constexpr double kG = 9.8066;  // m/s^2, SPEC §2

// a 1 kg body pressed in at rest on a line with g_n = -g cos(theta):
// the normal force is m g cos(theta) for all time
NormalContactParams pressed(double theta) {
  NormalContactParams p;
  p.mass_kg = 1.0;
  p.stiffness_n_per_m = 1e5;
  p.damping_ns_per_m = 600.0;
  p.normal_gravity_mps2 = -kG * std::cos(theta);
  p.gap0_m = p.mass_kg * p.normal_gravity_mps2 / p.stiffness_n_per_m;  // u_eq
  p.gap_rate0_mps = 0.0;
  return p;
}

TangentialParams disk(double mu, double theta, double v0, double omega0) {
  TangentialParams t;
  t.mass_kg = 1.0;
  t.inertia_kgm2 = 0.5 * 0.25 * 0.25;  // m R^2 / 2
  t.radius_m = 0.25;
  t.rotates = true;
  t.friction = mu;
  t.tangential_gravity_mps2 = kG * std::sin(theta);
  t.along_rate0_mps = v0;
  t.spin0_radps = omega0;
  return t;
}

TangentialParams block(double mu, double theta, double v0) {
  TangentialParams t;
  t.mass_kg = 1.0;
  t.inertia_kgm2 = 0.01;
  t.friction = mu;
  t.tangential_gravity_mps2 = kG * std::sin(theta);
  t.along_rate0_mps = v0;
  return t;
}

// rounding of closed forms evaluated at t <= 1 s with values of order 1:
// a few ulps of the largest term, 1e-12 leaves room for Phi's cancellation
constexpr double kTol = 1e-12;

TEST(TangentialMotion, BlockHoldsWhenTanThetaIsBelowMu) {
  // tan(theta) = 0.9 mu: the load m g sin(theta) is inside mu m g cos(theta)
  const double mu = 0.5;
  const double theta = std::atan(0.9 * mu);
  NormalContactMotion n(pressed(theta));
  n.extend_to(2.0);
  TangentialMotion t(block(mu, theta, 0.0), n);
  t.extend_to(2.0);
  ASSERT_EQ(t.phases().size(), 1u);
  EXPECT_EQ(t.phases()[0].kind, TangentialPhaseKind::stick);
  const TangentialState s = t.state_at(2.0);
  EXPECT_EQ(s.along_m, 0.0);
  EXPECT_EQ(s.along_rate_mps, 0.0);
  // the force that holds it is the load: f = -m g sin(theta)
  EXPECT_NEAR(s.friction_n, -kG * std::sin(theta), kTol);
}

TEST(TangentialMotion, BlockSlidesAtGTimesSinMinusMuCos) {
  const double mu = 0.5;
  const double theta = std::atan(1.1 * mu);
  NormalContactMotion n(pressed(theta));
  n.extend_to(1.0);
  TangentialMotion t(block(mu, theta, 0.0), n);
  t.extend_to(1.0);
  const double a = kG * (std::sin(theta) - mu * std::cos(theta));  // SPEC §7
  ASSERT_EQ(t.phases().size(), 1u);
  EXPECT_EQ(t.phases()[0].kind, TangentialPhaseKind::slip);
  EXPECT_NEAR(t.state_at(1.0).along_rate_mps, a, kTol);
  EXPECT_NEAR(t.state_at(0.5).along_m, 0.5 * a * 0.25, kTol);
}

TEST(TangentialMotion, BlockSlidesToRestAfterV0OverMuG) {
  const double mu = 0.4;
  const double v0 = 2.0;
  NormalContactMotion n(pressed(0.0));
  n.extend_to(1.0);
  TangentialMotion t(block(mu, 0.0, v0), n);
  t.extend_to(1.0);
  ASSERT_EQ(t.phases().size(), 2u);
  const double t_stop = v0 / (mu * kG);                // stop time
  const double d_stop = v0 * v0 / (2.0 * mu * kG);     // stop distance
  // the event is bisected to the last bit of a linear speed
  EXPECT_NEAR(t.phases()[1].start_s, t_stop, 1e-15);
  EXPECT_EQ(t.phases()[1].kind, TangentialPhaseKind::stick);
  EXPECT_NEAR(t.state_at(1.0).along_m, d_stop, kTol);
  EXPECT_NEAR(t.state_at(1.0).along_rate_mps, 0.0, kTol);
}

TEST(TangentialMotion, DiskRollsAtTwoThirdsGSinWhenMuIsEnough) {
  const double theta = std::numbers::pi / 6.0;
  NormalContactMotion n(pressed(theta));
  n.extend_to(1.0);
  TangentialMotion t(disk(0.3, theta, 0.0, 0.0), n);  // 0.3 >= tan(30 deg) / 3
  t.extend_to(1.0);
  ASSERT_EQ(t.phases().size(), 1u);
  EXPECT_EQ(t.phases()[0].kind, TangentialPhaseKind::stick);
  const TangentialState s = t.state_at(1.0);
  EXPECT_NEAR(s.along_rate_mps, 2.0 / 3.0 * kG * std::sin(theta), kTol);
  // no slip: omega = -v / R
  EXPECT_NEAR(s.spin_radps, -s.along_rate_mps / 0.25, kTol);
}

TEST(TangentialMotion, DiskSlipsWhenMuIsBelowTanThetaOverThree) {
  const double theta = std::numbers::pi / 6.0;
  const double mu = 0.1;
  NormalContactMotion n(pressed(theta));
  n.extend_to(1.0);
  TangentialMotion t(disk(mu, theta, 0.0, 0.0), n);
  t.extend_to(1.0);
  ASSERT_EQ(t.phases().size(), 1u);
  const TangentialState s = t.state_at(1.0);
  EXPECT_NEAR(s.along_rate_mps, kG * (std::sin(theta) - mu * std::cos(theta)), kTol);
  // angular acceleration 2 mu g cos(theta) / R, clockwise (negative)
  EXPECT_NEAR(s.spin_radps, -2.0 * mu * kG * std::cos(theta) / 0.25, kTol);
}

TEST(TangentialMotion, ThrownDiskRollsAtTwoThirdsV0AfterV0Over3MuG) {
  const double mu = 0.3;
  const double v0 = 3.0;
  NormalContactMotion n(pressed(0.0));
  n.extend_to(1.0);
  TangentialMotion t(disk(mu, 0.0, v0, 0.0), n);
  t.extend_to(1.0);
  ASSERT_EQ(t.phases().size(), 2u);
  EXPECT_NEAR(t.phases()[1].start_s, v0 / (3.0 * mu * kG), 1e-15);
  const TangentialState s = t.state_at(1.0);
  EXPECT_NEAR(s.along_rate_mps, 2.0 / 3.0 * v0, kTol);
  EXPECT_NEAR(s.slip_rate_mps, 0.0, kTol);
  // two thirds of the kinetic energy kept: m v^2 / 2 + I omega^2 / 2 = (3/4) m v^2
  const double ke = 0.5 * s.along_rate_mps * s.along_rate_mps +
                    0.5 * (0.5 * 0.0625) * s.spin_radps * s.spin_radps;
  EXPECT_NEAR(ke, 2.0 / 3.0 * 0.5 * v0 * v0, kTol);
}

TEST(TangentialMotion, BackspunDiskStopsAndComesBack) {
  // v0 = 1 m/s, omega0 = +16 rad/s: the contact point slips at v0 + omega0 R = 5 m/s;
  // slip ends at (v0 + omega0 R) / (3 mu g), then it rolls at (2 v0 - omega0 R) / 3
  const double mu = 0.3;
  NormalContactMotion n(pressed(0.0));
  n.extend_to(1.2);
  TangentialMotion t(disk(mu, 0.0, 1.0, 16.0), n);
  t.extend_to(1.2);
  ASSERT_EQ(t.phases().size(), 2u);
  EXPECT_NEAR(t.phases()[1].start_s, 5.0 / (3.0 * mu * kG), 1e-15);
  EXPECT_NEAR(t.state_at(1.2).along_rate_mps, (2.0 - 4.0) / 3.0, kTol);
  // it stopped (w = 0) at v0 / (mu g) while still slipping
  EXPECT_NEAR(t.state_at(1.0 / (mu * kG)).along_rate_mps, 0.0, kTol);
}

TEST(TangentialMotion, NoFrictionWhileApart) {
  // a disk above the line (gap 0.1 m, at rest): flight until it lands
  NormalContactParams p = pressed(0.0);
  p.gap0_m = 0.1;
  NormalContactMotion n(p);
  n.extend_to(0.1);
  TangentialMotion t(disk(0.5, 0.0, 1.0, 0.0), n);
  t.extend_to(0.1);
  EXPECT_EQ(t.phases()[0].kind, TangentialPhaseKind::flight);
  EXPECT_EQ(t.state_at(0.1).along_rate_mps, 1.0);
  EXPECT_EQ(t.state_at(0.1).spin_radps, 0.0);
}

}  // namespace
}  // namespace pb::internal
