// Tests for core/reference/src/exact_contact.cpp
//
// Each pair against its closed form (distances of circles to lines and to
// each other, the height of a turned ellipse's lowest point above a line) or,
// for ellipse-circle, against a direct minimisation over the ellipse's
// parameter written here.
#include "planarbench/reference/exact_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace pb {
namespace {

constexpr double kPi = std::numbers::pi;

// Tolerances: the closed forms below take 1e-15 m on O(1) m inputs (a few
// roundings of 1.1e-16 through a sin/cos and a pose transform); the
// self-consistency checks, 1e-14 / 1e-13, recompute the gap from rounded
// points a few units of magnitude apart.
void expect_consistent(const ContactGeometry& g) {
  EXPECT_NEAR(g.normal.norm(), 1.0, 1e-14);
  EXPECT_NEAR(g.gap_m, g.normal.dot(g.point_b_m - g.point_a_m), 1e-13);
}

TEST(ExactContact, CircleOnTurnedLine) {
  // ground through the origin declined 30 deg, disk radius 0.5 at (2, 2):
  // gap = n . c - R with n = (sin30, cos30)
  const ExactContact ec(HalfPlane{}, Circle{0.5});
  const Pose ground{Vec2(0, 0), -kPi / 6};
  const ContactGeometry g = ec.evaluate(ground, Pose{Vec2(2, 2), 1.234});
  const Vec2 n(std::sin(kPi / 6), std::cos(kPi / 6));
  EXPECT_NEAR(g.gap_m, n.dot(Vec2(2, 2)) - 0.5, 1e-15);
  EXPECT_NEAR((g.normal - n).norm(), 0.0, 1e-15);
  expect_consistent(g);
  // the same pair listed the other way round
  const ExactContact swapped(Circle{0.5}, HalfPlane{});
  const ContactGeometry h = swapped.evaluate(Pose{Vec2(2, 2), 1.234}, ground);
  EXPECT_EQ(h.gap_m, g.gap_m);
  EXPECT_NEAR((h.normal + n).norm(), 0.0, 1e-15);
}

TEST(ExactContact, CircleCircleApartAndOverlapping) {
  const ExactContact ec(Circle{0.5}, Circle{0.25});
  const ContactGeometry apart = ec.evaluate(Pose{Vec2(0, 0), 0}, Pose{Vec2(0.6, 0.8), 0});
  EXPECT_NEAR(apart.gap_m, 1.0 - 0.75, 1e-15);
  EXPECT_NEAR((apart.normal - Vec2(0.6, 0.8)).norm(), 0.0, 1e-15);
  const ContactGeometry over = ec.evaluate(Pose{Vec2(0, 0), 0}, Pose{Vec2(0.7, 0), 0});
  EXPECT_NEAR(over.gap_m, -0.05, 1e-15);
  expect_consistent(apart);
  expect_consistent(over);
}

TEST(ExactContact, TurnedEllipseOnLine) {
  // an ellipse turned by phi has its lowest point sqrt(a^2 sin^2 phi +
  // b^2 cos^2 phi) below its centre (support function of the ellipse)
  const double a = 0.7071, b = 0.25;
  const ExactContact ec(HalfPlane{}, Ellipse{a, b});
  for (const double phi : {0.0, 0.3, kPi / 4, 1.2, kPi / 2, 2.5}) {
    const ContactGeometry g = ec.evaluate(Pose{}, Pose{Vec2(0.3, 0.5), phi});
    const double extent = std::sqrt(a * a * std::sin(phi) * std::sin(phi) +
                                    b * b * std::cos(phi) * std::cos(phi));
    EXPECT_NEAR(g.gap_m, 0.5 - extent, 1e-15);
    EXPECT_NEAR(g.point_a_m.y(), 0.0, 1e-15);
    expect_consistent(g);
  }
}

TEST(ExactContact, EllipseCircleAgainstParameterMinimisation) {
  // gap = distance from the disk's centre to the ellipse - R, the distance by
  // a dense sampling of the ellipse refined by golden-section search
  const double a = 0.7071, b = 0.25, r = 0.5;
  const ExactContact ec(Ellipse{a, b}, Circle{r});
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 100; ++i) {
    const Pose pe{Vec2{u(rng), u(rng)}, 3 * u(rng)};
    const Vec2 c = pe.position_m + Vec2{1.2 * u(rng), 1.2 * u(rng)};
    const Vec2 cl = pe.to_local(c);
    auto f = [&](double t) { return (cl - Vec2(a * std::cos(t), b * std::sin(t))).norm(); };
    double bt = 0.0, bv = f(0.0);
    for (int k = 1; k < 4000; ++k) {
      const double t = 2 * kPi * k / 4000;
      if (f(t) < bv) bv = f(t), bt = t;
    }
    double lo = bt - 2 * kPi / 4000, hi = bt + 2 * kPi / 4000;
    for (int it = 0; it < 100; ++it) {
      const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
      (f(m1) < f(m2) ? hi : lo) = f(m1) < f(m2) ? m2 : m1;
    }
    const double dist = f(0.5 * (lo + hi));
    const bool inside = (cl.x() / a) * (cl.x() / a) + (cl.y() / b) * (cl.y() / b) < 1.0;
    const ContactGeometry g = ec.evaluate(pe, Pose{c, 0.7});
    // both sides reach double precision (the routine by its own Newton
    // iteration, the search here by shrinking to where f is flat within
    // eps): 1e-12 m on O(1) m allows the frame transforms' rounding
    EXPECT_NEAR(g.gap_m, (inside ? -dist : dist) - r, 1e-12);
    expect_consistent(g);
  }
}

TEST(ExactContact, PolygonCircleAndPolygonLine) {
  const Polygon sq{{Vec2(-1, -1), Vec2(1, -1), Vec2(1, 1), Vec2(-1, 1)}};
  const ExactContact pc(sq, Circle{0.5});
  // above the top edge, beside a corner, overlapping the edge
  EXPECT_NEAR(pc.evaluate(Pose{}, Pose{Vec2(0.2, 1.8), 0}).gap_m, 0.3, 1e-15);
  EXPECT_NEAR(pc.evaluate(Pose{}, Pose{Vec2(1.6, 1.8), 0}).gap_m, 1.0 - 0.5, 1e-15);
  const ContactGeometry over = pc.evaluate(Pose{}, Pose{Vec2(0.2, 1.4), 0});
  EXPECT_NEAR(over.gap_m, -0.1, 1e-15);
  EXPECT_NEAR(over.normal.y(), 1.0, 1e-15);
  expect_consistent(over);
  // the square turned 45 deg above a line: its corner is the lowest point
  const ExactContact pl(HalfPlane{}, sq);
  const ContactGeometry g = pl.evaluate(Pose{}, Pose{Vec2(0, 1.5), kPi / 4});
  EXPECT_NEAR(g.gap_m, 1.5 - std::sqrt(2.0), 1e-15);
  expect_consistent(g);
}

TEST(ExactContact, FaceOnLineActsAtItsDepthWeightedMiddle) {
  // SPEC §1, one force per pair: a square pressed 0.01 m flat into the line
  // pushes at its face's middle (no moment about its centre); tilted so that
  // its bottom corners sit 0.03 and 0.01 m deep, at their depth-weighted
  // centroid, 3/4 of the way to the deeper corner (worked out by hand)
  const Polygon sq{{Vec2(-0.1, -0.1), Vec2(0.1, -0.1), Vec2(0.1, 0.1), Vec2(-0.1, 0.1)}};
  const ExactContact pl(HalfPlane{}, sq);
  const ContactGeometry flat = pl.evaluate(Pose{}, Pose{Vec2(0.3, 0.09), 0.0});
  EXPECT_NEAR(flat.gap_m, -0.01, 1e-15);
  EXPECT_NEAR(flat.point_b_m.x(), 0.3, 1e-15);
  EXPECT_NEAR(flat.point_b_m.y(), -0.01, 1e-15);
  expect_consistent(flat);
  // turned by a with sin a = 0.1: the corners' heights differ by 0.2 sin a
  // = 0.02; the centre at height h puts them at h - 0.1 (cos a + sin a) and
  // h - 0.1 (cos a - sin a)
  const double a = std::asin(0.1);
  const double h = 0.1 * (std::cos(a) + 0.1) - 0.03;
  const ContactGeometry tilt = pl.evaluate(Pose{}, Pose{Vec2(0, h), a});
  EXPECT_NEAR(tilt.gap_m, -0.03, 1e-15);
  const Vec2 right = Pose{Vec2(0, h), a}.to_world(Vec2(0.1, -0.1));  // 0.01 deep
  const Vec2 left = Pose{Vec2(0, h), a}.to_world(Vec2(-0.1, -0.1));  // 0.03 deep
  const Vec2 expect = (0.03 * left + 0.01 * right) / 0.04;
  // depths 0.03, 0.01 m rounded through a sine, 1e-15 m each: 1e-14 m
  EXPECT_NEAR(tilt.point_b_m.x(), expect.x(), 1e-14);
  EXPECT_NEAR(tilt.point_b_m.y(), expect.y(), 1e-14);
  expect_consistent(tilt);
}

TEST(ExactContact, FaceSpreadIsTheCornersDepthWeightedVariance) {
  // ContactGeometry::spread_m2 of the tilted square above (corners 0.03 and
  // 0.01 m deep, 0.2 cos a apart along the line): for two points of depths
  // d1, d2 a distance L apart, d1 d2 L^2 / (d1 + d2)^2 = 0.03 x 0.01 x
  // (0.2 cos a)^2 / 0.04^2 (worked out by hand); flat, (0.2 / 2)^2 = 0.01;
  // one corner in, 0
  const Polygon sq{{Vec2(-0.1, -0.1), Vec2(0.1, -0.1), Vec2(0.1, 0.1), Vec2(-0.1, 0.1)}};
  const ExactContact pl(HalfPlane{}, sq);
  const double a = std::asin(0.1);
  const double h = 0.1 * (std::cos(a) + 0.1) - 0.03;
  const double along = 0.2 * std::cos(a);  // m, the corners' distance along the line
  // the depths carry 1e-15 m each (above); the variance 1e-16 m^2 of 1e-2
  EXPECT_NEAR(pl.evaluate(Pose{}, Pose{Vec2(0, h), a}).spread_m2,
              0.03 * 0.01 * along * along / (0.04 * 0.04), 1e-15);
  EXPECT_NEAR(pl.evaluate(Pose{}, Pose{Vec2(0.3, 0.09), 0.0}).spread_m2, 0.01, 1e-15);
  const double one_in = 0.1 * (std::cos(a) + std::sin(a)) - 0.005;  // only the left corner in
  EXPECT_EQ(pl.evaluate(Pose{}, Pose{Vec2(0, one_in), a}).spread_m2, 0.0);
}

// two convex polygons: a box of w x h centred at the origin
Polygon box(double w, double h) {
  return Polygon{{Vec2(-w / 2, -h / 2), Vec2(w / 2, -h / 2), Vec2(w / 2, h / 2), Vec2(-w / 2, h / 2)}};
}

TEST(ExactContact, EqualBoxesStackedPressByTheirOverlap) {
  // box b on box a, both 0.4 x 0.1, b lowered into a by delta: the overlap
  // along y is delta, along x the whole width; each corner of b lies on a's
  // side line (the outline's depth there is 0, issue 44)
  const double delta = 3e-5;  // m
  const ExactContact ec(box(0.4, 0.1), box(0.4, 0.1));
  const ContactGeometry g = ec.evaluate(Pose{Vec2(0, 0), 0.0}, Pose{Vec2(0, 0.1 - delta), 0.0});
  EXPECT_NEAR(g.gap_m, -delta, 1e-15);
  EXPECT_NEAR((g.normal - Vec2(0, 1)).norm(), 0.0, 1e-15);
  // one force at the middle of the face, no moment
  EXPECT_NEAR(g.point_b_m.x(), 0.0, 1e-15);
  EXPECT_NEAR(g.spread_m2, 0.04, 1e-14);  // the two corners at +-w/2: (w/2)^2
  expect_consistent(g);
}

TEST(ExactContact, HalfOverlappingBricksActAtTheOverlapsMiddle) {
  // brick b over the right half of brick a (offset 0.2 of 0.4): the clipped
  // face runs from b's left corner to a's right end, its middle at x = 0.1
  const double delta = 1e-4;
  const ExactContact ec(box(0.4, 0.2), box(0.4, 0.2));
  const ContactGeometry g = ec.evaluate(Pose{Vec2(0, 0), 0.0}, Pose{Vec2(0.2, 0.2 - delta), 0.0});
  EXPECT_NEAR(g.gap_m, -delta, 1e-15);
  EXPECT_NEAR(g.point_b_m.x(), 0.1, 1e-14);
  // tilted: b's left corner deeper, its weight moves the point left, still
  // between the clipped ends, and the penetration is the deeper end's
  const double phi = 1e-4;  // rad, b turned counter-clockwise: its left corner dips
  const ContactGeometry t = ec.evaluate(Pose{Vec2(0, 0), 0.0}, Pose{Vec2(0.2, 0.2 - delta), phi});
  EXPECT_LT(t.point_b_m.x(), 0.1);
  EXPECT_GT(t.point_b_m.x(), 0.0);
  EXPECT_GT(-t.gap_m, delta);
  expect_consistent(t);
}

TEST(ExactContact, ConvexPolygonsApartAreTheirDistance) {
  // a square of side 1 and one turned 45 deg whose corner points at it, 0.3 m off
  const ExactContact ec(box(1.0, 1.0), box(1.0, 1.0));
  const double r = std::sqrt(0.5);  // the turned square's centre-to-corner
  const ContactGeometry g = ec.evaluate(Pose{}, Pose{Vec2(0.5 + 0.3 + r, 0.0), kPi / 4});
  EXPECT_NEAR(g.gap_m, 0.3, 1e-14);
  EXPECT_NEAR((g.normal - Vec2(1, 0)).norm(), 0.0, 1e-12);
  expect_consistent(g);
  // a concave polygon has no exact routine with a polygon (its outline)
  const Polygon l{{Vec2(0, 0), Vec2(2, 0), Vec2(2, 1), Vec2(1, 1), Vec2(1, 2), Vec2(0, 2)}};
  EXPECT_FALSE(ExactContact::supported(l, box(1.0, 1.0)));
  EXPECT_TRUE(ExactContact::supported(box(1.0, 1.0), box(2.0, 1.0)));
}

TEST(ExactContact, SupportedPairs) {
  EXPECT_TRUE(ExactContact::supported(HalfPlane{}, Circle{1}));
  EXPECT_TRUE(ExactContact::supported(Circle{1}, Ellipse{1, 2}));
  EXPECT_TRUE(ExactContact::supported(Polygon{}, Circle{1}));
  EXPECT_TRUE(ExactContact::supported(Ellipse{1, 2}, HalfPlane{}));
  EXPECT_FALSE(ExactContact::supported(Ellipse{1, 2}, Ellipse{1, 2}));
  EXPECT_FALSE(ExactContact::supported(Ellipse{1, 2}, Polygon{}));
  EXPECT_FALSE(ExactContact::supported(HalfPlane{}, HalfPlane{}));
  EXPECT_THROW(ExactContact(Ellipse{1, 2}, Ellipse{1, 2}), std::invalid_argument);
}

}  // namespace
}  // namespace pb
