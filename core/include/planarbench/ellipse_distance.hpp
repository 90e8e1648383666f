// Closest point on an ellipse to a point (inside or outside), by the robust
// bisection of D. Eberly, "Distance from a Point to an Ellipse, an Ellipsoid,
// or a Hyperellipsoid", Geometric Tools (2013), section 2. The one
// implementation shared by the reference's exact geometry, the analytic
// truth's exact gap and the MuJoCo and Box2D adapters.
#pragma once

#include "planarbench/case.hpp"

namespace pb {

struct EllipseClosestPoint {
  Vec2 point_m = Vec2::Zero();          // m, on the ellipse, ellipse frame
  double signed_distance_m = 0.0;       // m, > 0 outside, < 0 inside
  Vec2 outward_normal = Vec2::UnitX();  // unit, at point_m
};

// Ellipse (x/a)^2 + (y/b)^2 = 1 in its own frame, a, b > 0 (either may be
// the larger); p in the same frame. Exact to rounding; no allocation.
[[nodiscard]] EllipseClosestPoint closest_point_on_ellipse(double a_m, double b_m, const Vec2& p_m);

}  // namespace pb
