// Tests for adapters/mujoco/mujoco_exact_depth.cpp
//
// Truths: the distance from a point to an ellipse by brute force (the
// minimum over 200000 points of the ellipse, refined by golden-section
// search on the parameter angle), and circles placed along an ellipse's
// normal at a known depth.
#include "mujoco_exact_depth.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace pb::internal::mujoco {
namespace {

constexpr double kPi = std::numbers::pi;

double brute_force_distance(double a, double b, double x, double y) {
  auto dist = [&](double t) { return std::hypot(x - a * std::cos(t), y - b * std::sin(t)); };
  const int n = 200000;
  double best_t = 0.0;
  double best = dist(0.0);
  for (int i = 1; i < n; ++i) {
    const double t = 2.0 * kPi * i / n;
    if (dist(t) < best) best = dist(t), best_t = t;
  }
  double lo = best_t - 2.0 * kPi / n;
  double hi = best_t + 2.0 * kPi / n;
  for (int i = 0; i < 200; ++i) {
    const double m1 = lo + (hi - lo) / 3.0;
    const double m2 = hi - (hi - lo) / 3.0;
    (dist(m1) < dist(m2) ? hi : lo) = (dist(m1) < dist(m2) ? m2 : m1);
  }
  return dist(0.5 * (lo + hi));
}

TEST(ExactDepth, PointEllipseDistanceMatchesBruteForce) {
  std::mt19937 rng(12345);  // seeded: the same points every run
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  for (int i = 0; i < 40; ++i) {
    const double x = u(rng);
    const double y = u(rng);
    // both axis orders; 1e-12 m: the brute force's refinement limit
    EXPECT_NEAR(point_ellipse_distance_m(0.7071, 0.25, x, y),
                brute_force_distance(0.7071, 0.25, x, y), 1e-12)
        << x << " " << y;
    EXPECT_NEAR(point_ellipse_distance_m(0.3, 0.9, x, y), brute_force_distance(0.3, 0.9, x, y),
                1e-12)
        << x << " " << y;
  }
  // on the axes, inside and outside (the robust algorithm's special branches);
  // 1e-15 m: there the distance is one subtraction of exact numbers
  EXPECT_NEAR(point_ellipse_distance_m(2.0, 1.0, 3.0, 0.0), 1.0, 1e-15);
  EXPECT_NEAR(point_ellipse_distance_m(2.0, 1.0, 0.0, 1.5), 0.5, 1e-15);
  EXPECT_NEAR(point_ellipse_distance_m(2.0, 1.0, 0.2, 0.0),
              brute_force_distance(2.0, 1.0, 0.2, 0.0), 1e-12);
}

TEST(ExactDepth, CircleAlongTheEllipseNormalAtAKnownDepth) {
  // ellipse a = 0.7071, b = 0.25 turned 90 deg at (1, 2); a circle R = 0.5
  // whose centre lies on the normal of the ellipse point at parameter t, at
  // R - depth from it: the penetration is depth
  const double a = 0.7071;
  const double b = 0.25;
  BodyState pe;
  pe.position_m = Vec2(1.0, 2.0);
  pe.angle_rad = kPi / 2.0;
  for (double t : {0.0, 0.4, 1.3, 2.2}) {
    const double depth = 1e-4;
    const Vec2 p(a * std::cos(t), b * std::sin(t));
    const Vec2 n = Vec2(std::cos(t) / a, std::sin(t) / b).normalized();
    const Vec2 local = p + (0.5 - depth) * n;
    BodyState pc;
    // turn the local offset by 90 deg into the world
    pc.position_m = pe.position_m + Vec2(-local.y(), local.x());
    const auto d1 = exact_penetration_m(Circle{0.5}, pc, Ellipse{a, b}, pe);
    const auto d2 = exact_penetration_m(Ellipse{a, b}, pe, Circle{0.5}, pc);
    ASSERT_TRUE(d1.has_value());
    // 1e-12 m: rounding of the placement (unit-size coordinates, a normalised
    // normal) and of the point-ellipse distance, checked to 1e-12 above
    EXPECT_NEAR(*d1, depth, 1e-12) << t;
    EXPECT_EQ(*d1, *d2);
  }
  EXPECT_FALSE(exact_penetration_m(Circle{1.0}, pe, Circle{1.0}, pe).has_value());
}

}  // namespace
}  // namespace pb::internal::mujoco
