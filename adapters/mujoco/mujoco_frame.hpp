// The one mapping between a case's frame and MuJoCo's. MuJoCo is 3D and has no
// planar joint: the case's x-y plane is MuJoCo's x-z plane (case x -> MuJoCo x,
// case y -> MuJoCo z), every moving body turns about MuJoCo's +y axis. A
// positive rotation about +y turns x toward -z, i.e. clockwise in the x-z view
// (right-hand rule; ENGINES.md), so the case's counter-clockwise angle theta is
// the hinge coordinate q = -theta. Every conversion goes through these functions.
#pragma once

#include <array>

#include "planarbench/case.hpp"

namespace pb::internal::mujoco {

// case point or vector (m, m/s, N) -> MuJoCo world vector (x, 0, y)
[[nodiscard]] std::array<double, 3> to_mj(const Vec2& v);
// MuJoCo world vector -> case vector; the y component (out of plane) is dropped
[[nodiscard]] Vec2 from_mj(const double* v3);

// case angle (rad, counter-clockwise) -> hinge coordinate about +y (rad)
[[nodiscard]] double hinge_from_ccw(double angle_rad);
// hinge coordinate about +y (rad) -> case angle (rad, counter-clockwise)
[[nodiscard]] double ccw_from_hinge(double hinge_rad);
// the same two for rates: case omega (rad/s, ccw) <-> hinge velocity about +y
[[nodiscard]] double hinge_rate_from_ccw(double omega_radps);
[[nodiscard]] double ccw_rate_from_hinge(double hinge_rate_radps);

// unit quaternion (w, x, y, z) of a frame turned by the case angle theta:
// a rotation by -theta about +y, i.e. (cos(theta/2), 0, -sin(theta/2), 0)
[[nodiscard]] std::array<double, 4> quat_from_ccw(double angle_rad);
// case angle of a MuJoCo rotation matrix (row-major 3x3, as mjData::xmat):
// the image of the body x axis is the first column (xmat[0], xmat[3], xmat[6])
// and its case angle is atan2(z, x)
[[nodiscard]] double ccw_from_xmat(const double* xmat9);

// case angular velocity (rad/s, ccw) from a MuJoCo world angular velocity vector
[[nodiscard]] double ccw_rate_from_mj(const double* omega3);

}  // namespace pb::internal::mujoco
