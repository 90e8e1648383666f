// The motion of a body along the normal of a fixed line under constant
// gravity and a clamped Kelvin-Voigt contact force (paper eq. 1, SPEC §1-§3),
// in closed form, piecewise between located events.
//
// u is the gap (distance of the body's surface from the line, < 0 when it
// penetrates, delta = -u), a = g . n the normal component of gravity. Phases:
//   separated  u >= 0, no force:         m u'' = m a           (parabola)
//   pressed    u < 0, F = -K u - c u' > 0: m u'' = m a + F     (damped oscillator)
//   clamped    u < 0, -K u - c u' <= 0:  m u'' = m a           (parabola)
// Events, each found by root finding on the closed form to the last bit:
//   separated -> pressed   u reaches 0 moving in (onset)
//   pressed   -> clamped   F reaches 0 (the clamp, SPEC §1: a contact never pulls)
//   pressed   -> separated F and u reach 0 together (only when c = 0)
//   clamped   -> separated u returns to 0 (offset)
//   clamped   -> pressed   F would become positive again while u < 0
#pragma once

#include <limits>
#include <vector>

#include "damped_mode.hpp"

namespace pb::internal {

struct NormalContactParams {
  double mass_kg = 0.0;              // kg, > 0
  double stiffness_n_per_m = 0.0;    // K, N/m, > 0
  double damping_ns_per_m = 0.0;     // c, N s/m, >= 0
  double normal_gravity_mps2 = 0.0;  // a = g . n, m/s^2 (< 0 presses onto the line)
  double gap0_m = 0.0;               // u(0), m
  double gap_rate0_mps = 0.0;        // u'(0), m/s
};

enum class NormalPhaseKind { separated, pressed, clamped };

struct NormalPhase {
  NormalPhaseKind kind = NormalPhaseKind::separated;
  double start_s = 0.0;        // s
  double end_s = 0.0;          // s, +inf when no event follows (yet)
  double gap0_m = 0.0;         // u at start_s, m
  double gap_rate0_mps = 0.0;  // u' at start_s, m/s
};

struct NormalState {
  double gap_m = 0.0;         // u, m
  double gap_rate_mps = 0.0;  // u', m/s
  double force_n = 0.0;       // F >= 0, N
  NormalPhaseKind kind = NormalPhaseKind::separated;
};

class NormalContactMotion {
 public:
  explicit NormalContactMotion(const NormalContactParams& p);

  // Locates every event up to t_s. Throws EngineError after an absurd number
  // of phases (a chattering case this closed form does not resolve).
  void extend_to(double t_s);
  // time up to which every event is known, s
  [[nodiscard]] double known_until_s() const { return known_until_s_; }

  // state at t_s (0 <= t_s <= known_until_s())
  [[nodiscard]] NormalState state_at(double t_s) const;
  [[nodiscard]] const std::vector<NormalPhase>& phases() const { return phases_; }
  // index of the phase holding t_s (the later one at an event time)
  [[nodiscard]] std::size_t phase_index_at(double t_s) const;

  // maxima of the force, N, and of the penetration -u, m, over [from_s, to_s]
  // inside phase i, from the closed form's stationary points
  [[nodiscard]] double max_force_n(std::size_t i, double from_s, double to_s) const;
  [[nodiscard]] double max_penetration_m(std::size_t i, double from_s, double to_s) const;

  [[nodiscard]] const NormalContactParams& params() const { return p_; }
  // static gap under gravity while pressed, u_eq = m a / K, m
  [[nodiscard]] double equilibrium_gap_m() const { return gap_eq_m_; }
  [[nodiscard]] double sigma_per_s() const { return sigma_; }           // c / (2 m)
  [[nodiscard]] double omega0_sq_per_s2() const { return omega0_sq_; }  // K / m

 private:
  // the oscillation about u_eq during a pressed phase
  [[nodiscard]] DampedMode pressed_mode(const NormalPhase& ph) const;
  // F - F_eq during a pressed phase, F_eq = -K u_eq the static load
  [[nodiscard]] DampedMode force_mode(const NormalPhase& ph) const;
  // F = -K u - c u' in a pressed phase at tau (the law of eq. 1, unclamped)
  [[nodiscard]] double pressed_force(const DampedMode& x, double tau_s) const;
  struct Event {
    double tau_s = std::numeric_limits<double>::infinity();  // s after the start; +inf: none
    NormalPhaseKind next = NormalPhaseKind::separated;       // the phase it starts
    bool final = false;  // none found, and none can come later either
  };
  // the phase's event within tau <= tau_max_s (quadratic events: at any tau)
  [[nodiscard]] Event next_event(const NormalPhase& ph, double tau_max_s) const;
  // the phase that the event starts
  [[nodiscard]] NormalPhase successor(const NormalPhase& ph, const Event& ev) const;

  NormalContactParams p_;
  double sigma_ = 0.0;      // 1/s
  double omega0_sq_ = 0.0;  // 1/s^2
  double gap_eq_m_ = 0.0;   // m
  std::vector<NormalPhase> phases_;
  double known_until_s_ = 0.0;
  bool last_is_final_ = false;  // the last phase has no event, ever
};

}  // namespace pb::internal
