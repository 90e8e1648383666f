// Tests for core/src/convex_pieces.cpp
//
// The pieces are checked with geometry written here, apart from CGAL and the
// code under test: orientation and convexity by cross products, areas by the
// shoelace formula, and coverage by point-in-convex-polygon tests on a seeded
// grid of sample points.
#include "planarbench/convex_pieces.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <utility>

#include "planarbench/outline.hpp"

namespace pb {
namespace {

using Points = std::vector<Vec2>;

double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

double area(const Points& p) {
  double a2 = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) a2 += cross(p[i], p[(i + 1) % p.size()]);
  return 0.5 * a2;
}

// counter-clockwise and convex: every turn left or straight (exact zero
// allowed: CGAL keeps collinear input points)
bool convex_ccw(const Points& p) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2 e1 = p[(i + 1) % p.size()] - p[i];
    const Vec2 e2 = p[(i + 2) % p.size()] - p[(i + 1) % p.size()];
    if (cross(e1, e2) < -1e-12 * e1.norm() * e2.norm()) return false;
  }
  return area(p) > 0.0;
}

// strictly inside a convex counter-clockwise polygon
bool inside_convex(const Points& p, const Vec2& q) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (cross(p[(i + 1) % p.size()] - p[i], q - p[i]) <= 0.0) return false;
  }
  return true;
}

// inside any simple polygon: crossing number
bool inside_polygon(const Points& p, const Vec2& q) {
  bool in = false;
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
    if ((p[i].y() > q.y()) != (p[j].y() > q.y()) &&
        q.x() < (p[j].x() - p[i].x()) * (q.y() - p[i].y()) / (p[j].y() - p[i].y()) + p[i].x()) {
      in = !in;
    }
  }
  return in;
}

// the properties every decomposition must have, with max_vertices = limit
void expect_partition(const Points& poly, int limit) {
  const ConvexDecomposition d = convex_pieces(poly, limit);
  ASSERT_FALSE(d.pieces.empty());
  EXPECT_FALSE(d.method.empty());
  std::set<std::pair<double, double>> vertices;
  for (const Vec2& v : poly) vertices.insert({v.x(), v.y()});
  double total = 0.0;
  for (const Points& piece : d.pieces) {
    EXPECT_TRUE(convex_ccw(piece)) << "a piece of " << piece.size() << " points, area " << area(piece) << " of a " << poly.size() << "-point polygon";
    if (limit > 0) {
      EXPECT_LE(static_cast<int>(piece.size()), limit);
    }
    EXPECT_GE(piece.size(), 3u);
    for (const Vec2& v : piece) EXPECT_EQ(vertices.count({v.x(), v.y()}), 1u) << "new vertex";
    total += area(piece);
  }
  // the same area: sums of O(1) products, 1e-12 relative
  EXPECT_NEAR(total, area(poly), 1e-12 * std::abs(area(poly)));
  // every sample inside the polygon (and off the diagonals) lies in exactly one
  // piece, every sample outside in none
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const Vec2& v : poly) {
    x0 = std::min(x0, v.x());
    x1 = std::max(x1, v.x());
    y0 = std::min(y0, v.y());
    y1 = std::max(y1, v.y());
  }
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> ux(x0, x1);
  std::uniform_real_distribution<double> uy(y0, y1);
  int inside = 0;
  for (int k = 0; k < 4000; ++k) {
    const double x = ux(rng);
    const double y = uy(rng);
    const Vec2 q(x, y);
    int hits = 0;
    for (const Points& piece : d.pieces) hits += inside_convex(piece, q) ? 1 : 0;
    if (inside_polygon(poly, q)) {
      ++inside;
      EXPECT_LE(hits, 1) << x << " " << y;  // 0 only on a shared edge: measure zero
    } else {
      EXPECT_EQ(hits, 0) << x << " " << y;
    }
  }
  EXPECT_GT(inside, 100);
}

const Points kArch = {{-0.2, 0}, {-0.12, 0}, {-0.12, 0.14}, {0.12, 0.14},
                      {0.12, 0}, {0.2, 0},   {0.2, 0.2},    {-0.2, 0.2}};
const Points kL = {{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};

TEST(ConvexPieces, ConvexPolygonIsItself) {
  const Points square = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  const ConvexDecomposition d = convex_pieces(square, 0);
  ASSERT_EQ(d.pieces.size(), 1u);
  EXPECT_EQ(d.pieces[0], square);
  EXPECT_TRUE(is_convex_ccw(square));
  const Points ellipse = make_outline(Ellipse{0.7, 0.25}, 180);
  EXPECT_EQ(convex_pieces(ellipse, 0).pieces.size(), 1u);
  // at most 8 points (Box2D): a 180-point convex polygon cut into fans
  expect_partition(ellipse, 8);
}

TEST(ConvexPieces, ArchAndLAreCutIntoTheFewestPieces) {
  EXPECT_FALSE(is_convex_ccw(kArch));
  // the arch: two legs and the bar, counted by hand
  EXPECT_EQ(convex_pieces(kArch, 0).pieces.size(), 3u);
  expect_partition(kArch, 0);
  expect_partition(kArch, 8);
  EXPECT_EQ(convex_pieces(kL, 0).pieces.size(), 2u);  // the L: two rectangles
  expect_partition(kL, 0);
}

TEST(ConvexPieces, CombsStarsAndRandomPolygons) {
  // a comb of 12 teeth (50 points): at least 13 pieces, each a tooth or the back
  Points comb = {{0, 0}};
  for (int k = 0; k < 12; ++k) {
    comb.emplace_back(2.0 * k + 1.0, 0.0);
    comb.emplace_back(2.0 * k + 1.0, -3.0);
    comb.emplace_back(2.0 * k + 1.5, -3.0);
    comb.emplace_back(2.0 * k + 1.5, 0.0);
  }
  comb.emplace_back(25.0, 0.0);
  comb.emplace_back(25.0, 1.0);
  comb.emplace_back(0.0, 1.0);
  expect_partition(comb, 0);
  expect_partition(comb, 8);
  // a seeded random star-shaped polygon (random radii about the origin),
  // above and below the optimal partition's size limit
  for (const int n : {20, kOptimalPartitionMaxVertices + 36}) {
    std::mt19937 rng(static_cast<unsigned>(n));
    std::uniform_real_distribution<double> r(0.3, 1.0);
    Points star;
    for (int k = 0; k < n; ++k) {
      const double t = 2.0 * std::numbers::pi * k / n;
      const double radius = r(rng);
      star.emplace_back(radius * std::cos(t), radius * std::sin(t));
    }
    expect_partition(star, 0);
    expect_partition(star, 8);
    EXPECT_NE(convex_pieces(star, 0).method.find(n > kOptimalPartitionMaxVertices ? "approx"
                                                                                   : "optimal"),
              std::string::npos);
  }
}

TEST(ConvexPieces, DeterministicAndRefusesDegenerateInput) {
  const ConvexDecomposition a = convex_pieces(kArch, 8);
  const ConvexDecomposition b = convex_pieces(kArch, 8);
  ASSERT_EQ(a.pieces.size(), b.pieces.size());
  for (std::size_t i = 0; i < a.pieces.size(); ++i) EXPECT_EQ(a.pieces[i], b.pieces[i]);
  EXPECT_THROW((void)convex_pieces({{0, 0}, {1, 0}}, 0), std::invalid_argument);
  EXPECT_THROW((void)convex_pieces(kArch, 2), std::invalid_argument);
}

}  // namespace
}  // namespace pb
