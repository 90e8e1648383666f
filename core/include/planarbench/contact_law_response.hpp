// What a contact law does in one collision of a point mass m against a fixed
// surface without gravity: restitution, duration, peak force. Adapters use it
// to map a compliant law onto engines that cannot express it (Box2D's rigid
// restitution, a linear spring-damper equivalent of Lankarani-Nikravesh).
#pragma once

#include <nlohmann/json.hpp>

#include "planarbench/case.hpp"

namespace pb {

struct CollisionResponse {
  double restitution = 0.0;        // separation speed / approach speed
  double force_duration_s = 0.0;   // s, force > 0 (until the clamp releases)
  double duration_s = 0.0;         // s, penetration > 0 (force phase + free flight out)
  double peak_force_n = 0.0;       // N
  double max_penetration_m = 0.0;  // m
  double impulse_ns = 0.0;         // N s
};

// the response as the adapters' mappings record it (restitution, force and
// contact duration, peak force, peak penetration, impulse)
[[nodiscard]] nlohmann::json to_json(const CollisionResponse& r);

// Clamped Kelvin-Voigt oscillator, closed form (no ramp): with
// zeta = c / (2 sqrt(k m)) < 1, omega_d = sqrt(k/m) sqrt(1 - zeta^2):
// e = exp(-zeta (pi - 2 asin zeta) / sqrt(1 - zeta^2)),
// force_duration = (pi - 2 asin zeta) / omega_d (ENGINES.md).
// (The clamp ends the force when k delta + c delta_dot = 0, before delta = 0;
// the mass then flies free until delta = 0, which adds time.)
[[nodiscard]] CollisionResponse kelvin_voigt_response(double stiffness_n_per_m,
                                                      double damping_ns_per_m, double mass_kg,
                                                      double approach_speed_mps);

// Any law (Lankarani-Nikravesh, Hertz, Kelvin-Voigt with ramp): integrated
// numerically with a fixed-step RK4 of 20000 steps over the contact, enough
// for 1e-8 relative accuracy on the figures above.
[[nodiscard]] CollisionResponse simulate_collision(const ContactLaw& law, double mass_kg,
                                                   double approach_speed_mps);

// The linear spring-damper (k, c) whose clamped collision matches the given
// force_duration_s and restitution for mass m: zeta from e by root finding on
// kelvin_voigt_response, then k from the duration.
struct LinearEquivalent {
  double stiffness_n_per_m = 0.0;  // N/m
  double damping_ns_per_m = 0.0;   // N s/m
};
[[nodiscard]] LinearEquivalent linear_equivalent(const CollisionResponse& target, double mass_kg);

}  // namespace pb
