#include "planarbench/contact_law_response.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "planarbench/contact_force.hpp"

namespace pb {

nlohmann::json to_json(const CollisionResponse& r) {
  return {{"restitution", r.restitution},
          {"force_duration_s", r.force_duration_s},
          {"duration_s", r.duration_s},
          {"peak_force_n", r.peak_force_n},
          {"max_penetration_m", r.max_penetration_m},
          {"impulse_ns", r.impulse_ns}};
}

namespace {

constexpr double kPi = std::numbers::pi;

// state of the 1D collision: penetration delta (m) and its rate (m/s)
using State = std::array<double, 2>;

// one classic RK4 step of m delta'' = -F(delta, delta'); the mass is in
// contact for the whole integration, so delta = 0 at the first touch counts as
// touching (the Kelvin-Voigt force jumps to c v there, not 0)
State rk4_step(const ContactLaw& law, double m, double v0, const State& s, double h) {
  auto f = [&](const State& x) {
    const double delta = std::max(x[0], std::numeric_limits<double>::min());
    return State{x[1], -contact_force_n(law, delta, x[1], v0) / m};
  };
  const State k1 = f(s);
  const State k2 = f({s[0] + 0.5 * h * k1[0], s[1] + 0.5 * h * k1[1]});
  const State k3 = f({s[0] + 0.5 * h * k2[0], s[1] + 0.5 * h * k2[1]});
  const State k4 = f({s[0] + h * k3[0], s[1] + h * k3[1]});
  return {s[0] + h / 6.0 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]),
          s[1] + h / 6.0 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])};
}

// integrates from first touch until the penetration returns to 0 with step h;
// the last step is shortened by bisection so that it lands on delta = 0
CollisionResponse integrate(const ContactLaw& law, double m, double v0, double h) {
  CollisionResponse r;
  State s{0.0, v0};
  double t = 0.0;
  bool force_on = true;
  r.peak_force_n = contact_force_n(law, std::numeric_limits<double>::min(), s[1], v0);
  constexpr long kMaxSteps = 50'000'000;
  for (long i = 0; i < kMaxSteps; ++i) {
    State next = rk4_step(law, m, v0, s, h);
    if (next[0] <= 0.0 && t > 0.0) {
      // bisection on the step length for the return to delta = 0
      double lo = 0.0;
      double hi = h;
      for (int it = 0; it < 200 && hi - lo > 1e-18 * (t + h); ++it) {
        const double mid = 0.5 * (lo + hi);
        (rk4_step(law, m, v0, s, mid)[0] > 0.0 ? lo : hi) = mid;
      }
      const State end = rk4_step(law, m, v0, s, hi);
      r.duration_s = t + hi;
      if (force_on) r.force_duration_s = r.duration_s;
      r.restitution = -end[1] / v0;
      r.impulse_ns = m * (v0 - end[1]);
      return r;
    }
    const double f = contact_force_n(law, next[0], next[1], v0);
    if (force_on && f <= 0.0 && next[1] < 0.0) {
      // the clamp releases inside this step: bisection on the step length
      force_on = false;
      double lo = 0.0;
      double hi = h;
      for (int it = 0; it < 200 && hi - lo > 1e-18 * (t + h); ++it) {
        const double mid = 0.5 * (lo + hi);
        const State x = rk4_step(law, m, v0, s, mid);
        (contact_force_n(law, x[0], x[1], v0) > 0.0 ? lo : hi) = mid;
      }
      r.force_duration_s = t + 0.5 * (lo + hi);
    }
    t += h;
    s = next;
    r.peak_force_n = std::max(r.peak_force_n, f);
    r.max_penetration_m = std::max(r.max_penetration_m, s[0]);
  }
  throw std::runtime_error("simulate_collision: no separation after 5e7 steps");
}

}  // namespace

CollisionResponse kelvin_voigt_response(double k, double c, double m, double v) {
  const double omega = std::sqrt(k / m);            // rad/s
  const double zeta = c / (2.0 * std::sqrt(k * m));  // damping ratio
  if (!(zeta < 1.0)) {
    return simulate_collision(KelvinVoigt{k, c, 0.0}, m, v);
  }
  const double wd = omega * std::sqrt(1.0 - zeta * zeta);
  const double a = zeta * omega;
  // delta(t) = (v / wd) exp(-a t) sin(wd t); the clamp releases when
  // k delta + c delta' = 0, at wd t = pi - 2 asin(zeta) (ENGINES.md)
  const double t_release = (kPi - 2.0 * std::asin(zeta)) / wd;
  auto delta = [&](double t) { return v / wd * std::exp(-a * t) * std::sin(wd * t); };
  auto rate = [&](double t) {
    return v / wd * std::exp(-a * t) * (wd * std::cos(wd * t) - a * std::sin(wd * t));
  };
  auto force = [&](double t) { return k * delta(t) + c * rate(t); };

  CollisionResponse r;
  r.force_duration_s = t_release;
  r.restitution = std::exp(-zeta * (kPi - 2.0 * std::asin(zeta)) / std::sqrt(1.0 - zeta * zeta));
  // after the release the mass flies out at constant speed e v (no gravity)
  r.duration_s = t_release + delta(t_release) / (r.restitution * v);
  r.impulse_ns = m * v * (1.0 + r.restitution);
  // max penetration where delta' = 0: tan(wd t) = wd / a
  r.max_penetration_m = delta(std::atan2(wd, a) / wd);
  // peak force: golden-section search of the unimodal force on [0, t_release]
  double lo = 0.0;
  double hi = t_release;
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int i = 0; i < 200; ++i) {
    const double x1 = hi - g * (hi - lo);
    const double x2 = lo + g * (hi - lo);
    if (force(x1) < force(x2)) {
      lo = x1;
    } else {
      hi = x2;
    }
  }
  r.peak_force_n = std::max(force(0.5 * (lo + hi)), c * v);
  return r;
}

CollisionResponse simulate_collision(const ContactLaw& law, double m, double v) {
  if (!(m > 0.0) || !(v > 0.0)) {
    throw std::invalid_argument("simulate_collision: mass and approach speed must be > 0");
  }
  // a first pass at a coarse step finds the duration; the second pass uses
  // 20000 steps over it (RK4 error ~ (T/20000)^4, far below 1e-8 relative)
  double h = 1e-6;
  if (const auto* kv = std::get_if<KelvinVoigt>(&law)) {
    h = kPi * std::sqrt(m / kv->stiffness_n_per_m) / 2000.0;
  } else {
    const double stiffness = std::holds_alternative<Hertz>(law)
                                 ? std::get<Hertz>(law).stiffness
                                 : std::get<LankaraniNikravesh>(law).stiffness;
    const double n = std::holds_alternative<Hertz>(law) ? std::get<Hertz>(law).exponent
                                                        : std::get<LankaraniNikravesh>(law).exponent;
    // energy balance: m v^2 / 2 = K delta_max^(n+1) / (n+1)
    const double delta_max = std::pow((n + 1.0) * m * v * v / (2.0 * stiffness), 1.0 / (n + 1.0));
    h = delta_max / v / 2000.0;
  }
  const CollisionResponse coarse = integrate(law, m, v, h);
  return integrate(law, m, v, coarse.duration_s / 20000.0);
}

LinearEquivalent linear_equivalent(const CollisionResponse& target, double m) {
  if (!(target.restitution > 0.0 && target.restitution < 1.0) || !(target.force_duration_s > 0.0)) {
    throw std::invalid_argument("linear_equivalent: needs 0 < restitution < 1 and a duration > 0");
  }
  // e(zeta) of the clamped oscillator falls monotonically from 1 at zeta = 0
  auto e_of = [](double z) {
    return std::exp(-z * (kPi - 2.0 * std::asin(z)) / std::sqrt(1.0 - z * z));
  };
  double lo = 0.0;
  double hi = 1.0 - 1e-12;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (e_of(mid) > target.restitution ? lo : hi) = mid;
  }
  const double zeta = 0.5 * (lo + hi);
  const double wd = (kPi - 2.0 * std::asin(zeta)) / target.force_duration_s;
  const double omega = wd / std::sqrt(1.0 - zeta * zeta);
  LinearEquivalent out;
  out.stiffness_n_per_m = m * omega * omega;
  out.damping_ns_per_m = 2.0 * zeta * std::sqrt(out.stiffness_n_per_m * m);
  return out;
}

}  // namespace pb
