// Evaluation of the case's contact force laws (paper §2.1.2, eqs. 1-7).
// Shared by the reference solver, the analytic truth and the adapters' force
// injection mode, so that every one of them applies the same law.
#pragma once

#include "planarbench/case.hpp"

namespace pb {

// Normal contact force, N, never negative (a contact never pulls).
//   delta_m                 penetration, m (<= 0: no contact, force 0)
//   delta_dot_mps           penetration rate, m/s (> 0 while approaching)
//   approach_speed_mps      delta_dot at the onset of this contact (latched),
//                           used by Lankarani-Nikravesh only; must be > 0 there
// Kelvin-Voigt (eq. 1) with the optional cubic damping ramp over damping_depth_m;
// Hertz F = K delta^n; Lankarani-Nikravesh (eq. 7)
// F = K delta^n [1 + 3(1 - e^2)/4 * delta_dot / approach_speed].
[[nodiscard]] double contact_force_n(const ContactLaw& law, double delta_m, double delta_dot_mps,
                                     double approach_speed_mps);

// A law at one instant as a linear spring-damper: the stiffness k and damping
// c with k delta + c delta_dot = the law's unclamped force at (delta,
// delta_dot), for engines whose contact is a linear spring-damper that may be
// set anew each step (MuJoCo's solref, ODE's ERP/CFM):
//   Kelvin-Voigt (eq. 1)        k = K, c = c (times the ramp's cubic step at delta)
//   Hertz (eq. 2)               k = K delta^(n-1) (the secant), c = 0
//   Lankarani-Nikravesh (eq. 7) k = K delta^(n-1), c = K delta^n 3 (1 - e^2) / 4 / approach
// (the damping coefficient of eq. 7 at this delta; 0 before an approach speed
// is latched). delta <= 0 gives k = c = 0.
struct LinearizedLaw {
  double stiffness_n_per_m = 0.0;  // N/m
  double damping_ns_per_m = 0.0;   // N s/m
};
[[nodiscard]] LinearizedLaw linearize_law(const ContactLaw& law, double delta_m,
                                          double approach_speed_mps);

// chi of F = K delta^n [1 + chi delta_dot / delta_dot_minus]: the law's
// damping_factor when set, else eq. 7's 3 (1 - e^2) / 4
[[nodiscard]] double damping_factor(const LankaraniNikravesh& law);

// The cubic step of MSC ADAMS IMPACT: 0 at x <= 0, 1 at x >= 1,
// 3x^2 - 2x^3 between (smooth in value and slope).
[[nodiscard]] double cubic_step(double x);

}  // namespace pb
