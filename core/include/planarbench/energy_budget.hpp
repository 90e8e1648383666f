// The energy a passive planar system can hold, and the runaway check built on
// it: the runner applies it on every output sample of every engine, and
// adapters may apply it at their own steps.
//
// Every force of a case is gravity or passive:
//  - a contact law F = F_e(delta) + F_d(delta, delta_dot), clamped at F >= 0,
//    with an elastic part F_e >= 0 and a damping part with F_d delta_dot >= 0
//    (Kelvin-Voigt, paper eq. 1 with c >= 0, also with the cubic ramp; Hertz,
//    eq. 2; Lankarani-Nikravesh, eq. 7, whose damping K delta^n 3 (1 - e^2) / 4
//    delta_dot / delta_dot_minus has the sign of delta_dot for e <= 1), acts on
//    the bodies with power -F delta_dot <= -dU_e/dt, U_e(delta) = int_0^delta
//    F_e: unclamped, -F_d delta_dot <= 0; clamped (F = 0), F_e + F_d < 0 needs
//    F_d < 0, hence delta_dot < 0 and -F_e delta_dot >= 0;
//  - Coulomb friction (SPEC §7) opposes the slip: its power -f v <= 0 (a
//    stuck pair's force does no work on a contact point that does not slip);
//  - a revolute joint to ground does no work.
// So the kinetic energy never exceeds what the case has made available,
//   KE(t) <= KE(0) + U_c(0) + W_g(t),   W_g(t) = sum_i m_i g . (x_i(t) - x_i(0)),
// U_c(0) the elastic energy of contacts that start penetrated, and the kinetic
// energy of a planar rigid body m |v|^2 / 2 + I omega^2 / 2 about its centre
// of mass. An engine whose kinetic energy exceeds the most energy made
// available so far by a large factor is creating energy: a numerical runaway,
// caught before it reaches inf or NaN (or hides behind an engine's clamp,
// such as Box2D's b2_maxTranslation per step).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <variant>
#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/contact_pairs.hpp"
#include "planarbench/engine.hpp"

namespace pb {

// The ratio KE / (energy made available) above which a run is a runaway.
// Measured with every shipped case on every engine (tests/faults/README.md):
// the default settings stay below 1.52 (MuJoCo's soft contact returning a
// disk set down at rest; every other run below 1 + 1e-9), coarse steps
// (MuJoCo dt = 1e-2) reach 5.8 at their first step and stay bounded;
// explicit force injection with ~2 steps per impact gains energy at every
// impact (2.1 to 5.2 after the dual pendulum's second impact); blow-ups reach
// 69 to 4e13. 10 lies between the last two: above what a bounded run reaches,
// far below a blow-up, which grows exponentially and passes 10 within a few
// steps.
constexpr double kRunawayEnergyFactor = 10.0;

// m/s: the budget never falls below the kinetic energy of every moving body
// at this speed, so that a case where nothing moves (no gravity, at rest)
// has a budget > 0; 1e-6 m/s moves a body 1e-10 m per 1e-4 s sample, below
// anything the output grid resolves
constexpr double kEnergyFloorSpeedMps = 1e-6;

// elastic energy of a law at penetration delta_m, J: U_e = int_0^delta F_e
[[nodiscard]] inline double elastic_energy_j(const ContactLaw& law, double delta_m) {
  if (!(delta_m > 0.0)) return 0.0;
  if (const auto* kv = std::get_if<KelvinVoigt>(&law)) {
    return 0.5 * kv->stiffness_n_per_m * delta_m * delta_m;  // K delta^2 / 2
  }
  // Hertz and Lankarani-Nikravesh: F_e = K delta^n, U_e = K delta^(n+1) / (n+1)
  const auto* hz = std::get_if<Hertz>(&law);
  const auto* ln = std::get_if<LankaraniNikravesh>(&law);
  const double k = hz ? hz->stiffness : ln->stiffness;
  const double n = hz ? hz->exponent : ln->exponent;
  return k * std::pow(delta_m, n + 1.0) / (n + 1.0);
}

// An a-priori bound, for guards that need one before the run: with
// E = KE + U_c (all contacts' elastic energy), passivity gives dE/dt <= the
// power of gravity sum m_i g . v_i <= |g| sqrt(M) sqrt(sum m_i |v_i|^2) <=
// |g| sqrt(2 M E) (Cauchy-Schwarz; M the moving mass), so d sqrt(E)/dt <=
// |g| sqrt(M / 2) and
//   KE(t) <= E(t) <= (sqrt(E(0)) + |g| t sqrt(M / 2))^2.
// For one body falling from rest this is its free-fall energy m (g t)^2 / 2.
struct EnergyBound {
  double initial_j = 0.0;       // J, E(0) = KE(0) + U_c(0)
  double moving_mass_kg = 0.0;  // kg, M
  double gravity_mps2 = 0.0;    // m/s^2, |g|

  // J, the bound on KE(t)
  [[nodiscard]] double kinetic_j(double t_s) const {
    const double root = std::sqrt(initial_j) + gravity_mps2 * t_s * std::sqrt(0.5 * moving_mass_kg);
    return root * root;
  }
  // m, the bound on how far a body of mass m_kg gets from where it started by
  // t_s: int_0^t |v| <= sqrt(2 / m) int_0^t sqrt(KE bound)
  [[nodiscard]] double displacement_m(double mass_kg, double t_s) const {
    const double a = gravity_mps2 * std::sqrt(0.5 * moving_mass_kg);  // sqrt(J)/s
    return std::sqrt(2.0 / mass_kg) * (std::sqrt(initial_j) * t_s + 0.5 * a * t_s * t_s);
  }
};

// KE(t) against KE(0) + U_c(0) + max over s <= t of W_g(s), the case's own
// energy budget. W_g is known two ways, each exact where the other is not:
//  - from positions, m g . (x(t) - x(0)): exact but for what the stored
//    position cannot resolve (a float engine, Box2D, has not moved a body
//    falling from 3 m after 1e-4 s: 4.9e-8 m is below a float's step there,
//    2.4e-7 m; at dt = 1e-7 s its positions stay put for 0.12 s);
//  - from velocities, int m g . v dt by the trapezoid rule over the samples,
//    plus the most that rule can miss on an interval where v moves between
//    its end values, m |g . (v1 - v0)| dt / 2: exact for a free fall (v
//    linear in t), whatever the positions say.
// The budget takes the larger, so neither produces a false runaway; both stay
// with the energy the case has, so an engine that throws a body up with
// energy from nowhere is caught (issue 35 item 8: MuJoCo at dt = 1e-2 threw
// block_stop's slab 3.5 m up at 27.8 m/s, 386 J from the 2 J it had, and
// the check then compared against 10 x an a-priori free-fall bound, 56 J at
// t = 0.88 s, and let it pass).
class EnergyBudget {
 public:
  // keeps a reference to `c`, which must outlive the budget
  explicit EnergyBudget(const Case& c) : case_(c) {
    for (const Body& b : c.bodies) {
      if (!b.fixed) floor_j_ += 0.5 * b.mass_kg * kEnergyFloorSpeedMps * kEnergyFloorSpeedMps;
    }
  }

  // The state at t = 0 (index = Case::bodies index) and the contacts active
  // then; a contact without a penetration (NaN) stores no energy.
  void start(const std::vector<BodyState>& states, const std::vector<ContactSample>& contacts) {
    initial_.assign(states.begin(), states.end());
    previous_.assign(states.begin(), states.end());
    previous_s_ = 0.0;
    velocity_work_j_ = 0.0;
    start_j_ = kinetic_j(states);
    const ContactPairs rules(case_);
    for (const ContactSample& s : contacts) {
      if (!std::isfinite(s.penetration_m)) continue;
      if (const ContactLaw* law = rules.law_between(s.body_a, s.body_b)) {
        start_j_ += elastic_energy_j(*law, s.penetration_m);
      }
    }
    most_available_j_ = std::max(floor_j_, start_j_);
    kinetic_now_j_ = start_j_;
    ratio_ = 0.0;
  }

  // Takes the state `elapsed_s` after start() and returns KE / the most
  // energy made available so far; passive dynamics keep it <= 1.
  double update(const std::vector<BodyState>& states, double elapsed_s) {
    const double dt = std::max(elapsed_s - previous_s_, 0.0);
    for (std::size_t i = 0; i < case_.bodies.size() && i < states.size(); ++i) {
      const Body& b = case_.bodies[i];
      if (b.fixed || i >= previous_.size()) continue;
      const double p0 = b.mass_kg * case_.gravity_mps2.dot(previous_[i].velocity_mps);  // W
      const double p1 = b.mass_kg * case_.gravity_mps2.dot(states[i].velocity_mps);     // W
      // the trapezoid (p0 + p1) dt / 2 plus its allowance |p1 - p0| dt / 2
      if (std::isfinite(p0) && std::isfinite(p1)) velocity_work_j_ += std::max(p0, p1) * dt;
    }
    previous_.assign(states.begin(), states.end());
    previous_s_ = elapsed_s;
    const double work_j = std::max(gravity_work_j(states), velocity_work_j_);
    most_available_j_ = std::max(most_available_j_, start_j_ + work_j);
    kinetic_now_j_ = kinetic_j(states);
    ratio_ = kinetic_now_j_ / most_available_j_;
    return ratio_;
  }

  // the last update() exceeded kRunawayEnergyFactor (false for NaN: the
  // non-finite check comes first)
  [[nodiscard]] bool runaway() const { return ratio_ > kRunawayEnergyFactor; }
  [[nodiscard]] double ratio() const { return ratio_; }
  // J, of the state last given
  [[nodiscard]] double kinetic_now_j() const { return kinetic_now_j_; }
  // J, KE(0) + U_c(0) + the largest W_g so far (at least the floor)
  [[nodiscard]] double most_available_j() const { return most_available_j_; }

  // what the last update() found, for a diverged run's reason (after
  // "energy runaway at t = ...: ")
  [[nodiscard]] std::string describe() const {
    char buf[320];
    std::snprintf(buf, sizeof buf,
                  "kinetic energy %.4g J is %.4g times the %.4g J the case has "
                  "made available (initial kinetic and contact elastic energy plus the work of "
                  "gravity); passive contact laws cannot create energy (limit %g times)",
                  kinetic_now_j_, ratio_, most_available_j_, kRunawayEnergyFactor);
    return buf;
  }

  // J, kinetic energy of the moving bodies
  [[nodiscard]] double kinetic_j(const std::vector<BodyState>& states) const {
    double ke = 0.0;
    for (std::size_t i = 0; i < case_.bodies.size() && i < states.size(); ++i) {
      const Body& b = case_.bodies[i];
      if (b.fixed) continue;
      const BodyState& s = states[i];
      ke += 0.5 * b.mass_kg * s.velocity_mps.squaredNorm() +
            0.5 * b.inertia_kgm2 * s.angular_velocity_radps * s.angular_velocity_radps;
    }
    return ke;
  }

  // J, work of gravity since t = 0: sum m g . (x(t) - x(0))
  [[nodiscard]] double gravity_work_j(const std::vector<BodyState>& states) const {
    double w = 0.0;
    for (std::size_t i = 0; i < case_.bodies.size() && i < states.size(); ++i) {
      const Body& b = case_.bodies[i];
      if (b.fixed || i >= initial_.size()) continue;
      w += b.mass_kg * case_.gravity_mps2.dot(states[i].position_m - initial_[i].position_m);
    }
    return w;
  }

 private:
  const Case& case_;
  std::vector<BodyState> initial_;
  std::vector<BodyState> previous_;  // the state of the last update
  double previous_s_ = 0.0;          // s, its time after start()
  double velocity_work_j_ = 0.0;     // J, W_g from velocities (with its allowance)
  double floor_j_ = 0.0;           // J
  double start_j_ = 0.0;           // J, KE(0) + U_c(0)
  double most_available_j_ = 0.0;  // J
  double kinetic_now_j_ = 0.0;     // J
  double ratio_ = 0.0;             // -
};

}  // namespace pb
