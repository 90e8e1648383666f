// Tests for core/reference/src/outline_contact.cpp
//
// Hand-made polygons whose distances are known in closed form, and an
// independent brute force over every pair of edges (the closest points of two
// segments by the clamped parametric solution of C. Ericson, Real-Time
// Collision Detection, 2005, §5.1.9) as the exact polygon distance.
#include "planarbench/reference/outline_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "planarbench/outline.hpp"

namespace pb {
namespace {

using Points = std::vector<Vec2>;

Points square(double x0, double y0, double side) {
  return {Vec2(x0, y0), Vec2(x0 + side, y0), Vec2(x0 + side, y0 + side), Vec2(x0, y0 + side)};
}

// the L: [0,3] x [0,1] united with [0,1] x [0,3], counter-clockwise
Points l_shape() {
  return {Vec2(0, 0), Vec2(3, 0), Vec2(3, 1), Vec2(1, 1), Vec2(1, 3), Vec2(0, 3)};
}

Points circle_points(Vec2 c, double r, int n) {
  Points p = make_outline(Circle{r}, n);
  for (auto& q : p) q += c;
  return p;
}

// squared distance between segments p1-q1 and p2-q2 (Ericson §5.1.9)
double segment_distance2(Vec2 p1, Vec2 q1, Vec2 p2, Vec2 q2) {
  const Vec2 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  double s = 0.0, t = 0.0;
  if (a <= 0.0 && e <= 0.0) return r.squaredNorm();
  if (a <= 0.0) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= 0.0) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), denom = a * e - b * b;
      s = denom != 0.0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return ((p1 + s * d1) - (p2 + t * d2)).squaredNorm();
}

// exact distance of two disjoint closed polylines: every pair of edges
double polygon_distance(const Points& a, const Points& b) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t j = 0; j < b.size(); ++j) {
      best = std::min(best, segment_distance2(a[i], a[(i + 1) % a.size()], b[j], b[(j + 1) % b.size()]));
    }
  }
  return std::sqrt(best);
}

ContactGeometry contact(const Points& a, const Points& b, const Pose& pa = {}, const Pose& pb = {}) {
  OutlineContactSearch s(a, b);
  return s.evaluate(pa, pb);
}

// every result satisfies its own definition
void expect_consistent(const ContactGeometry& g) {
  EXPECT_NEAR(g.normal.norm(), 1.0, 1e-14);
  EXPECT_NEAR(g.gap_m, g.normal.dot(g.point_b_m - g.point_a_m), 1e-13);
}

// The distance tolerance 1e-12 m: the inputs are O(1) m and each distance is
// a handful of rounded operations (~1e-16 relative each).
constexpr double kTol = 1e-12;
// Normals along an axis are built from exact coordinates: 1e-15 on their
// unit components; from turned or random poses 1e-12 (a few roundings of the
// pose transforms, divided by distances of O(0.1) m).

TEST(OutlineContact, SquareOnSquareParallelEdges) {
  // B's bottom edge 0.25 above A's top edge, overlapping in x over [0.3, 1]
  const Points a = square(0, 0, 1), b = square(0.3, 1.25, 1);
  const ContactGeometry g = contact(a, b);
  EXPECT_NEAR(g.gap_m, 0.25, kTol);
  EXPECT_NEAR(g.gap_m, polygon_distance(a, b), kTol);
  EXPECT_NEAR(g.normal.y(), 1.0, 1e-15);
  expect_consistent(g);
}

TEST(OutlineContact, SquareCornerToCorner) {
  // corners (1, 1) and (1.3, 1.4): distance 0.5 along (0.6, 0.8)
  const ContactGeometry g = contact(square(0, 0, 1), square(1.3, 1.4, 1));
  EXPECT_NEAR(g.gap_m, 0.5, kTol);
  EXPECT_NEAR(g.normal.x(), 0.6, 1e-15);
  EXPECT_NEAR(g.normal.y(), 0.8, 1e-15);
  expect_consistent(g);
}

TEST(OutlineContact, DistanceInvariantUnderRigidMotionOfTheScene) {
  // the same two squares seen from a turned and shifted frame
  const Pose frame{Vec2(-3.7, 12.1), 0.7};
  const ContactGeometry g =
      contact(square(0, 0, 1), square(0.3, 1.25, 1), frame, frame);
  EXPECT_NEAR(g.gap_m, 0.25, kTol);
  EXPECT_NEAR(g.normal.dot(frame.rotation() * Vec2(0, 1)), 1.0, 1e-14);
  expect_consistent(g);
}

TEST(OutlineContact, ConcaveLAgainstCircleInTheNotch) {
  // 64-point circle of radius 0.5 centred (2, 1.8) in the L's notch: its
  // lowest point (2, 1.3) is 0.3 above the edge y = 1; the inner corner and
  // the edge x = 1 are farther (0.78 and 0.5)
  const Points c = circle_points(Vec2(2.0, 1.8), 0.5, 64);
  const ContactGeometry g = contact(l_shape(), c);
  EXPECT_NEAR(g.gap_m, 0.3, kTol);
  EXPECT_NEAR(g.gap_m, polygon_distance(l_shape(), c), kTol);
  EXPECT_NEAR(g.normal.y(), 1.0, 1e-15);
  expect_consistent(g);
}

TEST(OutlineContact, VertexOnAnEdgeTouches) {
  // a triangle's apex exactly on the square's top edge
  const Points tri = {Vec2(0.5, 1.0), Vec2(0.9, 1.6), Vec2(0.1, 1.6)};
  const ContactGeometry g = contact(square(0, 0, 1), tri);
  EXPECT_NEAR(g.gap_m, 0.0, kTol);
  EXPECT_NEAR(g.normal.y(), 1.0, 1e-15);  // the edge's normal, not noise
  expect_consistent(g);
}

TEST(OutlineContact, CoincidentPointsTouch) {
  // two squares sharing the corner (1, 1)
  const ContactGeometry g = contact(square(0, 0, 1), square(1, 1, 1));
  EXPECT_NEAR(g.gap_m, 0.0, kTol);
  EXPECT_NEAR(g.normal.norm(), 1.0, 1e-14);
}

TEST(OutlineContact, CornerIntoEdgePenetration) {
  // a square turned 45 deg with its lowest corner 0.1 below A's top edge
  const double h = std::sqrt(0.5);
  const Points diamond = {Vec2(0.5, 0.9), Vec2(0.5 + h, 0.9 + h), Vec2(0.5, 0.9 + 2 * h),
                          Vec2(0.5 - h, 0.9 + h)};
  const ContactGeometry g = contact(square(0, 0, 1), diamond);
  EXPECT_NEAR(g.gap_m, -0.1, kTol);
  EXPECT_NEAR(g.penetration_m(), 0.1, kTol);
  EXPECT_NEAR(g.normal.y(), 1.0, 1e-15);
  // one point inside: the force acts at the corner and 0.1 above it
  EXPECT_NEAR((g.point_b_m - Vec2(0.5, 0.9)).norm(), 0.0, kTol);
  EXPECT_NEAR((g.point_a_m - Vec2(0.5, 1.0)).norm(), 0.0, kTol);
  expect_consistent(g);
}

// whether p lies inside the L of l_shape(): the union of its two rectangles
bool inside_l(const Vec2& p) {
  return (p.x() > 0 && p.x() < 3 && p.y() > 0 && p.y() < 1) ||
         (p.x() > 0 && p.x() < 1 && p.y() > 0 && p.y() < 3);
}

TEST(OutlineContact, TwoOverlapRegionsShareTheLineOfAction) {
  // a 64-point circle centred (1.4, 1.45), radius 0.5, overlaps the L's edge
  // y = 1 by 0.05 and its edge x = 1 by 0.1, in two separate regions (the
  // corner (1, 1) is 0.6 from the centre, outside the circle). delta and the
  // normal are the deeper region's (the circle pushed along +x); the line of
  // action passes through the depth-weighted centroid of the circle's points
  // inside the L in both regions (SPEC §1, one force per pair), worked out
  // here with the L as two rectangles and each depth as the least distance to
  // the L's six edges (segment_distance2 with a point for the first segment).
  const Points c = circle_points(Vec2(1.4, 1.45), 0.5, 64);
  const Points l = l_shape();
  double w = 0.0;
  Vec2 wp = Vec2::Zero();
  int regions_hit = 0;
  bool below = false, left = false;
  for (const Vec2& p : c) {
    if (!inside_l(p)) continue;
    double d2 = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < l.size(); ++i) {
      d2 = std::min(d2, segment_distance2(p, p, l[i], l[(i + 1) % l.size()]));
    }
    w += std::sqrt(d2);
    wp += std::sqrt(d2) * p;
    below = below || p.y() < 1.0;
    left = left || p.x() < 1.0;
  }
  regions_hit = (below ? 1 : 0) + (left ? 1 : 0);
  ASSERT_EQ(regions_hit, 2);
  const ContactGeometry g = contact(l, c);
  EXPECT_NEAR(g.gap_m, -0.1, kTol);  // the point at 180 deg, (0.9, 1.45)
  EXPECT_NEAR(g.normal.x(), 1.0, 1e-15);
  // a centroid of ~14 rounded points, each depth from a different formula
  // here than in the search: 1e-12 m
  EXPECT_NEAR(g.point_b_m.x(), wp.x() / w, 1e-12);
  EXPECT_NEAR(g.point_b_m.y(), wp.y() / w, 1e-12);
  // both regions pull the point: it lies off the deeper region's symmetry
  // line y = 1.45, towards the shallower region below it
  EXPECT_LT(g.point_b_m.y(), 1.45 - 1e-3);
  expect_consistent(g);
}

TEST(OutlineContact, SwappingBodiesNegatesTheNormal) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 50; ++i) {
    const Pose pa{Vec2{u(rng), u(rng)}, 3 * u(rng)};
    const Pose pb{Vec2{u(rng), 1.6 + u(rng)}, 3 * u(rng)};
    const Points a = square(-0.5, -0.5, 1.0);
    const Points b = make_outline(Ellipse{0.7, 0.3}, 40);
    const ContactGeometry g1 = contact(a, b, pa, pb);
    const ContactGeometry g2 = contact(b, a, pb, pa);
    EXPECT_NEAR(g1.gap_m, g2.gap_m, kTol);
    EXPECT_NEAR((g1.normal + g2.normal).norm(), 0.0, 1e-12);
    expect_consistent(g1);
  }
}

TEST(OutlineContact, ApartDistanceEqualsExactPolygonDistance) {
  // random disjoint placements of a coarse square and a 24-point ellipse
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Points a = square(-0.5, -0.5, 1.0);
  const Points b = make_outline(Ellipse{0.7, 0.3}, 24);
  int apart = 0;
  for (int i = 0; i < 200; ++i) {
    const Pose pa{Vec2(0, 0), 3 * u(rng)};
    const Pose pb{Vec2{1.5 * u(rng), 1.5 * u(rng)}, 3 * u(rng)};
    const ContactGeometry g = contact(a, b, pa, pb);
    if (g.gap_m <= 0.0) continue;
    ++apart;
    Points wa, wb;
    for (const auto& p : a) wa.push_back(pa.to_world(p));
    for (const auto& p : b) wb.push_back(pb.to_world(p));
    EXPECT_NEAR(g.gap_m, polygon_distance(wa, wb), kTol);
  }
  EXPECT_GT(apart, 50);  // the sample exercised the apart branch
}

TEST(OutlineContact, PaperTwoStagesMissTheCoarseCase) {
  // A coarse square (edges 2 m) below a 64-point circle: the closest pair of
  // outline points is a corner and a circle point, but the true closest
  // points are the circle's lowest point and the middle of the top edge,
  // not adjacent to that pair. The paper's literal refinement stops short;
  // the exhaustive projection finds the exact 0.5.
  const Points a = square(-1, -1, 2);
  const Points b = circle_points(Vec2(0, 2), 0.5, 64);
  WorldOutline wa, wb;
  place_outline(a, Pose{}, wa);
  place_outline(b, Pose{}, wb);
  // what the literal refinement does find: the nearest pair is a corner and
  // the circle point at 45 deg below the centre; the circle points next to it
  // (5.625 deg apart) reach the top edge no closer than
  // 2 - 0.5 sin(45 + 5.625 deg) - 1 = 0.6135 m
  EXPECT_NEAR(paper_two_stage_distance(wa, wb), 1.0 - 0.5 * std::sin(9.0 * std::numbers::pi / 32.0),
              kTol);
  EXPECT_NEAR(contact(a, b).gap_m, 0.5, kTol);
}

TEST(OutlineContact, PaperTwoStagesAgreeOnDenseOutlines) {
  // 180-point circles apart: the literal refinement is exact there
  const Points a = circle_points(Vec2(0, 0), 0.5, 180);
  const Points b = circle_points(Vec2(1.03, 0.41), 0.5, 180);
  WorldOutline wa, wb;
  place_outline(a, Pose{}, wa);
  place_outline(b, Pose{}, wb);
  EXPECT_NEAR(paper_two_stage_distance(wa, wb), contact(a, b).gap_m, kTol);
}

TEST(OutlineContact, CircleOutlineOnLineWithinSag) {
  // The N-point outline is inscribed in the circle: against a line its gap
  // exceeds the true one by 0 .. R (1 - cos(pi/N)), for any pose.
  const int n = 180;
  const double r = 0.5;
  const double sag = r * (1.0 - std::cos(std::numbers::pi / n));
  OutlineContactSearch s(contact_outline(HalfPlane{40.0}, 181), contact_outline(Circle{r}, n));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Pose ground{Vec2(0, 0), -std::numbers::pi / 6};
  const Vec2 nrm = ground.rotation() * Vec2(0, 1);
  for (int i = 0; i < 200; ++i) {
    const double h = r + 0.01 * (u(rng) - 0.5);  // centre height: apart or overlapping
    const double along = 5.0 * (u(rng) - 0.5);
    const Pose disk{ground.to_world(Vec2(along, 0)) + h * nrm, 2 * std::numbers::pi * u(rng)};
    const double exact_gap = h - r;
    const ContactGeometry g = s.evaluate(ground, disk);
    // 1e-12 m: rounding of the turned poses, far below the 3.8e-6 m sag
    EXPECT_GE(g.gap_m, exact_gap - 1e-12);
    EXPECT_LE(g.gap_m, exact_gap + sag + 1e-12);
    EXPECT_NEAR(g.normal.dot(nrm), 1.0, 1e-12);
  }
}

TEST(OutlineContact, HalfPlaneOutlineIsClosedBelowItsSurface) {
  const Points p = contact_outline(HalfPlane{20.0}, 5);
  ASSERT_EQ(p.size(), 6u);
  EXPECT_EQ(p.front(), Vec2(10.0, 0.0));
  EXPECT_EQ(p[4], Vec2(-10.0, 0.0));
  EXPECT_EQ(p.back(), Vec2(0.0, -10.0));
  EXPECT_GT(polygon_area_properties(p).area_m2, 0.0);  // counter-clockwise
}

}  // namespace
}  // namespace pb
