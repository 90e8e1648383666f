#include "planarbench/reference/reference_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "planarbench/errors.hpp"

namespace pb {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kEps = std::numeric_limits<double>::epsilon();
// runaway guard: no case needs anywhere near this many steps
constexpr long kMaxSteps = 200'000'000;
// The progress guard (issue 24): every kProgressWindow steps, the time they
// advanced is projected over what is left of the run; a run that would need
// more than kHopeless steps at that rate cannot end within kMaxSteps, even if
// it sped up 100-fold, and ends `diverged` now instead of spinning for minutes
// (a speed of 1e308 m/s or a spin of 1e20 rad/s: steps of ~1e-300 s). A run
// that ends normally takes at most ~1e5 steps in all (block_hold, the longest
// shipped: 6966); its one window would have to average h < 1.25e-10 s over
// 1e5 steps on a 2.5 s case to be stopped.
constexpr long kProgressWindow = 100'000;
constexpr double kHopeless = 100.0 * static_cast<double>(kMaxSteps);
// ... and steps per simulated second are bounded (issue 35): a window that
// averaged more than this many (h below 1e-8 s over 1e5 steps) is chattering
// between events or integrating a contact too stiff to resolve. The stiffest shipped contact (dual_pendulum's
// Hertz pair, 0.24 ms long) takes ~1e2 steps, 4e5 per simulated second; the
// bound is 250 times that.
constexpr double kMaxStepsPerSimSecond = 1e8;
// ... and a run whose accepted steps leave t unchanged (h below half an ulp of
// t: a speed of 1e200 m/s at t = 0 gives steps of ~1e-300 s, each costing up
// to one event location, ~7 ms) ends after this many in a row, at once: no
// run that ends can have one such step, t + h == t repeats forever
constexpr int kMaxStalledSteps = 100;
// golden-section iterations for a peak: the bracket shrinks by 0.618^40 = 4e-9
constexpr int kGoldenIterations = 40;
// refine only local maxima within 2 % of the episode's running peak
constexpr double kPeakWindow = 0.98;

IntegratorKind parse_integrator(const std::string& s) {
  if (s == "rk45") return IntegratorKind::rk45;
  if (s == "paper") return IntegratorKind::paper;
  if (s == "fixed") return IntegratorKind::fixed;
  throw std::invalid_argument("reference.integrator: unknown integrator '" + s + "'");
}

GeometryMode parse_geometry(const std::string& s) {
  if (s == "outline") return GeometryMode::outline;
  if (s == "exact") return GeometryMode::exact;
  throw std::invalid_argument("reference.geometry: unknown geometry '" + s + "'");
}

DetectionMode parse_detection(const std::string& s) {
  if (s == "fast") return DetectionMode::fast;
  if (s == "brute") return DetectionMode::brute;
  throw std::invalid_argument("reference.detection: unknown detection '" + s + "'");
}

bool declared(const PairMode& m) { return m.phase != ContactPhase::apart; }

// maximises f on [a, b] by golden-section search; returns the best value seen
template <class F>
double golden_max(F&& f, double a, double b, double best) {
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = b - g * (b - a);
  double x2 = a + g * (b - a);
  double f1 = f(x1);
  double f2 = f(x2);
  best = std::max({best, f1, f2});
  for (int i = 0; i < kGoldenIterations; ++i) {
    if (f1 < f2) {
      a = x1;
      x1 = x2;
      f1 = f2;
      x2 = a + g * (b - a);
      f2 = f(x2);
      best = std::max(best, f2);
    } else {
      b = x2;
      x2 = x1;
      f2 = f1;
      x1 = b - g * (b - a);
      f1 = f(x1);
      best = std::max(best, f1);
    }
  }
  return best;
}

// accepted steps of every solver on this thread (reference_steps_on_this_thread)
thread_local long t_reference_steps = 0;

}  // namespace

long reference_steps_on_this_thread() { return t_reference_steps; }

ReferenceSolver::ReferenceSolver(const Case& c, const ReferenceSettings& s)
    : sys_(c, parse_geometry(s.geometry), parse_detection(s.detection)),
      settings_(s),
      kind_(parse_integrator(s.integrator)),
      root_method_(kind_ == IntegratorKind::paper ? RootMethod::bisection : RootMethod::illinois),
      duration_s_(c.duration_s),
      dp_(sys_.state_size()),
      rk4_(sys_.state_size()) {
  const int n = sys_.state_size();
  sys_.initial_state(y_);
  f_.setZero(n);
  y1_.setZero(n);
  f1_.setZero(n);
  y_tmp_.setZero(n);
  pairs1_.assign(static_cast<std::size_t>(sys_.pair_count()), PairEvaluation{});
  for (auto& sg : seg_) sg.modes = sys_.modes();
  open_.assign(static_cast<std::size_t>(sys_.pair_count()), EpisodeState{});

  // phases at t = 0 from the initial geometry, then the first samples
  refresh_and_settle();
  record_samples();
  stats_.constraint_drift_m = sys_.joint_violation_m(y_);
  if (kind_ == IntegratorKind::rk45) {
    h_next_ = dp_.initial_step(sys_, y_, f_, settings_.rtol, settings_.atol, settings_.h_max);
  }
  set_output(0.0);
}

// ---- events -----------------------------------------------------------------

double ReferenceSolver::event_value(EventKind kind, int k, const PairEvaluation& e) const {
  const double thr = sys_.pair(k).threshold_m;
  switch (kind) {
    case EventKind::declare:
    case EventKind::release: return e.geometry.gap_m - thr;
    case EventKind::press:
    case EventKind::lift: return e.geometry.gap_m;
    case EventKind::unclamp:
    case EventKind::clamp: return e.unclamped_force_n;
    case EventKind::slip_ends: return sys_.modes()[static_cast<std::size_t>(k)].slip_sign * e.slip_rate_mps;
    case EventKind::stick_breaks: return sys_.pair(k).friction * e.force_n - std::abs(e.friction_n);
  }
  return 0.0;
}

bool ReferenceSolver::event_exits(EventKind kind, int k, const PairEvaluation& e) const {
  const double g = event_value(kind, k, e);
  switch (kind) {
    case EventKind::declare: return g <= 0.0;
    case EventKind::release: return g > 0.0;
    case EventKind::press: return g < 0.0;
    case EventKind::unclamp: return g > 0.0;
    case EventKind::clamp: return g < 0.0;
    case EventKind::lift: return g > 0.0;
    case EventKind::slip_ends:
    case EventKind::stick_breaks: return g < 0.0;
  }
  return false;
}

std::optional<ReferenceSolver::Event> ReferenceSolver::first_event(double h) {
  // phase changes due between the step start (pairs_) and its end (pairs1_)
  candidates_.clear();
  for (int k = 0; k < sys_.pair_count(); ++k) {
    const auto ku = static_cast<std::size_t>(k);
    const PairEvaluation& e0 = pairs_[ku];
    const PairEvaluation& e1 = pairs1_[ku];
    // the events that can end the pair's current phase
    EventKind kinds[3];
    int nk = 0;
    switch (sys_.modes()[ku].phase) {
      case ContactPhase::apart: kinds[nk++] = EventKind::declare; break;
      case ContactPhase::touching:
        kinds[nk++] = EventKind::release;
        kinds[nk++] = e0.geometry.gap_m >= 0.0 ? EventKind::press : EventKind::unclamp;
        break;
      case ContactPhase::pressing:
        kinds[nk++] = EventKind::clamp;
        kinds[nk++] = EventKind::lift;
        if (sys_.pair(k).has_friction()) {
          kinds[nk++] = sys_.modes()[ku].slip == SlipPhase::slip ? EventKind::slip_ends
                                                                 : EventKind::stick_breaks;
        }
        break;
    }
    for (int i = 0; i < nk; ++i) {
      const EventKind kind = kinds[i];
      if (!event_exits(kind, k, e1) || event_exits(kind, k, e0)) continue;
      // re-pressing after a clamp only matters while still penetrating
      if (kind == EventKind::unclamp && !(e1.geometry.gap_m < 0.0)) continue;
      candidates_.push_back(
          Candidate{k, kind, event_value(kind, k, e0), event_value(kind, k, e1)});
    }
  }
  if (candidates_.empty()) return std::nullopt;

  // locate each; the earliest wins
  std::optional<Event> best;
  for (const Candidate& c : candidates_) {
    double tau = 0.0;  // a value exactly 0 at the start: the change is due now
    if (c.g0 != 0.0) {
      // bracket [0, h]; probe = the step re-taken with length tau
      auto probe = [&](double x) {
        trial(x);
        const PairEvaluation& e = pairs1_[static_cast<std::size_t>(c.pair)];
        return std::pair<double, bool>(event_value(c.kind, c.pair, e),
                                       event_exits(c.kind, c.pair, e));
      };
      const double tol = 4.0 * kEps * (std::abs(t_) + h);
      tau = locate_event(probe, 0.0, c.g0, h, c.g1, tol, root_method_).hi;
    }
    if (!best || tau < best->tau) best = Event{c.pair, c.kind, tau};
  }
  // the state at the chosen event (the probes moved the trial)
  if (best->tau > 0.0) trial(best->tau);
  return best;
}

void ReferenceSolver::apply(const Event& ev) {
  const auto ku = static_cast<std::size_t>(ev.pair);
  PairMode& m = sys_.modes()[ku];
  const PairEvaluation& e = pairs_[ku];
  EpisodeState& st = open_[ku];
  switch (ev.kind) {
    case EventKind::declare: {
      m.phase = ContactPhase::touching;
      // delta_dot at the onset, latched for Lankarani-Nikravesh (paper eq. 6)
      m.approach_speed_mps = -e.gap_rate_mps;
      const ContactPair& p = sys_.pair(ev.pair);
      st = EpisodeState{};
      st.open = true;
      st.ep.body_a = p.body_a;
      st.ep.body_b = p.body_b;
      st.ep.onset_time_s = t_;
      st.ep.offset_time_s = kNaN;
      st.ep.approach_speed_mps = -e.gap_rate_mps;
      st.ep.separation_speed_mps = kNaN;
      st.ep.restitution = kNaN;
      st.impulse_at_onset_ns = y_[sys_.impulse_index(ev.pair)];
      break;
    }
    case EventKind::release: {
      m.phase = ContactPhase::apart;
      if (st.open) {
        st.ep.offset_time_s = t_;
        st.ep.separation_speed_mps = e.gap_rate_mps;
        st.ep.restitution = st.ep.approach_speed_mps > 0.0
                                ? st.ep.separation_speed_mps / st.ep.approach_speed_mps
                                : kNaN;
        st.ep.impulse_ns = y_[sys_.impulse_index(ev.pair)] - st.impulse_at_onset_ns;
        closed_.push_back(st.ep);
        st.open = false;
      }
      break;
    }
    case EventKind::press:
    case EventKind::unclamp:
      m.phase = ContactPhase::pressing;
      if (sys_.pair(ev.pair).has_friction()) sys_.choose_slip_phase(ev.pair, y_);
      break;
    case EventKind::clamp:
    case EventKind::lift: m.phase = ContactPhase::touching; break;
    case EventKind::slip_ends:
    case EventKind::stick_breaks: sys_.choose_slip_phase(ev.pair, y_); break;
  }
  ++stats_.events;
}

void ReferenceSolver::refresh_and_settle() {
  // a phase change at a point where another is already due (thr = 0, or an
  // initial state in contact) is applied at once, without a step
  for (int iter = 0; iter < 8; ++iter) {
    sys_.derivative(y_, f_);
    pairs_ = sys_.last_pairs();
    std::optional<Event> due;
    for (int k = 0; k < sys_.pair_count() && !due; ++k) {
      const auto ku = static_cast<std::size_t>(k);
      const PairEvaluation& e = pairs_[ku];
      const double s = e.geometry.gap_m;
      const double thr = sys_.pair(k).threshold_m;
      switch (sys_.modes()[ku].phase) {
        case ContactPhase::apart:
          if (s - thr <= 0.0) due = Event{k, EventKind::declare, 0.0};
          break;
        case ContactPhase::touching:
          if (s - thr > 0.0) {
            due = Event{k, EventKind::release, 0.0};
          } else if (s < 0.0 && e.unclamped_force_n > 0.0) {
            due = Event{k, EventKind::press, 0.0};
          }
          break;
        case ContactPhase::pressing:
          if (e.unclamped_force_n < 0.0) {
            due = Event{k, EventKind::clamp, 0.0};
          } else if (s > 0.0) {
            due = Event{k, EventKind::lift, 0.0};
          }
          break;
      }
    }
    if (!due) return;
    apply(*due);
  }
  throw EngineError(fmt::format("reference: contact phases do not settle at t = {:.15g} s", t_));
}

// ---- stepping ---------------------------------------------------------------

double ReferenceSolver::trial(double h) {
  if (kind_ == IntegratorKind::rk45) {
    err1_ = dp_.step(sys_, y_, f_, h, settings_.rtol, settings_.atol, y1_, f1_);
  } else {
    rk4_.step(sys_, y_, f_, h, y1_, f1_);
    err1_ = 0.0;
  }
  pairs1_ = sys_.last_pairs();
  return err1_;
}

double ReferenceSolver::propose_step() const {
  const auto& modes = sys_.modes();
  switch (kind_) {
    case IntegratorKind::fixed:
      return static_cast<double>(grid_next_) * settings_.dt - t_;
    case IntegratorKind::paper: {
      // paper §3.1: the step follows the closest distance
      bool any_declared = false;
      double h = settings_.h_max;
      for (std::size_t k = 0; k < modes.size(); ++k) {
        if (declared(modes[k])) {
          any_declared = true;
          continue;
        }
        const double closing = -pairs_[k].gap_rate_mps;  // m/s
        if (closing > 0.0) {
          const double gap = std::max(pairs_[k].geometry.gap_m, 0.0);
          h = std::min(h, std::clamp(settings_.gap_safety * gap / closing, settings_.h_min,
                                     settings_.h_max));
        }
      }
      return any_declared ? settings_.contact_dt : h;
    }
    case IntegratorKind::rk45: {
      double h = std::min(h_next_, settings_.h_max);
      // no contact can hide inside a step: at most twice the time to close the gap
      for (std::size_t k = 0; k < modes.size(); ++k) {
        const double closing = -pairs_[k].gap_rate_mps;
        if (declared(modes[k]) || !(closing > 0.0)) continue;
        const double to_close = (pairs_[k].geometry.gap_m - sys_.pair(static_cast<int>(k)).threshold_m) / closing;
        h = std::min(h, std::max(2.0 * to_close, 1e-12));
      }
      return h;
    }
  }
  return settings_.h_max;
}

void ReferenceSolver::accept(double h, std::optional<double> exact_end) {
  Segment& sg = seg_[static_cast<std::size_t>(1 - seg_newest_)];
  if (kind_ == IntegratorKind::rk45) {
    dp_.dense(t_, h, y_, y1_, f_, f1_, sg.dense);
  } else {
    sg.dense.set_hermite(t_, h, y_, y1_, f_, f1_);
  }
  sg.modes = sys_.modes();
  seg_newest_ = 1 - seg_newest_;
  seg_count_ = std::min(seg_count_ + 1, 2);

  const double t_before = t_;
  t_ = exact_end ? *exact_end : t_ + h;
  stalled_steps_ = t_ > t_before ? 0 : stalled_steps_ + 1;
  if (stalled_steps_ > kMaxStalledSteps) {
    throw EngineError(fmt::format(
        "reference: no progress: {} steps in a row left t = {:.15g} s where it was (step size "
        "{:.3g} s, below half an ulp of t)",
        kMaxStalledSteps, t_, h));
  }
  y_ = y1_;
  f_ = f1_;
  pairs_ = pairs1_;
  ++stats_.steps;
  ++t_reference_steps;
  if (!y_.allFinite()) {
    throw EngineError(fmt::format("reference: non-finite state at t = {:.15g} s", t_));
  }
  if (stats_.steps > kMaxSteps) {
    throw EngineError(fmt::format("reference: more than {} steps by t = {:.15g} s", kMaxSteps, t_));
  }
  if (stats_.steps % kProgressWindow == 0) {
    const double advanced = t_ - window_t_;
    const double left = std::max(duration_s_ - t_, 0.0);
    const double needed = left / advanced * static_cast<double>(kProgressWindow);
    if (advanced > 0.0 && static_cast<double>(kProgressWindow) / advanced > kMaxStepsPerSimSecond) {
      throw EngineError(fmt::format(
          "reference: too many steps per simulated second: the last {} advanced t by {:.3g} s "
          "(to t = {:.6g} s), {:.3g} per simulated second, beyond the bound {:.0e} (the "
          "stiffest shipped contact takes 4e5): events chattering, or a contact too stiff to "
          "resolve",
          kProgressWindow, advanced, t_, static_cast<double>(kProgressWindow) / advanced,
          kMaxStepsPerSimSecond));
    }
    if (!(advanced > 0.0) || needed > kHopeless) {
      throw EngineError(fmt::format(
          "reference: no progress: the last {} steps advanced t by {:.3g} s (to t = {:.6g} s); "
          "the {:.6g} s left would take {:.3g} steps at that rate, beyond {:.0e} (the step "
          "limit x 100)",
          kProgressWindow, advanced, t_, left, needed, kHopeless));
    }
    window_t_ = t_;
  }
  if (const std::string why = sys_.beyond_geometry(y_); !why.empty()) {
    throw EngineError(fmt::format("reference: {} at t = {:.15g} s", why, t_));
  }
  stats_.constraint_drift_m = std::max(stats_.constraint_drift_m, sys_.joint_violation_m(y_));
}

void ReferenceSolver::step(double t_limit) {
  double h = propose_step();
  std::optional<double> land;
  if (kind_ == IntegratorKind::fixed) {
    land = static_cast<double>(grid_next_) * settings_.dt;
  } else if (t_ + h >= t_limit) {
    h = t_limit - t_;
    land = t_limit;
  }

  // trial steps until one passes the error test (rk45)
  bool rejected = false;
  for (;;) {
    const double err = trial(h);
    if (kind_ != IntegratorKind::rk45 || err <= 1.0) break;
    ++stats_.rejected;
    rejected = true;
    h *= std::max(0.1, 0.9 * std::pow(err, -0.2));
    land.reset();
    if (h < 1e-14 * std::max(1.0, std::abs(t_))) {
      throw EngineError(fmt::format("reference: step size underflow at t = {:.15g} s", t_));
    }
  }
  const double h_tried = h;
  const double err = err1_;

  const std::optional<Event> ev = first_event(h);
  if (ev) {
    if (ev->tau > 0.0) {
      accept(ev->tau, std::nullopt);
      zero_length_events_ = 0;
    } else if (++zero_length_events_ > 8) {
      throw EngineError(fmt::format("reference: contact chatters at t = {:.15g} s", t_));
    }
    apply(*ev);
    refresh_and_settle();
  } else {
    accept(h, land);
    zero_length_events_ = 0;
    if (kind_ == IntegratorKind::fixed) ++grid_next_;
  }
  if (!ev || ev->tau > 0.0) record_samples();

  if (kind_ == IntegratorKind::rk45) {
    // HNW I §II.4: h_new = h * min(facmax, max(facmin, 0.9 err^(-1/5)))
    const double fac = err > 0.0 ? 0.9 * std::pow(err, -0.2) : 5.0;
    h_next_ = h_tried * std::clamp(fac, 0.2, rejected ? 1.0 : 5.0);
  }
}

void ReferenceSolver::advance_to(double t_s) {
  if (t_s < t_out_) {
    throw EngineError(fmt::format("reference: advance_to({}) before the current time {}", t_s, t_out_));
  }
  switch (kind_) {
    case IntegratorKind::rk45: {
      const double t_stop = std::max(duration_s_, t_s);
      while (t_ < t_s) step(t_stop);
      set_output(t_s);
      break;
    }
    case IntegratorKind::paper:
      while (t_ < t_s) step(t_s);
      set_output(t_);
      break;
    case IntegratorKind::fixed:
      while (static_cast<double>(grid_next_) * settings_.dt <= t_s + 1e-9 * settings_.dt) {
        step(t_s);
      }
      set_output(t_);
      break;
  }
}

// ---- episodes ---------------------------------------------------------------

const ReferenceSolver::Segment& ReferenceSolver::segment_at(double t_s) const {
  const Segment& newest = seg_[static_cast<std::size_t>(seg_newest_)];
  const Segment& older = seg_[static_cast<std::size_t>(1 - seg_newest_)];
  return (seg_count_ > 1 && t_s <= older.dense.t1_s()) ? older : newest;
}

void ReferenceSolver::record_samples() {
  for (int k = 0; k < sys_.pair_count(); ++k) {
    const auto ku = static_cast<std::size_t>(k);
    EpisodeState& st = open_[ku];
    if (!st.open) continue;
    const Sample s{t_, std::max(pairs_[ku].force_n, 0.0), pairs_[ku].geometry.penetration_m()};
    st.ep.peak_force_n = std::max(st.ep.peak_force_n, s.force_n);
    st.ep.max_penetration_m = std::max(st.ep.max_penetration_m, s.penetration_m);
    st.last[0] = st.last[1];
    st.last[1] = st.last[2];
    st.last[2] = s;
    ++st.samples;
    if (st.samples >= 3 && seg_count_ == 2) refine_peaks(k, st);
  }
}

void ReferenceSolver::refine_peaks(int k, EpisodeState& st) {
  const Sample& a = st.last[0];
  const Sample& m = st.last[1];
  const Sample& b = st.last[2];
  const auto ku = static_cast<std::size_t>(k);
  // the two newest steps must be exactly [a, m] and [m, b]
  const Segment& older = seg_[static_cast<std::size_t>(1 - seg_newest_)];
  if (older.dense.t0_s != a.t_s) return;
  auto is_peak = [&](double va, double vm, double vb, double running) {
    return vm > 0.0 && vm >= va && vm >= vb && (vm > va || vm > vb) && vm >= kPeakWindow * running;
  };
  auto evaluate_at = [&](double t) {
    const Segment& sg = segment_at(t);
    sg.dense.evaluate(t, y_tmp_);
    return sys_.evaluate_pair(k, y_tmp_, sg.modes[ku]);
  };
  if (is_peak(a.force_n, m.force_n, b.force_n, st.ep.peak_force_n)) {
    st.ep.peak_force_n = golden_max(
        [&](double t) { return std::max(evaluate_at(t).force_n, 0.0); }, a.t_s, b.t_s,
        st.ep.peak_force_n);
  }
  if (is_peak(a.penetration_m, m.penetration_m, b.penetration_m, st.ep.max_penetration_m)) {
    st.ep.max_penetration_m = golden_max(
        [&](double t) { return evaluate_at(t).geometry.penetration_m(); }, a.t_s, b.t_s,
        st.ep.max_penetration_m);
  }
}

std::vector<ContactEpisode> ReferenceSolver::episodes() const {
  std::vector<ContactEpisode> all = closed_;
  for (std::size_t k = 0; k < open_.size(); ++k) {
    if (!open_[k].open) continue;
    ContactEpisode ep = open_[k].ep;
    ep.impulse_ns = y_[sys_.impulse_index(static_cast<int>(k))] - open_[k].impulse_at_onset_ns;
    all.push_back(ep);
  }
  std::stable_sort(all.begin(), all.end(), [](const ContactEpisode& x, const ContactEpisode& y) {
    return x.onset_time_s < y.onset_time_s;
  });
  return all;
}

// ---- output -----------------------------------------------------------------

void ReferenceSolver::set_output(double t_s) {
  t_out_ = t_s;
  if (t_s >= t_ || seg_count_ == 0) {
    y_out_ = y_;
    out_modes_ = sys_.modes();
    out_pairs_ = pairs_;
    return;
  }
  // between steps (rk45): the dense output of the step holding t_s, with the
  // phases of that step
  const Segment& sg = segment_at(t_s);
  if (t_s < sg.dense.t0_s) {
    throw EngineError(fmt::format("reference: output time {} before the kept steps", t_s));
  }
  sg.dense.evaluate(t_s, y_out_);
  out_modes_ = sg.modes;
  if (sys_.has_friction()) {
    // the friction forces need the whole derivative (issue 32: stored per sample)
    sys_.evaluate_with_friction(y_out_, out_modes_, out_pairs_);
    return;
  }
  out_pairs_.resize(out_modes_.size());
  for (int k = 0; k < sys_.pair_count(); ++k) {
    const auto ku = static_cast<std::size_t>(k);
    if (declared(out_modes_[ku])) out_pairs_[ku] = sys_.evaluate_pair(k, y_out_, out_modes_[ku]);
  }
}

BodyState ReferenceSolver::body_state(int body) const { return sys_.body_state(body, y_out_); }

void ReferenceSolver::contacts(std::vector<ContactSample>& out) const {
  out.clear();
  for (int k = 0; k < sys_.pair_count(); ++k) {
    const auto ku = static_cast<std::size_t>(k);
    if (!declared(out_modes_[ku])) continue;
    const PairEvaluation& e = out_pairs_[ku];
    ContactSample cs;
    cs.body_a = sys_.pair(k).body_a;
    cs.body_b = sys_.pair(k).body_b;
    cs.force_n = std::max(e.force_n, 0.0);
    cs.penetration_m = e.geometry.penetration_m();
    cs.normal = e.geometry.normal;
    cs.point_m = 0.5 * (e.geometry.point_a_m + e.geometry.point_b_m);
    // friction_n is along (n.y, -n.x), the opposite of the stored tangent
    cs.tangential_force_n = e.friction_n == 0.0 ? 0.0 : -e.friction_n;
    out.push_back(cs);
  }
}

SolverStats ReferenceSolver::stats() const {
  SolverStats s = stats_;
  s.rhs_evaluations = sys_.evaluations();
  return s;
}

double ReferenceSolver::energy_j() const { return sys_.energy_j(y_out_); }

double ReferenceSolver::friction_dissipation_j() const {
  if (!sys_.has_friction()) return 0.0;
  double w = 0.0;
  for (int k = 0; k < sys_.pair_count(); ++k) w += y_out_[sys_.dissipation_index(k)];
  return w;
}

double ReferenceSolver::tangential_impulse_ns(int k) const {
  return sys_.has_friction() ? y_out_[sys_.tangential_impulse_index(k)] : 0.0;
}

}  // namespace pb
