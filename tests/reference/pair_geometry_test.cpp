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
