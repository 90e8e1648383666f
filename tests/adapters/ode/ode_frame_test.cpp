// Tests for adapters/ode/ode_frame.cpp
#include "ode_frame.hpp"

#include <gtest/gtest.h>
#include <ode/ode.h>

#include <cmath>
#include <numbers>

#include "ode_library.hpp"

namespace pb::internal::ode {
namespace {

constexpr double kPi = std::numbers::pi;

// A case angle a turns the body x axis to (cos a, sin a): counter-clockwise
// seen from +z. ODE's own dRFromAxisAndAngle about +z (right-hand rule) must
// give the same matrix as our quaternion, and reading the matrix back must
// give a. 1e-15: a few roundings of unit-size numbers.
TEST(OdeFrame, AngleAboutPlusZIsCounterClockwise) {
  ensure_ode_ready_in_this_thread();
  for (const double a : {0.0, 0.3, kPi / 6.0, kPi / 2.0, 2.5, -1.0, -3.0}) {
    const Quaternion q = to_ode_quaternion(a);
    const dQuaternion dq = {q[0], q[1], q[2], q[3]};
    dMatrix3 from_q;
    dRfromQ(from_q, dq);
    dMatrix3 from_axis;
    dRFromAxisAndAngle(from_axis, 0.0, 0.0, 1.0, a);
    for (int k = 0; k < 12; ++k) EXPECT_NEAR(from_q[k], from_axis[k], 1e-15) << k;
    // the body x axis (first column) points at (cos a, sin a)
    EXPECT_NEAR(from_q[0], std::cos(a), 1e-15);
    EXPECT_NEAR(from_q[4], std::sin(a), 1e-15);
    EXPECT_NEAR(angle_from_ode_rotation(from_q), a, 1e-15);
  }
}

// a body placed through the mapping reports the same pose back; 1e-15: a
// few roundings of unit-size numbers (ODE stores the quaternion and rotates)
TEST(OdeFrame, BodyPoseRoundTrip) {
  ensure_ode_ready_in_this_thread();
  dWorldID w = dWorldCreate();
  dBodyID b = dBodyCreate(w);
  const Vec2 p(1.25, -0.5);
  const Vector3 v = to_ode_vector(p);
  EXPECT_EQ(v[2], 0.0);
  dBodySetPosition(b, v[0], v[1], v[2]);
  const Quaternion q = to_ode_quaternion(kPi / 6.0);
  const dQuaternion dq = {q[0], q[1], q[2], q[3]};
  dBodySetQuaternion(b, dq);
  EXPECT_EQ(to_case_vector(dBodyGetPosition(b)), p);
  EXPECT_NEAR(angle_from_ode_rotation(dBodyGetRotation(b)), kPi / 6.0, 1e-15);
  // a body point (1, 0) lies at p + (cos 30, sin 30) in the world
  dVector3 world_point;
  dBodyGetRelPointPos(b, 1.0, 0.0, 0.0, world_point);
  EXPECT_NEAR(world_point[0], p.x() + std::cos(kPi / 6.0), 1e-15);
  EXPECT_NEAR(world_point[1], p.y() + std::sin(kPi / 6.0), 1e-15);
  dWorldDestroy(w);
}

// the drift removal keeps the z rotation of a slightly tilted quaternion and
// drops the tilt; a pure z rotation is unchanged. 1e-16 and 1e-15: one or
// two roundings of unit-size components (eps = 2.2e-16)
TEST(OdeFrame, PlanarQuaternionDropsTilt) {
  const Quaternion pure = to_ode_quaternion(0.7);
  const Quaternion same = planar_quaternion(pure.data());
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(same[k], pure[k], 1e-16);
  // a 1e-6 rad tilt about x composed with the z rotation
  const double t = 1e-6;
  const double qt[4] = {std::cos(0.35) * std::cos(t / 2), std::cos(0.35) * std::sin(t / 2),
                        std::sin(0.35) * std::sin(t / 2), std::sin(0.35) * std::cos(t / 2)};
  const Quaternion flat = planar_quaternion(qt);
  EXPECT_EQ(flat[1], 0.0);
  EXPECT_EQ(flat[2], 0.0);
  EXPECT_NEAR(2.0 * std::atan2(flat[3], flat[0]), 0.7, 1e-15);
}

// continuity across the +-pi cut; 1e-15 (1e-14 near 10 rad): a few roundings
// of numbers of that size
TEST(OdeFrame, UnwrappedAngle) {
  EXPECT_NEAR(unwrapped_angle(3.1, -3.1), 2.0 * kPi - 3.1, 1e-15);
  EXPECT_NEAR(unwrapped_angle(-3.1, 3.1), 3.1 - 2.0 * kPi, 1e-15);
  EXPECT_NEAR(unwrapped_angle(10.0, 10.0 - 2.0 * kPi + 0.01), 10.01, 1e-14);
  EXPECT_EQ(unwrapped_angle(0.5, 0.6), 0.6);
}

}  // namespace
}  // namespace pb::internal::ode
