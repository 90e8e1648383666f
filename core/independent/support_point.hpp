// The deepest point of a body below a line, in closed form: the support
// function h(u) = max over the shape of u . (p - centre) and its maximiser,
// for the direction u = -n into the line's solid side (n its outward normal).
// Written for the independent truth (no code shared with core/reference).
//   circle of radius R:     h(u) = R, point centre + R u
//   ellipse, semi-axes a, b (body frame; u' = R(theta)^T u):
//                           h(u) = sqrt(a^2 u'x^2 + b^2 u'y^2),
//                           point (a^2 u'x, b^2 u'y) / h  (the normal of the
//                           ellipse (x/a)^2 + (y/b)^2 = 1 at that point,
//                           (x / a^2, y / b^2), is parallel to u')
//   polygon:                the vertex with the largest u . v_i (a linear
//                           function over a polygon is largest at a vertex)
#pragma once

#include <limits>

#include "planarbench/case.hpp"

namespace pb::independent {

// a body's pose in the world
struct Pose {
  Vec2 centre_m = Vec2::Zero();  // m, centre of mass (body origin)
  double angle_rad = 0.0;        // rad
};

struct SupportPoint {
  Vec2 point_m = Vec2::Zero();  // m, world, the shape's point farthest along u
  double reach_m = 0.0;         // m, u . (point - centre)
  int vertex = -1;              // polygons: the vertex's index; -1 otherwise
  // polygons: the largest u . (v_j - centre) over the other vertices, m
  // (-inf for smooth shapes): a second vertex reaching the line ends the
  // single-vertex contact this truth handles
  double next_reach_m = -std::numeric_limits<double>::infinity();
};

// support of a circle, ellipse or polygon at pose p in the world unit direction u
[[nodiscard]] SupportPoint support_point(const Shape& shape, const Pose& p, const Vec2& u);

}  // namespace pb::independent
