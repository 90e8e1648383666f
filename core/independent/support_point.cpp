#include "support_point.hpp"

#include <cmath>
#include <stdexcept>
#include <variant>

#include "plane_rotation.hpp"

namespace pb::independent {

SupportPoint support_point(const Shape& shape, const Pose& p, const Vec2& u) {
  SupportPoint out;
  if (const auto* circle = std::get_if<Circle>(&shape)) {
    out.reach_m = circle->radius_m;
    out.point_m = p.centre_m + circle->radius_m * u;
    return out;
  }
  if (const auto* e = std::get_if<Ellipse>(&shape)) {
    const Vec2 ub = rotate(-p.angle_rad, u);
    const double a2 = e->semi_axis_a_m * e->semi_axis_a_m;
    const double b2 = e->semi_axis_b_m * e->semi_axis_b_m;
    const double h = std::sqrt(a2 * ub.x() * ub.x() + b2 * ub.y() * ub.y());
    out.reach_m = h;
    out.point_m = p.centre_m + rotate(p.angle_rad, Vec2(a2 * ub.x() / h, b2 * ub.y() / h));
    return out;
  }
  if (const auto* poly = std::get_if<Polygon>(&shape)) {
    out.reach_m = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < poly->points_m.size(); ++i) {
      const Vec2 r = rotate(p.angle_rad, poly->points_m[i]);
      const double reach = u.dot(r);
      if (reach > out.reach_m) {
        out.next_reach_m = out.reach_m;
        out.reach_m = reach;
        out.vertex = static_cast<int>(i);
        out.point_m = p.centre_m + r;
      } else if (reach > out.next_reach_m) {
        out.next_reach_m = reach;
      }
    }
    return out;
  }
  throw std::logic_error("independent truth: support_point of a half-plane");
}

}  // namespace pb::independent
