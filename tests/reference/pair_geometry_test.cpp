// Tests for core/reference/src/pair_geometry.cpp
#include "planarbench/reference/pair_geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pb {
namespace {

Body body(Shape s, int points = 180) {
  Body b;
  b.name = "body";
  b.shape = std::move(s);
  b.outline_points = points;
  return b;
}

// A disk of radius 0.5 with its centre 0.6 above a line: the exact gap is
// 0.1; the 180-point outline, with a point straight below the centre, too.
TEST(PairGeometry, ModesAgreeWhereTheOutlineIsExact) {
  PairGeometry exact(body(HalfPlane{}), body(Circle{0.5}), GeometryMode::exact);
  PairGeometry outline(body(HalfPlane{}, 181), body(Circle{0.5}), GeometryMode::outline);
  const Pose disk{Vec2(0.0, 0.6), 0.0};
  // exact: 0.6 - 0.5 in doubles, one rounding; the outline's point below the
  // centre comes from sin(3 pi / 2) and a pose transform, a few roundings more
  EXPECT_NEAR(exact.evaluate(Pose{}, disk).gap_m, 0.1, 1e-15);
  EXPECT_NEAR(outline.evaluate(Pose{}, disk).gap_m, 0.1, 1e-14);
}

// A square pressed tilted into a half-plane of 180 outline points (22 mm
// apart over its 4 m): frictionless, the paper's rule takes the line of action
// from the half-plane's points inside the square (more of them than its two
// corners); with friction, from the square's own corners, as geometry=exact
// does, in both detection modes: the same point and spread as the exact
// routine (whose closed form exact_contact_test checks) to the outline's
// rounding of the corners' placement
TEST(PairGeometry, FrictionOnAHalfPlaneActsAtTheBodysOwnPoints) {
  const Polygon sq{{Vec2(-0.1, -0.1), Vec2(0.1, -0.1), Vec2(0.1, 0.1), Vec2(-0.1, 0.1)}};
  Body line = body(HalfPlane{4.0});
  Body square = body(sq, 4);
  const double a = std::asin(0.001);
  const Pose pose{Vec2(0.013, 0.1 * (std::cos(a) + 0.001) - 3e-4), a};  // corners 3e-4, 1e-4 deep
  PairGeometry exact(line, square, GeometryMode::exact);
  const ContactGeometry want = exact.evaluate(Pose{}, pose);
  ASSERT_GT(want.spread_m2, 0.0);
  for (const DetectionMode d : {DetectionMode::fast, DetectionMode::brute}) {
    PairGeometry with(line, square, GeometryMode::outline, d, true);
    const ContactGeometry g = with.evaluate(Pose{}, pose);
    // corners placed by a rotation and a sum: 1e-16 m each; the centroid and
    // spread of two depths ~1e-4 m: 1e-12 m, 1e-14 m^2
    EXPECT_NEAR(g.gap_m, want.gap_m, 1e-15);
    EXPECT_NEAR(g.point_b_m.x(), want.point_b_m.x(), 1e-12);
    EXPECT_NEAR(g.point_b_m.y(), want.point_b_m.y(), 1e-12);
    EXPECT_NEAR(g.spread_m2, want.spread_m2, 1e-14);
    PairGeometry without(line, square, GeometryMode::outline, d, false);
    // frictionless: the line's samples 22 mm apart under the 0.2 m face; their
    // centroid is off the corners' by several mm
    EXPECT_GT(std::abs(without.evaluate(Pose{}, pose).point_b_m.x() - want.point_b_m.x()), 1e-3);
  }
}

// concave_corner's L (issue 31) turned 20 deg with its outer corner 20 mm into
// a half-plane of 180 outline points: one vertex inside, and the line's
// samples inside the lopsided wedge around it. The pair acts at the vertex,
// as geometry=exact does, in both detection modes; the paper's rule alone
// (the body with more points inside) takes the samples' centroid, 19 mm
// beside the corner here (measured with the rule removed: x = 0.0325 m).
TEST(PairGeometry, OneVertexInsideASampledBodyActsAtTheVertex) {
  const Polygon ell{{Vec2(-0.11, -0.11), Vec2(0.19, -0.11), Vec2(0.19, -0.01), Vec2(-0.01, -0.01),
                     Vec2(-0.01, 0.19), Vec2(-0.11, 0.19)}};
  Body line = body(HalfPlane{4.0});
  Body l_body = body(ell, 6);
  const double a = 20.0 * std::acos(-1.0) / 180.0;
  const Vec2 corner(-0.11 * std::cos(a) + 0.11 * std::sin(a), -0.11 * std::sin(a) - 0.11 * std::cos(a));
  const Pose pose{Vec2(0.013 - corner.x(), -0.02 - corner.y()), a};  // the corner at (0.013, -0.02)
  PairGeometry exact(line, l_body, GeometryMode::exact);
  const ContactGeometry want = exact.evaluate(Pose{}, pose);
  // the exact routine's line of action through the corner (a placement by a
  // rotation and a sum: 1e-16 m)
  ASSERT_NEAR(want.point_b_m.x(), 0.013, 1e-15);
  for (const DetectionMode d : {DetectionMode::fast, DetectionMode::brute}) {
    PairGeometry g(line, l_body, GeometryMode::outline, d, false);
    const ContactGeometry got = g.evaluate(Pose{}, pose);
    // the same vertex placed by the outline's own rotation: 1e-15 m
    EXPECT_NEAR(got.gap_m, want.gap_m, 1e-15);
    EXPECT_NEAR(got.point_b_m.x(), 0.013, 1e-15);
    EXPECT_NEAR(got.point_b_m.y(), -0.02, 1e-15);
  }
}

// head_on's two 180-point disks (R = 0.2 m) pressed vertex against vertex,
// 2 mm deep: each deepest vertex lies on the bisector of the other's wedge,
// as deep below both faces. The contact pushes along the centre line, not
// along whichever face the rounding made nearer (issue 35: the normal flipped
// by 2 deg between steps and, with friction, so did the slip direction, 4e6
// steps for 0.5 s); both detection modes, with and without friction
TEST(PairGeometry, VertexOnAWedgesBisectorIsPushedAlongIt) {
  Body a = body(Circle{0.2});
  Body b = body(Circle{0.2});
  for (const double y : {0.0, 1e-17, -3e-17}) {  // on the axis and off it by rounding
    const Pose pa{Vec2(-0.199, y), 0.0};
    const Pose pb{Vec2(0.199, 0.0), 0.0};
    for (const DetectionMode d : {DetectionMode::fast, DetectionMode::brute}) {
      for (const bool friction : {false, true}) {
        PairGeometry g(a, b, GeometryMode::outline, d, friction);
        const ContactGeometry c = g.evaluate(pa, pb);
        ASSERT_LT(c.gap_m, 0.0);
        // the bisector of two faces 2 deg apart, from normals each rounded
        // to 1e-16: along x to 1e-15 (a face's normal would be 0.01745 off)
        EXPECT_NEAR(c.normal.y(), 0.0, 1e-15) << y << " " << friction;
        EXPECT_NEAR(c.normal.x(), 1.0, 1e-15);
      }
    }
  }
}

TEST(PairGeometry, SupportDependsOnTheMode) {
  std::string why;
  EXPECT_TRUE(PairGeometry::supported(body(Ellipse{1, 0.5}), body(Ellipse{1, 0.5}),
                                      GeometryMode::outline, &why));
  EXPECT_FALSE(PairGeometry::supported(body(Ellipse{1, 0.5}), body(Ellipse{1, 0.5}),
                                       GeometryMode::exact, &why));
  EXPECT_NE(why.find("geometry=outline"), std::string::npos);
  EXPECT_FALSE(PairGeometry::supported(body(HalfPlane{}), body(HalfPlane{}),
                                       GeometryMode::outline, &why));
  EXPECT_FALSE(PairGeometry::supported(body(Circle{1}, 2), body(HalfPlane{}),
                                       GeometryMode::outline, &why));
  // two polygons are exact as outlines in both modes
  const Polygon sq{{Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)}};
  EXPECT_TRUE(PairGeometry::supported(body(sq), body(sq), GeometryMode::exact, &why));
  EXPECT_THROW(PairGeometry(body(HalfPlane{}), body(HalfPlane{}), GeometryMode::exact),
               std::invalid_argument);
}

}  // namespace
}  // namespace pb
