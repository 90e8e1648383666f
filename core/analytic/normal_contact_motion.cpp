#include "normal_contact_motion.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "planarbench/errors.hpp"
#include "root_finding.hpp"

namespace pb::internal {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// more phases than any physical run has (two bounces are 6): a guard against
// an endless chatter of zero-length phases, not a physical limit
constexpr std::size_t kMaxPhases = 100000;

// u = u0 + v0 tau + a tau^2 / 2 and its rate: the free parabola
double parabola_gap(const NormalPhase& ph, double a, double tau) {
  return ph.gap0_m + tau * (ph.gap_rate0_mps + 0.5 * a * tau);
}
double parabola_rate(const NormalPhase& ph, double a, double tau) {
  return ph.gap_rate0_mps + a * tau;
}

}  // namespace

NormalContactMotion::NormalContactMotion(const NormalContactParams& p) : p_(p) {
  // m u'' + c u' + K u = m a  ->  u'' + 2 sigma u' + w0^2 (u - u_eq) = 0
  sigma_ = p_.damping_ns_per_m / (2.0 * p_.mass_kg);
  omega0_sq_ = p_.stiffness_n_per_m / p_.mass_kg;
  gap_eq_m_ = p_.mass_kg * p_.normal_gravity_mps2 / p_.stiffness_n_per_m;

  // the first phase from the initial state: touching (u = 0) counts as contact
  // when the body moves in or, at rest, gravity presses it in
  NormalPhase first;
  first.start_s = 0.0;
  first.end_s = kInf;
  first.gap0_m = p_.gap0_m;
  first.gap_rate0_mps = p_.gap_rate0_mps;
  const double u0 = p_.gap0_m;
  const double v0 = p_.gap_rate0_mps;
  const double a = p_.normal_gravity_mps2;
  const bool in_contact = u0 < 0.0 || (u0 == 0.0 && (v0 < 0.0 || (v0 == 0.0 && a < 0.0)));
  if (!in_contact) {
    first.kind = NormalPhaseKind::separated;
  } else {
    // force now and its rate if pressed (u'' = a + F/m): pressed when it is
    // positive or zero and growing (or, at a standstill, pushed by gravity)
    const double k = p_.stiffness_n_per_m;
    const double c = p_.damping_ns_per_m;
    const double f0 = -k * u0 - c * v0;
    const double f1 = -k * v0 - c * (a + std::max(f0, 0.0) / p_.mass_kg);
    const bool pressed = f0 > 0.0 || (f0 == 0.0 && (f1 > 0.0 || (f1 == 0.0 && a < 0.0)));
    first.kind = pressed ? NormalPhaseKind::pressed : NormalPhaseKind::clamped;
  }
  phases_.push_back(first);
}

DampedMode NormalContactMotion::pressed_mode(const NormalPhase& ph) const {
  return DampedMode(sigma_, omega0_sq_, ph.gap0_m - gap_eq_m_, ph.gap_rate0_mps);
}

DampedMode NormalContactMotion::force_mode(const NormalPhase& ph) const {
  // F - F_eq = -K x - c x' obeys the same equation: its initial value and rate
  // follow from x(0), x'(0) and x''(0) = -2 sigma x'(0) - w0^2 x(0)
  const double k = p_.stiffness_n_per_m;
  const double c = p_.damping_ns_per_m;
  const double x0 = ph.gap0_m - gap_eq_m_;
  const double v0 = ph.gap_rate0_mps;
  const double acc0 = -2.0 * sigma_ * v0 - omega0_sq_ * x0;
  return DampedMode(sigma_, omega0_sq_, -k * x0 - c * v0, -k * v0 - c * acc0);
}

double NormalContactMotion::pressed_force(const DampedMode& x, double tau_s) const {
  // paper eq. 1 with delta = -u: F = K delta + c delta_dot
  return -p_.stiffness_n_per_m * (gap_eq_m_ + x.value(tau_s)) - p_.damping_ns_per_m * x.rate(tau_s);
}

NormalContactMotion::Event NormalContactMotion::next_event(const NormalPhase& ph,
                                                           double tau_max_s) const {
  const double a = p_.normal_gravity_mps2;
  const double k = p_.stiffness_n_per_m;
  const double c = p_.damping_ns_per_m;
  Event ev;
  switch (ph.kind) {
    case NormalPhaseKind::separated: {
      // onset: the parabola reaches u = 0 moving in
      ev.tau_s = first_quadratic_crossing(ph.gap0_m, ph.gap_rate0_mps, 0.5 * a, Crossing::downward);
      ev.next = NormalPhaseKind::pressed;
      ev.final = std::isinf(ev.tau_s);
      return ev;
    }
    case NormalPhaseKind::clamped: {
      // offset (u back to 0) or the force turning positive again; the force
      // -K u - c u' on the parabola is a quadratic in tau as well
      const double t_out =
          first_quadratic_crossing(ph.gap0_m, ph.gap_rate0_mps, 0.5 * a, Crossing::upward);
      const double t_in =
          first_quadratic_crossing(-k * ph.gap0_m - c * ph.gap_rate0_mps,
                                   -k * ph.gap_rate0_mps - c * a, -0.5 * k * a, Crossing::upward);
      ev.tau_s = std::min(t_out, t_in);
      ev.next = t_out <= t_in ? NormalPhaseKind::separated : NormalPhaseKind::pressed;
      ev.final = std::isinf(ev.tau_s);
      return ev;
    }
    case NormalPhaseKind::pressed:
      break;
  }

  // pressed: F = F_eq + y(tau), y a DampedMode of the same equation (a linear
  // combination of x and x'); the clamp is the first downward zero of F
  const DampedMode x = pressed_mode(ph);
  const DampedMode y = force_mode(ph);
  const double f_eq = -k * gap_eq_m_;  // N, the static load -m a

  // no zero is possible once the envelope of y stays below a positive F_eq
  double tau_limit = tau_max_s;
  if (f_eq > 0.0) {
    double tau_bound = kInf;
    if (y.envelope_rate() > 0.0) {
      const double amp = y.envelope_amplitude();
      tau_bound = amp <= f_eq ? 0.0 : std::log(amp / f_eq) / y.envelope_rate();
      tau_bound *= 1.0 + 1e-9;  // margin for the rounding of the bound itself
    } else if (y.damped_frequency() > 0.0) {
      // undamped: periodic, one full period shows every value it takes
      tau_bound = 2.0 * std::numbers::pi / y.damped_frequency();
    }
    if (tau_bound <= tau_limit) {
      tau_limit = tau_bound;
      ev.final = true;
    }
  }

  // monotone segments between the stationary points of y bracket each zero
  double lo = 0.0;
  double f_lo = pressed_force(x, lo);
  for (int i = 0;; ++i) {
    const double hi = std::min(y.stationary_point(i), tau_limit);
    const double f_hi = pressed_force(x, hi);
    if (f_lo > 0.0 && f_hi <= 0.0) {
      ev.tau_s =
          first_true_by_bisection([&](double t) { return pressed_force(x, t) <= 0.0; }, lo, hi);
      // where the force and the gap vanish together (no damping) the body
      // leaves; otherwise it is still inside, the force clamped
      const bool out = p_.damping_ns_per_m == 0.0 || gap_eq_m_ + x.value(ev.tau_s) >= 0.0;
      ev.next = out ? NormalPhaseKind::separated : NormalPhaseKind::clamped;
      ev.final = false;
      return ev;
    }
    if (!(hi < tau_limit)) break;
    lo = hi;
    f_lo = f_hi;
  }
  return ev;
}

NormalPhase NormalContactMotion::successor(const NormalPhase& ph, const Event& ev) const {
  const double a = p_.normal_gravity_mps2;
  const double tau = ev.tau_s;
  NormalPhase next;
  next.kind = ev.next;
  next.start_s = ph.start_s + tau;
  next.end_s = kInf;
  // the state at the event from the closed form of the ending phase
  if (ph.kind == NormalPhaseKind::pressed) {
    const DampedMode x = pressed_mode(ph);
    next.gap0_m = gap_eq_m_ + x.value(tau);
    next.gap_rate0_mps = x.rate(tau);
  } else {
    next.gap0_m = parabola_gap(ph, a, tau);
    next.gap_rate0_mps = parabola_rate(ph, a, tau);
  }
  // onset and offset are at u = 0 exactly, by definition of the event
  if (ph.kind == NormalPhaseKind::separated || next.kind == NormalPhaseKind::separated) {
    next.gap0_m = 0.0;
  }
  return next;
}

void NormalContactMotion::extend_to(double t_s) {
  while (!last_is_final_ && known_until_s_ < t_s) {
    NormalPhase& ph = phases_.back();
    const Event ev = next_event(ph, t_s - ph.start_s);
    if (std::isinf(ev.tau_s)) {
      last_is_final_ = ev.final;
      known_until_s_ = ev.final ? kInf : t_s;
      return;
    }
    if (phases_.size() >= kMaxPhases) {
      throw EngineError(fmt::format(
          "analytic: more than {} contact phases before t = {:.9g} s (chattering contact)",
          kMaxPhases, ph.start_s));
    }
    ph.end_s = ph.start_s + ev.tau_s;
    const NormalPhase next = successor(ph, ev);
    known_until_s_ = next.start_s;
    phases_.push_back(next);
  }
}

std::size_t NormalContactMotion::phase_index_at(double t_s) const {
  const auto it = std::upper_bound(phases_.begin(), phases_.end(), t_s,
                                   [](double t, const NormalPhase& ph) { return t < ph.start_s; });
  return it == phases_.begin() ? 0 : static_cast<std::size_t>(it - phases_.begin()) - 1;
}

NormalState NormalContactMotion::state_at(double t_s) const {
  const NormalPhase& ph = phases_[phase_index_at(t_s)];
  const double tau = t_s - ph.start_s;
  NormalState s;
  s.kind = ph.kind;
  if (ph.kind == NormalPhaseKind::pressed) {
    const DampedMode x = pressed_mode(ph);
    s.gap_m = gap_eq_m_ + x.value(tau);
    s.gap_rate_mps = x.rate(tau);
    // touching without penetration carries no force (contact_force.hpp)
    s.force_n = s.gap_m < 0.0 ? std::max(0.0, pressed_force(x, tau)) : 0.0;
  } else {
    s.gap_m = parabola_gap(ph, p_.normal_gravity_mps2, tau);
    s.gap_rate_mps = parabola_rate(ph, p_.normal_gravity_mps2, tau);
    s.force_n = 0.0;
  }
  return s;
}

double NormalContactMotion::max_force_n(std::size_t i, double from_s, double to_s) const {
  const NormalPhase& ph = phases_.at(i);
  if (ph.kind != NormalPhaseKind::pressed) return 0.0;
  const double ta = from_s - ph.start_s;
  const double tb = to_s - ph.start_s;
  const DampedMode x = pressed_mode(ph);
  const DampedMode f = force_mode(ph);
  double best = std::max(pressed_force(x, ta), pressed_force(x, tb));
  // the first maximum inside is the largest one: the envelope decays
  int used = 0;
  for (int j = 0; used < 2; ++j) {
    const double s = f.stationary_point(j);
    if (!(s < tb)) break;
    if (s <= ta) continue;
    best = std::max(best, pressed_force(x, s));
    ++used;
  }
  return std::max(best, 0.0);
}

double NormalContactMotion::max_penetration_m(std::size_t i, double from_s, double to_s) const {
  const NormalPhase& ph = phases_.at(i);
  const double ta = from_s - ph.start_s;
  const double tb = to_s - ph.start_s;
  const double a = p_.normal_gravity_mps2;
  if (ph.kind != NormalPhaseKind::pressed) {
    double best = std::max(-parabola_gap(ph, a, ta), -parabola_gap(ph, a, tb));
    // the apex of the parabola, u' = 0
    if (a != 0.0) {
      const double apex = -ph.gap_rate0_mps / a;
      if (apex > ta && apex < tb) best = std::max(best, -parabola_gap(ph, a, apex));
    }
    return best;
  }
  const DampedMode x = pressed_mode(ph);
  double best = std::max(-(gap_eq_m_ + x.value(ta)), -(gap_eq_m_ + x.value(tb)));
  int used = 0;
  for (int j = 0; used < 2; ++j) {
    const double s = x.stationary_point(j);
    if (!(s < tb)) break;
    if (s <= ta) continue;
    best = std::max(best, -(gap_eq_m_ + x.value(s)));
    ++used;
  }
  return best;
}

}  // namespace pb::internal
