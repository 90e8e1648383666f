// Tests for core/src/ellipse_distance.cpp
//
// The truth is a direct minimisation of |p - (a cos t, b sin t)|^2 over the
// parameter t: a dense grid, then Newton's method on the derivative, written
// here independently of Eberly's bisection.
#include "planarbench/ellipse_distance.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace pb {
namespace {

// distance from p to the ellipse by minimising over the parameter angle
double distance_by_parameter(double a, double b, const Vec2& p) {
  auto f = [&](double t) { return (p - Vec2(a * std::cos(t), b * std::sin(t))).squaredNorm(); };
  double best_t = 0.0;
  double best = f(0.0);
  const int n = 20000;
  for (int i = 1; i < n; ++i) {
    const double t = 2.0 * std::numbers::pi * i / n;
    if (f(t) < best) best = f(t), best_t = t;
  }
  // Newton on f'(t) = 2 [(a cos t - px)(-a sin t) + (b sin t - py)(b cos t)]
  double t = best_t;
  for (int it = 0; it < 50; ++it) {
    const double c = std::cos(t), s = std::sin(t);
    const double g = (a * c - p.x()) * (-a * s) + (b * s - p.y()) * (b * c);
    const double h = (a * s) * (a * s) + (a * c - p.x()) * (-a * c) + (b * c) * (b * c) +
                     (b * s - p.y()) * (-b * s);
    if (!(h > 0.0)) break;
    t -= g / h;
  }
  return std::sqrt(std::min(best, f(t)));
}

void check_point(double a, double b, const Vec2& p) {
  const EllipseClosestPoint cp = closest_point_on_ellipse(a, b, p);
  const Vec2 q = cp.point_m;
  // on the ellipse
  EXPECT_NEAR((q.x() / a) * (q.x() / a) + (q.y() / b) * (q.y() / b), 1.0, 1e-14);
  // the distance of the minimisation, signed by inside / outside
  const bool inside = (p.x() / a) * (p.x() / a) + (p.y() / b) * (p.y() / b) < 1.0;
  const double d = distance_by_parameter(a, b, p);
  // the brute-force parameter search is refined to ~1e-13 m; distances here are O(1) m
  EXPECT_NEAR(std::abs(cp.signed_distance_m), d, 1e-12);
  EXPECT_EQ(cp.signed_distance_m < 0.0, inside && d > 0.0);
  // p - q along the normal (orthogonal to the tangent (-a sin t, b cos t))
  if ((p - q).norm() > 1e-9) {
    const Vec2 tangent(-q.y() * a / b, q.x() * b / a);
    // direction of p - q: rounding of q (~1e-16 m) over the nearest test
    // point's |p - q| = 1e-7 m (NearTheBoundary) is ~1e-9
    EXPECT_NEAR((p - q).normalized().dot(tangent.normalized()), 0.0, 1e-9);
    EXPECT_NEAR(std::abs((p - q).normalized().dot(cp.outward_normal)), 1.0, 1e-9);
  }
}

TEST(EllipseDistance, RandomPointsInsideAndOutside) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  // the dual_pendulum ellipse, the same turned (a < b) and a circle
  for (const auto& ab : {Vec2(0.7071, 0.25), Vec2(0.25, 0.7071), Vec2(0.5, 0.5)}) {
    for (int i = 0; i < 200; ++i) check_point(ab.x(), ab.y(), Vec2{u(rng), u(rng)});
  }
}

TEST(EllipseDistance, SpecialPointsOnTheAxes) {
  const double a = 0.7071, b = 0.25;
  // the centre: the nearest points are the ends of the minor axis
  EXPECT_NEAR(closest_point_on_ellipse(a, b, Vec2(0, 0)).signed_distance_m, -b, 1e-15);
  // on the major axis inside the evolute, x < (a^2 - b^2)/a: off the axis
  const Vec2 p(0.3, 0.0);
  const EllipseClosestPoint cp = closest_point_on_ellipse(a, b, p);
  EXPECT_GT(std::abs(cp.point_m.y()), 0.0);
  check_point(a, b, p);
  // on the major axis outside: the end of the axis
  EXPECT_NEAR(closest_point_on_ellipse(a, b, Vec2(1.0, 0.0)).signed_distance_m, 1.0 - a, 1e-15);
  // on the minor axis outside and inside
  EXPECT_NEAR(closest_point_on_ellipse(a, b, Vec2(0.0, -0.4)).signed_distance_m, 0.4 - b, 1e-15);
  check_point(a, b, Vec2(0.0, 0.1));
  // on the ellipse itself
  const Vec2 on(a * std::cos(0.3), b * std::sin(0.3));
  // a point on the ellipse to rounding of cos/sin: a few ulps of 0.7 m
  EXPECT_NEAR(closest_point_on_ellipse(a, b, on).signed_distance_m, 0.0, 1e-15);
}

TEST(EllipseDistance, NearTheBoundaryOfTheDualPendulumContact) {
  // points 1e-4 m around the end of the minor axis, where the pendulums meet
  const double a = 0.7071, b = 0.25;
  for (const double dy : {-1e-4, -1e-7, 1e-7, 1e-4}) {
    for (const double dx : {-1e-3, 0.0, 2e-3}) check_point(a, b, Vec2(dx, -(b + dy)));
  }
}

}  // namespace
}  // namespace pb
