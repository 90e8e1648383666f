// Exact penetration of pairs whose MuJoCo collider is approximate (libccd MPR),
// computed from the case's own geometry, to measure MPR's depth error during a
// run. Covered: circle-ellipse (the dual pendulum).
#pragma once

#include <optional>

#include "planarbench/case.hpp"
#include "planarbench/engine.hpp"

namespace pb::internal::mujoco {

// Distance from the point (x, y) to the ellipse x^2/a^2 + y^2/b^2 = 1 (its own
// frame), m. D. Eberly, "Distance from a point to an ellipse, an ellipsoid, or
// a hyperellipsoid" (Geometric Tools, 2013): reduce to the first quadrant and
// bisect on the Lagrange parameter, robust for points near the axes.
[[nodiscard]] double point_ellipse_distance_m(double a, double b, double x, double y);

// Penetration (m, > 0 overlapping) of a circle and an ellipse in the given
// poses, either order; nullopt for any other pair of shapes.
[[nodiscard]] std::optional<double> exact_penetration_m(const Shape& a, const BodyState& pose_a,
                                                        const Shape& b, const BodyState& pose_b);

}  // namespace pb::internal::mujoco
