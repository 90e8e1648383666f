// The point of an ellipse's boundary nearest to a point outside it, written
// for the independent truth (no code shared with core/src/ellipse_distance.cpp).
//
// Method: D. Eberly, "Distance from a Point to an Ellipse, an Ellipsoid, or a
// Hyperellipsoid" (Geometric Tools, 2013, §2). For the ellipse
// (x0/e0)^2 + (x1/e1)^2 = 1 with e0 >= e1 > 0 and a query y in the first
// quadrant, the nearest point is x_i = e_i^2 y_i / (t + e_i^2), where t is the
// root of F(t) = (e0 y0 / (t + e0^2))^2 + (e1 y1 / (t + e1^2))^2 - 1 in
// t > -e1^2. F is strictly decreasing there, so bisection on a bracket that
// is known in closed form converges without fail; it is run until the
// midpoint equals an end (the last bit). The other quadrants follow by
// symmetry (signs of y restored at the end).
#pragma once

#include "planarbench/case.hpp"

namespace pb::independent {

struct EllipseNearest {
  Vec2 point_m = Vec2::Zero();  // m, ellipse frame, on the boundary
  double distance_m = 0.0;      // m, |query - point|, >= 0
  bool outside = true;          // false when the query is inside or on the boundary
};

// semi_x_m along the ellipse frame's x, semi_y_m along its y (either may be
// the larger); query_m in the ellipse frame
[[nodiscard]] EllipseNearest nearest_on_ellipse(double semi_x_m, double semi_y_m,
                                                const Vec2& query_m);

}  // namespace pb::independent
