#include "planarbench/broad_phase.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <variant>

namespace pb {

Aabb shape_aabb(const Shape& shape, const Vec2& position_m, double angle_rad) {
  const double c = std::cos(angle_rad);
  const double s = std::sin(angle_rad);
  if (const auto* circle = std::get_if<Circle>(&shape)) {
    const double r = circle->radius_m;
    return Aabb{position_m.x() - r, position_m.y() - r, position_m.x() + r, position_m.y() + r};
  }
  if (const auto* e = std::get_if<Ellipse>(&shape)) {
    // the extents of the rotated ellipse: sqrt(a^2 cos^2 + b^2 sin^2) along x
    const double a = e->semi_axis_a_m;
    const double b = e->semi_axis_b_m;
    const double hx = std::sqrt(a * a * c * c + b * b * s * s);
    const double hy = std::sqrt(a * a * s * s + b * b * c * c);
    return Aabb{position_m.x() - hx, position_m.y() - hy, position_m.x() + hx, position_m.y() + hy};
  }
  Aabb box{INFINITY, INFINITY, -INFINITY, -INFINITY};
  if (const auto* p = std::get_if<Polygon>(&shape)) {
    for (const Vec2& v : p->points_m) {
      const double x = position_m.x() + c * v.x() - s * v.y();
      const double y = position_m.y() + s * v.x() + c * v.y();
      box.min_x = std::min(box.min_x, x);
      box.min_y = std::min(box.min_y, y);
      box.max_x = std::max(box.max_x, x);
      box.max_y = std::max(box.max_y, y);
    }
    return box;
  }
  // a half-plane: unbounded
  return Aabb{-INFINITY, -INFINITY, INFINITY, INFINITY};
}

double height_above_half_plane(const Aabb& box, const Vec2& plane_position_m,
                               double plane_angle_rad) {
  // outward normal: the body frame's +y turned by the plane's angle
  const double nx = -std::sin(plane_angle_rad);
  const double ny = std::cos(plane_angle_rad);
  // the corner lowest along n
  const double x = nx >= 0.0 ? box.min_x : box.max_x;
  const double y = ny >= 0.0 ? box.min_y : box.max_y;
  return nx * (x - plane_position_m.x()) + ny * (y - plane_position_m.y());
}

void overlapping_pairs(const std::vector<Aabb>& boxes, const std::vector<int>& ids,
                       std::vector<std::pair<int, int>>& out, std::vector<int>& order) {
  out.clear();
  const auto n = boxes.size();
  if (n < 2) return;
  // sweep along the axis over which the box centres spread most
  double mean_x = 0.0, mean_y = 0.0;
  for (const Aabb& b : boxes) {
    mean_x += 0.5 * (b.min_x + b.max_x);
    mean_y += 0.5 * (b.min_y + b.max_y);
  }
  mean_x /= static_cast<double>(n);
  mean_y /= static_cast<double>(n);
  double var_x = 0.0, var_y = 0.0;
  for (const Aabb& b : boxes) {
    const double dx = 0.5 * (b.min_x + b.max_x) - mean_x;
    const double dy = 0.5 * (b.min_y + b.max_y) - mean_y;
    var_x += dx * dx;
    var_y += dy * dy;
  }
  const bool along_x = var_x >= var_y;
  auto lo = [&](int i) { return along_x ? boxes[static_cast<std::size_t>(i)].min_x : boxes[static_cast<std::size_t>(i)].min_y; };
  auto hi = [&](int i) { return along_x ? boxes[static_cast<std::size_t>(i)].max_x : boxes[static_cast<std::size_t>(i)].max_y; };
  order.resize(n);
  std::iota(order.begin(), order.end(), 0);
  // ties by index: the same boxes give the same order on every machine
  std::sort(order.begin(), order.end(), [&](int a, int b) { return lo(a) < lo(b) || (lo(a) == lo(b) && a < b); });
  for (std::size_t u = 0; u < n; ++u) {
    const int i = order[u];
    const double end = hi(i);
    for (std::size_t v = u + 1; v < n && lo(order[v]) <= end; ++v) {
      const int j = order[v];
      if (!boxes[static_cast<std::size_t>(i)].overlaps(boxes[static_cast<std::size_t>(j)])) continue;
      const int a = ids[static_cast<std::size_t>(i)];
      const int b = ids[static_cast<std::size_t>(j)];
      out.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  std::sort(out.begin(), out.end());
}

}  // namespace pb
