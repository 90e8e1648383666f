// Tests for adapters/box2d/box2d_contact_probe.cpp
#include "box2d_contact_probe.hpp"

#include <box2d/b2_world.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "box2d_frame.hpp"
#include "box2d_geometry.hpp"
#include "box2d_test_cases.hpp"

namespace pb::internal::box2d {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kEpsF = 1.1920928955078125e-07;  // float32 epsilon

b2Body* make_body(b2World& world, const Body& b, int index) {
  const b2BodyDef def = body_def(b);
  b2Body* body = world.CreateBody(&def);
  FixtureOptions opt;
  opt.body_index = index;
  opt.half_plane_half_length_m = 20.0;
  add_fixtures(*body, b, opt);
  return body;
}

// A disk at height R + h above a half-plane tilted by -30 deg: apart by h
// (b2Distance), overlapping by -h (the manifold), always with the plane's
// outward normal from a = plane to b = disk, and the opposite normal with the
// bodies swapped. Tolerance: float coordinates of ~3 m, 8 eps_f 3 m.
TEST(Box2dContactProbe, DiskOverTiltedPlaneBothSidesOfTouch) {
  const double angle = -kPi / 6.0;
  const Vec2 n(std::sin(kPi / 6.0), std::cos(kPi / 6.0));
  const Vec2 t(std::cos(angle), std::sin(angle));
  for (const double h : {0.3, 0.001, -0.001, -0.004}) {
    b2World world(b2Vec2(0.0f, 0.0f));
    const Body plane = box2d_test::ground_body(angle);
    const Body disk = box2d_test::disk_body("d", 0.5, 1.0, 2.0 * t + (0.5 + h) * n);
    b2Body* a = make_body(world, plane, 0);
    b2Body* b = make_body(world, disk, 1);
    const ContactGeometry g = probe_contact(*a, *b, ProbeScope::every_child);
    ASSERT_TRUE(g.valid);
    EXPECT_EQ(g.touching, h < 0.0) << h;
    EXPECT_NEAR(g.penetration_m, -h, 8 * kEpsF * 3.0) << h;
    EXPECT_NEAR(g.normal.x(), n.x(), 8 * kEpsF) << h;
    EXPECT_NEAR(g.normal.y(), n.y(), 8 * kEpsF) << h;
    // midway between the line and the disk's lowest point
    const Vec2 mid = 2.0 * t + 0.5 * h * n;
    EXPECT_NEAR((g.point_m - mid).norm(), 0.0, 8 * kEpsF * 3.0) << h;
    const ContactGeometry swapped = probe_contact(*b, *a, ProbeScope::every_child);
    // the broad phase pairs nothing before a step; after one of length 0
    // (b2World::Step finds new contacts, moves nothing) it holds the pair
    // that matters: the same answer, bit for bit
    EXPECT_FALSE(probe_contact(*a, *b).valid) << h;
    world.Step(0.0f, 8, 3);
    const ContactGeometry broad = probe_contact(*a, *b);
    EXPECT_EQ(broad.valid, g.valid) << h;
    EXPECT_EQ(broad.penetration_m, g.penetration_m) << h;
    EXPECT_EQ(broad.normal, g.normal) << h;
    EXPECT_EQ(broad.point_m, g.point_m) << h;
    EXPECT_NEAR(swapped.normal.x(), -n.x(), 8 * kEpsF) << h;
    EXPECT_NEAR(swapped.penetration_m, -h, 8 * kEpsF * 3.0) << h;
  }
}

// The dual pendulum at its first contact: the ellipse vertical (major axis
// down), the disk beside it. The fan of polygons against Box2D's circle gives
// the horizontal normal from the ellipse to the disk and the overlap. The
// skinned outline lies inside the exact ellipse by at most the chord sagitta
// at the flat side, s^2 / (8 rho) with s = 2 pi a / 180 and rho = a^2 / b
// (7.6e-6 m), so the overlap is the exact one minus up to that.
TEST(Box2dContactProbe, EllipseFanAgainstDisk) {
  b2World world(b2Vec2(0.0f, 0.0f));
  const double a_m = 0.7071;
  const double b_m = 0.25;
  const Body ellipse = box2d_test::ellipse_body("e", a_m, b_m, 1.0, Vec2(0.0, -0.7071), -kPi / 2.0);
  const double overlap = 2e-4;
  const Body disk = box2d_test::disk_body("d", 0.5, 1.0, Vec2(0.75 - overlap, -0.7071));
  b2Body* e = make_body(world, ellipse, 0);
  b2Body* d = make_body(world, disk, 1);
  const ContactGeometry g = probe_contact(*e, *d, ProbeScope::every_child);
  ASSERT_TRUE(g.touching);
  const double chord = 2 * kPi * a_m / 180.0;
  const double sagitta = chord * chord / (8.0 * a_m * a_m / b_m);
  EXPECT_LE(g.penetration_m, overlap + 8 * kEpsF);
  EXPECT_GE(g.penetration_m, overlap - sagitta - 8 * kEpsF);
  EXPECT_NEAR(g.normal.x(), 1.0, 1e-3);  // a chord's normal: within its 1 deg turn
  EXPECT_NEAR(g.point_m.x(), 0.25 - 0.5 * overlap, sagitta + 8 * kEpsF);
}

}  // namespace
}  // namespace pb::internal::box2d
