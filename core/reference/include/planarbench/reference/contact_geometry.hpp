// The geometry of one contact pair at one instant: signed gap, normal and the
// two contact points, world frame. Shared by the outline search (paper
// §2.1.1) and the exact primitives (geometry=exact).
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <limits>

#include "planarbench/case.hpp"

namespace pb {

// rigid placement of a body frame in the world
struct Pose {
  Vec2 position_m = Vec2::Zero();  // m, body origin (centre of mass) in the world
  double angle_rad = 0.0;          // rad, counter-clockwise

  [[nodiscard]] Eigen::Matrix2d rotation() const {
    const double c = std::cos(angle_rad);
    const double s = std::sin(angle_rad);
    Eigen::Matrix2d r;
    r << c, -s, s, c;
    return r;
  }
  // body frame -> world frame
  [[nodiscard]] Vec2 to_world(const Vec2& local_m) const { return position_m + rotation() * local_m; }
  // world frame -> body frame
  [[nodiscard]] Vec2 to_local(const Vec2& world_m) const {
    return rotation().transpose() * (world_m - position_m);
  }
};

// Contact geometry of the ordered pair (a, b).
//   gap_m > 0: the bodies are apart, gap_m is their distance;
//   gap_m < 0: they overlap, -gap_m is the penetration delta;
//   normal: unit, from body a towards body b (the direction b must move to
//   separate); gap_m == normal . (point_b_m - point_a_m) up to rounding
//   whenever |gap_m| > 1e-12 (1 + |point|): at a touch the points coincide and
//   the normal comes from the geometry, not from their difference.
// Apart, the points are the closest points; overlapping, one of them is the
// deepest point of one body inside the other and the other is its nearest
// point on the other body's boundary.
struct ContactGeometry {
  double gap_m = std::numeric_limits<double>::infinity();  // m, signed
  Vec2 normal = Vec2(0.0, 1.0);                             // unit, a -> b
  Vec2 point_a_m = Vec2::Zero();                            // m, world, on body a
  Vec2 point_b_m = Vec2::Zero();                            // m, world, on body b
  // m^2: overlapping at several points (a face), the depth-weighted variance
  // of those points' positions along the tangent about the line of action,
  // sum_i d_i ((p_i - p) x n)^2 / sum_i d_i; 0 at one point. The law's
  // damping spread over the points by depth (the weights that place the line
  // of action) has a couple -c spread omega besides its force, applied to
  // pairs whose friction can hold a face (contact_dynamics.cpp)
  double spread_m2 = 0.0;

  [[nodiscard]] double penetration_m() const { return gap_m < 0.0 ? -gap_m : 0.0; }
  // the same contact seen with a and b exchanged
  [[nodiscard]] ContactGeometry swapped() const {
    return ContactGeometry{gap_m, -normal, point_b_m, point_a_m, spread_m2};
  }
};

// 2D cross product a x b (z component), used for torques and sides
[[nodiscard]] inline double cross2(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}
// the vector turned by +90 degrees: omega x r = omega * perp(r)
[[nodiscard]] inline Vec2 perp(const Vec2& r) { return Vec2(-r.y(), r.x()); }

}  // namespace pb
