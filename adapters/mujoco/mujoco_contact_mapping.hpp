// The case's contact law as MuJoCo's soft contact: a linear spring-damper in
// the direct solref form (-k/m_eff, -c/m_eff). MuJoCo's reference acceleration
// is a_ref = -b v - k r in constraint space (ENGINES.md; engine_core_constraint.c
// mj_makeImpedance: K = -solref[0]/dmax^2, B = -solref[1]/dmax, a_ref = -B v -
// K d r), and with d = dmax near 1 the constraint follows a_ref, so a force law
// in N/m needs k and c divided by the effective mass along the normal.
#pragma once

#include <array>
#include <nlohmann/json.hpp>
#include <string>

#include "planarbench/case.hpp"

namespace pb::internal::mujoco {

// Where the effective mass and the approach speed of a pair were taken.
struct Calibration {
  double effective_mass_kg = 0.0;   // kg, 1 / (J M^-1 J^T) along the contact normal
  double approach_speed_mps = 0.0;  // m/s, normal approach speed at first touch (0: at rest)
  std::string source;               // e.g. "contact-free probe at first touch, t = 0.725 s"
};

struct LawMapping {
  double stiffness_n_per_m = 0.0;             // N/m, the linear spring MuJoCo gets
  double damping_ns_per_m = 0.0;              // N s/m, the linear damper MuJoCo gets
  std::array<double, 2> solref = {0.0, 0.0};  // (-k/m_eff, -c/m_eff), 1/s^2 and 1/s
  bool exact = false;                         // true for plain Kelvin-Voigt (linear law, no ramp)
  double force_duration_s = 0.0;              // s, force phase of one impact of (k, c) on m_eff
  // what the law became, the numbers, what was lost
  nlohmann::json json = nlohmann::json::object();
};

// Approach speed assumed for a nonlinear law whose pair starts at rest in
// contact (no impact to calibrate on), m/s.
inline constexpr double kFallbackApproachSpeedMps = 1.0;

// Kelvin-Voigt without ramp -> (k, c) exactly. Kelvin-Voigt with a damping
// ramp, Hertz and Lankarani-Nikravesh -> the linear spring-damper whose
// clamped collision has the same force duration and restitution as the law's
// own collision at (m_eff, v_approach) (simulate_collision, linear_equivalent);
// Hertz is elastic, so c = 0 and k = m_eff (pi / duration)^2.
[[nodiscard]] LawMapping map_contact_law(const ContactLaw& law, const Calibration& cal);

}  // namespace pb::internal::mujoco
