// Tests for adapters/box2d/box2d_frame.cpp
#include "box2d_frame.hpp"

#include <box2d/b2_world.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "box2d_test_cases.hpp"

namespace pb::internal::box2d {
namespace {

constexpr double kPi = std::numbers::pi;
// float32 machine epsilon: Box2D's state is float
constexpr double kEpsF = 1.1920928955078125e-07;

// A case angle a turns the body x axis to (cos a, sin a), counter-clockwise.
// Box2D's b2Rot and b2Mul must agree: a body point (1, 0) of a body at p with
// angle a lies at p + (cos a, sin a), (0, 1) at p + (-sin a, cos a).
// Tolerance: a few float roundings of unit-size numbers, 4 eps_f.
TEST(Box2dFrame, AngleIsCounterClockwiseAndPointsMapAlike) {
  for (const double a : {0.0, kPi / 6.0, kPi / 2.0, 2.5, -1.0, -3.0}) {
    const Vec2 p(1.25, -0.5);
    const b2Transform xf = to_b2_transform(p, a);
    const Vec2 ex = from_b2(b2Mul(xf, b2Vec2(1.0f, 0.0f)));
    const Vec2 ey = from_b2(b2Mul(xf, b2Vec2(0.0f, 1.0f)));
    EXPECT_NEAR(ex.x(), p.x() + std::cos(a), 4 * kEpsF * 2.0) << a;
    EXPECT_NEAR(ex.y(), p.y() + std::sin(a), 4 * kEpsF * 2.0) << a;
    EXPECT_NEAR(ey.x(), p.x() - std::sin(a), 4 * kEpsF * 2.0) << a;
    EXPECT_NEAR(ey.y(), p.y() + std::cos(a), 4 * kEpsF * 2.0) << a;
  }
}

// a body created through body_def reports the case's pose and velocities
// back through body_state (float rounding only), and a dynamic body's
// material point moves as v + omega x r
TEST(Box2dFrame, BodyRoundTripAndPointVelocity) {
  b2World world(b2Vec2(0.0f, 0.0f));
  Body b = box2d_test::disk_body("d", 0.5, 2.0, Vec2(0.3, -1.7));
  b.angle_rad = 0.7;
  b.velocity_mps = Vec2(1.5, -2.0);
  b.angular_velocity_radps = 3.0;
  const b2BodyDef def = body_def(b);
  EXPECT_EQ(def.type, b2_dynamicBody);
  EXPECT_FALSE(def.allowSleep);
  b2Body* body = world.CreateBody(&def);
  const BodyState s = body_state(*body);
  EXPECT_NEAR(s.position_m.x(), 0.3, kEpsF);
  EXPECT_NEAR(s.position_m.y(), -1.7, 2 * kEpsF);
  EXPECT_NEAR(s.angle_rad, 0.7, kEpsF);
  EXPECT_NEAR(s.velocity_mps.x(), 1.5, 2 * kEpsF);
  EXPECT_NEAR(s.velocity_mps.y(), -2.0, 2 * kEpsF);
  EXPECT_NEAR(s.angular_velocity_radps, 3.0, 4 * kEpsF);
  // Box2D's own b2Body::GetLinearVelocityFromWorldPoint agrees with ours
  const Vec2 q(0.8, -1.2);
  const Vec2 ours = point_velocity(s, q);
  const Vec2 theirs = from_b2(body->GetLinearVelocityFromWorldPoint(to_b2(q)));
  EXPECT_NEAR(ours.x(), theirs.x(), 16 * kEpsF);
  EXPECT_NEAR(ours.y(), theirs.y(), 16 * kEpsF);
  // omega = 3 rad/s CCW, r = (0.5, 0.5): v_q = v + 3 (-0.5, 0.5)
  EXPECT_NEAR(ours.x(), 1.5 - 1.5, 16 * kEpsF);
  EXPECT_NEAR(ours.y(), -2.0 + 1.5, 16 * kEpsF);
}

// a positive angular velocity turns the body counter-clockwise in Box2D's
// integration: after one step of 0.01 s at omega = 2 rad/s the angle grew by
// 0.02 rad (free body, no gravity; float rounding)
TEST(Box2dFrame, PositiveOmegaTurnsCounterClockwise) {
  b2World world(b2Vec2(0.0f, 0.0f));
  Body b = box2d_test::disk_body("d", 0.5, 1.0, Vec2::Zero());
  b.angular_velocity_radps = 2.0;
  const b2BodyDef def = body_def(b);
  b2Body* body = world.CreateBody(&def);
  world.Step(0.01f, 8, 3);
  EXPECT_NEAR(body_state(*body).angle_rad, 0.02, 8 * kEpsF);
  const Vec2 ex = from_b2(body->GetWorldVector(b2Vec2(1.0f, 0.0f)));
  EXPECT_GT(ex.y(), 0.0);  // body x axis turned toward +y
}

// fixed bodies are static and never move
TEST(Box2dFrame, FixedBodiesAreStatic) {
  const Body g = box2d_test::ground_body(-kPi / 6.0);
  EXPECT_EQ(body_def(g).type, b2_staticBody);
}

}  // namespace
}  // namespace pb::internal::box2d
