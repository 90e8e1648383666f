#include "planarbench/convex_pieces.hpp"

#include <fmt/format.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Partition_traits_2.h>
#include <CGAL/partition_2.h>
#include <algorithm>
#include <list>
#include <stdexcept>

namespace pb {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Traits = CGAL::Partition_traits_2<Kernel>;
using CgalPoint = Traits::Point_2;
using CgalPolygon = Traits::Polygon_2;

double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// the piece without its straight vertices (a turn of exactly zero, e.g. the
// polygon's own points along one edge): the same region, strictly convex
ConvexPiece without_straight_vertices(const ConvexPiece& piece) {
  ConvexPiece out;
  const std::size_t n = piece.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& prev = piece[(i + n - 1) % n];
    const Vec2& next = piece[(i + 1) % n];
    if (cross(piece[i] - prev, next - piece[i]) != 0.0) out.push_back(piece[i]);
  }
  return out.size() >= 3 ? out : piece;
}

// a convex piece of more than max_vertices points cut by diagonals from its
// first point: fans of max_vertices points sharing their end points
void split_piece(const ConvexPiece& piece, int max_vertices, std::vector<ConvexPiece>& out) {
  const auto n = static_cast<int>(piece.size());
  if (max_vertices <= 0 || n <= max_vertices) {
    out.push_back(piece);
    return;
  }
  int start = 1;
  while (start < n - 1) {
    const int end = std::min(start + max_vertices - 2, n - 1);
    ConvexPiece sub;
    sub.push_back(piece[0]);
    for (int i = start; i <= end; ++i) sub.push_back(piece[static_cast<std::size_t>(i)]);
    out.push_back(std::move(sub));
    start = end;
  }
}

}  // namespace

bool is_convex_ccw(const std::vector<Vec2>& polygon, double rel_tol) {
  const std::size_t n = polygon.size();
  if (n < 3) return false;
  double area2 = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 e1 = polygon[(i + 1) % n] - polygon[i];
    const Vec2 e2 = polygon[(i + 2) % n] - polygon[(i + 1) % n];
    if (cross(e1, e2) < -rel_tol * e1.norm() * e2.norm()) return false;
    area2 += cross(polygon[i], polygon[(i + 1) % n]);
  }
  return area2 > 0.0;
}

ConvexDecomposition convex_pieces(const std::vector<Vec2>& polygon_ccw, int max_vertices) {
  const auto n = static_cast<int>(polygon_ccw.size());
  if (n < 3) throw std::invalid_argument("convex_pieces: a polygon needs at least 3 points");
  if (max_vertices > 0 && max_vertices < 3) {
    throw std::invalid_argument("convex_pieces: max_vertices must be 0 (no limit) or >= 3");
  }
  ConvexDecomposition out;
  std::vector<ConvexPiece> convex;
  if (is_convex_ccw(polygon_ccw)) {
    convex.push_back(polygon_ccw);
    out.method = "convex: the polygon itself";
  } else {
    CgalPolygon poly;
    for (const Vec2& p : polygon_ccw) poly.push_back(CgalPoint(p.x(), p.y()));
    std::list<CgalPolygon> parts;
    const bool optimal = n <= kOptimalPartitionMaxVertices;
    if (optimal) {
      CGAL::optimal_convex_partition_2(poly.vertices_begin(), poly.vertices_end(),
                                       std::back_inserter(parts));
    } else {
      CGAL::approx_convex_partition_2(poly.vertices_begin(), poly.vertices_end(),
                                      std::back_inserter(parts));
    }
    for (const CgalPolygon& part : parts) {
      ConvexPiece piece;
      for (auto v = part.vertices_begin(); v != part.vertices_end(); ++v) {
        piece.emplace_back(CGAL::to_double(v->x()), CGAL::to_double(v->y()));
      }
      // CGAL gives counter-clockwise pieces of a counter-clockwise polygon
      if (part.orientation() == CGAL::CLOCKWISE) std::reverse(piece.begin(), piece.end());
      convex.push_back(std::move(piece));
    }
    out.method = fmt::format(
        "{} into {} convex pieces",
        optimal ? "CGAL::optimal_convex_partition_2 (fewest pieces)"
                : "CGAL::approx_convex_partition_2 (Hertel-Mehlhorn, at most 4x the fewest)",
        convex.size());
  }
  for (const ConvexPiece& piece : convex) {
    split_piece(without_straight_vertices(piece), max_vertices, out.pieces);
  }
  if (out.pieces.size() != convex.size()) {
    out.method += fmt::format(", cut into {} pieces of at most {} points", out.pieces.size(),
                              max_vertices);
  }
  return out;
}

}  // namespace pb
