// The independent truth's integration: the equations of motion of
// rigid_bodies.hpp with the contact forces of contact_law.hpp at the geometry
// of pair_contact.hpp, integrated by Boost.Odeint's Dormand-Prince 5(4) with
// step-size control and dense output (runge_kutta_dopri5 through
// make_dense_output; Boost.Odeint documentation, "Dense output steppers").
//
// Each pair is in one mode: apart (no force), pressing (the law's force) or
// clamped (overlapping, the law's force would pull: 0, SPEC §1). Within a
// mode the right-hand side is smooth; the mode changes only at located
// events, so that no discontinuity of the force (Kelvin-Voigt's jump to
// c delta_dot at onset, the kink of the clamp) ever sits inside a step:
//   apart -> pressing      delta rises through 0 (onset: the approach speed
//                          delta_dot is latched for eq. 6)
//   pressing -> clamped    the unclamped force falls through 0
//   clamped -> pressing    it rises through 0 again
//   pressing / clamped -> apart  delta falls through 0 (offset)
// After every accepted step each event function is evaluated at the step's
// end; a change of sign is located by bisection on the dense output to the
// last bit of t, the step is cut there, the mode switched and the stepper
// restarted from the dense output's state at the event (its RHS in the step
// was the old mode's smooth extension). A step is at most max_step_s long, so
// that no event goes unseen by rising and falling within one step.
//
// Episodes (SPEC §4) are kept here, not by core's EpisodeTracker: onset and
// offset at the located events, approach delta_dot at onset and separation
// -delta_dot at offset, restitution their ratio, the impulse as an extra
// state (integral of the force, one per pair, integrated with the motion),
// the peak force and the largest penetration located on the dense output
// (Brent's minimiser, boost::math::tools::brent_find_minima, around the
// largest of six samples per step).
#pragma once

#include <boost/numeric/odeint.hpp>
#include <optional>
#include <vector>

#include "contact_law.hpp"
#include "pair_contact.hpp"
#include "planarbench/case.hpp"
#include "planarbench/engine.hpp"
#include "rigid_bodies.hpp"

namespace pb::independent {

struct IntegrationSettings {
  double abs_tol = 1e-12;    // per state component: m, rad, m/s, rad/s, N s
  double rel_tol = 1e-12;    // -
  double max_step_s = 1e-3;  // s
};

class HybridIntegration {
 public:
  // the case must be supported (independent_truth.hpp says which are)
  HybridIntegration(const Case& c, const IntegrationSettings& s);

  // to t_s >= time(): every event up to t_s located and applied
  void advance_to(double t_s);
  [[nodiscard]] double time() const { return time_s_; }
  void body_states(std::vector<BodyState>& out) const;
  // pairs overlapping now: the law's force (0 while clamped)
  void contacts(std::vector<ContactSample>& out) const;
  // closed episodes, then the open ones (offset NaN; impulse and peaks so far)
  [[nodiscard]] std::vector<ContactEpisode> episodes() const;
  [[nodiscard]] long steps() const { return steps_; }
  // kinetic plus gravity's potential energy now, J (tests)
  [[nodiscard]] double energy() const;
  [[nodiscard]] const IntegrationSettings& settings() const { return settings_; }
  [[nodiscard]] std::vector<std::string> laws() const;

 private:
  enum class Mode { apart, pressing, clamped };
  enum class EventKind { onset, offset, clamp, press, second_vertex };
  struct Pair {
    explicit Pair(const ContactPair& cp) : a(cp.body_a), b(cp.body_b), name(cp.name), law(cp.law) {}
    int a = -1;
    int b = -1;
    std::string name;
    NormalLaw law;
    Mode mode = Mode::apart;
    double approach_mps = 0.0;  // m/s, delta_dot latched at onset
    bool open = false;
    ContactEpisode episode;
    double impulse_at_onset_ns = 0.0;  // N s, the impulse state at onset
  };
  struct Event {
    double t_s = 0.0;
    std::size_t pair = 0;
    EventKind kind = EventKind::onset;
  };
  using Dense = boost::numeric::odeint::result_of::make_dense_output<
      boost::numeric::odeint::runge_kutta_dopri5<State>>::type;

  void rhs(const State& x, State& dxdt) const;
  [[nodiscard]] PairContact contact_at(std::size_t p, const std::vector<BodyMotion>& m) const;
  [[nodiscard]] PairContact contact_at(std::size_t p, const State& x) const;
  [[nodiscard]] bool fires(const Pair& p, EventKind kind, const PairContact& c) const;
  [[nodiscard]] double force_n(const Pair& p, const PairContact& c) const;  // clamped at 0
  [[nodiscard]] double locate(std::size_t p, EventKind kind, double lo_s, double hi_s) const;
  void track_extremes(double t0_s, double t1_s);
  void step();
  void apply(const Event& e);

  Case case_;
  IntegrationSettings settings_;
  RigidBodies model_;
  std::vector<Pair> pairs_;
  Dense dense_;
  bool segment_stepped_ = false;  // a step taken since the last (re)start
  State segment_start_;           // the state at the last (re)start
  std::optional<Event> pending_;  // located in the last step, applied once time passes it
  std::vector<ContactEpisode> closed_;
  State now_;            // the state at time_s_
  double time_s_ = 0.0;  // s
  long steps_ = 0;
  mutable std::vector<BodyMotion> motions_;   // scratch of rhs()
  mutable std::vector<AppliedForce> forces_;  // scratch of rhs()
};

}  // namespace pb::independent
