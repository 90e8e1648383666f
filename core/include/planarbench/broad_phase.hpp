// A broad phase over axis-aligned bounding boxes (SPEC §11): which bodies of
// a scene are near enough to need a contact test. Sort and sweep along the
// axis over which the boxes spread most (Baraff 1992, "Dynamic simulation of
// non-penetrating rigid bodies", §4.4; Ericson, "Real-Time Collision
// Detection", 2005, §7.5.1): O(n log n + pairs) for boxes spread along
// either axis, and a stack (all boxes at one x) sweeps along y. Half-planes
// have no box: a body is near one when its box comes within the margin of
// its surface. Deterministic: the pairs come out sorted.
#pragma once

#include <utility>
#include <vector>

#include "planarbench/case.hpp"

namespace pb {

struct Aabb {
  double min_x = 0.0, min_y = 0.0, max_x = 0.0, max_y = 0.0;  // m, world
  [[nodiscard]] Aabb expanded(double margin_m) const {
    return Aabb{min_x - margin_m, min_y - margin_m, max_x + margin_m, max_y + margin_m};
  }
  [[nodiscard]] bool overlaps(const Aabb& o) const {
    return min_x <= o.max_x && o.min_x <= max_x && min_y <= o.max_y && o.min_y <= max_y;
  }
};

// the box of a body's shape (not a half-plane's) at a pose: exact for
// circles, ellipses and polygons (their vertices)
[[nodiscard]] Aabb shape_aabb(const Shape& shape, const Vec2& position_m, double angle_rad);

// m, how far the box lies above the surface of a half-plane placed at
// (position, angle): the least height of its corners over the surface line
// along the outward normal (negative: a corner is below the surface)
[[nodiscard]] double height_above_half_plane(const Aabb& box, const Vec2& plane_position_m,
                                             double plane_angle_rad);

// The pairs (ids[a], ids[b]) of the boxes that overlap, written to `out`
// sorted by (first, second) with first < second; `ids` names each box (a
// body index). Reuses `out` and `order` (scratch) without allocating once
// they have grown.
void overlapping_pairs(const std::vector<Aabb>& boxes, const std::vector<int>& ids,
                       std::vector<std::pair<int, int>>& out, std::vector<int>& order);

}  // namespace pb
