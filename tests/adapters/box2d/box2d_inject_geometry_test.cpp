// Tests for adapters/box2d/box2d_inject_geometry.cpp
#include "box2d_inject_geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace pb::internal::box2d {
namespace {

constexpr double kPi = std::numbers::pi;

// brute force: the closest of 2e6 points of the ellipse to p, a distance D
// away; the nearest sample is within half a spacing s/2 along the curve, so
// its distance exceeds D by at most (s/2)^2 / (2 D) (+ curvature terms of the
// same order): 1e-11 m for the probes below (s <= 2.3e-6 m, D >= 0.03 m)
double brute_distance(double a, double b, const Vec2& p) {
  double best = std::numeric_limits<double>::infinity();
  const int n = 2000000;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * kPi * k / n;
    best = std::min(best, (Vec2(a * std::cos(t), b * std::sin(t)) - p).norm());
  }
  return best;
}

// The closest point lies on the ellipse and its distance is the brute-force
// minimum, outside and inside, on and off the axes, for a > b and a < b
// (inside near the centre on the major axis the closest point leaves the
// axis). Tolerances: 1e-9 m, the bisection's double precision with margin
// against the brute force's 1e-12 m.
TEST(Box2dInjectGeometry, ClosestPointOnEllipseMatchesBruteForce) {
  struct Probe {
    double a, b;
    Vec2 p;
  };
  const Probe probes[] = {{0.7071, 0.25, Vec2(1.0, 0.6)},  {0.7071, 0.25, Vec2(-0.3, 0.1)},
                          {0.7071, 0.25, Vec2(0.2, 0.0)},  {0.7071, 0.25, Vec2(0.0, -0.9)},
                          {0.25, 0.7071, Vec2(0.4, -1.3)}, {0.25, 0.7071, Vec2(-0.05, 0.2)},
                          {0.5, 0.5, Vec2(0.33, 0.44)},    {0.7071, 0.25, Vec2(0.9, 0.0)}};
  for (const auto& pr : probes) {
    const Vec2 q = closest_point_on_ellipse(pr.a, pr.b, pr.p);
    // 1e-12: the point is on the curve to the rounding of its parametrisation
    EXPECT_NEAR((q.x() / pr.a) * (q.x() / pr.a) + (q.y() / pr.b) * (q.y() / pr.b), 1.0, 1e-12);
    EXPECT_NEAR((q - pr.p).norm(), brute_distance(pr.a, pr.b, pr.p), 1e-9) << pr.p.transpose();
  }
}

// A disk of radius R hovering h above a half-plane tilted by -30 deg: gap h,
// normal = the plane's outward normal (sin30, cos30) from the plane (a) to
// the disk (b), point midway between the surfaces; swapping a and b flips
// only the normal. Tolerances 1e-15: a few roundings of unit-size doubles
// (rotation by a rounded sin/cos, one dot product, one subtraction).
TEST(Box2dInjectGeometry, HalfPlaneAndCircle) {
  const double angle = -kPi / 6.0;
  const Vec2 n(std::sin(kPi / 6.0), std::cos(kPi / 6.0));
  const Vec2 t(std::cos(angle), std::sin(angle));
  const Pose plane{Vec2(0.2, -0.1), angle};
  const Pose disk{plane.position_m + 1.5 * t + (0.5 + 0.01) * n, 0.3};
  const PrimitiveContact c = primitive_contact(HalfPlane{}, plane, Circle{0.5}, disk);
  EXPECT_NEAR(c.penetration_m, -0.01, 1e-15);
  EXPECT_NEAR(c.normal.x(), n.x(), 1e-15);
  EXPECT_NEAR(c.normal.y(), n.y(), 1e-15);
  const Vec2 mid = plane.position_m + 1.5 * t + 0.005 * n;
  EXPECT_NEAR((c.point_m - mid).norm(), 0.0, 1e-15);
  const PrimitiveContact swapped = primitive_contact(Circle{0.5}, disk, HalfPlane{}, plane);
  EXPECT_NEAR(swapped.normal.x(), -n.x(), 1e-15);
  EXPECT_NEAR(swapped.penetration_m, -0.01, 1e-15);
}

// An ellipse (a, b) turned by theta above flat ground: its lowest point is
// sqrt(a^2 sin^2 theta + b^2 cos^2 theta) below its centre (support function
// of an ellipse), at x offset -(a^2 - b^2) sin theta cos theta / that depth.
// Tolerances: 1e-15 as above; 1e-14 on x, where the support point divides
// by the depth and rotates back (a few more roundings).
TEST(Box2dInjectGeometry, HalfPlaneAndRotatedEllipse) {
  const double a = 0.4;
  const double b = 0.2;
  const double th = kPi / 6.0;
  const double depth =
      std::sqrt(a * a * std::sin(th) * std::sin(th) + b * b * std::cos(th) * std::cos(th));
  const Pose ground{Vec2::Zero(), 0.0};
  const Pose ellipse{Vec2(0.3, depth - 0.002), th};  // 2 mm into the ground
  const PrimitiveContact c = primitive_contact(HalfPlane{}, ground, Ellipse{a, b}, ellipse);
  EXPECT_NEAR(c.penetration_m, 0.002, 1e-15);
  EXPECT_NEAR(c.normal.y(), 1.0, 1e-15);
  const double x_low = -(a * a - b * b) * std::sin(th) * std::cos(th) / depth;
  EXPECT_NEAR(c.point_m.x(), 0.3 + x_low, 1e-14);
  EXPECT_LT(x_low, 0.0);  // a CCW turn puts the lowest point left of the centre
  EXPECT_NEAR(c.point_m.y(), -0.001, 1e-15);
}

// two disks: gap = distance - radii, normal along the centre line from a to b
// (|(0.6, 0.45)| = 0.75 = 0.5 + 0.25: just touching); 1e-15: one hypot of
// rounded decimals
TEST(Box2dInjectGeometry, CircleCircle) {
  const PrimitiveContact c =
      primitive_contact(Circle{0.5}, Pose{Vec2(0, 0), 0}, Circle{0.25}, Pose{Vec2(0.6, 0.45), 0});
  EXPECT_NEAR(c.penetration_m, 0.75 - 0.75, 1e-15);
  EXPECT_NEAR(c.normal.x(), 0.8, 1e-15);
  EXPECT_NEAR(c.normal.y(), 0.6, 1e-15);
}

// An ellipse standing vertical (the dual pendulum at its first contact) and a
// disk beside it: the contact is at the ellipse's side, normal +x, gap the
// distance between the side and the disk's surface; the disk in the ellipse's
// frame is rotated along with it (pose angle -pi/2: major axis down).
// Tolerances: 1e-12 m, the closest-point solver's accuracy (checked to 1e-9
// against brute force above, exact here on the axis up to rounding of the
// -pi/2 rotation, cos(-pi/2) = 6e-17); 1e-9 on the normal's y, which the
// rotation's 6e-17 offset and the solver's convergence tilt slightly.
TEST(Box2dInjectGeometry, EllipseCircleAtTheDualPendulumContact) {
  const Pose ellipse{Vec2(0.0, -0.7071), -kPi / 2.0};
  const Pose disk{Vec2(0.75 - 1e-4, -0.7071), 0.0};
  const PrimitiveContact c = primitive_contact(Ellipse{0.7071, 0.25}, ellipse, Circle{0.5}, disk);
  EXPECT_NEAR(c.penetration_m, 1e-4, 1e-12);
  EXPECT_NEAR(c.normal.x(), 1.0, 1e-12);
  EXPECT_NEAR(c.normal.y(), 0.0, 1e-9);
  EXPECT_NEAR(c.point_m.x(), 0.25 - 0.5e-4, 1e-12);
  // the disk's centre inside the ellipse counts its full depth
  const PrimitiveContact deep =
      primitive_contact(Ellipse{0.7071, 0.25}, ellipse, Circle{0.1}, Pose{Vec2(0.2, -0.7071), 0.0});
  EXPECT_NEAR(deep.penetration_m, 0.05 + 0.1, 1e-12);
}

// a square polygon and a disk beside an edge, and beyond a corner
// (corner distance |(0.3, 0.4)| = 0.5); 1e-15: a few unit-size roundings
TEST(Box2dInjectGeometry, PolygonCircle) {
  const Polygon square{{{0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}, {-0.5, -0.5}}};
  const PrimitiveContact side =
      primitive_contact(square, Pose{Vec2::Zero(), 0.0}, Circle{0.2}, Pose{Vec2(0.65, 0.1), 0.0});
  EXPECT_NEAR(side.penetration_m, 0.05, 1e-15);
  EXPECT_NEAR(side.normal.x(), 1.0, 1e-15);
  const PrimitiveContact corner =
      primitive_contact(square, Pose{Vec2::Zero(), 0.0}, Circle{0.2}, Pose{Vec2(0.8, 0.9), 0.0});
  EXPECT_NEAR(corner.penetration_m, 0.2 - 0.5, 1e-15);
  EXPECT_NEAR(corner.normal.x(), 0.6, 1e-15);
  EXPECT_NEAR(corner.normal.y(), 0.8, 1e-15);
}

// pairs without a closed form are named
TEST(Box2dInjectGeometry, SupportedPairs) {
  EXPECT_TRUE(primitive_contact_unsupported_reason(HalfPlane{}, Ellipse{1, 1}).empty());
  EXPECT_TRUE(primitive_contact_unsupported_reason(Ellipse{1, 1}, Circle{1}).empty());
  EXPECT_TRUE(primitive_contact_unsupported_reason(Circle{1}, Polygon{}).empty());
  EXPECT_FALSE(primitive_contact_unsupported_reason(Ellipse{1, 1}, Ellipse{1, 1}).empty());
  EXPECT_FALSE(primitive_contact_unsupported_reason(Polygon{}, Ellipse{1, 1}).empty());
  EXPECT_FALSE(primitive_contact_unsupported_reason(HalfPlane{}, HalfPlane{}).empty());
}

}  // namespace
}  // namespace pb::internal::box2d
