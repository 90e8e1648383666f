// The dropped object of a file of measured impacts and one impact's state in
// the project's convention (SPEC §8): angles counter-clockwise positive, the
// ground the line y = 0 with its solid side below.
//
// The MCube ellipse (../shared/data/mcube/README.md, from the dataset's own
// README): semi-axes a = 35 mm along the body x axis and b = 25 mm, mass
// 36.4 g, radius of gyration 19.2354 mm (= sqrt((a^2 + b^2) / 5), the value the
// dataset's predictions use; its README rounds it to 19.2 mm).
#pragma once

#include <array>

#include "planarbench/case.hpp"

namespace pb {

struct ImpactObject {
  double semi_axis_a_m = 0.035;      // m, along body x
  double semi_axis_b_m = 0.025;      // m, along body y
  double mass_kg = 0.0364;           // kg
  double gyration_radius_m = 0.0192354;  // m, k: I = m k^2
  [[nodiscard]] double inertia_kgm2() const { return mass_kg * gyration_radius_m * gyration_radius_m; }
};

inline constexpr double kImpactGravity_mps2 = 9.81;  // m/s^2, the dataset's README

// One impact's velocities and angle, the project's convention: angle_rad and
// angular velocity counter-clockwise positive.
struct ImpactState {
  double angle_rad = 0.0;
  Vec2 velocity_mps = Vec2::Zero();
  double angular_velocity_radps = 0.0;
  // (x', y', theta') as one vector, the order of the error norm's M
  [[nodiscard]] std::array<double, 3> velocities() const {
    return {velocity_mps.x(), velocity_mps.y(), angular_velocity_radps};
  }
};

// The signs that turn a stored angle and angular velocity into the project's:
// angle = angle_sign * stored, omega = rate_sign * stored (impact_convention.hpp
// measures which pair the data obey).
struct AngleConvention {
  double angle_sign = 1.0;
  double rate_sign = 1.0;
};

// row = (x, y, theta, x', y', theta') as stored
[[nodiscard]] ImpactState to_model(const std::array<double, 6>& row, AngleConvention c);
// (x', y', theta') of a model-convention state back in the stored convention
[[nodiscard]] std::array<double, 3> to_stored(const ImpactState& s, AngleConvention c);

// m, world vector from the centre to the lowest point of the ellipse at
// `angle_rad` (the contact point on horizontal ground): the point whose
// outward normal is -y. In the body frame u = R(-angle) (0, -1) =
// (-sin, -cos) and p = (a^2 u_x, b^2 u_y) / sqrt(a^2 u_x^2 + b^2 u_y^2).
[[nodiscard]] Vec2 lowest_point_offset(const ImpactObject& o, double angle_rad);
// m, height of the centre above the ground when the ellipse touches it at
// `angle_rad`: sqrt(a^2 sin^2 + b^2 cos^2) (the support function along -y)
[[nodiscard]] double touching_height(const ImpactObject& o, double angle_rad);

// the angular momentum about the point `offset_m` from the centre,
// L = I omega - m (offset x v) (kg m^2/s)
[[nodiscard]] double angular_momentum_about(const ImpactObject& o, const ImpactState& s,
                                            const Vec2& offset_m);

}  // namespace pb
