// The contact law without its clamp at zero: the force a contact would exert
// if it could pull. The reference solver integrates the pressing phase of a
// contact with it, so that the right-hand side is smooth inside that phase,
// and locates the clamp (this value crossing zero) as an event.
//
// For delta > 0 it comes from the shared contact_force_n itself: every law of
// paper eqs. 1-7 is affine in delta_dot, F = A(delta) + B(delta) delta_dot, and
// contact_force_n clamps only the sum, so A = F(delta, 0) and B follows from a
// probe at delta_dot = +1 m/s (or -1 m/s when B < 0) that is not clamped.
// For delta <= 0 (reached only by trial stages just past an event) the law is
// continued smoothly: Kelvin-Voigt K delta + c delta_dot (with the damping ramp
// K delta), Hertz and Lankarani-Nikravesh 0.
#pragma once

#include "planarbench/case.hpp"

namespace pb {

// N; delta_m penetration (m), delta_dot_mps its rate (m/s, > 0 approaching),
// approach_speed_mps the latched onset speed (Lankarani-Nikravesh)
[[nodiscard]] double unclamped_force_n(const ContactLaw& law, double delta_m, double delta_dot_mps,
                                       double approach_speed_mps);

// N s/m: B of F = A + B delta_dot at penetration delta_m > 0, the law's
// damping coefficient there (Kelvin-Voigt c, or c ramped by depth;
// Lankarani-Nikravesh K delta^n 3 (1 - e^2) / (4 delta_dot^-)); every law of
// the case format is affine in delta_dot
[[nodiscard]] double law_damping_ns_per_m(const ContactLaw& law, double delta_m,
                                          double approach_speed_mps);

}  // namespace pb
