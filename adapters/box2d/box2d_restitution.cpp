#include "box2d_restitution.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <variant>

#include "planarbench/contact_law_response.hpp"

namespace pb::internal::box2d {

namespace {
bool closed_form(const ContactLaw& law) {
  const auto* kv = std::get_if<KelvinVoigt>(&law);
  return kv != nullptr && kv->damping_depth_m == 0.0;
}
}  // namespace

double overdamped_kv_restitution(double stiffness_n_per_m, double damping_ns_per_m,
                                 double mass_kg) {
  const double zeta = damping_ns_per_m / (2.0 * std::sqrt(stiffness_n_per_m * mass_kg));
  if (zeta == 1.0) return std::exp(-2.0);  // the limit of both branches
  const double s = std::sqrt(zeta * zeta - 1.0);
  const double x = (zeta + s) / (zeta - s);  // > 1
  return (std::pow(x, (s - zeta) / s) - std::pow(x, -(s + zeta) / s)) / (4.0 * zeta * s);
}

double law_restitution(const ContactLaw& law, double m_eff_kg, double v_approach_mps) {
  const double v = std::max(v_approach_mps, kMinApproachSpeed_mps);
  if (closed_form(law)) {
    const auto& kv = std::get<KelvinVoigt>(law);
    // kelvin_voigt_response integrates an overdamped contact (20000 RK4
    // steps, ~2 ms: a fifth of a brick pyramid's run, its resting contacts
    // re-touching every few steps at zeta 1.4-1.8); its closed form is exact
    const double zeta = kv.damping_ns_per_m / (2.0 * std::sqrt(kv.stiffness_n_per_m * m_eff_kg));
    if (!(zeta < 1.0)) {
      return overdamped_kv_restitution(kv.stiffness_n_per_m, kv.damping_ns_per_m, m_eff_kg);
    }
    return kelvin_voigt_response(kv.stiffness_n_per_m, kv.damping_ns_per_m, m_eff_kg, v)
        .restitution;
  }
  return simulate_collision(law, m_eff_kg, v).restitution;
}

std::string law_restitution_method(const ContactLaw& law) {
  if (closed_form(law)) {
    return "clamped Kelvin-Voigt closed form, no gravity, zeta = c / (2 sqrt(k m_eff)): "
           "kelvin_voigt_response's e = exp(-zeta (pi - 2 asin zeta) / sqrt(1 - zeta^2)) for "
           "zeta < 1; overdamped_kv_restitution's e = (x^((s - zeta)/s) - x^(-(s + zeta)/s)) / "
           "(4 zeta s), s = sqrt(zeta^2 - 1), x = (zeta + s) / (zeta - s), for zeta >= 1 "
           "(e^-2 at zeta = 1)";
  }
  return "simulate_collision: the restitution the law really produces in one collision of m_eff "
         "against a fixed surface at the approach speed (RK4, no gravity)";
}

double elastic_contact_duration_s(const ContactLaw& law, double m_eff_kg, double v_approach_mps) {
  double stiffness = 0.0;  // N/m^n
  double n = 1.0;
  if (const auto* kv = std::get_if<KelvinVoigt>(&law)) {
    stiffness = kv->stiffness_n_per_m;
  } else if (const auto* hz = std::get_if<Hertz>(&law)) {
    stiffness = hz->stiffness;
    n = hz->exponent;
  } else {
    const auto& ln = std::get<LankaraniNikravesh>(law);
    stiffness = ln.stiffness;
    n = ln.exponent;
  }
  const double v = std::max(v_approach_mps, kMinApproachSpeed_mps);
  const double delta_max =
      std::pow((n + 1.0) * m_eff_kg * v * v / (2.0 * stiffness), 1.0 / (n + 1.0));
  const double c_n = 2.0 * std::sqrt(std::numbers::pi) * std::tgamma(1.0 + 1.0 / (n + 1.0)) /
                     std::tgamma(0.5 + 1.0 / (n + 1.0));
  return c_n * delta_max / v;
}

bool restitution_depends_on_state(const ContactLaw& law) {
  return std::holds_alternative<KelvinVoigt>(law);
}

}  // namespace pb::internal::box2d
