// Tests for adapters/ode/ode_world.cpp
#include "ode_world.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>
#include <thread>

#include "ode_library.hpp"
#include "ode_test_cases.hpp"
#include "planarbench/errors.hpp"

namespace pb::internal::ode {
namespace {

using ode_test::disk_body;
using ode_test::ellipse_body;
using ode_test::ground_body;

constexpr double kPi = std::numbers::pi;

// The case's mass and planar inertia reach ODE unchanged (an engine's own 3D
// inertia, 2/5 m R^2 for a sphere, would be wrong for a disk: ENGINES.md);
// the initial state reads back through the frame mapping (the angle through
// a quaternion and a rotation matrix: 1e-15, a few roundings).
TEST(OdeWorld, ExplicitMassAndState) {
  Case c;
  c.bodies = {ground_body(), ellipse_body("e", 0.7071, 0.25, 2.0, Vec2(1.0, 2.0), 0.4)};
  c.bodies[1].velocity_mps = Vec2(0.5, -1.5);
  c.bodies[1].angular_velocity_radps = 3.0;
  OdeWorld w(c);
  EXPECT_EQ(w.body(0), nullptr);
  dMass m;
  dBodyGetMass(w.body(1), &m);
  EXPECT_EQ(m.mass, 2.0);
  EXPECT_EQ(m.I[2 * 4 + 2], c.bodies[1].inertia_kgm2);  // I_zz
  for (int k = 0; k < 3; ++k) EXPECT_EQ(m.c[k], 0.0);   // centre of mass at the origin
  const BodyState s = w.state(1);
  EXPECT_EQ(s.position_m, Vec2(1.0, 2.0));
  EXPECT_NEAR(s.angle_rad, 0.4, 1e-15);
  EXPECT_EQ(s.velocity_mps, Vec2(0.5, -1.5));
  EXPECT_EQ(s.angular_velocity_radps, 3.0);
  // fixed bodies report the case's pose
  EXPECT_EQ(w.state(0).position_m, Vec2::Zero());
}

// A free body spinning and drifting: Plane2D keeps it in z = 0 and the drift
// removal keeps its rotation about z only, over 10^4 steps of 1e-4 s. The
// spin is torque-free, so omega stays 3 rad/s. ODE's default orientation
// update (q += h/2 w q, then normalised) turns by 2 atan(w h / 2) per step,
// (w h)^3 / 12 less than w h: the angle lags 3 t by n (w h)^3 / 12 = 2.25e-8
// rad after n = 10^4 steps; bound: that lag + 1e-12. Plane2D zeroes the
// out-of-plane velocity each step, so z stays at rounding level (1e-12 m);
// omega is constant up to the drift removal's renormalisation (1e-9 rad/s).
TEST(OdeWorld, PlanarBodyStaysPlanar) {
  Case c;
  c.gravity_mps2 = Vec2(0.0, -9.8066);
  c.bodies = {ellipse_body("e", 0.7071, 0.25, 1.0, Vec2::Zero(), 0.0)};
  c.bodies[0].angular_velocity_radps = 3.0;
  OdeWorld w(c);
  double angle = 0.0;
  for (int i = 0; i < 10000; ++i) {
    dWorldStep(w.world(), 1e-4);
    w.remove_planar_drift();
    angle += 3.0 * 1e-4;
  }
  const dReal* q = dBodyGetQuaternion(w.body(0));
  EXPECT_EQ(q[1], 0.0);
  EXPECT_EQ(q[2], 0.0);
  EXPECT_NEAR(std::abs(dBodyGetPosition(w.body(0))[2]), 0.0, 1e-12);
  const BodyState s = w.state(0);
  EXPECT_NEAR(s.angular_velocity_radps, 3.0, 1e-9);
  const double lag = 1e4 * std::pow(3.0 * 1e-4, 3) / 12.0;
  EXPECT_NEAR(s.angle_rad, std::remainder(angle, 2.0 * kPi), lag * 1.01 + 1e-12);
  EXPECT_GT(std::remainder(angle, 2.0 * kPi) - s.angle_rad, 0.5 * lag);  // the lag is ODE's
}

// A pendulum hinge keeps the body's anchor point on the pivot (the
// constraint drift stays at the level of ODE's joint ERP correction).
TEST(OdeWorld, HingeHoldsThePivot) {
  Case c;
  c.bodies = {disk_body("bob", 0.5, 1.0, Vec2(0.5, -0.5))};
  RevoluteJoint j;
  j.body = 0;
  j.anchor_world_m = Vec2::Zero();
  j.anchor_local_m = Vec2(-0.5, 0.5);
  c.joints = {j};
  OdeWorld w(c);
  double worst = 0.0;
  for (int i = 0; i < 20000; ++i) {
    dWorldStep(w.world(), 1e-4);
    const BodyState s = w.state(0);
    const Eigen::Rotation2Dd r(s.angle_rad);
    worst = std::max(worst, (s.position_m + r * j.anchor_local_m).norm());
  }
  // 1e-6 m: measured ~1e-9 m; ODE's ERP 0.2 corrects the O(h^2 omega^2 L) drift each step
  EXPECT_LT(worst, 1e-6);
}

// Two worlds stepped at the same time in two threads (each world has its own
// threading implementation; ODE's shared default one breaks): both finish
// with the same bits as a world stepped alone.
TEST(OdeWorld, TwoWorldsInTwoThreads) {
  Case c;
  c.bodies = {disk_body("bob", 0.5, 1.0, Vec2(0.5, -0.5))};
  RevoluteJoint j;
  j.body = 0;
  c.joints = {j};
  auto run = [&c] {
    OdeWorld w(c);
    for (int i = 0; i < 20000; ++i) dWorldStep(w.world(), 1e-4);
    return w.state(0).position_m;
  };
  const Vec2 alone = run();
  Vec2 a;
  Vec2 b;
  std::thread ta([&] {
    ensure_ode_ready_in_this_thread();
    a = run();
  });
  std::thread tb([&] {
    ensure_ode_ready_in_this_thread();
    b = run();
  });
  ta.join();
  tb.join();
  EXPECT_EQ(a, alone);
  EXPECT_EQ(b, alone);
}

TEST(OdeWorld, MovingHalfPlaneIsRefused) {
  Case c;
  c.bodies = {ground_body()};
  c.bodies[0].fixed = false;
  c.bodies[0].mass_kg = 1.0;
  c.bodies[0].inertia_kgm2 = 1.0;
  EXPECT_THROW(OdeWorld w(c), EngineError);
}

// non-finite or runaway states are flagged
TEST(OdeWorld, BlowUpDetection) {
  Case c;
  c.bodies = {disk_body("b", 0.5, 1.0, Vec2::Zero())};
  OdeWorld w(c);
  EXPECT_EQ(w.first_blown_up_body(), -1);
  dBodySetLinearVel(w.body(0), 2e6, 0.0, 0.0);
  EXPECT_EQ(w.first_blown_up_body(), 0);
  dBodySetLinearVel(w.body(0), std::nan(""), 0.0, 0.0);
  EXPECT_EQ(w.first_blown_up_body(), 0);
}

}  // namespace
}  // namespace pb::internal::ode
