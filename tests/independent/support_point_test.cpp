// Tests for core/independent/support_point.cpp
#include "support_point.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace pb::independent {
namespace {

// An ellipse (a, b) turned by theta, against the direction u = (0, -1): its
// lowest point. Closed form: in the body frame u' = (-sin theta, -cos theta),
// so h = sqrt(a^2 sin^2 theta + b^2 cos^2 theta); checked also against the
// largest u . p over 2e5 points of the parametrisation, which errs below the
// true maximum by at most |d^2 (u . p) / dt^2| (dt / 2)^2 / 2 <= a (pi / 2e5)^2 / 2
// = 3.7e-11 m (a the larger semi-axis, dt = 2 pi / 2e5 the spacing).
TEST(SupportPoint, EllipseLowestPoint) {
  const double a = 0.3;
  const double b = 0.15;
  const Vec2 u(0.0, -1.0);
  for (const double theta : {0.0, 0.3, 1.0, 2.0, -0.7}) {
    const Pose pose{Vec2(1.0, 2.0), theta};
    const SupportPoint s = support_point(Ellipse{a, b}, pose, u);
    const double h = std::sqrt(a * a * std::sin(theta) * std::sin(theta) +
                               b * b * std::cos(theta) * std::cos(theta));
    EXPECT_NEAR(s.reach_m, h, 1e-15) << theta;  // one square root's rounding
    EXPECT_NEAR(u.dot(s.point_m - pose.centre_m), h, 1e-15) << theta;
    double best = -1.0;
    for (int k = 0; k < 200000; ++k) {
      const double t = 2.0 * std::numbers::pi * k / 200000.0;
      const Vec2 body(a * std::cos(t), b * std::sin(t));
      const Vec2 world(std::cos(theta) * body.x() - std::sin(theta) * body.y(),
                       std::sin(theta) * body.x() + std::cos(theta) * body.y());
      best = std::max(best, u.dot(world));
    }
    EXPECT_LE(best, h + 1e-15);
    EXPECT_GE(best, h - 3.7e-11);  // the sampling's bound above
    // the support point is on the ellipse
    const double c = std::cos(theta);
    const double si = std::sin(theta);
    const Vec2 r = s.point_m - pose.centre_m;
    const Vec2 body(c * r.x() + si * r.y(), -si * r.x() + c * r.y());
    EXPECT_NEAR(std::pow(body.x() / a, 2) + std::pow(body.y() / b, 2), 1.0, 1e-14);
  }
}

TEST(SupportPoint, Circle) {
  const SupportPoint s = support_point(Circle{0.5}, Pose{Vec2(1.0, 1.0), 2.0}, Vec2(0.6, -0.8));
  EXPECT_EQ(s.reach_m, 0.5);
  EXPECT_NEAR((s.point_m - Vec2(1.3, 0.6)).norm(), 0.0, 1e-15);
  EXPECT_EQ(s.vertex, -1);
}

// a unit square turned by 0.1 rad: the lowest vertex is (-0.5, -0.5) turned
// (its y = -0.5 sin 0.1 - 0.5 cos 0.1), the next one (0.5, -0.5) turned
// (y = 0.5 sin 0.1 - 0.5 cos 0.1); one rounding each: 1e-15
TEST(SupportPoint, PolygonDeepestAndNextVertex) {
  const Polygon sq{{Vec2(-0.5, -0.5), Vec2(0.5, -0.5), Vec2(0.5, 0.5), Vec2(-0.5, 0.5)}};
  const double th = 0.1;
  const SupportPoint s = support_point(sq, Pose{Vec2::Zero(), th}, Vec2(0.0, -1.0));
  EXPECT_EQ(s.vertex, 0);
  EXPECT_NEAR(s.reach_m, -(-0.5 * std::sin(th) - 0.5 * std::cos(th)), 1e-15);
  EXPECT_NEAR(s.next_reach_m, -(0.5 * std::sin(th) - 0.5 * std::cos(th)), 1e-15);
}

}  // namespace
}  // namespace pb::independent
