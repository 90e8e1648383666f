#include "ode_frame.hpp"

#include <cmath>
#include <numbers>

namespace pb::internal::ode {

Vector3 to_ode_vector(const Vec2& v) {
  return {v.x(), v.y(), 0.0};
}

Vec2 to_case_vector(const double* v3) {
  return {v3[0], v3[1]};
}

Quaternion to_ode_quaternion(double angle_rad) {
  return {std::cos(0.5 * angle_rad), 0.0, 0.0, std::sin(0.5 * angle_rad)};
}

double angle_from_ode_rotation(const double* r) {
  // first column of R = the body x axis in world coordinates
  return std::atan2(r[4], r[0]);
}

Quaternion planar_quaternion(const double* q) {
  const double norm = std::hypot(q[0], q[3]);
  if (!(norm > 0.0)) return {1.0, 0.0, 0.0, 0.0};
  return {q[0] / norm, 0.0, 0.0, q[3] / norm};
}

double unwrapped_angle(double previous_rad, double wrapped_rad) {
  constexpr double two_pi = 2.0 * std::numbers::pi;
  return wrapped_rad - two_pi * std::round((wrapped_rad - previous_rad) / two_pi);
}

}  // namespace pb::internal::ode
