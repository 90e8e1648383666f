#include "mujoco_contact_mapping.hpp"

#include <cmath>
#include <numbers>
#include <variant>

#include "planarbench/contact_law_response.hpp"

namespace pb::internal::mujoco {

namespace {

nlohmann::json law_parameters(const ContactLaw& law) {
  if (const auto* kv = std::get_if<KelvinVoigt>(&law)) {
    return {{"stiffness_n_per_m", kv->stiffness_n_per_m},
            {"damping_ns_per_m", kv->damping_ns_per_m},
            {"damping_depth_m", kv->damping_depth_m}};
  }
  if (const auto* hz = std::get_if<Hertz>(&law)) {
    return {{"stiffness", hz->stiffness}, {"exponent", hz->exponent}};
  }
  const auto& ln = std::get<LankaraniNikravesh>(law);
  nlohmann::json j = {{"stiffness", ln.stiffness}, {"exponent", ln.exponent}, {"restitution", ln.restitution}};
  if (ln.damping_factor) j["damping_factor"] = *ln.damping_factor;  // issue 34's laws only
  return j;
}

// the linear (k, c) whose clamped collision matches `target` for mass m
LinearEquivalent matched_linear(const CollisionResponse& target, double m) {
  // an elastic law (Hertz) has e = 1: no damper, and half a period of
  // sqrt(k/m) lasts the force duration
  if (target.restitution >= 1.0 - 1e-9) {
    const double omega = std::numbers::pi / target.force_duration_s;  // rad/s
    return {m * omega * omega, 0.0};
  }
  return linear_equivalent(target, m);
}

}  // namespace

LawMapping map_contact_law(const ContactLaw& law, const Calibration& cal) {
  LawMapping out;
  const double m = cal.effective_mass_kg;
  nlohmann::json j;
  j["law"] = contact_law_name(law);
  j["law_parameters"] = law_parameters(law);
  j["effective_mass_kg"] = m;
  j["effective_mass_from"] = cal.source;
  nlohmann::json lost = nlohmann::json::array();

  const auto* kv = std::get_if<KelvinVoigt>(&law);
  if (kv && kv->damping_depth_m <= 0.0) {
    // linear law: expressed exactly (up to the impedance, see the engine's notes)
    out.stiffness_n_per_m = kv->stiffness_n_per_m;
    out.damping_ns_per_m = kv->damping_ns_per_m;
    out.exact = true;
    j["expressed_as"] = "Kelvin-Voigt as MuJoCo's direct solref (-k/m_eff, -c/m_eff)";
  } else {
    // a nonlinear law: calibrated on one collision at the expected approach speed
    double v = cal.approach_speed_mps;
    if (!(v > 0.0)) {
      v = kFallbackApproachSpeedMps;
      lost.push_back(
          "the pair starts at rest in contact: no impact to calibrate on, the linear "
          "equivalent assumes an approach speed of 1 m/s");
    }
    const CollisionResponse target = simulate_collision(law, m, v);
    const LinearEquivalent eq = matched_linear(target, m);
    out.stiffness_n_per_m = eq.stiffness_n_per_m;
    out.damping_ns_per_m = eq.damping_ns_per_m;
    j["expressed_as"] =
        "linear spring-damper with the law's force duration and effective restitution at "
        "(m_eff, approach speed), as MuJoCo's direct solref (-k/m_eff, -c/m_eff)";
    j["approach_speed_mps"] = v;
    j["law_response"] = to_json(target);
    j["linear_response"] =
        to_json(kelvin_voigt_response(eq.stiffness_n_per_m, eq.damping_ns_per_m, m, v));
    if (kv) {
      lost.push_back(
          "the cubic damping ramp over damping_depth (MuJoCo's damping is linear in the "
          "penetration rate from first touch)");
    } else {
      lost.push_back(
          "the nonlinearity F ~ delta^n: a linear spring matches force duration and "
          "restitution of one impact at the calibration speed; peak force and peak "
          "penetration differ (law_response vs linear_response), other speeds differ more");
    }
    if (std::holds_alternative<LankaraniNikravesh>(law)) {
      lost.push_back(
          "the hysteresis damping scaled by the latched approach speed: the linear damper's "
          "restitution is the law's effective one at the calibration speed only");
    }
  }
  out.solref = {-out.stiffness_n_per_m / m, -out.damping_ns_per_m / m};
  // the force phase of one impact of the linear law (independent of the speed)
  out.force_duration_s =
      kelvin_voigt_response(out.stiffness_n_per_m, out.damping_ns_per_m, m, 1.0).force_duration_s;
  j["linear_force_duration_s"] = out.force_duration_s;
  j["stiffness_n_per_m"] = out.stiffness_n_per_m;
  j["damping_ns_per_m"] = out.damping_ns_per_m;
  j["solref"] = {out.solref[0], out.solref[1]};
  j["not_expressed"] = lost;
  out.json = std::move(j);
  return out;
}

}  // namespace pb::internal::mujoco
