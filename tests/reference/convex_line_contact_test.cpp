// Tests for core/reference/src/convex_line_contact.cpp
//
// The truth is the brute-force search, OutlineContactSearch (every outline
// point against every edge; tested against closed forms in
// outline_contact_test.cpp). Wherever the closed form answers, it must give
// the brute force's gap, normal and contact points; where it refuses, the
// engine asks the tree search, tested to the bit in fast_outline_contact_test.
//
// Tolerances. The two compute the same quantities by different arithmetic:
// the brute force measures each depth as a point's distance to one world edge
// of the surface, the closed form as an affine function of the pose. Each is
// a few roundings of world coordinates of size L (the scene's largest, here
// <= 25 m): |error| <= ~10 ulp(L) = 4e-14 m. Hence
// * gap and contact points apart: 1e-12 m (25 times that);
// * normal: 1e-12 (both are the surface's unit normal, rounded differently);
// * the line of action's point overlapping: the centroid sum_i w_i p_i /
//   sum_i w_i moves by at most sum_i |dw_i| |p_i - c| / sum_i w_i with
//   |dw_i| <= 4e-14 m, so its tolerance is 1e-12 m + 25 x count x 4e-14 m x
//   chord / sum_i w_i, computed per pose from an independent loop over the
//   world points (the factor 25 as above). Shallow overlaps, whose depth sum
//   is itself near the rounding, are the ill-conditioned ones for any method.
// Level faces (the body's two lowest points at one height to 1e-9 m): the
// brute force's deepest or closest point is then any point of that face, or
// a surface vertex above it, picked by rounding (convex_line_contact.hpp).
// There the normal may be the surface's or the face's: tolerance kLevelTilt
// = 1e-10 rad, the tilt the closed form accepts; apart, both searches'
// points on the body must lie on the face (1e-12 m), and the closed form's
// point on the surface must be its point's foot.
#include "planarbench/reference/convex_line_contact.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <initializer_list>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "planarbench/outline.hpp"
#include "planarbench/reference/outline_contact.hpp"
#include "planarbench/reference/pair_geometry.hpp"

namespace pb {
namespace {

using Rng = std::mt19937_64;

constexpr double kPi = std::numbers::pi;
constexpr double kTol = 1e-12;              // m and -, see the top of the file
constexpr double kDepthRounding_m = 4e-14;  // m, one depth's rounding at L <= 25 m (top)
constexpr double kSafety = 25.0;            // -, the factor of the tolerances above
constexpr double kLevelTilt = 1e-10;        // rad, a level face's normal (top)
constexpr double kLevel_m = 1e-9;           // m, two lowest points this close: a level face

double uniform(Rng& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// a polygon through points at sorted random angles on an ellipse: strictly convex
Polygon random_convex_polygon(Rng& rng, int n, double rx_m, double ry_m) {
  std::vector<double> t(static_cast<std::size_t>(n));
  for (double& a : t) a = uniform(rng, 0.0, 2.0 * kPi);
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end()), t.end());
  Polygon p;
  for (const double a : t) p.points_m.emplace_back(rx_m * std::cos(a), ry_m * std::sin(a));
  return p;
}

// The independent conditioning of an overlap: count, depth sum and chord of
// the convex body's outline points below the line, in the world.
struct Overlap {
  int count = 0;
  double depth_sum_m = 0.0;
  double chord_m = 0.0;
};
Overlap overlap_below(const std::vector<Vec2>& local, const Pose& body, const Pose& line) {
  const Vec2 n = line.rotation() * Vec2(0, 1);
  const Vec2 t = line.rotation() * Vec2(1, 0);
  Overlap o;
  double u_min = 1e300, u_max = -1e300;
  for (const Vec2& q : local) {
    const Vec2 p = body.to_world(q) - line.position_m;
    if (n.dot(p) < 0.0) {
      ++o.count;
      o.depth_sum_m -= n.dot(p);
      u_min = std::min(u_min, t.dot(p));
      u_max = std::max(u_max, t.dot(p));
    }
  }
  o.chord_m = o.count > 0 ? u_max - u_min : 0.0;
  return o;
}

Polygon poly(std::initializer_list<std::array<double, 2>> xy) {
  Polygon p;
  for (const auto& v : xy) p.points_m.emplace_back(v[0], v[1]);
  return p;
}

// outline points of the half-plane's surface inside the convex body (the
// brute force's crossing-number test, outline_contact.hpp)
int surface_points_inside(const std::vector<Vec2>& ground_local, const Pose& line,
                          const std::vector<Vec2>& body_local, const Pose& body) {
  WorldOutline placed;
  place_outline(body_local, body, placed);
  int inside = 0;
  for (std::size_t i = 0; i + 1 < ground_local.size(); ++i) {  // the last point closes the polygon below
    const Vec2 p = line.to_world(ground_local[i]);
    inside += nearest_boundary_point(p.x(), p.y(), placed).inside ? 1 : 0;
  }
  return inside;
}

void expect_same(const ContactGeometry& g, const ContactGeometry& brute, double point_tol_m,
                 const std::string& what) {
  EXPECT_NEAR(g.gap_m, brute.gap_m, kTol) << what;
  EXPECT_LE((g.normal - brute.normal).norm(), kTol) << what;
  EXPECT_LE((g.point_a_m - brute.point_a_m).norm(), point_tol_m) << what;
  EXPECT_LE((g.point_b_m - brute.point_b_m).norm(), point_tol_m) << what;
}

// distance from p to the segment [a, b]
double segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 e = b - a;
  const double t = std::clamp((p - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * e)).norm();
}

// The body's lowest face when it is level with the line (its two lowest
// outline points within kLevel_m in height), else an empty pair.
struct Face {
  bool level = false;
  Vec2 a = Vec2::Zero(), b = Vec2::Zero();
};
Face level_face(const std::vector<Vec2>& local, const Pose& body, const Pose& line) {
  const Vec2 n = line.rotation() * Vec2(0, 1);
  std::vector<std::pair<double, Vec2>> by_height;
  for (const Vec2& q : local) {
    const Vec2 p = body.to_world(q);
    by_height.emplace_back(n.dot(p - line.position_m), p);
  }
  std::partial_sort(by_height.begin(), by_height.begin() + 2, by_height.end(),
                    [](const auto& x, const auto& y) { return x.first < y.first; });
  Face f;
  f.level = by_height[1].first - by_height[0].first < kLevel_m;
  f.a = by_height[0].second;
  f.b = by_height[1].second;
  return f;
}

// On a level face: gap as always, the normal to kLevelTilt, and apart the
// body-side points on the face (see the top of the file).
void expect_same_on_level_face(const ContactGeometry& g, const ContactGeometry& brute, const Face& face,
                               bool line_is_a, double point_tol_m, const std::string& what) {
  EXPECT_NEAR(g.gap_m, brute.gap_m, kTol) << what;
  EXPECT_LE((g.normal - brute.normal).norm(), kLevelTilt) << what;
  if (brute.gap_m < 0.0) {
    EXPECT_LE((g.point_a_m - brute.point_a_m).norm(), point_tol_m) << what;
    EXPECT_LE((g.point_b_m - brute.point_b_m).norm(), point_tol_m) << what;
    return;
  }
  const Vec2& on_body = line_is_a ? g.point_b_m : g.point_a_m;
  const Vec2& on_line = line_is_a ? g.point_a_m : g.point_b_m;
  const Vec2& brute_on_body = line_is_a ? brute.point_b_m : brute.point_a_m;
  EXPECT_LE(segment_distance(on_body, face.a, face.b), kTol) << what;
  EXPECT_LE(segment_distance(brute_on_body, face.a, face.b), kTol) << what;
  const Vec2 up = line_is_a ? g.normal : Vec2(-g.normal);
  EXPECT_LE((on_line - (on_body - g.gap_m * up)).norm(), kTol) << what;
}

struct Tally {
  int answered_apart = 0, answered_overlapping = 0, refused = 0, level = 0;
};

// One pose of a convex shape against a half-plane, in either order, checked
// against the brute force where the closed form answers.
void check_pose(ConvexLineContact& closed, OutlineContactSearch& brute, const std::vector<Vec2>& local,
                bool line_is_a, const Pose& line, const Pose& body, Tally& tally,
                const std::string& what) {
  const Pose& pa = line_is_a ? line : body;
  const Pose& pb = line_is_a ? body : line;
  const std::optional<ContactGeometry> g = closed.evaluate(pa, pb);
  if (!g) {
    ++tally.refused;
    return;
  }
  const ContactGeometry gb = brute.evaluate(pa, pb);
  double tol = kTol;
  if (gb.gap_m < 0.0) {
    ++tally.answered_overlapping;
    const Overlap o = overlap_below(local, body, line);
    ASSERT_GT(o.count, 0) << what;
    tol += kSafety * o.count * kDepthRounding_m * o.chord_m / o.depth_sum_m;
  } else {
    ++tally.answered_apart;
  }
  const Face face = level_face(local, body, line);
  if (face.level) {
    ++tally.level;
    expect_same_on_level_face(*g, gb, face, line_is_a, tol, what + " level, gap " + std::to_string(gb.gap_m));
    return;
  }
  expect_same(*g, gb, tol, what + " gap " + std::to_string(gb.gap_m));
}

// Disks, ellipses and random convex polygons (3 .. 300 points) against a
// tilted, displaced half-plane, both orders, from 5 % of the size apart to
// 30 % pressed in, with and without history. Most poses must be answered.
TEST(ConvexLineContact, MatchesTheBruteForce) {
  Rng rng(20261125);
  Tally tally;
  for (int trial = 0; trial < 60; ++trial) {
    const double size_m = uniform(rng, 0.05, 2.0);
    Shape shape;
    int n = 0;
    switch (trial % 3) {
      case 0:
        shape = Circle{size_m};
        n = std::vector<int>{45, 180, 720}[static_cast<std::size_t>(trial / 3 % 3)];
        break;
      case 1:
        shape = Ellipse{size_m, size_m * uniform(rng, 0.2, 1.0)};
        n = 180;
        break;
      default:
        shape = random_convex_polygon(rng, static_cast<int>(uniform(rng, 3, 300)), size_m,
                                      size_m * uniform(rng, 0.3, 1.0));
        n = 0;
    }
    const HalfPlane plane{uniform(rng, 10.0, 40.0)};
    const int n_line = static_cast<int>(uniform(rng, 2, 400));
    const bool line_is_a = trial % 2 == 0;
    std::optional<ConvexLineContact> closed =
        line_is_a ? ConvexLineContact::make(plane, n_line, shape, n)
                  : ConvexLineContact::make(shape, n, plane, n_line);
    ASSERT_TRUE(closed) << "trial " << trial;
    const std::vector<Vec2> local = contact_outline(shape, n);
    const std::vector<Vec2> ground = contact_outline(plane, n_line);
    OutlineContactSearch brute(line_is_a ? ground : local, line_is_a ? local : ground);
    const Pose line{Vec2(uniform(rng, -5, 5), uniform(rng, -5, 5)), uniform(rng, -kPi, kPi)};
    const Vec2 up = line.rotation() * Vec2(0, 1);
    const Vec2 along = line.rotation() * Vec2(1, 0);
    const double u = uniform(rng, -0.3, 0.3) * plane.extent_m;
    for (int k = 0; k < 12; ++k) {
      if (k % 4 == 0) closed->forget_history();
      const double h = size_m * uniform(rng, 0.7, 1.05);  // origin height: pressed in .. apart
      const Pose body{line.position_m + u * along + h * up + 0.01 * k * size_m * along,
                      uniform(rng, -kPi, kPi)};
      check_pose(*closed, brute, local, line_is_a, line, body, tally,
                 "trial " + std::to_string(trial) + " pose " + std::to_string(k));
    }
  }
  // what the poses exercised (counts printed by a failure)
  EXPECT_GT(tally.answered_apart, 100) << tally.answered_overlapping << " " << tally.refused;
  EXPECT_GT(tally.answered_overlapping, 300) << tally.answered_apart << " " << tally.refused;
  EXPECT_LT(tally.refused, 60) << tally.answered_apart << " " << tally.answered_overlapping;
}

// falling_ball's pair (ground declined 30 deg, 40 m; disk 0.5 m) at the
// outline sizes of the benchmark, pressed in up to 60 mm: runs longer than
// kDirectSumPoints (the prefix sums) and shorter (the direct sum).
TEST(ConvexLineContact, FallingBallPairAtEverySize) {
  Rng rng(180);
  const Pose ground{Vec2(0, 0), -kPi / 6};
  const Vec2 normal = ground.rotation() * Vec2(0, 1);
  const Vec2 along = ground.rotation() * Vec2(1, 0);
  for (const int n : {45, 180, 1440}) {
    auto closed = ConvexLineContact::make(HalfPlane{40.0}, n, Circle{0.5}, n);
    ASSERT_TRUE(closed);
    const std::vector<Vec2> local = contact_outline(Circle{0.5}, n);
    OutlineContactSearch brute(contact_outline(HalfPlane{40.0}, n), local);
    Tally tally;
    bool long_run = false;
    for (int k = 0; k < (n > 1000 ? 8 : 40); ++k) {
      const double h = 0.5 + uniform(rng, -0.06, 0.001);
      const Pose disk{uniform(rng, -15, 15) * along + h * normal, uniform(rng, -kPi, kPi)};
      const int refused_before = tally.refused;
      check_pose(*closed, brute, local, true, ground, disk, tally, "n " + std::to_string(n));
      if (tally.refused > refused_before) {
        // refused only where the disk has no more points inside than the surface
        EXPECT_LE(overlap_below(local, disk, ground).count,
                  surface_points_inside(contact_outline(HalfPlane{40.0}, n), ground, local, disk))
            << "n " << n;
      }
      long_run = long_run || overlap_below(local, disk, ground).count > ConvexLineContact::kDirectSumPoints;
    }
    EXPECT_LE(tally.refused, 2) << "n " << n;  // the coarse ground can tie a shallow disk
    if (n == 1440) {
      EXPECT_TRUE(long_run);
    }
  }
}

// sliding's pair (cases/sliding.toml: incline declined 45 deg, 20 m, 180
// points; disk 0.25 m, 180 points, not turned): the disk's lowest edge is
// level with the incline, so every pose is a level face. Apart by up to
// 1 mm and pressed in by up to 1.5 mm (its static penetration is 0.69 mm),
// sliding 2 m down the incline past many surface vertices: all answered.
TEST(ConvexLineContact, SlidingDiskOnItsLevelFace) {
  const Pose ground{Vec2(0, 0), -kPi / 4};
  const Vec2 normal = ground.rotation() * Vec2(0, 1);
  const Vec2 along = ground.rotation() * Vec2(1, 0);
  auto closed = ConvexLineContact::make(HalfPlane{20.0}, 180, Circle{0.25}, 180);
  ASSERT_TRUE(closed);
  const std::vector<Vec2> local = contact_outline(Circle{0.25}, 180);
  OutlineContactSearch brute(contact_outline(HalfPlane{20.0}, 180), local);
  Tally tally;
  for (int k = 0; k < 200; ++k) {
    const double gap_m = 1e-3 - 2.5e-3 * (k % 11) / 10.0;
    const Pose disk{(0.25 + gap_m) * normal + 0.01 * k * along, 0.0};
    check_pose(*closed, brute, local, true, ground, disk, tally, "k " + std::to_string(k));
  }
  EXPECT_EQ(tally.refused, 0);
  EXPECT_EQ(tally.level, 200);
}

// The cost, counted: along a slowly moving sequence (the disk slides 10 um and
// turns 1e-4 rad per evaluation, as an integrator asks) each warm evaluation
// computes a bounded number of heights whatever N: the walks move a step or
// two (bound 40: a search of a 1440-point outline by halving takes 2 x 11
// heights per end, a scan 1440), sums at most kDirectSumPoints points one by
// one, and probes the sorted surface in O(log N) (4 binary searches of
// log2(N) + 1 probes).
TEST(ConvexLineContact, WarmWorkDoesNotGrowWithN) {
  const Pose ground{Vec2(0, 0), -kPi / 6};
  const Vec2 normal = ground.rotation() * Vec2(0, 1);
  const Vec2 along = ground.rotation() * Vec2(1, 0);
  for (const double depth_m : {-1e-3, 0.057}) {
    for (const int n : {45, 180, 1440}) {
      auto closed = ConvexLineContact::make(HalfPlane{40.0}, n, Circle{0.5}, n);
      ASSERT_TRUE(closed);
      int worst_heights = 0, worst_summed = 0, worst_probes = 0;
      for (int k = 0; k < 64; ++k) {
        const Pose disk{(0.5 - depth_m) * normal + 1e-5 * k * along, 0.3 + 1e-4 * k};
        ASSERT_TRUE(closed->evaluate(ground, disk)) << "n " << n << " k " << k;
        if (k == 0) continue;  // the cold start
        worst_heights = std::max(worst_heights, closed->last_work().heights);
        worst_summed = std::max(worst_summed, closed->last_work().summed_points);
        worst_probes = std::max(worst_probes, closed->last_work().surface_probes);
      }
      const std::string what = "n " + std::to_string(n) + " depth " + std::to_string(depth_m);
      EXPECT_LE(worst_heights, 40) << what;
      EXPECT_LE(worst_summed, ConvexLineContact::kDirectSumPoints) << what;
      EXPECT_LE(worst_probes, 4 * (static_cast<int>(std::log2(n)) + 2)) << what;
    }
  }
}

// History only saves work: the same pose sequence warm and cold gives the
// same bits (the same vertices are found, so the same sums are taken).
TEST(ConvexLineContact, WarmAndColdAgreeToTheBit) {
  const Pose ground{Vec2(1, 2), 0.2};
  const Vec2 normal = ground.rotation() * Vec2(0, 1);
  auto warm = ConvexLineContact::make(Ellipse{0.7, 0.25}, 180, HalfPlane{20.0}, 50);
  auto cold = ConvexLineContact::make(Ellipse{0.7, 0.25}, 180, HalfPlane{20.0}, 50);
  ASSERT_TRUE(warm && cold);
  int answered = 0;
  for (int k = 0; k < 200; ++k) {
    const Pose body{ground.position_m + (0.2 - 0.002 * k) * normal, 0.05 * k};
    cold->forget_history();
    const auto gw = warm->evaluate(body, ground);
    const auto gc = cold->evaluate(body, ground);
    ASSERT_EQ(gw.has_value(), gc.has_value()) << k;
    if (!gw) continue;
    ++answered;
    EXPECT_EQ(gw->gap_m, gc->gap_m) << k;
    EXPECT_EQ(gw->normal, gc->normal) << k;
    EXPECT_EQ(gw->point_a_m, gc->point_a_m) << k;
    EXPECT_EQ(gw->point_b_m, gc->point_b_m) << k;
  }
  EXPECT_GT(answered, 150);
}

// What it refuses: pairs it has no closed form for, and poses it cannot
// decide for certain. PairGeometry then answers from the trees, so the
// engine's result still equals the brute force's.
TEST(ConvexLineContact, RefusesWhatItCannotDecide) {
  // not exactly one half-plane, or not strictly convex
  EXPECT_FALSE(ConvexLineContact::make(Circle{0.5}, 90, Circle{0.5}, 90));
  EXPECT_FALSE(ConvexLineContact::make(HalfPlane{4.0}, 10, HalfPlane{4.0}, 10));
  const Polygon l_shape = poly({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});
  EXPECT_FALSE(ConvexLineContact::make(HalfPlane{4.0}, 10, l_shape, 0));
  const Polygon collinear = poly({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}});
  EXPECT_FALSE(ConvexLineContact::make(HalfPlane{4.0}, 10, collinear, 0));
  const Polygon clockwise = poly({{0, 0}, {0, 1}, {1, 1}, {1, 0}});
  EXPECT_FALSE(ConvexLineContact::make(HalfPlane{4.0}, 10, clockwise, 0));

  const Polygon square = poly({{-0.1, -0.1}, {0.1, -0.1}, {0.1, 0.1}, {-0.1, 0.1}});
  auto closed = ConvexLineContact::make(HalfPlane{8.0}, 801, square, 0);
  ASSERT_TRUE(closed);
  // lying flat, apart and pressed in: a level face, answered (pressed in,
  // the surface has 20 points inside the square against its 2: the
  // surface's centroid)
  EXPECT_TRUE(closed->evaluate(Pose{}, Pose{Vec2(0.3, 0.1 + 1e-3), 0.0}));
  EXPECT_TRUE(closed->evaluate(Pose{}, Pose{Vec2(0.3, 0.1 - 1e-3), 0.0}));
  // tilted by 1e-9 rad its corners differ in depth by 2e-10 m, far beyond
  // rounding: answered as any tilted pose
  EXPECT_TRUE(closed->evaluate(Pose{}, Pose{Vec2(0.3, 0.1 + 1e-3), 1e-9}));
  // tilted it answers; over the segment's end, or too deep near it, it does not
  EXPECT_TRUE(closed->evaluate(Pose{}, Pose{Vec2(0.3, 0.14), 0.3}));
  const Pose past_the_end{Vec2(3.95, 0.14), 0.3};
  EXPECT_FALSE(closed->evaluate(Pose{}, past_the_end));
  EXPECT_FALSE(closed->evaluate(Pose{}, Pose{Vec2(3.7, -0.05), 0.3}));
  // a 20-gon pressed into a surface sampled every 1 mm: more surface points
  // inside (about 150) than the direct sum takes
  auto fine = ConvexLineContact::make(HalfPlane{8.0}, 8001, Circle{0.1}, 20);
  ASSERT_TRUE(fine);
  EXPECT_FALSE(fine->evaluate(Pose{}, Pose{Vec2(0.3, 0.1 * std::cos(kPi / 20) - 2e-3), 0.0}));

  // PairGeometry falls back to the trees there and still equals the brute force
  Body ground{.name = "ground", .shape = HalfPlane{8.0}};
  ground.outline_points = 801;
  Body box{.name = "box", .shape = square};
  PairGeometry pair(ground, box, GeometryMode::outline, DetectionMode::fast);
  OutlineContactSearch brute(contact_outline(ground.shape, 801), square.points_m);
  for (const Pose& p : {past_the_end, Pose{Vec2(0.3, 0.14), 0.3}}) {
    const ContactGeometry g = pair.evaluate(Pose{}, p);
    const ContactGeometry gb = brute.evaluate(Pose{}, p);
    EXPECT_NEAR(g.gap_m, gb.gap_m, kTol);
    EXPECT_LE((g.point_b_m - gb.point_b_m).norm(), 1e-9);  // centroid of a shallow run (top)
  }
  EXPECT_EQ(pair.closed_form_evaluations(), 1);
  EXPECT_EQ(pair.tree_evaluations(), 1);
}

// A square lying on a finely sampled surface (incline_launch: 801 points over
// 8 m, the square's side 0.2 m), flat and tilted by up to 0.05 rad, apart by
// 1 mm to pressed in by 3 mm, sliding along: the surface's points inside the
// square outnumber its corners, so the line of action is the centroid of the
// surface's points, each as deep as its distance to the square's boundary.
TEST(ConvexLineContact, PolygonOnAFineSurfaceUsesTheSurfacePoints) {
  const Polygon square = poly({{-0.1, -0.1}, {0.1, -0.1}, {0.1, 0.1}, {-0.1, 0.1}});
  const Pose ground{Vec2(0.5, -0.2), -20.0 * kPi / 180.0};
  const Vec2 normal = ground.rotation() * Vec2(0, 1);
  const Vec2 along = ground.rotation() * Vec2(1, 0);
  auto closed = ConvexLineContact::make(square, 0, HalfPlane{8.0}, 801);
  ASSERT_TRUE(closed);
  const std::vector<Vec2> local = contact_outline(square, 0);
  const std::vector<Vec2> surface = contact_outline(HalfPlane{8.0}, 801);
  OutlineContactSearch brute(local, surface);
  Tally tally;
  int surface_side = 0;
  for (int k = 0; k < 120; ++k) {
    const double tilt = k % 3 == 0 ? 0.0 : 0.05 * std::sin(0.7 * k);
    const double gap_m = 1.1e-3 - 4e-3 * (k % 9) / 8.0;  // never 0: touching is the trees' case
    // the centre at the height that puts the lowest corner at gap_m
    const double lowest = 0.1 * (std::cos(tilt) + std::abs(std::sin(tilt)));
    const Pose box{ground.position_m + (lowest + gap_m) * normal + (0.0123 * k - 0.7) * along,
                   ground.angle_rad + tilt};
    const int refused_before = tally.refused;
    check_pose(*closed, brute, local, false, ground, box, tally, "k " + std::to_string(k));
    const int corners = overlap_below(local, box, ground).count;
    const int surface_points = surface_points_inside(surface, ground, local, box);
    if (tally.refused > refused_before) {
      // refused only when neither side has clearly more points inside
      EXPECT_LE(std::abs(corners - surface_points), 1) << "k " << k;
    } else if (corners < surface_points) {
      ++surface_side;
    }
  }
  EXPECT_LE(tally.refused, 12);
  EXPECT_GT(surface_side, 40);
}

}  // namespace
}  // namespace pb
