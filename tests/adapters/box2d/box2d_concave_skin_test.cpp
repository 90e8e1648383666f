// Tests for inset_piece (adapters/box2d/box2d_geometry.cpp): the Box2D cores
// of a concave polygon's convex pieces, skinned, reproduce the polygon.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "box2d_geometry.hpp"
#include "planarbench/convex_pieces.hpp"

namespace pb::internal::box2d {
namespace {

constexpr double kR = 0.01;  // m, the skin (b2_polygonRadius)

// m, distance from p to the segment a-b
double segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

// m, distance from p to a convex counter-clockwise polygon (0 inside)
double polygon_distance(const Vec2& p, const std::vector<Vec2>& poly) {
  bool inside = true;
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2& a = poly[i];
    const Vec2& b = poly[(i + 1) % poly.size()];
    const Vec2 e = b - a;
    if (e.x() * (p - a).y() - e.y() * (p - a).x() < 0.0) inside = false;
    d = std::min(d, segment_distance(p, a, b));
  }
  return inside ? 0.0 : d;
}

// m, how far p lies outside the skinned cores (negative: inside the skin);
// only its sign and its value near the surface matter here
double skinned_gap(const Vec2& p, const std::vector<std::vector<Vec2>>& cores) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& c : cores) best = std::min(best, polygon_distance(p, c) - kR);
  return best;
}

std::vector<std::vector<Vec2>> cores_of(const std::vector<Vec2>& polygon) {
  std::vector<std::vector<Vec2>> cores;
  for (const ConvexPiece& piece : convex_pieces(polygon, 8).pieces) {
    const std::optional<std::vector<Vec2>> core = inset_piece(piece, polygon, kR);
    EXPECT_TRUE(core.has_value());
    if (core) {
      EXPECT_TRUE(is_convex_ccw(*core));
      cores.push_back(*core);
    }
  }
  return cores;
}

// The L of cases/concave_corner.toml: its only two-piece partition cuts along
// the diagonal from the reflex vertex to the outer corner, a vertex of both
// pieces. Skinned, the cores round that 90 deg corner as a convex square's:
// it lies r (sqrt(2) - 1) outside them (the inset corner is (r, r) in, at
// r sqrt(2); the skin reaches r of it), not r (1/sin(22.5 deg) - 1) = 1.61 r
// as each 45 deg piece inset on its own left it. Tolerance 1e-15 m: the
// rounding of coordinates of ~0.2 m.
TEST(Box2dConcaveSkin, SharedCornerIsRoundedAsTheBodysCorner) {
  const std::vector<Vec2> l = {{-0.11, -0.11}, {0.19, -0.11}, {0.19, -0.01},
                               {-0.01, -0.01}, {-0.01, 0.19}, {-0.11, 0.19}};
  const auto cores = cores_of(l);
  ASSERT_EQ(cores.size(), 2u);
  EXPECT_NEAR(skinned_gap(l[0], cores), kR * (std::sqrt(2.0) - 1.0), 1e-15);
  // what every piece inset on its own gave: the corner 1.61 r away
  std::vector<std::vector<Vec2>> own;
  for (const ConvexPiece& piece : convex_pieces(l, 8).pieces) own.push_back(inset_outline(piece, kR));
  EXPECT_NEAR(skinned_gap(l[0], own), kR * (1.0 / std::sin(M_PI / 8.0) - 1.0), 1e-15);
}

// The boot of cases/concave_seam_face.toml: its seam runs from the reflex
// vertex to the heel's outer corner, not along that corner's bisector. Both
// pieces keep clipped cores (no fallback), the sole is the skinned surface
// from r to 0.4 - r (gap 0: every point of it touched by the skin, nothing
// beyond it), the heel corner is rounded by r (sqrt(2) - 1) like a square's,
// the reflex corner stays sharp (gap 0 at it: the skins of both pieces reach
// it) and no point of the outline's edges lies inside the skin (gap >= 0: the
// skin never leaves the outline). Tolerance 1e-15 m: rounding of ~0.2 m
// coordinates.
TEST(Box2dConcaveSkin, SeamFaceKeepsTheSoleAndTheReflexCorner) {
  const std::vector<Vec2> boot = {{-0.2, -0.09982758620689655}, {0.2, -0.09982758620689655},
                                  {0.2, 0.14017241379310344},   {-0.12, -0.039827586206896554},
                                  {-0.12, 0.17017241379310344}, {-0.2, 0.17017241379310344}};
  const auto cores = cores_of(boot);
  ASSERT_EQ(cores.size(), 2u);
  for (int k = 0; k <= 100; ++k) {
    const double x = -0.2 + kR + (0.4 - 2.0 * kR) * k / 100.0;
    EXPECT_NEAR(skinned_gap(Vec2(x, boot[0].y()), cores), 0.0, 1e-15) << "sole at x = " << x;
  }
  EXPECT_NEAR(skinned_gap(boot[0], cores), kR * (std::sqrt(2.0) - 1.0), 1e-15);
  EXPECT_NEAR(skinned_gap(boot[3], cores), 0.0, 1e-15);
  for (std::size_t i = 0; i < boot.size(); ++i) {
    for (int k = 0; k <= 50; ++k) {
      const Vec2 q = boot[i] + (boot[(i + 1) % boot.size()] - boot[i]) * (k / 50.0);
      EXPECT_GE(skinned_gap(q, cores), -1e-15) << "edge " << i << " at " << k;
    }
  }
}

// A point of a piece that is not one of the polygon's: no core (the caller
// insets the piece on its own).
TEST(Box2dConcaveSkin, ForeignPieceHasNoCore) {
  const std::vector<Vec2> square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_FALSE(inset_piece({{0, 0}, {0.5, 0}, {0, 0.5}}, square, kR).has_value());
}

}  // namespace
}  // namespace pb::internal::box2d
