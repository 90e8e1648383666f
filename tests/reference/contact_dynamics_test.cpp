// Tests for core/reference/src/contact_dynamics.cpp
//
// A free disk (m = 1 kg, R = 0.5 m) pressed 1 cm into a horizontal line
// while moving down at 2 m/s: delta = 0.01 m, delta_dot = 2 m/s, Kelvin-Voigt
// F = K delta + c delta_dot = 100 + 20 N up, through the centre.
#include "planarbench/reference/contact_dynamics.hpp"

#include <gtest/gtest.h>

namespace pb {
namespace {

Case disk_on_line(double height) {
  Case c;
  c.gravity_mps2 = Vec2(0, -9.8066);
  Body ground;
  ground.name = "ground";
  ground.shape = HalfPlane{20.0};
  ground.fixed = true;
  ground.outline_points = 181;
  Body disk;
  disk.name = "disk";
  disk.shape = Circle{0.5};
  disk.mass_kg = 1.0;
  disk.inertia_kgm2 = 0.125;
  disk.position_m = Vec2(0.0, height);
  disk.velocity_mps = Vec2(0.3, -2.0);
  c.bodies = {ground, disk};
  ContactPair p;
  p.name = "ground_disk";
  p.body_a = 0;
  p.body_b = 1;
  p.law = KelvinVoigt{1e4, 10.0, 0.0};
  c.contacts = {p};
  return c;
}

TEST(ContactDynamics, StateLayout) {
  ContactDynamics d(disk_on_line(0.49), GeometryMode::exact);
  EXPECT_EQ(d.coordinates(), 3);
  EXPECT_EQ(d.state_size(), 7);  // q (3), u (3), one impulse
  EXPECT_EQ(d.impulse_index(0), 6);
}

// Tolerances: quantities copied or differenced from the O(1) state take
// 1e-15 (a rounding or two: 0.49 - 0.5 is not exactly -0.01 in doubles);
// the O(100) N force and what it feeds take 1e-12 (K delta with delta off by
// ~1e-17 m times 1e4 N/m, plus the force's own roundings ~1e-14 N).
TEST(ContactDynamics, PressingPhaseAppliesTheLaw) {
  ContactDynamics d(disk_on_line(0.49), GeometryMode::exact);
  Eigen::VectorXd y, dy;
  d.initial_state(y);
  d.modes()[0].phase = ContactPhase::pressing;
  d.derivative(y, dy);
  const PairEvaluation& e = d.last_pairs()[0];
  EXPECT_NEAR(e.geometry.gap_m, -0.01, 1e-15);
  EXPECT_NEAR(e.gap_rate_mps, -2.0, 1e-15);  // closing
  EXPECT_NEAR(e.force_n, 120.0, 1e-12);
  // q' = u; u' = F/m - g along y, no torque through the centre; J' = F
  EXPECT_NEAR(dy[0], 0.3, 1e-15);
  EXPECT_NEAR(dy[1], -2.0, 1e-15);
  EXPECT_NEAR(dy[3], 0.0, 1e-15);
  EXPECT_NEAR(dy[4], 120.0 - 9.8066, 1e-12);
  EXPECT_NEAR(dy[5], 0.0, 1e-15);
  EXPECT_NEAR(dy[6], 120.0, 1e-12);
}

TEST(ContactDynamics, OtherPhasesApplyNoForce) {
  ContactDynamics d(disk_on_line(0.49), GeometryMode::exact);
  Eigen::VectorXd y, dy;
  d.initial_state(y);
  for (const ContactPhase ph : {ContactPhase::apart, ContactPhase::touching}) {
    d.modes()[0].phase = ph;
    d.derivative(y, dy);
    EXPECT_NEAR(dy[4], -9.8066, 1e-15);
    EXPECT_EQ(dy[6], 0.0);
    // the unclamped force is still evaluated, for event location
    EXPECT_NEAR(d.last_pairs()[0].unclamped_force_n, 120.0, 1e-12);
  }
}

TEST(ContactDynamics, OffCentreForceMakesATorque) {
  // the 8-point outline turned so that a point is off the vertical: the
  // force acts at the deepest point, off the centre line, and turns the disk
  Case c = disk_on_line(0.49);
  c.bodies[1].outline_points = 8;
  c.bodies[1].angle_rad = 0.3;
  ContactDynamics d(c, GeometryMode::outline);
  Eigen::VectorXd y, dy;
  d.initial_state(y);
  y[1] = 0.45;  // deep enough that the lowest outline point penetrates
  d.modes()[0].phase = ContactPhase::pressing;
  d.derivative(y, dy);
  const PairEvaluation& e = d.last_pairs()[0];
  ASSERT_GT(e.force_n, 0.0);
  // torque about the centre of F n applied at p_b, over I
  const Vec2 r = e.geometry.point_b_m - Vec2(y[0], y[1]);
  // 1e-9 rad/s^2 on a torque term of O(100): relative 1e-11, a few roundings
  // of the outline's trig and the lever arm
  EXPECT_NEAR(dy[5], cross2(r, e.force_n * e.geometry.normal) / 0.125, 1e-9);
  EXPECT_NE(dy[5], 0.0);
}

}  // namespace
}  // namespace pb
