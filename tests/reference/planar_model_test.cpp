// Tests for core/reference/src/planar_model.cpp
//
// A pendulum in joint coordinates: the centre stays on its circle about the
// pivot, velocities are omega x r, and generalised forces satisfy virtual
// work (Q dq = f . dp for a small displacement of the material point).
#include "planarbench/reference/planar_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace pb {
namespace {

// a free disk and a pendulum (an ellipse hung from (0, 0), centre at (-0.5, -0.5))
Case two_bodies() {
  Case c;
  Body disk;
  disk.name = "disk";
  disk.shape = Circle{0.5};
  disk.mass_kg = 2.0;
  disk.inertia_kgm2 = 0.25;
  disk.position_m = Vec2(3.0, 1.0);
  disk.velocity_mps = Vec2(0.5, -1.0);
  disk.angular_velocity_radps = 2.0;
  Body ell;
  ell.name = "ellipse";
  ell.shape = Ellipse{0.7071, 0.25};
  ell.mass_kg = 1.0;
  ell.inertia_kgm2 = 0.140625;
  ell.position_m = Vec2(-0.5, -0.5);
  ell.angle_rad = std::numbers::pi / 4;
  ell.angular_velocity_radps = 0.3;
  c.bodies = {disk, ell};
  RevoluteJoint j;
  j.body = 1;
  j.anchor_world_m = Vec2(0, 0);
  j.anchor_local_m = Pose{ell.position_m, ell.angle_rad}.to_local(Vec2(0, 0));
  c.joints = {j};
  return c;
}

TEST(PlanarModel, CoordinatesAndMassMatrix) {
  const PlanarModel m(two_bodies());
  ASSERT_EQ(m.coordinates(), 4);  // x, y, theta of the disk; theta of the pendulum
  EXPECT_EQ(m.kind(0), PlanarModel::Kind::free);
  EXPECT_EQ(m.kind(1), PlanarModel::Kind::pendulum);
  // pivot inertia by the parallel-axis theorem: 0.140625 + 1 * 0.5
  // all three numbers are exact binary fractions, only the 0.5 = |r|^2 is
  // summed from rounded squares: 1e-15
  EXPECT_NEAR(m.mass_diagonal()[3], 0.640625, 1e-15);
  EXPECT_EQ(m.mass_diagonal()[0], 2.0);
  EXPECT_EQ(m.mass_diagonal()[2], 0.25);
}

TEST(PlanarModel, PendulumKinematicsHoldTheJoint) {
  const PlanarModel m(two_bodies());
  Eigen::VectorXd q, u;
  m.initial_state(q, u);
  // 1e-15 m here and below: O(1) m positions through a sin/cos and a
  // rotation, a few roundings of 1.1e-16
  EXPECT_NEAR((m.pose(1, q).position_m - Vec2(-0.5, -0.5)).norm(), 0.0, 1e-15);
  for (const double th : {-1.0, 0.2, 2.5}) {
    q[3] = th;
    const Pose p = m.pose(1, q);
    EXPECT_NEAR(p.position_m.norm(), std::sqrt(0.5), 1e-15);  // on its circle
    EXPECT_LT(m.joint_violation_m(q), 1e-15);
    const BodyState s = m.state(1, q, u);
    // v = omega x (c - pivot)
    EXPECT_NEAR((s.velocity_mps - 0.3 * Vec2(-p.position_m.y(), p.position_m.x())).norm(), 0.0,
                1e-15);
  }
}

TEST(PlanarModel, GeneralisedForcesByVirtualWork) {
  const PlanarModel m(two_bodies());
  Eigen::VectorXd q, u;
  m.initial_state(q, u);
  const Vec2 f(3.0, -7.0);  // N
  for (int body = 0; body < 2; ++body) {
    // a material point of the body, followed through a small change of each coordinate
    const Pose p0 = m.pose(body, q);
    const Vec2 local(0.2, -0.4);
    Eigen::VectorXd gen = Eigen::VectorXd::Zero(4);
    m.add_point_force(body, q, p0.to_world(local), f, gen);
    for (int i = 0; i < 4; ++i) {
      const double h = 1e-7;
      Eigen::VectorXd qp = q, qm = q;
      qp[i] += h;
      qm[i] -= h;
      const Vec2 dp = (m.pose(body, qp).to_world(local) - m.pose(body, qm).to_world(local)) / (2 * h);
      // central difference: truncation h^2 ~ 1e-14 is negligible; rounding
      // eps |p| / h ~ 1e-16 * 3 m / 1e-7 = 3e-9 m per unit, times |f| ~ 7.6 N:
      // 2e-8 N, so 1e-7 (a wrong lever arm errs by O(1) N)
      EXPECT_NEAR(gen[i], f.dot(dp), 1e-7) << body << " " << i;
    }
  }
}

TEST(PlanarModel, GravityAndEnergy) {
  Case c = two_bodies();
  c.gravity_mps2 = Vec2(0, -9.8066);
  const PlanarModel m(c);
  Eigen::VectorXd q, u;
  m.initial_state(q, u);
  Eigen::VectorXd gen;
  m.gravity_forces(q, gen);
  // one product: its rounding is 2e-15 at most on 19.6 N; 1e-14 allowed
  EXPECT_NEAR(gen[1], -2.0 * 9.8066, 1e-14);
  // torque of the weight about the pivot: r x (0, -m g) = -r_x m g = 0.5 * 9.8066
  // the lever arm r_x = -0.5 m comes through a rotation: a few roundings on 4.9 N m
  EXPECT_NEAR(gen[3], 0.5 * 9.8066, 1e-14);
  // kinetic energy from the body states, potential -m g . c
  const BodyState d = m.state(0, q, u), e = m.state(1, q, u);
  const double expect = 0.5 * 2.0 * d.velocity_mps.squaredNorm() + 0.5 * 0.25 * 4.0 +
                        0.5 * 1.0 * e.velocity_mps.squaredNorm() + 0.5 * 0.140625 * 0.09 +
                        2.0 * 9.8066 * 1.0 + 1.0 * 9.8066 * (-0.5);
  // ~15 J summed from a dozen rounded terms: 1e-13 J
  EXPECT_NEAR(m.energy_j(q, u), expect, 1e-13);
}

TEST(PlanarModel, RefusesWhatItCannotModel) {
  Case c = two_bodies();
  c.joints.push_back(c.joints[0]);  // a second joint on the pendulum
  EXPECT_THROW(PlanarModel{c}, std::invalid_argument);
  Case d = two_bodies();
  d.bodies[0].shape = HalfPlane{};  // a moving half-plane
  EXPECT_THROW(PlanarModel{d}, std::invalid_argument);
  Case e = two_bodies();
  e.bodies[0].inertia_kgm2 = 0.0;
  EXPECT_THROW(PlanarModel{e}, std::invalid_argument);
}

}  // namespace
}  // namespace pb
