// A convex decomposition of simple polygons, for engines whose collision
// takes convex shapes only (MuJoCo meshes collide as their convex hull, ODE's
// dCreateConvex and Box2D's b2PolygonShape are convex, Box2D's of at most
// b2_maxPolygonVertices = 8 points). The partition is CGAL's (2-D Polygon
// Partitioning, CGAL 5.5 from Debian's libcgal-dev); nothing here cuts a
// polygon by hand but the split of a convex piece by diagonals.
#pragma once

#include <string>
#include <vector>

#include "planarbench/case.hpp"

namespace pb {

// one convex piece: counter-clockwise points, body frame, m
using ConvexPiece = std::vector<Vec2>;

struct ConvexDecomposition {
  std::vector<ConvexPiece> pieces;  // union = the polygon, interiors disjoint
  std::string method;               // one line: how, e.g. "CGAL::optimal_convex_partition_2, 3 pieces"
};

// true when every turn of the counter-clockwise polygon is a left turn or
// straight, within a relative tolerance: cross(e1, e2) >= -rel_tol |e1| |e2|
[[nodiscard]] bool is_convex_ccw(const std::vector<Vec2>& polygon, double rel_tol = 1e-12);

// polygons up to this many points get CGAL's optimal partition (fewest
// pieces, O(n^4)); larger ones its approximation. Measured on random star
// polygons (Release, 2-core Debian 12 machine): 3 ms at 32 points, 22 ms at
// 64; O(n^4) puts 128 at ~0.35 s, where the approximation takes 0.6 ms.
inline constexpr int kOptimalPartitionMaxVertices = 64;

// Convex pieces of a simple counter-clockwise polygon (as the case loader
// validates it: no self-intersection, no repeated points). A convex polygon
// is one piece, itself. A non-convex one is partitioned by CGAL into convex
// pieces whose points are the polygon's own (the partition adds diagonals
// only; points where a piece runs straight on are dropped from it):
// CGAL::optimal_convex_partition_2 (Greene's dynamic programming,
// fewest pieces) for at most kOptimalPartitionMaxVertices points, else
// CGAL::approx_convex_partition_2 (Hertel-Mehlhorn, at most 4 times the
// fewest). max_vertices > 0: a piece with more points is split further by
// diagonals from its first point into convex pieces of at most max_vertices
// points; 0 = no limit. Deterministic: the same input gives the same pieces
// in the same order. Throws std::invalid_argument for fewer than 3 points or
// max_vertices in [1, 2].
[[nodiscard]] ConvexDecomposition convex_pieces(const std::vector<Vec2>& polygon_ccw,
                                                int max_vertices);

}  // namespace pb
