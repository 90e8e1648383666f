#include "tangential_motion.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "planarbench/errors.hpp"
#include "root_finding.hpp"

namespace pb::internal {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// m/s: a slip speed this small at a phase change counts as none (the events
// are bisected to the last bit, leaving ~1e-16 m/s; a point this fast moves
// 1e-13 m in one 1e-4 s output interval)
constexpr double kNoSlipMps = 1e-9;
// a guard against an endless chatter of zero-length phases, not a physical limit
constexpr std::size_t kMaxPhases = 100000;

const char* kind_name(TangentialPhaseKind k) {
  switch (k) {
    case TangentialPhaseKind::flight: return "flight";
    case TangentialPhaseKind::slip: return "slip";
    case TangentialPhaseKind::stick: return "stick";
  }
  return "?";
}

}  // namespace

TangentialMotion::TangentialMotion(const TangentialParams& p, const NormalContactMotion& normal)
    : p_(p), normal_(normal) {
  // 1 / m_t = 1 / m + R^2 / I: the contact point's inverse mass along t
  m_t_ = p_.rotates ? 1.0 / (1.0 / p_.mass_kg + p_.radius_m * p_.radius_m / p_.inertia_kgm2)
                    : p_.mass_kg;
  // a tenth of 1 / omega_0: the normal force turns by 0.1 rad of its
  // oscillation between samples, so a sign change of an event function
  // that follows it is bracketed unless it lasts less than that
  scan_step_s_ = 0.1 / std::sqrt(normal_.omega0_sq_per_s2());
  TangentialState s0;
  s0.along_m = p_.along0_m;
  s0.along_rate_mps = p_.along_rate0_mps;
  s0.angle_rad = p_.angle0_rad;
  s0.spin_radps = p_.spin0_radps;
  s0.slip_rate_mps = p_.along_rate0_mps + (p_.rotates ? p_.spin0_radps * p_.radius_m : 0.0);
  phases_.push_back(begin_phase(0.0, s0));
}

double TangentialMotion::phi_ns(double t_s) const {
  const NormalState s = normal_.state_at(t_s);
  const NormalContactParams& q = normal_.params();
  return q.mass_kg * (s.gap_rate_mps - q.gap_rate0_mps) - q.mass_kg * q.normal_gravity_mps2 * t_s;
}

double TangentialMotion::psi_ns2(double t_s) const {
  const NormalState s = normal_.state_at(t_s);
  const NormalContactParams& q = normal_.params();
  return q.mass_kg * (s.gap_m - q.gap0_m - q.gap_rate0_mps * t_s -
                      0.5 * q.normal_gravity_mps2 * t_s * t_s);
}

TangentialState TangentialMotion::state_in(const TangentialPhase& ph, double t_s) const {
  const double tau = t_s - ph.start_s;
  const double m = p_.mass_kg;
  const double r = p_.rotates ? p_.radius_m : 0.0;
  const double g_t = p_.tangential_gravity_mps2;
  TangentialState s;
  switch (ph.kind) {
    case TangentialPhaseKind::flight:
      s.along_rate_mps = ph.along_rate0_mps + g_t * tau;
      s.along_m = ph.along0_m + tau * (ph.along_rate0_mps + 0.5 * g_t * tau);
      s.spin_radps = ph.spin0_radps;
      s.angle_rad = ph.angle0_rad + ph.spin0_radps * tau;
      break;
    case TangentialPhaseKind::slip: {
      const double k = p_.friction * ph.slip_sign;
      const double d_phi = phi_ns(t_s) - ph.phi0_ns;
      const double d_psi = psi_ns2(t_s) - ph.psi0_ns2 - ph.phi0_ns * tau;
      s.along_rate_mps = ph.along_rate0_mps + g_t * tau - k * d_phi / m;
      s.along_m = ph.along0_m + tau * (ph.along_rate0_mps + 0.5 * g_t * tau) - k * d_psi / m;
      s.spin_radps = ph.spin0_radps;
      s.angle_rad = ph.angle0_rad + ph.spin0_radps * tau;
      if (p_.rotates) {
        s.spin_radps -= r * k * d_phi / p_.inertia_kgm2;
        s.angle_rad -= r * k * d_psi / p_.inertia_kgm2;
      }
      s.friction_n = -k * normal_.state_at(t_s).force_n;
      break;
    }
    case TangentialPhaseKind::stick: {
      s.friction_n = -m_t_ * g_t;
      const double a = g_t + s.friction_n / m;
      const double alpha = p_.rotates ? r * s.friction_n / p_.inertia_kgm2 : 0.0;
      s.along_rate_mps = ph.along_rate0_mps + a * tau;
      s.along_m = ph.along0_m + tau * (ph.along_rate0_mps + 0.5 * a * tau);
      s.spin_radps = ph.spin0_radps + alpha * tau;
      s.angle_rad = ph.angle0_rad + tau * (ph.spin0_radps + 0.5 * alpha * tau);
      break;
    }
  }
  s.slip_rate_mps = s.along_rate_mps + s.spin_radps * r;
  return s;
}

TangentialPhase TangentialMotion::begin_phase(double t_s, const TangentialState& s) const {
  TangentialPhase ph;
  ph.start_s = t_s;
  ph.end_s = kInf;
  ph.along0_m = s.along_m;
  ph.along_rate0_mps = s.along_rate_mps;
  ph.angle0_rad = s.angle_rad;
  ph.spin0_radps = s.spin_radps;
  const NormalState n = normal_.state_at(t_s);
  if (n.kind != NormalPhaseKind::pressed) {
    ph.kind = TangentialPhaseKind::flight;
    return ph;
  }
  ph.phi0_ns = phi_ns(t_s);
  ph.psi0_ns2 = psi_ns2(t_s);
  const double load = m_t_ * p_.tangential_gravity_mps2;  // N, the force stick needs, negated
  const bool holds = std::abs(load) <= p_.friction * n.force_n;
  if (std::abs(s.slip_rate_mps) <= kNoSlipMps && holds) {
    ph.kind = TangentialPhaseKind::stick;
    return ph;
  }
  ph.kind = TangentialPhaseKind::slip;
  if (std::abs(s.slip_rate_mps) > kNoSlipMps) {
    ph.slip_sign = s.slip_rate_mps > 0.0 ? 1.0 : -1.0;
  } else {
    ph.slip_sign = p_.tangential_gravity_mps2 > 0.0 ? 1.0 : -1.0;
  }
  return ph;
}

double TangentialMotion::next_event(const TangentialPhase& ph, double from_s,
                                    double until_s) const {
  // the event function, < 0 once the phase must end
  auto g = [&](double t) {
    if (ph.kind == TangentialPhaseKind::slip) return ph.slip_sign * state_in(ph, t).slip_rate_mps;
    return p_.friction * normal_.state_at(t).force_n - std::abs(m_t_ * p_.tangential_gravity_mps2);
  };
  if (ph.kind == TangentialPhaseKind::flight || !(until_s > from_s)) return kInf;
  double t_a = from_s;
  bool out_a = g(t_a) < 0.0;
  while (t_a < until_s) {
    const double t_b = std::min(until_s, t_a + scan_step_s_);
    const bool out_b = g(t_b) < 0.0;
    if (out_b && !out_a) {
      return first_true_by_bisection([&](double t) { return g(t) < 0.0; }, t_a, t_b);
    }
    t_a = t_b;
    out_a = out_b;
  }
  return kInf;
}

void TangentialMotion::extend_to(double t_s) {
  while (true) {
    if (phases_.size() > kMaxPhases) {
      throw EngineError(fmt::format(
          "analytic: more than {} stick / slip phases by t = {:.6g} s: a chatter the closed "
          "form does not resolve",
          kMaxPhases, phases_.back().start_s));
    }
    TangentialPhase& ph = phases_.back();
    if (std::isfinite(ph.end_s)) {
      const TangentialState s = state_in(ph, ph.end_s);
      phases_.push_back(begin_phase(ph.end_s, s));
      searched_until_s_ = phases_.back().start_s;
      continue;
    }
    if (searched_until_s_ >= t_s) return;
    // the normal phase holding the start bounds this phase
    const auto& np = normal_.phases()[normal_.phase_index_at(ph.start_s)];
    const double limit = std::min(t_s, np.end_s);
    const double from = std::max(ph.start_s, searched_until_s_);
    const double ev = next_event(ph, from, limit);
    if (std::isfinite(ev)) {
      ph.end_s = ev;
    } else if (np.end_s <= t_s) {
      ph.end_s = np.end_s;
    } else {
      searched_until_s_ = t_s;
      return;
    }
  }
}

TangentialState TangentialMotion::state_at(double t_s) const {
  const auto it = std::upper_bound(phases_.begin(), phases_.end(), t_s,
                                   [](double t, const TangentialPhase& ph) { return t < ph.start_s; });
  const TangentialPhase& ph = it == phases_.begin() ? phases_.front() : *(it - 1);
  return state_in(ph, t_s);
}

long TangentialMotion::phases_begun(double t_s) const {
  long n = 0;
  for (const auto& ph : phases_) n += ph.start_s <= t_s ? 1 : 0;
  return n;
}

nlohmann::json TangentialMotion::mapping() const {
  nlohmann::json j;
  j["description"] =
      "Coulomb friction at the contact point (SPEC §7), rigid stick: slip f = -mu F(t) s with "
      "F(t) the closed-form normal force; stick f = -m_t g_t while |m_t g_t| <= mu F(t); events "
      "bisected to the last bit after a scan in steps of 0.1 / omega_0";
  j["friction"] = p_.friction;
  j["tangential_gravity_mps2"] = p_.tangential_gravity_mps2;
  j["contact_radius_m"] = p_.rotates ? p_.radius_m : 0.0;
  j["tangential_mass_kg"] = m_t_;
  j["stick_acceleration_mps2"] =
      p_.tangential_gravity_mps2 * (1.0 - m_t_ / p_.mass_kg);
  j["scan_step_s"] = scan_step_s_;
  nlohmann::json phases = nlohmann::json::array();
  for (const auto& ph : phases_) {
    nlohmann::json x = {{"kind", kind_name(ph.kind)}, {"start_s", ph.start_s}};
    x["end_s"] = std::isfinite(ph.end_s) ? nlohmann::json(ph.end_s) : nlohmann::json(nullptr);
    if (ph.kind == TangentialPhaseKind::slip) x["slip_sign"] = ph.slip_sign;
    x["along_rate0_mps"] = ph.along_rate0_mps;
    x["spin0_radps"] = ph.spin0_radps;
    phases.push_back(x);
  }
  j["phases"] = phases;
  return j;
}

}  // namespace pb::internal
