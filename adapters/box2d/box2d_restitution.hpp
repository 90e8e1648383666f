// Box2D is rigid: a compliant contact law is expressed by the restitution it
// produces. This file computes that restitution for a law, an effective mass
// and an approach speed, and the effective mass J M^-1 J^T of a contact.
#pragma once

#include <string>

#include "planarbench/case.hpp"
#include "planarbench/contact_set_mass.hpp"

namespace pb::internal::box2d {

// how a body responds to an impulse: fixed, free, or pinned to the ground by
// one revolute joint (planarbench/contact_set_mass.hpp computes the
// effective mass of one point, 1 / (J M^-1 J^T), and of a set of points)
using BodyInertia = PlanarInertia;

// approach speeds below this are raised to it before the law is evaluated, m/s
// (simulate_collision needs v > 0; the restitution of Kelvin-Voigt without
// ramp, Hertz and Lankarani-Nikravesh does not depend on v)
constexpr double kMinApproachSpeed_mps = 1e-3;

// The restitution the law produces in one collision of m_eff against a fixed
// surface at approach speed v, without gravity:
//   Kelvin-Voigt without ramp: the closed form of the clamped oscillator
//     (kelvin_voigt_response below zeta = 1, overdamped_kv_restitution from
//     it on; depends on m_eff through zeta = c / (2 sqrt(k m)));
//   everything else: simulate_collision (the restitution the law really
//     produces, e.g. Lankarani-Nikravesh's is not its nominal e).
// No allocation: safe inside Box2D's contact callbacks.
[[nodiscard]] double law_restitution(const ContactLaw& law, double m_eff_kg, double v_approach_mps);

// The clamped Kelvin-Voigt restitution for zeta = c / (2 sqrt(k m)) >= 1, in
// closed form. With omega = sqrt(k/m), s = sqrt(zeta^2 - 1), the penetration
// from delta(0) = 0, delta'(0) = v is delta = v (e^(r1 t) - e^(r2 t)) /
// (2 omega s), r1,2 = omega (-zeta +- s); the clamp releases when
// k delta + c delta' = 0, at omega s t_r = ln x, x = (zeta + s) / (zeta - s),
// where delta' = -(omega / (2 zeta)) delta, and the mass leaves at that speed:
//   e = -delta'(t_r) / v = (x^((s - zeta)/s) - x^(-(s + zeta)/s)) / (4 zeta s),
// independent of v; e^-2 at zeta = 1 (delta = v t e^(-omega t), t_r = 2/omega),
// the limit of the underdamped exp(-zeta (pi - 2 asin zeta) / sqrt(1 - zeta^2)).
[[nodiscard]] double overdamped_kv_restitution(double stiffness_n_per_m, double damping_ns_per_m,
                                               double mass_kg);

// how law_restitution computes the restitution of this law, for the mapping
[[nodiscard]] std::string law_restitution_method(const ContactLaw& law);

// s, the duration of an elastic collision with the law's spring part,
// F = K delta^n (n = 1 for Kelvin-Voigt): with delta_max from the energy
// balance m v^2 / 2 = K delta_max^(n+1) / (n+1), the time in contact is
// c_n delta_max / v, c_n = 2 sqrt(pi) Gamma(1 + 1/(n+1)) / Gamma(1/2 + 1/(n+1))
// (pi for n = 1, i.e. pi sqrt(m/k); 2.943 for Hertz, n = 3/2; Johnson,
// Contact Mechanics, §11.4). Closed form: an estimate of the steps a contact
// takes, safe for any parameters.
[[nodiscard]] double elastic_contact_duration_s(const ContactLaw& law, double m_eff_kg,
                                                double v_approach_mps);

// true when the law's restitution changes with m_eff or v. Hertz and
// Lankarani-Nikravesh do not: with delta = D x, t = (D / v) tau,
// D = (m v^2 / K)^(1/(n+1)), eq. 7 becomes x'' = -x^n (1 + 3 (1 - e^2)/4 x'),
// x'(0) = 1, free of K, m and v.
[[nodiscard]] bool restitution_depends_on_state(const ContactLaw& law);

}  // namespace pb::internal::box2d
