// Tests for core/independent/ellipse_closest_point.cpp
#include "ellipse_closest_point.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace pb::independent {
namespace {

// a circle (a = b): the nearest point is along the ray from the centre,
// (3, 4) / 5 at distance 5 - 1 = 4 (a 3-4-5 triangle: exact in binary to a
// few ulps; 1e-15 covers the bisection's last bit)
TEST(EllipseClosestPoint, CircleAlongTheRay) {
  const EllipseNearest q = nearest_on_ellipse(1.0, 1.0, Vec2(3.0, 4.0));
  ASSERT_TRUE(q.outside);
  EXPECT_NEAR(q.point_m.x(), 0.6, 1e-15);
  EXPECT_NEAR(q.point_m.y(), 0.8, 1e-15);
  EXPECT_NEAR(q.distance_m, 4.0, 1e-15);
}

// on an axis outside: the vertex or co-vertex, whichever axis the point is
// on and whichever semi-axis is the larger (a < b takes the swapped branch)
TEST(EllipseClosestPoint, OnTheAxes) {
  struct Row {
    double a, b;
    Vec2 query, point;
    double distance;
  };
  const Row rows[] = {
      {2.0, 1.0, Vec2(5.0, 0.0), Vec2(2.0, 0.0), 3.0},
      {2.0, 1.0, Vec2(-5.0, 0.0), Vec2(-2.0, 0.0), 3.0},
      {2.0, 1.0, Vec2(0.0, 3.0), Vec2(0.0, 1.0), 2.0},
      {2.0, 1.0, Vec2(0.0, -3.0), Vec2(0.0, -1.0), 2.0},
      {1.0, 2.0, Vec2(0.0, 5.0), Vec2(0.0, 2.0), 3.0},
      {1.0, 2.0, Vec2(4.0, 0.0), Vec2(1.0, 0.0), 3.0},
  };
  for (const Row& r : rows) {
    const EllipseNearest q = nearest_on_ellipse(r.a, r.b, r.query);
    ASSERT_TRUE(q.outside);
    // exact: no arithmetic on these branches beyond the difference
    EXPECT_EQ(q.point_m, r.point) << r.query.transpose();
    EXPECT_EQ(q.distance_m, r.distance) << r.query.transpose();
  }
}

// Off the axes, in every quadrant: a point p = (a cos t, b sin t) of the
// ellipse moved by d along the outward normal there, n ~ (cos t / a, sin t / b),
// has p as its nearest point for every d > 0 (a convex set's nearest-point map
// sends p + d n back to p), at distance d. Tolerance: the bisection stops at
// the last bit of the root s ~ O(1); x_i = e_i^2 y_i / (t + e_i^2) then carries
// a few ulps of the O(1) coordinates: 1e-14 m.
TEST(EllipseClosestPoint, PointMovedAlongTheNormalComesBack) {
  for (const auto& [a, b] : {std::pair{0.7071, 0.25}, std::pair{0.3, 0.15}, std::pair{0.2, 0.5}}) {
    for (int k = 0; k < 16; ++k) {
      const double t = 0.1 + k * 2.0 * std::numbers::pi / 16.0;  // off the axes
      const Vec2 p(a * std::cos(t), b * std::sin(t));
      const Vec2 n = Vec2(std::cos(t) / a, std::sin(t) / b).normalized();
      for (const double d : {1e-6, 0.01, 0.5, 3.0}) {
        const EllipseNearest q = nearest_on_ellipse(a, b, p + d * n);
        ASSERT_TRUE(q.outside);
        EXPECT_NEAR((q.point_m - p).norm(), 0.0, 1e-14)
            << a << " " << b << " t " << t << " d " << d;
        EXPECT_NEAR(q.distance_m, d, 1e-14) << a << " " << b << " t " << t << " d " << d;
      }
    }
  }
}

TEST(EllipseClosestPoint, InsideIsNotOutside) {
  EXPECT_FALSE(nearest_on_ellipse(2.0, 1.0, Vec2(0.5, 0.5)).outside);
  EXPECT_FALSE(nearest_on_ellipse(2.0, 1.0, Vec2(2.0, 0.0)).outside);  // on the boundary
}

}  // namespace
}  // namespace pb::independent
