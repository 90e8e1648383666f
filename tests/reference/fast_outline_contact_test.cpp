// Tests for core/reference/src/fast_outline_contact.cpp
//
// The truth is the brute-force search, OutlineContactSearch (every outline
// point against every edge of the other outline; tested on its own against
// closed forms in outline_contact_test.cpp). The fast search must give its
// result - gap, normal and both contact points - for any pair of simple
// counter-clockwise outlines in any poses.
//
// Tolerance 1e-12 (m for gaps and points, - for unit normals). Both searches
// place every vertex they use in the world with the same expression and apply
// the same point-edge formulas, so on this machine they agree to the last bit;
// 1e-12 is what the contract promises on any machine: a compiler that fuses
// multiply-adds differently in the two files changes the world vertices by
// ~1e-16 relative (1e-15 m at the 10 m scale used here), the per-point
// distances by the same, and the centroid of a run of up to 300 points by a
// few hundred roundings of that: < 1e-13 m, below 1e-12 with a margin of ten.
//
// Ties. Exact ties between distances (two points equally deep, a point
// equidistant from two edges) have probability zero in random data up to a
// flip of the last bit, where both searches still compute the same bits and
// apply the same tie-breaking rules (lowest edge index; the brute force's
// sweep order over points). Those rules are exercised on purpose by the
// axis-aligned polygons of ExactTiesFollowTheBruteForceOrder, whose
// coordinates and distances are exact in binary.
#include "planarbench/reference/fast_outline_contact.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "planarbench/outline.hpp"
#include "planarbench/reference/outline_contact.hpp"

namespace pb {
namespace {

using Points = std::vector<Vec2>;
using Rng = std::mt19937_64;

constexpr double kTol = 1e-12;  // see the top of the file
constexpr double kPi = std::numbers::pi;

double uniform(Rng& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}
int uniform_int(Rng& rng, int lo, int hi) {
  return std::uniform_int_distribution<int>(lo, hi)(rng);
}

// n distinct sorted angles in [0, 2 pi): counter-clockwise order
std::vector<double> sorted_angles(Rng& rng, int n) {
  std::vector<double> a(static_cast<std::size_t>(n));
  for (double& t : a) t = uniform(rng, 0.0, 2.0 * kPi);
  std::sort(a.begin(), a.end());
  a.erase(std::unique(a.begin(), a.end()), a.end());
  return a;
}

// points at random angles on an ellipse: a convex polygon
Points random_convex(Rng& rng, int n, double rx_m, double ry_m) {
  Points p;
  for (double t : sorted_angles(rng, n)) p.emplace_back(rx_m * std::cos(t), ry_m * std::sin(t));
  return p;
}

// points at random angles and random radii in [r_min, r_max]: star-shaped
// about the origin, so simple and counter-clockwise, concave in general
Points random_star(Rng& rng, int n, double r_min_m, double r_max_m) {
  Points p;
  for (double t : sorted_angles(rng, n)) {
    const double r = uniform(rng, r_min_m, r_max_m);
    p.emplace_back(r * std::cos(t), r * std::sin(t));
  }
  return p;
}

// a random outline of 3 .. 300 points, convex or concave, of size ~scale_m
Points random_outline(Rng& rng, double scale_m) {
  const int n = uniform_int(rng, 3, 300);
  if (uniform_int(rng, 0, 1) == 0) {
    return random_convex(rng, n, scale_m * uniform(rng, 0.3, 1.0), scale_m * uniform(rng, 0.3, 1.0));
  }
  return random_star(rng, n, scale_m * uniform(rng, 0.2, 0.6), scale_m);
}

std::string describe(const ContactGeometry& g) {
  return "gap " + std::to_string(g.gap_m) + " normal (" + std::to_string(g.normal.x()) + ", " +
         std::to_string(g.normal.y()) + ")";
}

// the fast result equals the brute force's (tolerance: top of the file)
void expect_same(const ContactGeometry& fast, const ContactGeometry& brute, const std::string& what) {
  EXPECT_NEAR(fast.gap_m, brute.gap_m, kTol) << what << " brute " << describe(brute);
  EXPECT_LE((fast.normal - brute.normal).norm(), kTol) << what << " brute " << describe(brute)
                                                         << " fast " << describe(fast);
  EXPECT_LE((fast.point_a_m - brute.point_a_m).norm(), kTol) << what << " brute " << describe(brute);
  EXPECT_LE((fast.point_b_m - brute.point_b_m).norm(), kTol) << what << " brute " << describe(brute);
}

bool bitwise_equal(const ContactGeometry& x, const ContactGeometry& y) {
  return x.gap_m == y.gap_m && x.normal == y.normal && x.point_a_m == y.point_a_m &&
         x.point_b_m == y.point_b_m;
}

// Counts the outcomes so that each test can check it exercised what it meant to.
struct Outcomes {
  int apart = 0, overlapping = 0;
  void add(const ContactGeometry& g) { (g.gap_m > 0.0 ? apart : overlapping) += 1; }
};

// Random pairs of outlines (3 .. 300 points, convex or star-shaped) at random
// poses: centres 0 .. 2.5 sizes apart, so that the pairs range from far apart
// through touching to deeply overlapping.
TEST(FastOutlineContact, RandomPosesMatchTheBruteForce) {
  Rng rng(20240601);
  Outcomes seen;
  for (int trial = 0; trial < 150; ++trial) {
    const Points a = random_outline(rng, 1.0);
    const Points b = random_outline(rng, uniform(rng, 0.2, 1.5));
    OutlineContactSearch brute(a, b);
    FastOutlineContactSearch fast(a, b);
    for (int k = 0; k < 8; ++k) {
      const Pose pa{Vec2(uniform(rng, -10, 10), uniform(rng, -10, 10)), uniform(rng, -kPi, kPi)};
      const double dist = uniform(rng, 0.0, 2.5);
      const double dir = uniform(rng, -kPi, kPi);
      const Pose pb{pa.position_m + dist * Vec2(std::cos(dir), std::sin(dir)), uniform(rng, -kPi, kPi)};
      const ContactGeometry gb = brute.evaluate(pa, pb);
      expect_same(fast.evaluate(pa, pb), gb, "trial " + std::to_string(trial));
      seen.add(gb);
    }
  }
  // both branches of the result were exercised many times
  EXPECT_GT(seen.apart, 200);
  EXPECT_GT(seen.overlapping, 200);
}

// Touching: body b moved along the brute-force normal until the gap is zero
// to rounding, then a hair apart and a hair into overlap, where points sit on
// the other boundary to within rounding (the crossing tests' hardest case).
TEST(FastOutlineContact, TouchingPosesMatchTheBruteForce) {
  Rng rng(7);
  Outcomes seen;
  for (int trial = 0; trial < 150; ++trial) {
    const Points a = random_outline(rng, 1.0);
    const Points b = random_outline(rng, uniform(rng, 0.2, 1.5));
    OutlineContactSearch brute(a, b);
    FastOutlineContactSearch fast(a, b);
    const Pose pa{Vec2(uniform(rng, -3, 3), uniform(rng, -3, 3)), uniform(rng, -kPi, kPi)};
    const double dir = uniform(rng, -kPi, kPi);
    Pose pb{pa.position_m + 3.0 * Vec2(std::cos(dir), std::sin(dir)), uniform(rng, -kPi, kPi)};
    const ContactGeometry far = brute.evaluate(pa, pb);
    for (const double offset_m : {0.0, 1e-9, -1e-9, 1e-6, -1e-6}) {
      Pose p = pb;
      p.position_m -= (far.gap_m - offset_m) * far.normal;
      const ContactGeometry gb = brute.evaluate(pa, p);
      expect_same(fast.evaluate(pa, p), gb, "trial " + std::to_string(trial));
      seen.add(gb);
    }
  }
  EXPECT_GT(seen.apart, 150);
  EXPECT_GT(seen.overlapping, 150);
}

// One body wholly inside the other, both ways: no edge comes near the other
// outline, so every point's status is decided by a single crossing test and
// every point is inside (the run is the whole outline).
TEST(FastOutlineContact, DeepInsideMatchesTheBruteForce) {
  Rng rng(99);
  for (int trial = 0; trial < 60; ++trial) {
    // A star with points at radii 0.5 .. 1 m and angles jittered about an
    // even spacing (gaps < 2 pi 1.5 / n <= 68 deg for n >= 8) keeps every
    // edge more than 0.5 cos(34 deg) = 0.41 m from its centre: it holds the
    // outline of radius <= 0.2 m placed within 0.07 m of that centre.
    const int n_big = uniform_int(rng, 8, 300);
    Points big;
    for (int i = 0; i < n_big; ++i) {
      const double t = 2.0 * kPi * (i + uniform(rng, 0.0, 0.5)) / n_big;
      const double r = uniform(rng, 0.5, 1.0);
      big.emplace_back(r * std::cos(t), r * std::sin(t));
    }
    const Points small = random_outline(rng, 0.2);
    const Pose p_big{Vec2(uniform(rng, -5, 5), uniform(rng, -5, 5)), uniform(rng, -kPi, kPi)};
    const Pose p_small{p_big.position_m + Vec2(uniform(rng, -0.05, 0.05), uniform(rng, -0.05, 0.05)),
                       uniform(rng, -kPi, kPi)};
    for (const bool small_is_a : {true, false}) {
      const Points& a = small_is_a ? small : big;
      const Points& b = small_is_a ? big : small;
      const Pose& pa = small_is_a ? p_small : p_big;
      const Pose& pb = small_is_a ? p_big : p_small;
      OutlineContactSearch brute(a, b);
      FastOutlineContactSearch fast(a, b);
      const ContactGeometry gb = brute.evaluate(pa, pb);
      ASSERT_LT(gb.gap_m, 0.0);
      expect_same(fast.evaluate(pa, pb), gb, "trial " + std::to_string(trial));
      EXPECT_EQ(fast.last_work().inside_points, static_cast<int>(small.size()));
    }
  }
}

// how many separate runs of consecutive points of `a` lie inside `b` (both
// in the world), by a winding-number test written independently here
int inside_regions(const Points& a, const Points& b) {
  auto inside = [&](const Vec2& p) {
    int winding = 0;
    for (std::size_t j = 0; j < b.size(); ++j) {
      const Vec2& u = b[j];
      const Vec2& v = b[(j + 1) % b.size()];
      const double side = (v.x() - u.x()) * (p.y() - u.y()) - (p.x() - u.x()) * (v.y() - u.y());
      if (u.y() <= p.y() && v.y() > p.y() && side > 0) ++winding;
      if (u.y() > p.y() && v.y() <= p.y() && side < 0) --winding;
    }
    return winding != 0;
  };
  int regions = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (inside(a[i]) && !inside(a[(i + a.size() - 1) % a.size()])) ++regions;
  }
  return regions;
}

Points placed(const Points& local, const Pose& pose) {
  Points w;
  for (const auto& p : local) w.push_back(pose.to_world(p));
  return w;
}

// Concave against concave with the centres close: several overlap regions,
// points deep inside, runs that wrap around the outline's point 0.
TEST(FastOutlineContact, ConcaveOverlapsMatchTheBruteForce) {
  Rng rng(31337);
  int several_regions = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const Points a = random_star(rng, uniform_int(rng, 3, 300), 0.3, 1.0);
    const Points b = random_star(rng, uniform_int(rng, 3, 300), 0.3, 1.0);
    OutlineContactSearch brute(a, b);
    FastOutlineContactSearch fast(a, b);
    const Pose pa{Vec2(uniform(rng, -1, 1), uniform(rng, -1, 1)), uniform(rng, -kPi, kPi)};
    const Pose pb{pa.position_m + Vec2(uniform(rng, -1.2, 1.2), uniform(rng, -1.2, 1.2)),
                  uniform(rng, -kPi, kPi)};
    const ContactGeometry gb = brute.evaluate(pa, pb);
    expect_same(fast.evaluate(pa, pb), gb, "trial " + std::to_string(trial));
    if (inside_regions(placed(a, pa), placed(b, pb)) >= 2) ++several_regions;
  }
  // the sample held many pairs with two or more separate overlap regions
  EXPECT_GT(several_regions, 30);
}

// Sequences of slowly moving poses, as the integrators ask for them: b
// approaches a, presses into it while turning, and leaves again. Each step
// reuses the search (temporal coherence) and must still equal the brute
// force; so must a fresh search (no history), since the history only
// tightens a bound (both compute the same numbers: identical here, 1e-12 for
// a compiler that contracts multiply-adds differently at different inlined
// call sites).
TEST(FastOutlineContact, SlowlyMovingPosesMatchTheBruteForceAndACold) {
  Rng rng(4242);
  Outcomes seen;
  for (int trial = 0; trial < 16; ++trial) {
    const Points a = random_outline(rng, 1.0);
    const Points b = random_outline(rng, uniform(rng, 0.3, 1.0));
    OutlineContactSearch brute(a, b);
    FastOutlineContactSearch warm(a, b);
    const Pose pa{Vec2(uniform(rng, -2, 2), uniform(rng, -2, 2)), uniform(rng, -kPi, kPi)};
    const double dir = uniform(rng, -kPi, kPi);
    const Vec2 u(std::cos(dir), std::sin(dir));
    const double angle0 = uniform(rng, -kPi, kPi);
    const double spin = uniform(rng, -0.5, 0.5);  // rad over the sequence
    const int steps = 80;
    for (int s = 0; s <= steps; ++s) {
      // centre distance 2.6 -> 0.6 -> 2.6 m: apart, touching, overlapping
      const double f = static_cast<double>(s) / steps;
      const double dist = 0.6 + 2.0 * std::abs(2.0 * f - 1.0);
      const Pose pb{pa.position_m + dist * u, angle0 + spin * f};
      const ContactGeometry gb = brute.evaluate(pa, pb);
      const ContactGeometry gw = warm.evaluate(pa, pb);
      expect_same(gw, gb, "trial " + std::to_string(trial) + " step " + std::to_string(s));
      seen.add(gb);
      if (s % 10 == 0) {
        FastOutlineContactSearch cold(a, b);
        expect_same(cold.evaluate(pa, pb), gw, "cold, trial " + std::to_string(trial));
      }
    }
  }
  EXPECT_GT(seen.apart, 300);
  EXPECT_GT(seen.overlapping, 300);
}

// Outlines with repeated points (zero-length edges) and midpoints inserted
// into edges (collinear neighbours, whose shared vertex is a tie between two
// edges for many points): the degenerate inputs a point list can hold.
TEST(FastOutlineContact, RepeatedPointsAndCollinearEdgesMatchTheBruteForce) {
  Rng rng(2718);
  auto roughen = [&](const Points& p) {
    Points q;
    for (std::size_t i = 0; i < p.size(); ++i) {
      q.push_back(p[i]);
      const int what = uniform_int(rng, 0, 5);
      if (what == 0) q.push_back(p[i]);                                  // repeated
      if (what == 1) q.push_back(0.5 * (p[i] + p[(i + 1) % p.size()]));  // collinear
    }
    return q;
  };
  Outcomes seen;
  for (int trial = 0; trial < 100; ++trial) {
    const Points a = roughen(random_outline(rng, 1.0));
    const Points b = roughen(random_outline(rng, uniform(rng, 0.2, 1.5)));
    OutlineContactSearch brute(a, b);
    FastOutlineContactSearch fast(a, b);
    for (int k = 0; k < 5; ++k) {
      const Pose pa{Vec2(uniform(rng, -3, 3), uniform(rng, -3, 3)), uniform(rng, -kPi, kPi)};
      const double dist = uniform(rng, 0.3, 2.0);
      const double dir = uniform(rng, -kPi, kPi);
      const Pose pb{pa.position_m + dist * Vec2(std::cos(dir), std::sin(dir)), uniform(rng, -kPi, kPi)};
      const ContactGeometry gb = brute.evaluate(pa, pb);
      expect_same(fast.evaluate(pa, pb), gb, "trial " + std::to_string(trial));
      seen.add(gb);
    }
  }
  EXPECT_GT(seen.apart, 100);
  EXPECT_GT(seen.overlapping, 100);
}

// The cases' pair: a tilted half-plane (its surface segment closed by one
// point far below, contact_outline) and a disk, as in falling_ball (ground
// declined 30 deg, extent 40 m, disk radius 0.5 m), near contact, touching
// and pressed in, for outline sizes 45 .. 1440.
TEST(FastOutlineContact, HalfPlaneAndDiskMatchTheBruteForce) {
  Rng rng(180);
  const Pose ground{Vec2(0, 0), -kPi / 6};
  const Vec2 normal = ground.rotation() * Vec2(0, 1);
  const Vec2 along = ground.rotation() * Vec2(1, 0);
  for (const int n : {45, 180, 1440}) {
    OutlineContactSearch brute(contact_outline(HalfPlane{40.0}, n), contact_outline(Circle{0.5}, n));
    FastOutlineContactSearch fast(contact_outline(HalfPlane{40.0}, n), contact_outline(Circle{0.5}, n));
    // fewer at N = 1440, where each brute-force evaluation is 4e6 distances
    for (int k = 0; k < (n > 1000 ? 8 : 40); ++k) {
      // centre height 0.5 m + (-60 mm .. +1 mm): pressed in .. near contact
      const double h = 0.5 + uniform(rng, -0.06, 0.001);
      const Pose disk{uniform(rng, -15, 15) * along + h * normal, uniform(rng, -kPi, kPi)};
      const ContactGeometry gb = brute.evaluate(ground, disk);
      expect_same(fast.evaluate(ground, disk), gb, "n " + std::to_string(n));
    }
  }
}

// The cost claim, counted rather than timed, on falling_ball's pair. Near
// contact (gap 1 mm) the search examines a number of node pairs and
// point-edge distances that does not grow like the brute force's 2 N (N + 1)
// (4.1e6 at N = 1440): measured 24 .. 81 node pairs and 12 .. 24 distances
// for N = 45 .. 1440 (bounds 200 and 100: a linear scan at N = 1440 would
// exceed them 20-fold). Pressed in by 57 mm (falling_ball's first peak),
// each inside point costs one nearest search of a few distances (measured
// 3.5 per point at N = 1440; bound 8).
TEST(FastOutlineContact, WorkStaysLogarithmicNearContact) {
  const Pose ground{Vec2(0, 0), -kPi / 6};
  const Vec2 normal = ground.rotation() * Vec2(0, 1);
  for (const int n : {45, 180, 1440}) {
    FastOutlineContactSearch fast(contact_outline(HalfPlane{40.0}, n), contact_outline(Circle{0.5}, n));
    (void)fast.evaluate(ground, Pose{(0.5 + 1e-3) * normal, 0.3});
    const FastSearchWork near = fast.last_work();
    EXPECT_EQ(near.inside_points, 0);
    EXPECT_LT(near.point_edge_tests, 100) << "n " << n;
    EXPECT_LT(near.node_pairs, 200) << "n " << n;

    (void)fast.evaluate(ground, Pose{(0.5 - 0.057) * normal, 0.3});
    const FastSearchWork pressed = fast.last_work();
    EXPECT_GT(pressed.inside_points, 0);
    EXPECT_EQ(pressed.nearest_queries, pressed.inside_points);
    EXPECT_LT(pressed.point_edge_tests, 8 * pressed.inside_points + 100) << "n " << n;
    EXPECT_LT(pressed.node_pairs, 200) << "n " << n;
  }
}

// Axis-aligned outlines with dyadic coordinates at angle 0: every distance is
// exact, so whole sets of points tie exactly (flat faces parallel to each
// other, apart and pressed into each other). The fast search must break
// every tie as the brute force does, to the bit.
TEST(FastOutlineContact, ExactTiesFollowTheBruteForceOrder) {
  // a w x h rectangle at (x0, y0) with k points per side, counter-clockwise
  auto rectangle = [](double x0, double y0, double w, double h, int k) {
    Points p;
    for (int i = 0; i < k; ++i) p.emplace_back(x0 + w * i / k, y0);
    for (int i = 0; i < k; ++i) p.emplace_back(x0 + w, y0 + h * i / k);
    for (int i = 0; i < k; ++i) p.emplace_back(x0 + w - w * i / k, y0 + h);
    for (int i = 0; i < k; ++i) p.emplace_back(x0, y0 + h - h * i / k);
    return p;
  };
  int cases = 0;
  for (const int ka : {1, 4, 8}) {
    for (const int kb : {1, 2, 8}) {
      for (const double wb : {1.0, 0.5, 2.0}) {
        // b above a (apart, touching, pressed in by 1/8) and shifted sideways
        for (const double dy : {0.25, 0.0, -0.125}) {
          for (const double dx : {-0.5, 0.0, 0.25}) {
            const Points a = rectangle(-0.5, -0.5, 1.0, 1.0, ka);
            const Points b = rectangle(-0.5 * wb + dx, 0.5 + dy, wb, 0.5, kb);
            OutlineContactSearch brute(a, b);
            FastOutlineContactSearch fast(a, b);
            const ContactGeometry gb = brute.evaluate(Pose{}, Pose{});
            const ContactGeometry gf = fast.evaluate(Pose{}, Pose{});
            EXPECT_TRUE(bitwise_equal(gf, gb))
                << "ka " << ka << " kb " << kb << " wb " << wb << " dy " << dy << " dx " << dx
                << ": brute " << describe(gb) << " point_a (" << gb.point_a_m.transpose()
                << ") fast " << describe(gf) << " point_a (" << gf.point_a_m.transpose() << ")";
            ++cases;
          }
        }
      }
    }
  }
  EXPECT_EQ(cases, 243);
}

// The hand-made polygons of outline_contact_test.cpp whose answers are known
// in closed form: the L's notch and two overlap regions with a circle.
TEST(FastOutlineContact, ConcaveLAgainstCircles) {
  const Points l = {Vec2(0, 0), Vec2(3, 0), Vec2(3, 1), Vec2(1, 1), Vec2(1, 3), Vec2(0, 3)};
  for (const Vec2& centre : {Vec2(2.0, 1.8), Vec2(1.4, 1.45)}) {
    Points c = make_outline(Circle{0.5}, 64);
    for (auto& q : c) q += centre;
    OutlineContactSearch brute(l, c);
    FastOutlineContactSearch fast(l, c);
    expect_same(fast.evaluate(Pose{}, Pose{}), brute.evaluate(Pose{}, Pose{}), "L");
  }
}

}  // namespace
}  // namespace pb
