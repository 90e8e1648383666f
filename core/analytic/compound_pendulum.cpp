#include "compound_pendulum.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "jacobi_elliptic.hpp"

namespace pb::internal {

const char* pendulum_regime_name(PendulumRegime r) {
  switch (r) {
    case PendulumRegime::rest:
      return "rest";
    case PendulumRegime::spin:
      return "spin";
    case PendulumRegime::libration:
      return "libration";
    case PendulumRegime::separatrix:
      return "separatrix";
    case PendulumRegime::rotation:
      return "rotation";
  }
  return "rest";
}

CompoundPendulum::CompoundPendulum(const Vec2& pivot_m, const Body& body, const Vec2& gravity_mps2)
    : pivot_m_(pivot_m), centre0_m_(body.position_m), angle0_rad_(body.angle_rad) {
  const Vec2 arm = body.position_m - pivot_m;
  const double g = gravity_mps2.norm();
  d_m_ = arm.norm();
  mass_kg_ = body.mass_kg;
  inertia_pivot_ = body.inertia_kgm2 + body.mass_kg * d_m_ * d_m_;  // parallel axes
  down_ = g > 0.0 ? Vec2(gravity_mps2 / g) : Vec2(0.0, -1.0);
  across_ = Vec2(-down_.y(), down_.x());
  phi0_rad_ = std::atan2(arm.dot(across_), arm.dot(down_));
  phi_rate0_radps_ = body.angular_velocity_radps;
  direction_ = phi_rate0_radps_ < 0.0 ? -1.0 : 1.0;

  // no gravity torque: uniform rotation about the pivot
  if (g == 0.0 || d_m_ == 0.0) {
    regime_ = phi_rate0_radps_ == 0.0 ? PendulumRegime::rest : PendulumRegime::spin;
    return;
  }
  omega0_ = std::sqrt(mass_kg_ * g * d_m_ / inertia_pivot_);
  const double half_sin = std::sin(0.5 * phi0_rad_);
  const double rate_term = phi_rate0_radps_ / (2.0 * omega0_);
  k_ = std::sqrt(half_sin * half_sin + rate_term * rate_term);
  if (k_ == 0.0) {
    regime_ = PendulumRegime::rest;
  } else if (k_ < 1.0) {
    regime_ = PendulumRegime::libration;
    const double s0 = std::clamp(half_sin / k_, -1.0, 1.0);
    // at a turning point u0 = +-K exactly
    arg0_ = std::abs(s0) == 1.0 ? s0 * complete_elliptic_k(k_ * k_)
                                : elliptic_f(std::asin(s0), k_ * k_);
  } else if (k_ == 1.0) {
    regime_ = PendulumRegime::separatrix;
    arg0_ = std::atanh(std::clamp(half_sin, -1.0, 1.0));  // F(phi | 1) = atanh(sin phi)
  } else {
    regime_ = PendulumRegime::rotation;
    arg0_ = elliptic_f(0.5 * phi0_rad_, 1.0 / (k_ * k_));
  }
}

void CompoundPendulum::arm_angle(double t_s, double& phi_rad, double& phi_rate_radps) const {
  switch (regime_) {
    case PendulumRegime::rest:
      phi_rad = phi0_rad_;
      phi_rate_radps = 0.0;
      return;
    case PendulumRegime::spin:
      phi_rad = phi0_rad_ + phi_rate0_radps_ * t_s;
      phi_rate_radps = phi_rate0_radps_;
      return;
    case PendulumRegime::libration:
    case PendulumRegime::separatrix: {
      const JacobiValues j =
          jacobi_elliptic(arg0_ + direction_ * omega0_ * t_s, k_ >= 1.0 ? 1.0 : k_ * k_);
      phi_rad = 2.0 * std::asin(k_ * j.sn);
      phi_rate_radps = 2.0 * k_ * omega0_ * direction_ * j.cn;
      return;
    }
    case PendulumRegime::rotation: {
      const JacobiValues j =
          jacobi_elliptic(arg0_ + direction_ * k_ * omega0_ * t_s, 1.0 / (k_ * k_));
      phi_rad = 2.0 * j.am;
      phi_rate_radps = 2.0 * k_ * omega0_ * direction_ * j.dn;
      return;
    }
  }
}

BodyState CompoundPendulum::state_at(double t_s) const {
  BodyState s;
  if (regime_ == PendulumRegime::rest) {
    s.position_m = centre0_m_;
    s.angle_rad = angle0_rad_;
    return s;
  }
  double phi = 0.0;
  double rate = 0.0;
  arm_angle(t_s, phi, rate);
  const Vec2 radial = std::cos(phi) * down_ + std::sin(phi) * across_;
  const Vec2 tangential = -std::sin(phi) * down_ + std::cos(phi) * across_;
  s.position_m = pivot_m_ + d_m_ * radial;
  s.velocity_mps = d_m_ * rate * tangential;
  s.angle_rad = angle0_rad_ + (phi - phi0_rad_);
  s.angular_velocity_radps = rate;
  return s;
}

double CompoundPendulum::time_scale_s() const {
  constexpr double inf = std::numeric_limits<double>::infinity();
  switch (regime_) {
    case PendulumRegime::rest:
      return inf;
    case PendulumRegime::spin:
      return std::numbers::pi / std::abs(phi_rate0_radps_);
    case PendulumRegime::libration:
      return complete_elliptic_k(k_ * k_) / omega0_;
    case PendulumRegime::separatrix:
      return 1.0 / omega0_;
    case PendulumRegime::rotation:
      return complete_elliptic_k(1.0 / (k_ * k_)) / (k_ * omega0_);
  }
  return inf;
}

double CompoundPendulum::period_s() const {
  constexpr double inf = std::numeric_limits<double>::infinity();
  switch (regime_) {
    case PendulumRegime::libration:
      return 4.0 * complete_elliptic_k(k_ * k_) / omega0_;
    case PendulumRegime::rotation:
      return 2.0 * complete_elliptic_k(1.0 / (k_ * k_)) / (k_ * omega0_);
    case PendulumRegime::spin:
      return 2.0 * std::numbers::pi / std::abs(phi_rate0_radps_);
    default:
      return inf;
  }
}

nlohmann::json CompoundPendulum::describe() const {
  nlohmann::json j;
  j["regime"] = pendulum_regime_name(regime_);
  j["pivot_m"] = {pivot_m_.x(), pivot_m_.y()};
  j["pivot_distance_m"] = d_m_;
  j["inertia_about_pivot_kgm2"] = inertia_pivot_;
  if (d_m_ > 0.0) j["equivalent_length_m"] = inertia_pivot_ / (mass_kg_ * d_m_);
  j["natural_frequency_radps"] = omega0_;
  j["modulus_k"] = k_;
  j["initial_arm_angle_rad"] = phi0_rad_;
  if (regime_ == PendulumRegime::libration || regime_ == PendulumRegime::rotation ||
      regime_ == PendulumRegime::spin) {
    j["period_s"] = period_s();
  }
  return j;
}

}  // namespace pb::internal
