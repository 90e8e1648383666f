// Tests for core/src/outline.cpp
#include "planarbench/outline.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace pb {
namespace {

constexpr double kPi = std::numbers::pi;

// twice the signed area of the triangle a, b, c: > 0 for a left turn
double turn(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

// A circle outline is the regular n-gon inscribed in the circle: point k at
// polar angle 2 pi k / n, so every point lies on the circle and every turn is
// to the left (counter-clockwise).
TEST(Outline, CirclePointsLieOnTheCircleCounterClockwise) {
  const double r = 0.5;  // m
  const int n = 180;
  const auto pts = make_outline(Circle{r}, n);
  ASSERT_EQ(pts.size(), 180u);
  // point 0 at angle 0, exactly
  EXPECT_EQ(pts[0].x(), r);
  EXPECT_EQ(pts[0].y(), 0.0);
  for (int k = 0; k < n; ++k) {
    const Vec2& p = pts[static_cast<std::size_t>(k)];
    // radius exact to rounding of cos/sin: a few ulps of 0.5 m
    EXPECT_NEAR(p.norm(), r, 4e-16) << k;
    // polar angle 2 pi k / n (atan2 in (-pi, pi], so compare cos and sin)
    const double t = 2.0 * kPi * k / n;
    EXPECT_NEAR(p.x(), r * std::cos(t), 1e-16) << k;
    EXPECT_NEAR(p.y(), r * std::sin(t), 1e-16) << k;
    const Vec2& q = pts[static_cast<std::size_t>((k + 1) % n)];
    const Vec2& s = pts[static_cast<std::size_t>((k + 2) % n)];
    EXPECT_GT(turn(p, q, s), 0.0) << k;
  }
}

// An ellipse outline is (a cos t, b sin t) with t = 2 pi k / n: every point
// satisfies (x/a)^2 + (y/b)^2 = 1.
TEST(Outline, EllipsePointsLieOnTheEllipseCounterClockwise) {
  const double a = 0.7071, b = 0.25;  // m
  const int n = 180;
  const auto pts = make_outline(Ellipse{a, b}, n);
  ASSERT_EQ(pts.size(), 180u);
  EXPECT_EQ(pts[0], Vec2(a, 0.0));
  // point n/4 is the top of the ellipse, (0, b) to rounding of cos(pi/2)
  // a cos(pi/2) = 0.7071 * 6e-17 ~ 4e-17: within 1e-16
  EXPECT_NEAR(pts[45].x(), 0.0, 1e-16);
  EXPECT_NEAR(pts[45].y(), b, 1e-16);
  for (int k = 0; k < n; ++k) {
    const Vec2& p = pts[static_cast<std::size_t>(k)];
    const double level = (p.x() / a) * (p.x() / a) + (p.y() / b) * (p.y() / b);
    EXPECT_NEAR(level, 1.0, 1e-15) << k;  // rounding of a few operations near 1
    const Vec2& q = pts[static_cast<std::size_t>((k + 1) % n)];
    const Vec2& s = pts[static_cast<std::size_t>((k + 2) % n)];
    EXPECT_GT(turn(p, q, s), 0.0) << k;
  }
}

// The half-plane surface runs from +extent/2 to -extent/2 along body x, so
// the solid (y <= 0) is on the left of the direction of travel.
TEST(Outline, HalfPlaneSurfaceRunsFromPlusToMinusHalfExtent) {
  const auto pts = make_outline(HalfPlane{40.0}, 5);
  ASSERT_EQ(pts.size(), 5u);
  const double expected[] = {20.0, 10.0, 0.0, -10.0, -20.0};
  for (std::size_t k = 0; k < 5; ++k) {
    EXPECT_EQ(pts[k].x(), expected[k]) << k;  // multiples of 10 are exact in binary
    EXPECT_EQ(pts[k].y(), 0.0) << k;
  }
}

TEST(Outline, PolygonOutlineIsItsOwnPoints) {
  const Polygon square{{Vec2(-1, -1), Vec2(1, -1), Vec2(1, 1), Vec2(-1, 1)}};
  const auto pts = make_outline(square, 180);
  ASSERT_EQ(pts.size(), 4u);
  EXPECT_EQ(pts[2], Vec2(1, 1));
}

TEST(Outline, TooFewPointsAreRejected) {
  EXPECT_THROW((void)make_outline(Circle{1.0}, 2), std::invalid_argument);
  EXPECT_THROW((void)make_outline(HalfPlane{1.0}, 1), std::invalid_argument);
}

// Unit square [0,1]^2, written away from the origin on purpose: area 1,
// centroid (0.5, 0.5), polar moment about the centroid (b h^3 + h b^3)/12 = 1/6
// (Gere & Goodno, Mechanics of Materials, Appendix E, rectangle).
TEST(PolygonAreaProperties, UnitSquareAgainstHandFormulas) {
  const auto props = polygon_area_properties({Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)});
  // exact in binary: every product and sum here is a small dyadic rational,
  // except 1/6, which gets one rounding
  EXPECT_EQ(props.area_m2, 1.0);
  EXPECT_EQ(props.centroid_m, Vec2(0.5, 0.5));
  EXPECT_NEAR(props.polar_moment_centroid_m4, 1.0 / 6.0, 1e-16);  // one ulp of 1/6 is 2.8e-17
}

// Right triangle with legs b = 3 (along x) and h = 2 (along y) at (10, 20):
// area b h / 2 = 3, centroid at corner + (b/3, h/3), second moments about the
// centroid I_x = b h^3 / 36, I_y = h b^3 / 36, so J = b h (b^2 + h^2) / 36
// = 6 * 13 / 36 (Gere & Goodno, Appendix E, right triangle).
TEST(PolygonAreaProperties, RightTriangleAgainstHandFormulas) {
  const Vec2 o(10.0, 20.0);
  const auto props = polygon_area_properties({o, o + Vec2(3, 0), o + Vec2(0, 2)});
  // sums of a few products of small integers: exact or one rounding
  EXPECT_NEAR(props.area_m2, 3.0, 1e-15);
  EXPECT_NEAR(props.centroid_m.x(), 11.0, 1e-14);  // one rounding of 11 and of 1/3 scale
  EXPECT_NEAR(props.centroid_m.y(), 20.0 + 2.0 / 3.0, 1e-14);
  EXPECT_NEAR(props.polar_moment_centroid_m4, 6.0 * 13.0 / 36.0, 1e-14);
}

// Listing the same triangle clockwise flips the sign of area and moment and
// leaves the centroid.
TEST(PolygonAreaProperties, ClockwisePointsGiveNegativeArea) {
  const auto props = polygon_area_properties({Vec2(0, 0), Vec2(0, 2), Vec2(3, 0)});
  // same sums as above in reverse order: a few ulps
  EXPECT_NEAR(props.area_m2, -3.0, 1e-15);
  EXPECT_NEAR(props.centroid_m.x(), 1.0, 1e-15);
  EXPECT_NEAR(props.polar_moment_centroid_m4, -6.0 * 13.0 / 36.0, 1e-14);
}

TEST(ShapeAreaProperties, ExactCircleAndEllipse) {
  const auto disk = shape_area_properties(Circle{0.5});
  EXPECT_DOUBLE_EQ(disk.area_m2, kPi * 0.25);             // pi R^2
  EXPECT_DOUBLE_EQ(disk.polar_moment_centroid_m4, kPi * 0.0625 / 2.0);  // pi R^4 / 2
  const double a = 0.7071, b = 0.25;
  const auto ell = shape_area_properties(Ellipse{a, b});
  EXPECT_DOUBLE_EQ(ell.area_m2, kPi * a * b);                            // pi a b
  EXPECT_DOUBLE_EQ(ell.polar_moment_centroid_m4, kPi * a * b * (a * a + b * b) / 4.0);
  EXPECT_THROW((void)shape_area_properties(HalfPlane{20.0}), std::invalid_argument);
  const auto sq = shape_area_properties(Polygon{{Vec2(-1, -1), Vec2(1, -1), Vec2(1, 1), Vec2(-1, 1)}});
  EXPECT_EQ(sq.area_m2, 4.0);
  EXPECT_NEAR(sq.polar_moment_centroid_m4, 2.0 * 2.0 * (4.0 + 4.0) / 12.0, 1e-15);  // b h (b^2+h^2)/12
}

// The N-point outline of a disk is the regular N-gon inscribed in it, whose
// area is (N/2) R^2 sin(2 pi / N) and whose polar moment about the centre is
// (N/12) R^4 sin(2 pi/N) (2 + cos(2 pi/N)) (sum over the N isosceles triangles
// of the polygon moment formula). Both fall short of the disk's pi R^2 and
// pi R^4 / 2 by O(1/N^2): the area error is (2 pi^3 / 3) R^2 / N^2 + O(1/N^4).
TEST(OutlineAreaConvergence, RegularPolygonAreaApproachesTheDisk) {
  const double r = 0.5;  // m
  double previous_error = 0.0;
  for (const int n : {45, 90, 180, 360, 720}) {
    const auto props = polygon_area_properties(make_outline(Circle{r}, n));
    const double s = std::sin(2.0 * kPi / n);
    const double c = std::cos(2.0 * kPi / n);
    // the closed forms; the code sums N terms, rounding up to ~N ulps of 0.8
    EXPECT_NEAR(props.area_m2, 0.5 * n * r * r * s, 1e-13) << n;
    EXPECT_NEAR(props.polar_moment_centroid_m4, n / 12.0 * r * r * r * r * s * (2.0 + c), 1e-13) << n;
    EXPECT_NEAR(props.centroid_m.norm(), 0.0, 1e-15) << n;  // symmetric sum: rounding of O(0.5 m) terms
    // leading term of the error, to 1 % (the next term is O(1/N^2) relative)
    const double error = kPi * r * r - props.area_m2;
    const double leading = 2.0 * kPi * kPi * kPi / 3.0 * r * r / (static_cast<double>(n) * n);
    EXPECT_NEAR(error / leading, 1.0, 0.01) << n;
    // doubling N divides the error by 4 (within 1 %)
    if (previous_error > 0.0) {
      EXPECT_NEAR(previous_error / error, 4.0, 0.04) << n;
    }
    previous_error = error;
  }
}

}  // namespace
}  // namespace pb
