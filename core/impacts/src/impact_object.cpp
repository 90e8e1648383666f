#include "planarbench/impacts/impact_object.hpp"

#include <cmath>

namespace pb {

ImpactState to_model(const std::array<double, 6>& row, AngleConvention c) {
  ImpactState s;
  s.angle_rad = c.angle_sign * row[2];
  s.velocity_mps = Vec2(row[3], row[4]);
  s.angular_velocity_radps = c.rate_sign * row[5];
  return s;
}

std::array<double, 3> to_stored(const ImpactState& s, AngleConvention c) {
  return {s.velocity_mps.x(), s.velocity_mps.y(), c.rate_sign * s.angular_velocity_radps};
}

Vec2 lowest_point_offset(const ImpactObject& o, double angle_rad) {
  const double a2 = o.semi_axis_a_m * o.semi_axis_a_m;
  const double b2 = o.semi_axis_b_m * o.semi_axis_b_m;
  const double c = std::cos(angle_rad);
  const double s = std::sin(angle_rad);
  const double ux = -s;
  const double uy = -c;
  const double norm = std::sqrt(a2 * ux * ux + b2 * uy * uy);
  const Vec2 body(a2 * ux / norm, b2 * uy / norm);
  return Vec2(c * body.x() - s * body.y(), s * body.x() + c * body.y());
}

double touching_height(const ImpactObject& o, double angle_rad) {
  const double s = std::sin(angle_rad);
  const double c = std::cos(angle_rad);
  return std::sqrt(o.semi_axis_a_m * o.semi_axis_a_m * s * s +
                   o.semi_axis_b_m * o.semi_axis_b_m * c * c);
}

double angular_momentum_about(const ImpactObject& o, const ImpactState& s, const Vec2& offset_m) {
  const Vec2& v = s.velocity_mps;
  const double cross = offset_m.x() * v.y() - offset_m.y() * v.x();
  return o.inertia_kgm2() * s.angular_velocity_radps - o.mass_kg * cross;
}

}  // namespace pb
