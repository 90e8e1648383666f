// Outline points of shapes (paper §2.1.1, SPEC §2) and area properties of
// polygons and of the exact shapes.
#include "planarbench/outline.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "planarbench/overloaded.hpp"

namespace pb {

namespace {

// n points (rx cos t_k, ry sin t_k), t_k = 2 pi k / n: counter-clockwise,
// point 0 at t = 0, evenly spaced in the parameter angle
std::vector<Vec2> parametric_ellipse(double rx_m, double ry_m, int n) {
  if (n < 3) throw std::invalid_argument("outline needs at least 3 points, got " + std::to_string(n));
  std::vector<Vec2> out;
  out.reserve(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    const double t = 2.0 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(n);
    out.emplace_back(rx_m * std::cos(t), ry_m * std::sin(t));
  }
  return out;
}

// n points evenly along the surface y = 0 from x = +extent/2 to x = -extent/2:
// the solid (y <= 0) lies to the left of this direction, as for a
// counter-clockwise outline
std::vector<Vec2> halfplane_surface(double extent_m, int n) {
  if (n < 2) throw std::invalid_argument("half-plane outline needs at least 2 points, got " + std::to_string(n));
  std::vector<Vec2> out;
  out.reserve(static_cast<std::size_t>(n));
  const double half = 0.5 * extent_m;
  for (int k = 0; k < n; ++k) {
    const double s = static_cast<double>(k) / static_cast<double>(n - 1);  // 0 .. 1
    out.emplace_back(half - extent_m * s, 0.0);
  }
  out.back().x() = -half;  // exact end point despite rounding
  return out;
}

}  // namespace

std::vector<Vec2> make_outline(const Shape& shape, int n) {
  return std::visit(
      overloaded{
          [n](const Circle& c) { return parametric_ellipse(c.radius_m, c.radius_m, n); },
          [n](const Ellipse& e) { return parametric_ellipse(e.semi_axis_a_m, e.semi_axis_b_m, n); },
          [](const Polygon& p) { return p.points_m; },
          [n](const HalfPlane& h) { return halfplane_surface(h.extent_m, n); }},
      shape);
}

// Shoelace area and centroid (P. Bourke, "Calculating the area and centroid
// of a polygon", 1988) and polar second moment from the edge sums
//   J_O = 1/12 sum c_i (x_i^2 + x_i x_j + x_j^2 + y_i^2 + y_i y_j + y_j^2),
//   c_i = x_i y_j - x_j y_i, j = i + 1 (Wikipedia, "Second moment of area",
// "Any polygon"), moved to the centroid by the parallel-axis theorem
// J_C = J_O - A |C|^2. The sums run about point 0 rather than the origin, which
// keeps them accurate for polygons far from the origin. Signed: area and
// moment are negative for clockwise points. With zero area the centroid is
// left at point 0.
AreaProperties polygon_area_properties(const std::vector<Vec2>& points) {
  AreaProperties out;
  const std::size_t n = points.size();
  if (n < 3) return out;
  const Vec2 origin = points[0];
  double twice_area = 0.0;   // m^2
  Vec2 six_first_moment = Vec2::Zero();  // m^3, 6 A C
  double twelve_polar = 0.0;  // m^4, 12 J_O about point 0
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = points[i] - origin;
    const Vec2 b = points[(i + 1) % n] - origin;
    const double c = a.x() * b.y() - b.x() * a.y();
    twice_area += c;
    six_first_moment += c * (a + b);
    twelve_polar += c * (a.x() * a.x() + a.x() * b.x() + b.x() * b.x() + a.y() * a.y() +
                         a.y() * b.y() + b.y() * b.y());
  }
  out.area_m2 = 0.5 * twice_area;
  if (out.area_m2 == 0.0) {
    out.centroid_m = origin;
    return out;
  }
  const Vec2 centroid_from_origin = six_first_moment / (3.0 * twice_area);
  out.centroid_m = origin + centroid_from_origin;
  out.polar_moment_centroid_m4 =
      twelve_polar / 12.0 - out.area_m2 * centroid_from_origin.squaredNorm();
  return out;
}

// exact geometry: disk A = pi R^2, J = pi R^4 / 2; ellipse A = pi a b,
// J = pi a b (a^2 + b^2) / 4 (e.g. Gere & Goodno, Mechanics of Materials,
// Appendix E); polygons through the shoelace sums above
AreaProperties shape_area_properties(const Shape& shape) {
  const double pi = std::numbers::pi;
  return std::visit(
      overloaded{[pi](const Circle& c) {
                   const double r2 = c.radius_m * c.radius_m;
                   return AreaProperties{pi * r2, Vec2::Zero(), 0.5 * pi * r2 * r2};
                 },
                 [pi](const Ellipse& e) {
                   const double a = e.semi_axis_a_m;
                   const double b = e.semi_axis_b_m;
                   return AreaProperties{pi * a * b, Vec2::Zero(), 0.25 * pi * a * b * (a * a + b * b)};
                 },
                 [](const Polygon& p) { return polygon_area_properties(p.points_m); },
                 [](const HalfPlane&) -> AreaProperties {
                   throw std::invalid_argument("a half-plane has no finite area");
                 }},
      shape);
}

}  // namespace pb
