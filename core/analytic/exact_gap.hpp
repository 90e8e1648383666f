// Signed distance between the exact shapes of two bodies (circle, ellipse,
// half-plane): the first contact of the pendulums is the first zero of it.
// Point-to-ellipse distance after D. Eberly, "Distance from a Point to an
// Ellipse, an Ellipsoid, or a Hyperellipsoid" (Geometric Tools, 2013): the
// closest point x_i = e_i^2 y_i / (t + e_i^2) with t the root of
// sum (e_i y_i / (t + e_i^2))^2 = 1, found by bisection to the last bit.
#pragma once

#include "planarbench/case.hpp"

namespace pb::internal {

struct Pose {
  Vec2 position_m = Vec2::Zero();  // m, centre (body origin)
  double angle_rad = 0.0;          // rad
};

struct ExactGap {
  double gap_m = 0.0;             // m, signed: < 0 when the shapes overlap
  Vec2 normal = Vec2::Zero();     // unit, from body a to body b
  Vec2 point_a_m = Vec2::Zero();  // m, world, the point of a nearest to b
  Vec2 point_b_m = Vec2::Zero();  // m, world, the point of b nearest to a
};

// the point of the ellipse (a cos t, b sin t) nearest to p (ellipse frame),
// and the signed distance (< 0 when p is inside): pb::closest_point_on_ellipse
// (planarbench/ellipse_distance.hpp) in this file's terms
struct EllipseClosest {
  Vec2 point = Vec2::Zero();
  double signed_distance_m = 0.0;
};
[[nodiscard]] EllipseClosest closest_point_on_ellipse(double a_m, double b_m, const Vec2& p_m);

// whether exact_gap handles this pair of shapes (circle-circle,
// circle-ellipse, circle-half-plane, ellipse-half-plane)
[[nodiscard]] bool exact_gap_supported(const Shape& a, const Shape& b);

// the gap between shape a at pose pa and shape b at pose pb (supported pairs only)
[[nodiscard]] ExactGap exact_gap(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb);

}  // namespace pb::internal
