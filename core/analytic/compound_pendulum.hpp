// The exact large-amplitude compound pendulum: a rigid body turning about a
// fixed pivot under gravity alone, in closed form with Jacobi elliptic
// functions (e.g. Lawden, Elliptic Functions and Applications, §5.2;
// DLMF 22.19.2). phi is the angle of the pivot -> centre line from the
// direction of gravity, counter-clockwise; with d the pivot distance,
// I_p = I_c + m d^2 and w0^2 = m |g| d / I_p, phi'' = -w0^2 sin phi.
// With k^2 = sin^2(phi0/2) + (phi0' / (2 w0))^2:
//   k < 1  (libration)  sin(phi/2) = k sn(u0 + s w0 t | k^2),  phi' = 2 k w0 s cn(...)
//   k = 1  (separatrix) the same with sn = tanh, cn = sech
//   k > 1  (rotation)   phi/2 = am(v0 + s k w0 t | 1/k^2),   phi' = 2 k w0 s dn(...)
// s = sign of phi0' (+1 at rest); u0 = F(asin(sin(phi0/2)/k) | k), v0 = F(phi0/2 | 1/k)
// (incomplete elliptic integral of the first kind, jacobi_elliptic.hpp).
// The body turns with its arm: body angle = angle0 + phi - phi0.
#pragma once

#include <nlohmann/json.hpp>

#include "planarbench/case.hpp"
#include "planarbench/engine.hpp"

namespace pb::internal {

enum class PendulumRegime {
  rest,        // hanging at rest at the stable equilibrium: stays put
  spin,        // no gravity torque (pivot at the centre, or g = 0): uniform rotation
  libration,   // k < 1
  separatrix,  // k = 1
  rotation,    // k > 1, goes over the top
};

[[nodiscard]] const char* pendulum_regime_name(PendulumRegime r);

class CompoundPendulum {
 public:
  // body: mass, inertia about its centre, initial pose and angular velocity;
  // its centre's velocity is taken as the joint allows (omega x arm)
  CompoundPendulum(const Vec2& pivot_m, const Body& body, const Vec2& gravity_mps2);

  [[nodiscard]] BodyState state_at(double t_s) const;
  // arm angle phi, rad, and its rate, rad/s, at t_s
  void arm_angle(double t_s, double& phi_rad, double& phi_rate_radps) const;

  [[nodiscard]] PendulumRegime regime() const { return regime_; }
  [[nodiscard]] double modulus() const { return k_; }                       // k
  [[nodiscard]] double natural_frequency_radps() const { return omega0_; }  // w0
  [[nodiscard]] double pivot_distance_m() const { return d_m_; }            // d
  [[nodiscard]] double initial_arm_angle_rad() const { return phi0_rad_; }  // phi0
  // the time of one swing from a turning point to the bottom (libration),
  // of a half turn (rotation, spin), 1/w0 (separatrix); +inf at rest, s
  [[nodiscard]] double time_scale_s() const;
  // full period of phi (libration: 4 K(k) / w0; rotation: one turn), s; +inf otherwise
  [[nodiscard]] double period_s() const;
  [[nodiscard]] nlohmann::json describe() const;

 private:
  PendulumRegime regime_ = PendulumRegime::rest;
  Vec2 pivot_m_;
  Vec2 down_;       // unit vector along gravity
  Vec2 across_;     // down_ turned by +90 degrees
  Vec2 centre0_m_;  // m
  double angle0_rad_ = 0.0;
  double d_m_ = 0.0;            // m, pivot distance
  double inertia_pivot_ = 0.0;  // kg m^2
  double mass_kg_ = 0.0;
  double omega0_ = 0.0;           // rad/s
  double k_ = 0.0;                // modulus
  double phi0_rad_ = 0.0;         // rad
  double phi_rate0_radps_ = 0.0;  // rad/s
  double direction_ = 1.0;        // s
  double arg0_ = 0.0;             // u0 or v0
};

}  // namespace pb::internal
