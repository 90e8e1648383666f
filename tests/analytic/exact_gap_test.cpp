// Tests for core/analytic/exact_gap.cpp
#include "exact_gap.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "independent_integrators.hpp"

namespace pb::internal {
namespace {

// Random points (seeded) around ellipses of several shapes, either axis the
// longer: the distance agrees with brute force to 1e-12 m and is negative
// inside; outside, the nearest points agree too (inside, points near the
// medial axis have two nearest points, so only the distance is compared).
TEST(ClosestPointOnEllipse, AgreesWithBruteForce) {
  std::mt19937 rng(20240601);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (const auto& [a, b] : {std::pair{0.7071, 0.25}, std::pair{0.25, 0.7071}, std::pair{1.0, 1.0},
                             std::pair{1.5, 0.01}}) {
    for (int i = 0; i < 300; ++i) {
      // braces: the two draws happen in this order with every compiler
      const Vec2 p{u(rng), u(rng)};
      const EllipseClosest c = closest_point_on_ellipse(a, b, p);
      const Vec2 q = testing::nearest_on_ellipse_brute(a, b, p);
      const bool inside = std::pow(p.x() / a, 2) + std::pow(p.y() / b, 2) < 1.0;
      // 1e-12 m: both are converged to rounding of numbers of size ~1
      EXPECT_NEAR(std::abs(c.signed_distance_m), (p - q).norm(), 1e-12)
          << a << " " << b << " " << p.transpose();
      EXPECT_EQ(c.signed_distance_m < 0.0, inside);
      // on the ellipse: each coordinate carries a rounding error of ~eps x max(a, b),
      // which (y / b)^2 amplifies by 2 max(a, b) / min(a, b); 8 eps x that ratio
      // leaves a factor 4 for the sum's own roundings (1.8e-15 for the circle,
      // 5.0e-15 for 0.7071 x 0.25). It failed before the root search ran on
      // s + 1: p = (0.2036, -7.07e-5), inside near the major axis, was 8.3e-14 off.
      const double on_tol =
          8.0 * std::numeric_limits<double>::epsilon() * std::max(a, b) / std::min(a, b);
      EXPECT_NEAR(std::pow(c.point.x() / a, 2) + std::pow(c.point.y() / b, 2), 1.0, on_tol);
      if (!inside) {
        EXPECT_LE((c.point - q).norm(), 1e-8) << a << " " << b << " " << p.transpose();
      }
    }
  }
}

// Points on the axes: the co-vertex, the vertex, and inside near the centre
// on the major axis the off-axis point x = a^2 p / (a^2 - b^2)
// (Eberly 2013, §2.9).
TEST(ClosestPointOnEllipse, PointsOnTheAxes) {
  const double a = 2.0;
  const double b = 1.0;
  const EllipseClosest minor = closest_point_on_ellipse(a, b, Vec2(0.0, 3.0));
  EXPECT_EQ(minor.point, Vec2(0.0, 1.0));
  EXPECT_EQ(minor.signed_distance_m, 2.0);
  const EllipseClosest major = closest_point_on_ellipse(a, b, Vec2(-5.0, 0.0));
  EXPECT_EQ(major.point, Vec2(-2.0, 0.0));
  EXPECT_EQ(major.signed_distance_m, 3.0);
  const EllipseClosest in = closest_point_on_ellipse(a, b, Vec2(0.6, 0.0));
  EXPECT_NEAR(in.point.x(), 4.0 * 0.6 / 3.0, 1e-15);
  EXPECT_NEAR(std::abs(in.point.y()), std::sqrt(1.0 - std::pow(0.8 / 2.0, 2)), 1e-15);
  EXPECT_LT(in.signed_distance_m, 0.0);
}

Pose pose(double x, double y, double angle) {
  return Pose{Vec2(x, y), angle};
}

TEST(ExactGap, CircleCircle) {
  const ExactGap g = exact_gap(Circle{0.5}, pose(0.0, 0.0, 0.0), Circle{0.25}, pose(3.0, 4.0, 1.0));
  EXPECT_DOUBLE_EQ(g.gap_m, 5.0 - 0.75);
  EXPECT_NEAR((g.normal - Vec2(0.6, 0.8)).norm(), 0.0, 1e-16);
  EXPECT_NEAR((g.point_a_m - Vec2(0.3, 0.4)).norm(), 0.0, 1e-16);
  EXPECT_NEAR((g.point_b_m - Vec2(3.0 - 0.15, 4.0 - 0.2)).norm(), 0.0, 1e-15);
}

// A half-plane at (1, 2) turned by 30 degrees: its outward normal is
// (-sin30, cos30); a disk's gap is the height of its centre minus R.
TEST(ExactGap, HalfPlaneCircleEitherOrder) {
  const double th = std::numbers::pi / 6.0;
  const Vec2 n(-std::sin(th), std::cos(th));
  const Pose line = pose(1.0, 2.0, th);
  const Pose disk{Vec2(1.0, 2.0) + 0.8 * n + 0.3 * Vec2(n.y(), -n.x()), 0.0};
  const ExactGap g = exact_gap(HalfPlane{}, line, Circle{0.5}, disk);
  EXPECT_NEAR(g.gap_m, 0.3, 1e-15);
  EXPECT_NEAR((g.normal - n).norm(), 0.0, 1e-15);
  EXPECT_NEAR((g.point_b_m - (disk.position_m - 0.5 * n)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((g.point_a_m - (disk.position_m - 0.8 * n)).norm(), 0.0, 1e-15);
  const ExactGap r = exact_gap(Circle{0.5}, disk, HalfPlane{}, line);
  EXPECT_NEAR(r.gap_m, 0.3, 1e-15);
  EXPECT_NEAR((r.normal + n).norm(), 0.0, 1e-15);
  EXPECT_EQ(r.point_a_m, g.point_b_m);
  EXPECT_EQ(r.point_b_m, g.point_a_m);
}

// An ellipse above a horizontal line: its lowest point by brute-force
// sampling of the turned outline.
TEST(ExactGap, HalfPlaneEllipse) {
  const Ellipse e{0.7071, 0.25};
  const Pose ep = pose(0.2, 1.0, 0.6);
  const ExactGap g = exact_gap(HalfPlane{}, pose(0.0, 0.0, 0.0), e, ep);
  double lowest = 1e300;
  for (int i = 0; i < 200000; ++i) {
    const double t = 2.0 * std::numbers::pi * i / 200000.0;
    const double x = e.semi_axis_a_m * std::cos(t);
    const double y = e.semi_axis_b_m * std::sin(t);
    lowest = std::min(lowest, 1.0 + std::sin(0.6) * x + std::cos(0.6) * y);
  }
  // sampling at 3e-5 rad misses the minimum by ~(3e-5)^2 * 0.7 / 2
  EXPECT_NEAR(g.gap_m, lowest, 1e-9);
  EXPECT_LE(g.gap_m, lowest);
  EXPECT_NEAR(g.point_b_m.y(), g.gap_m, 1e-15);
}

// The dual pendulum's pair at the moment the ellipse hangs straight down:
// ellipse centre (0, -0.7071), major axis vertical; disk centre (0.75,
// -0.7071), R = 0.5: the disk's side touches the ellipse's co-vertex
// (0.25, -0.7071), gap 0, normal +x from the ellipse to the disk.
TEST(ExactGap, EllipseDiskTouchAtTheVertical) {
  const ExactGap g = exact_gap(Ellipse{0.7071, 0.25}, pose(0.0, -0.7071, 0.5 * std::numbers::pi),
                               Circle{0.5}, pose(0.75, -0.7071, 0.0));
  EXPECT_NEAR(g.gap_m, 0.0, 1e-15);
  EXPECT_NEAR((g.normal - Vec2(1.0, 0.0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((g.point_a_m - Vec2(0.25, -0.7071)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((g.point_b_m - Vec2(0.25, -0.7071)).norm(), 0.0, 1e-15);
  // turned around: normal from the disk to the ellipse
  const ExactGap r = exact_gap(Circle{0.5}, pose(0.75, -0.7071, 0.0), Ellipse{0.7071, 0.25},
                               pose(0.0, -0.7071, 0.5 * std::numbers::pi));
  EXPECT_NEAR((r.normal - Vec2(-1.0, 0.0)).norm(), 0.0, 1e-15);
}

TEST(ExactGap, SupportedPairs) {
  EXPECT_TRUE(exact_gap_supported(Circle{1.0}, Circle{1.0}));
  EXPECT_TRUE(exact_gap_supported(Ellipse{1.0, 0.5}, Circle{1.0}));
  EXPECT_TRUE(exact_gap_supported(HalfPlane{}, Ellipse{1.0, 0.5}));
  EXPECT_TRUE(exact_gap_supported(Circle{1.0}, HalfPlane{}));
  EXPECT_FALSE(exact_gap_supported(Ellipse{1.0, 0.5}, Ellipse{1.0, 0.5}));
  EXPECT_FALSE(exact_gap_supported(HalfPlane{}, HalfPlane{}));
  EXPECT_FALSE(exact_gap_supported(Polygon{}, Circle{1.0}));
}

}  // namespace
}  // namespace pb::internal
