#include "mujoco_frame.hpp"

#include <cmath>

namespace pb::internal::mujoco {

std::array<double, 3> to_mj(const Vec2& v) {
  return {v.x(), 0.0, v.y()};
}

Vec2 from_mj(const double* v3) {
  return Vec2(v3[0], v3[2]);
}

// the sign flip of the whole adapter: +y hinge turns clockwise in the x-z view
double hinge_from_ccw(double angle_rad) {
  return -angle_rad;
}
double ccw_from_hinge(double hinge_rad) {
  return -hinge_rad;
}
double hinge_rate_from_ccw(double omega_radps) {
  return -omega_radps;
}
double ccw_rate_from_hinge(double hinge_rate_radps) {
  return -hinge_rate_radps;
}

std::array<double, 4> quat_from_ccw(double angle_rad) {
  // axis-angle quaternion (cos(phi/2), u sin(phi/2)) with u = +y, phi = -theta
  const double phi = hinge_from_ccw(angle_rad);
  return {std::cos(0.5 * phi), 0.0, std::sin(0.5 * phi), 0.0};
}

double ccw_from_xmat(const double* xmat9) {
  return std::atan2(xmat9[6], xmat9[0]);
}

// the world angular velocity of a planar body is along y; its y component is
// the hinge rate about +y
double ccw_rate_from_mj(const double* omega3) {
  return ccw_rate_from_hinge(omega3[1]);
}

}  // namespace pb::internal::mujoco
