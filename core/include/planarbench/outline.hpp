// Outline points of shapes and area properties of polygons (paper §2.1.1:
// every body is a closed list of points in its body frame).
#pragma once

#include <vector>

#include "planarbench/case.hpp"

namespace pb {

// Outline of a shape in its body frame: n points, counter-clockwise, point 0
// at parameter angle 0, evenly spaced in the parameter angle (SPEC §2).
// Circle: (R cos t, R sin t); ellipse: (a cos t, b sin t); polygon: its own
// points (n ignored); half-plane: n points evenly along the surface segment
// from (+extent/2, 0) to (-extent/2, 0) (counter-clockwise seen from the solid).
[[nodiscard]] std::vector<Vec2> make_outline(const Shape& shape, int n);

struct AreaProperties {
  double area_m2 = 0.0;                        // m^2
  Vec2 centroid_m = Vec2::Zero();              // m
  double polar_moment_centroid_m4 = 0.0;       // m^4, integral of r^2 dA about the centroid
};

// Area, centroid and polar second moment of a simple polygon (shoelace
// formulas); area > 0 for counter-clockwise points.
[[nodiscard]] AreaProperties polygon_area_properties(const std::vector<Vec2>& points);

// Area and polar moment of a shape's exact geometry (circle, ellipse) or of the
// polygon. Half-planes have no finite area: throws std::invalid_argument.
[[nodiscard]] AreaProperties shape_area_properties(const Shape& shape);

}  // namespace pb
