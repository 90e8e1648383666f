// Closed-form contact geometry of primitive shapes, for the force-injection
// mode: the adapter measures penetration, normal and point itself (in double
// precision, from the exact shapes) and applies the case's force law.
#pragma once

#include <string>

#include "planarbench/case.hpp"

namespace pb::internal::box2d {

struct Pose {
  Vec2 position_m = Vec2::Zero();  // m, body origin (centre of mass), world
  double angle_rad = 0.0;          // rad, counter-clockwise
};

struct PrimitiveContact {
  double penetration_m = 0.0;   // m, > 0 overlap, < 0 gap
  Vec2 normal = Vec2::Zero();   // unit, from body a to body b
  Vec2 point_m = Vec2::Zero();  // m, midpoint of the two surface points
};

// Why the pair has no closed form here ("" when it has): supported are
// half-plane with circle, ellipse or polygon (support point), circle-circle,
// ellipse-circle (point-to-ellipse distance) and polygon-circle (closest
// point on the boundary), in either order.
[[nodiscard]] std::string primitive_contact_unsupported_reason(const Shape& a, const Shape& b);

// Contact of shape a at pose pa with shape b at pose pb; the pair must be
// supported (primitive_contact_unsupported_reason is empty).
[[nodiscard]] PrimitiveContact primitive_contact(const Shape& a, const Pose& pa, const Shape& b,
                                                 const Pose& pb);

// Closest point of the ellipse (semi-axes a along x, b along y, centred at
// the origin) to the point p, both in the ellipse frame; p may lie inside.
// D. Eberly, "Distance from a Point to an Ellipse, an Ellipsoid, or a
// Hyperellipsoid" (Geometric Tools, 2013): bisection on the root of
// (r0 z0 / (s + r0))^2 + (z1 / (s + 1))^2 = 1.
[[nodiscard]] Vec2 closest_point_on_ellipse(double a_m, double b_m, const Vec2& p_m);

}  // namespace pb::internal::box2d
