#include "internal/start_overlap.hpp"

#include <fmt/format.h>

#include <cmath>
#include <variant>

#include "planarbench/overloaded.hpp"

namespace pb::internal {

namespace {

// the point in the body's frame (origin at its centre, x along its angle)
Vec2 to_body_frame(const Body& b, const Vec2& p) {
  const Vec2 d = p - b.position_m;
  const double c = std::cos(b.angle_rad);
  const double s = std::sin(b.angle_rad);
  return {c * d.x() + s * d.y(), -s * d.x() + c * d.y()};
}

// even-odd crossing test (W. R. Franklin's PNPOLY rule): strict inside for
// any simple polygon, convex or not; a point on an edge may count either way
bool inside_polygon(const std::vector<Vec2>& pts, const Vec2& p) {
  bool inside = false;
  for (std::size_t i = 0, j = pts.size() - 1; i < pts.size(); j = i++) {
    const Vec2& a = pts[i];
    const Vec2& b = pts[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x()) {
      inside = !inside;
    }
  }
  return inside;
}

}  // namespace

std::optional<std::string> point_inside_body(const Body& b, const Vec2& point) {
  const Vec2 q = to_body_frame(b, point);
  return std::visit(
      overloaded{
          [&](const Circle& s) -> std::optional<std::string> {
            const double r = q.norm();
            if (!(r < s.radius_m)) return std::nullopt;
            return fmt::format("{:.6g} m from its centre, inside its radius {:.6g} m", r, s.radius_m);
          },
          [&](const Ellipse& s) -> std::optional<std::string> {
            const double u = q.x() / s.semi_axis_a_m;
            const double v = q.y() / s.semi_axis_b_m;
            if (!(u * u + v * v < 1.0)) return std::nullopt;
            return std::string("inside its ellipse");
          },
          [&](const Polygon& s) -> std::optional<std::string> {
            if (!inside_polygon(s.points_m, q)) return std::nullopt;
            return std::string("inside its outline");
          },
          [&](const HalfPlane&) -> std::optional<std::string> {
            if (!(q.y() < 0.0)) return std::nullopt;
            return fmt::format("{:.6g} m below its surface", -q.y());
          }},
      b.shape);
}

}  // namespace pb::internal
