// The one place that maps a case's planar frame to ODE's 3D frame and back.
// Case x-y plane = ODE x-y plane at z = 0; the case angle is a rotation about
// ODE's +z axis, counter-clockwise positive seen from +z (right-hand rule).
#pragma once

#include <array>

#include "planarbench/case.hpp"

namespace pb::internal::ode {

// ODE quaternion order is (w, x, y, z) (ODE manual, "Rotation functions")
using Quaternion = std::array<double, 4>;
using Vector3 = std::array<double, 3>;

// (x, y) -> (x, y, 0)
[[nodiscard]] Vector3 to_ode_vector(const Vec2& v);
// (x, y, z) -> (x, y); z is what the planar constraint keeps at 0
[[nodiscard]] Vec2 to_case_vector(const double* v3);

// rotation by angle_rad about +z: (cos(a/2), 0, 0, sin(a/2))
[[nodiscard]] Quaternion to_ode_quaternion(double angle_rad);

// case angle in (-pi, pi] of an ODE rotation matrix (dMatrix3, row-major
// with a row stride of 4): the direction of the body x axis in the x-y plane,
// atan2(R[1][0], R[0][0])
[[nodiscard]] double angle_from_ode_rotation(const double* rotation_3x4);

// the pure z rotation nearest to quaternion q (w, x, y, z): x and y dropped,
// renormalised. Removes the out-of-plane drift that Plane2D leaves to the
// application (ODE demo_plane2d.cpp does the same each step).
[[nodiscard]] Quaternion planar_quaternion(const double* q_wxyz);

// angle continuous with `previous_rad`: the 2 pi multiple nearest to it
[[nodiscard]] double unwrapped_angle(double previous_rad, double wrapped_rad);

}  // namespace pb::internal::ode
