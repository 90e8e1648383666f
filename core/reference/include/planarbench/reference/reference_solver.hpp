// The reference solver: integrates ContactDynamics with one of three
// integrators, locates every contact event, and keeps the episode table.
//
// Events (per pair, by phase; s = signed gap, thr = ContactPair::threshold_m,
// F_u = the law without its clamp):
//   apart    -> touching  when s falls to thr: the contact is declared (the
//                         paper's "distance reaches zero", 1e-10 m); the
//                         episode opens, delta_dot there is latched as the
//                         approach speed (Lankarani-Nikravesh delta_dot^-);
//   touching -> pressing  when s falls below 0 (delta turns positive), or, with
//                         delta > 0 after a clamp, when F_u rises above 0;
//   pressing -> touching  when F_u falls below 0 (the clamp: the law would
//                         pull) or s rises above 0;
//   touching -> apart     when s rises above thr: the episode closes there.
// A pair with friction, while pressing (coulomb_friction.hpp; v its slip
// speed, s the latched slip direction, f its tangential force, F its normal
// force, mu its coefficient):
//   slip     -> ?         when s v falls below 0 (the slip stops or reverses),
//   stick    -> ?         when |f| rises above mu F (the load leaves the cone);
// at each, and when the pair starts pressing, choose_slip_phase decides.
// Each event is located by re-taking the step from its start with a shorter
// length (event_location.hpp) until the phase change is bracketed to a few
// ulps of t; the step is then accepted up to that point, so that no step ever
// straddles a discontinuity of the force law or of its slope.
//
// Integrators (setting `integrator`):
//   rk45   Dormand-Prince 5(4), error per step <= atol + rtol |y|, step-size
//          control of HNW I §II.4 (factor 0.9 err^(-1/5) in [0.2, 5]); output
//          between steps by its dense output; steps also kept below twice the
//          time to close the gap at the current closing speed, so that no
//          contact can hide inside one step; events by Illinois.
//   paper  classic RK4 with the paper's step control (§3.1, "the step grows
//          when the closest distance is large and shrinks as it approaches
//          zero"): h = clamp(gap_safety * gap / closing speed, h_min, h_max)
//          while every pair is apart (h_max when nothing approaches), the fixed
//          contact_dt while a contact is declared; onset (and every other
//          event) located by bisection; lands on the output times.
//   fixed  classic RK4 on the grid k dt; a step holding an event is split at
//          the event and completed to the grid point; output at the last grid
//          point not after the requested time.
// Episode figures: onset / offset at the located events, approach and
// separation speeds there, impulse = difference of the integrated impulse
// state, peak force and peak penetration = the largest values at the steps,
// refined around every local maximum near the peak by golden-section search
// on the dense output.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/engine.hpp"
#include "planarbench/reference/contact_dynamics.hpp"
#include "planarbench/reference/dense_output.hpp"
#include "planarbench/reference/dormand_prince.hpp"
#include "planarbench/reference/event_location.hpp"
#include "planarbench/reference/reference_settings.hpp"
#include "planarbench/reference/rk4.hpp"

namespace pb {

enum class IntegratorKind { rk45, paper, fixed };

struct SolverStats {
  long steps = 0;                  // accepted steps
  long rejected = 0;               // rk45 steps that failed the error test
  long events = 0;                 // located phase changes
  long rhs_evaluations = 0;        // evaluations of f (each one a contact search per pair)
  double constraint_drift_m = 0.0; // m, largest joint violation at the accepted steps
};

// every accepted step of every ReferenceSolver on this thread (the
// no-look-ahead guard's trace, Engine::library_steps_on_this_thread)
[[nodiscard]] long reference_steps_on_this_thread();

class ReferenceSolver {
 public:
  // throws std::invalid_argument for a case or settings it cannot run
  ReferenceSolver(const Case& c, const ReferenceSettings& s);

  // advances the output to t_s (rk45, paper: exactly; fixed: the last grid
  // point not after t_s). Throws EngineError on failure.
  void advance_to(double t_s);

  [[nodiscard]] double time() const { return t_out_; }
  [[nodiscard]] BodyState body_state(int body) const;
  // declared contacts at time()
  void contacts(std::vector<ContactSample>& out) const;
  [[nodiscard]] std::vector<ContactEpisode> episodes() const;
  [[nodiscard]] SolverStats stats() const;
  [[nodiscard]] long near_rebuilds() const { return sys_.near_rebuilds(); }
  // total mechanical energy at time(), J
  [[nodiscard]] double energy_j() const;
  // energy dissipated by friction up to time(), J (0 without friction)
  [[nodiscard]] double friction_dissipation_j() const;
  // tangential impulse of pair k's friction on body b up to time(), N s
  [[nodiscard]] double tangential_impulse_ns(int k) const;
  [[nodiscard]] IntegratorKind integrator() const { return kind_; }

 private:
  enum class EventKind { declare, release, press, unclamp, clamp, lift, slip_ends, stick_breaks };
  struct Event {
    int pair = -1;
    EventKind kind = EventKind::declare;
    double tau = 0.0;  // s, from the step start
  };
  struct Candidate {
    int pair = -1;
    EventKind kind = EventKind::declare;
    double g0 = 0.0;  // event function at the step start
    double g1 = 0.0;  // and at its end
  };
  struct Segment {
    DenseSegment dense;
    std::vector<PairMode> modes;  // the phases during the step
  };
  struct Sample {
    double t_s = 0.0;
    double force_n = 0.0;
    double penetration_m = 0.0;
  };
  struct EpisodeState {
    bool open = false;
    ContactEpisode ep;
    double impulse_at_onset_ns = 0.0;
    std::array<Sample, 3> last{};  // newest last
    int samples = 0;
  };

  void step(double t_limit);
  double propose_step() const;
  double trial(double h);
  [[nodiscard]] std::optional<Event> first_event(double h);
  void accept(double h, std::optional<double> exact_end);
  void apply(const Event& e);
  void refresh_and_settle();
  // the change of pair k due now (its event function past the phase's bound), if any
  [[nodiscard]] std::optional<Event> due_now(int k, const PairEvaluation& e) const;
  // y and the per-pair vectors to the grown pair list (a scene's new pairs)
  void grow_state();
  void count_zero_length_event(const Event& ev);
  [[nodiscard]] bool undoes_zero_length_event(const Event& ev) const;
  // the held pairs' changes due at the new step start, then none held
  void settle_grazing();
  void record_samples();
  void refine_peaks(int k, EpisodeState& st);
  void set_output(double t_s);
  [[nodiscard]] double event_value(EventKind kind, int k, const PairEvaluation& e) const;
  [[nodiscard]] bool event_exits(EventKind kind, int k, const PairEvaluation& e) const;
  [[nodiscard]] const Segment& segment_at(double t_s) const;

  ContactDynamics sys_;
  ReferenceSettings settings_;
  IntegratorKind kind_ = IntegratorKind::rk45;
  RootMethod root_method_ = RootMethod::illinois;
  double duration_s_ = 0.0;
  DormandPrince5 dp_;
  ClassicRk4 rk4_;

  // state at the integrator's time t_
  double t_ = 0.0;
  Eigen::VectorXd y_, f_;
  std::vector<PairEvaluation> pairs_;
  // trial step end
  Eigen::VectorXd y1_, f1_;
  std::vector<PairEvaluation> pairs1_;
  double err1_ = 0.0;
  // rk45 controller, fixed grid
  double h_next_ = 0.0;
  long grid_next_ = 1;
  // zero-length events since the last step of positive length: per pair,
  // how many and its phase before the first
  struct ZeroLength {
    int pair = -1;
    int count = 0;
    ContactPhase phase_before = ContactPhase::apart;
  };
  std::vector<ZeroLength> zero_length_events_;
  // pairs held in their phase for this step: their events flip across a
  // boundary they sit on (step())
  std::vector<int> grazing_;
  // the progress guard: simulated time at the start of the current window
  double window_t_ = 0.0;
  int stalled_steps_ = 0;  // consecutive accepted steps that left t where it was
  std::vector<Candidate> candidates_;
  std::vector<std::size_t> order_;  // candidates_ by their secant estimate
  DenseSegment trial_dense_;        // a scene's trial step's dense output (first_event)
  // the two newest accepted steps
  std::array<Segment, 2> seg_;
  int seg_newest_ = 1;
  int seg_count_ = 0;
  // output
  double t_out_ = 0.0;
  Eigen::VectorXd y_out_, y_tmp_;
  std::vector<PairMode> out_modes_;
  std::vector<PairEvaluation> out_pairs_;
  // episodes
  std::vector<EpisodeState> open_;
  std::vector<ContactEpisode> closed_;
  SolverStats stats_;
};

}  // namespace pb
