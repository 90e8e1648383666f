#include "mujoco_exact_depth.hpp"

#include <cmath>

#include "planarbench/ellipse_distance.hpp"

namespace pb::internal::mujoco {

double point_ellipse_distance_m(double a, double b, double x, double y) {
  // the shared Eberly solution (planarbench/ellipse_distance.hpp), unsigned
  return std::abs(closest_point_on_ellipse(a, b, Vec2(x, y)).signed_distance_m);
}

std::optional<double> exact_penetration_m(const Shape& a, const BodyState& pa, const Shape& b,
                                          const BodyState& pb) {
  const Circle* c = std::get_if<Circle>(&a);
  const Ellipse* e = std::get_if<Ellipse>(&b);
  const BodyState* pc = &pa;
  const BodyState* pe = &pb;
  if (!c || !e) {
    c = std::get_if<Circle>(&b);
    e = std::get_if<Ellipse>(&a);
    pc = &pb;
    pe = &pa;
  }
  if (!c || !e) return std::nullopt;
  // the circle's centre in the ellipse's frame
  const Vec2 d = pc->position_m - pe->position_m;
  const double cs = std::cos(pe->angle_rad);
  const double sn = std::sin(pe->angle_rad);
  const double x = cs * d.x() + sn * d.y();
  const double y = -sn * d.x() + cs * d.y();
  const double signed_dist =
      closest_point_on_ellipse(e->semi_axis_a_m, e->semi_axis_b_m, Vec2(x, y)).signed_distance_m;
  // centre outside (signed distance > 0): overlap R - dist; inside: R + dist
  return c->radius_m - signed_dist;
}

}  // namespace pb::internal::mujoco
