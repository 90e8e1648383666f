// Validation of a polygon shape as the case format wants it: a simple,
// counter-clockwise outline in the body frame with its centroid at the origin.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/outline.hpp"

namespace pb::internal {

// relative tolerances of the checks, as fractions of the polygon's size (the
// diagonal of its bounding box): far above rounding of coordinates written
// with ~15 digits, far below any shape anyone means
constexpr double kPolygonAreaTolerance = 1e-12;     // x size^2
constexpr double kPolygonCentroidTolerance = 1e-9;  // x size

// sign of the turn a -> b -> c: > 0 counter-clockwise, < 0 clockwise, 0 collinear
inline double orientation(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

// p on the closed segment [a, b], given that a, b, p are collinear
inline bool within_segment(const Vec2& a, const Vec2& b, const Vec2& p) {
  return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) &&
         std::min(a.y(), b.y()) <= p.y() && p.y() <= std::max(a.y(), b.y());
}

// closed segments [a, b] and [c, d] share a point (the orientation test of
// Cormen et al., Introduction to Algorithms, §33.1)
inline bool segments_touch(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double o1 = orientation(a, b, c);
  const double o2 = orientation(a, b, d);
  const double o3 = orientation(c, d, a);
  const double o4 = orientation(c, d, b);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) {
    return true;
  }
  return (o1 == 0 && within_segment(a, b, c)) || (o2 == 0 && within_segment(a, b, d)) ||
         (o3 == 0 && within_segment(c, d, a)) || (o4 == 0 && within_segment(c, d, b));
}

// the first problem of the polygon, or nothing when it is acceptable
inline std::optional<std::string> polygon_problem(const std::vector<Vec2>& p) {
  const std::size_t n = p.size();
  if (n < 3) return fmt::format("needs at least 3 points (got {})", n);

  // repeated consecutive points (the outline closes by itself)
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    if (p[i] == p[j]) {
      if (j == 0) {
        return fmt::format("the last point repeats the first ({}, {}): leave the outline open, "
                           "it closes by itself",
                           p[0].x(), p[0].y());
      }
      return fmt::format("points {} and {} are the same point ({}, {}): remove one", i, j,
                         p[i].x(), p[i].y());
    }
  }

  // size of the polygon: the diagonal of its bounding box, m
  Vec2 lo = p[0];
  Vec2 hi = p[0];
  for (const auto& q : p) {
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  const double size = (hi - lo).norm();

  // zero area: collinear points, or lobes that cancel
  const AreaProperties props = polygon_area_properties(p);
  if (std::abs(props.area_m2) <= kPolygonAreaTolerance * size * size) {
    return fmt::format("encloses zero area ({} m^2): the points are collinear or the outline "
                       "crosses itself",
                       props.area_m2);
  }

  // self-intersection: non-adjacent edges must not touch, adjacent edges
  // must not fold back onto each other; O(n^2), fine for <= 10000 points
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& a = p[i];
    const Vec2& b = p[(i + 1) % n];
    const Vec2& c = p[(i + 2) % n];
    const Vec2 ab = b - a;
    const Vec2 bc = c - b;
    if (orientation(a, b, c) == 0 && ab.dot(bc) < 0) {
      return fmt::format("the outline folds back on itself at point {} ({}, {}): it must be a "
                         "simple polygon",
                         (i + 1) % n, b.x(), b.y());
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& a = p[i];
    const Vec2& b = p[(i + 1) % n];
    const Vec2 box_lo = a.cwiseMin(b);
    const Vec2 box_hi = a.cwiseMax(b);
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // edges n-1 -> 0 and 0 -> 1 share point 0
      const Vec2& c = p[j];
      const Vec2& d = p[(j + 1) % n];
      // bounding boxes first: most pairs are far apart
      if (std::max(c.x(), d.x()) < box_lo.x() || std::min(c.x(), d.x()) > box_hi.x() ||
          std::max(c.y(), d.y()) < box_lo.y() || std::min(c.y(), d.y()) > box_hi.y()) {
        continue;
      }
      if (segments_touch(a, b, c, d)) {
        return fmt::format("edges {}-{} and {}-{} intersect: the outline must be a simple "
                           "polygon",
                           i, (i + 1) % n, j, (j + 1) % n);
      }
    }
  }

  // orientation
  if (props.area_m2 < 0) {
    return std::string("points are clockwise; the format wants counter-clockwise: reverse them");
  }

  // centroid at the body origin (the body frame's origin is the centre of mass)
  const double tolerance = kPolygonCentroidTolerance * size;
  if (props.centroid_m.norm() > tolerance) {
    return fmt::format("centroid is at ({:g}, {:g}), not at the body origin (tolerance {:.3g} m "
                       "= 1e-9 x size): subtract it from every point",
                       props.centroid_m.x(), props.centroid_m.y(), tolerance);
  }
  return std::nullopt;
}

}  // namespace pb::internal
