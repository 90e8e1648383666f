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
// A pair's phase changes at most twice at one instant (apart -> touching ->
// pressing, a contact that starts pressed in): each change is due on the
// pair's own geometry and law, which the change of phase leaves as they were
// (the next is the other way only if its condition is the opposite's, which
// the strict inequalities exclude). Four leaves room and names the pair.
constexpr int kMaxSettleChanges = 4;
// zero-length events of one pair in a row (its event function exactly 0 at
// a step's start, again and again: the pair chatters)
constexpr int kMaxZeroLengthEvents = 8;

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
  sys_.initial_state(y_);
  // a scene's group pairs near at t = 0 get their slots before the first step
  const Eigen::Index declared_size = y_.size();
  sys_.update_near(y_);
  const int n = sys_.state_size();
  y_.conservativeResize(n);
  y_.tail(n - declared_size).setZero();
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
  for (const int k : sys_.active()) {
    if (!grazing_.empty() && std::find(grazing_.begin(), grazing_.end(), k) != grazing_.end()) continue;
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
      // A pair slipping against its latched direction faster than the stick
      // speed is due now: its slip began from rest the way the load drove it
      // and the motion went the other way, as when two pairs of a body broke
      // their stick together (a pyramid's top brick, issue 44: both slipped,
      // one pushing along its slip, and the brick walked 3.5 cm in 2 s). Its
      // event function was past its bound at the step's start, so no crossing
      // would ever be located.
      if (kind == EventKind::slip_ends && event_value(kind, k, e0) < -kStickSpeed_mps) {
        candidates_.push_back(Candidate{k, kind, 0.0, event_value(kind, k, e1)});
        continue;
      }
      if (!event_exits(kind, k, e1) || event_exits(kind, k, e0)) continue;
      // re-pressing after a clamp only matters while still penetrating
      if (kind == EventKind::unclamp && !(e1.geometry.gap_m < 0.0)) continue;
      candidates_.push_back(
          Candidate{k, kind, event_value(kind, k, e0), event_value(kind, k, e1)});
    }
  }
  if (candidates_.empty()) return std::nullopt;

  // The earliest wins. Each candidate is located over the whole step [0, h],
  // and in the order of its secant estimate; once one is located at tau*, a
  // candidate whose event has not happened by tau* (the trial re-taken to
  // tau*) happens later and is not located: a scene's step with dozens of
  // candidates locates about one, where each location is up to 200 trials of
  // every pair (before: all of them). Ties keep the first in pair order.
  order_.resize(candidates_.size());
  for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = i;
  auto estimate = [&](const Candidate& c) { return c.g0 == 0.0 ? 0.0 : c.g0 / (c.g0 - c.g1); };
  if (candidates_.size() > 1) {
    std::stable_sort(order_.begin(), order_.end(), [&](std::size_t x, std::size_t y) {
      return estimate(candidates_[x]) < estimate(candidates_[y]);
    });
  }
  std::optional<Event> best;
  std::size_t best_index = 0;
  double checked_at = -1.0;  // s, the tau the trial state now holds (-1: none)
  // A scene's event is found first on the step's dense output, the pair's own
  // geometry at interpolated poses (no derivative of every pair), then the
  // trial is taken to that time once: the event has happened there, or it is
  // located on trials from there to the step's end (a few). Each of a pile's
  // thousands of events cost ~40 trials of every pair before. The shipped
  // cases (no groups) locate on trials alone, as always: their bits.
  const bool dense_first = sys_.has_groups();
  if (dense_first && !candidates_.empty()) {
    if (kind_ == IntegratorKind::rk45) {
      dp_.dense(t_, h, y_, y1_, f_, f1_, trial_dense_);
    } else {
      trial_dense_.set_hermite(t_, h, y_, y1_, f_, f1_);
    }
  }
  for (const std::size_t i : order_) {
    const Candidate& c = candidates_[i];
    if (best) {
      if (checked_at != best->tau) {
        trial(best->tau);
        checked_at = best->tau;
      }
      if (!event_exits(c.kind, c.pair, pairs1_[static_cast<std::size_t>(c.pair)])) continue;
    }
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
      // slip and stick need the friction of every pair: trials only
      const bool on_dense = dense_first && c.kind != EventKind::slip_ends &&
                            c.kind != EventKind::stick_breaks;
      if (on_dense) {
        auto dense_probe = [&](double x) {
          trial_dense_.evaluate(t_ + x, y_tmp_);
          const PairEvaluation e = sys_.evaluate_pair(c.pair, y_tmp_, sys_.modes()[static_cast<std::size_t>(c.pair)]);
          return std::pair<double, bool>(event_value(c.kind, c.pair, e),
                                         event_exits(c.kind, c.pair, e));
        };
        const double tau_d = locate_event(dense_probe, 0.0, c.g0, h, c.g1, tol, root_method_).hi;
        // then on the trials, in a bracket the dense estimate narrowed: from
        // tau_d on if it has not happened there, else back from tau_d in
        // widening strides (the interpolant's error is a tiny part of h)
        const auto [g_d, exits_d] = probe(tau_d);
        double lo = 0.0, g_lo = c.g0, hi = h, g_hi = c.g1;
        if (!exits_d) {
          lo = tau_d;
          g_lo = g_d;
        } else {
          hi = tau_d;
          g_hi = g_d;
          for (double w = std::max(tol, 1e-3 * tau_d); tau_d - w > 0.0; w *= 16.0) {
            const auto [g_x, exits_x] = probe(tau_d - w);
            if (!exits_x) {
              lo = tau_d - w;
              g_lo = g_x;
              break;
            }
            hi = tau_d - w;
            g_hi = g_x;
          }
        }
        tau = locate_event(probe, lo, g_lo, hi, g_hi, tol, root_method_).hi;
        checked_at = -1.0;
      } else {
        tau = locate_event(probe, 0.0, c.g0, h, c.g1, tol, root_method_).hi;
        checked_at = -1.0;
      }
    }
    if (!best || tau < best->tau || (tau == best->tau && i < best_index)) {
      best = Event{c.pair, c.kind, tau};
      best_index = i;
    }
  }
  // the state at the chosen event (the probes moved the trial)
  if (best->tau > 0.0 && checked_at != best->tau) trial(best->tau);
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

std::optional<ReferenceSolver::Event> ReferenceSolver::due_now(int k, const PairEvaluation& e) const {
  const double s = e.geometry.gap_m;
  const double thr = sys_.pair(k).threshold_m;
  switch (sys_.modes()[static_cast<std::size_t>(k)].phase) {
    case ContactPhase::apart:
      if (s - thr <= 0.0) return Event{k, EventKind::declare, 0.0};
      break;
    case ContactPhase::touching:
      if (s - thr > 0.0) return Event{k, EventKind::release, 0.0};
      if (s < 0.0 && e.unclamped_force_n > 0.0) return Event{k, EventKind::press, 0.0};
      break;
    case ContactPhase::pressing:
      if (e.unclamped_force_n < 0.0) return Event{k, EventKind::clamp, 0.0};
      if (s > 0.0) return Event{k, EventKind::lift, 0.0};
      break;
  }
  return std::nullopt;
}

void ReferenceSolver::refresh_and_settle() {
  // A phase change at a point where another is already due (thr = 0, or an
  // initial state in contact: a scene pressed in at its static pose) is
  // applied at once, without a step. Whether a pair's change is due depends
  // on its own geometry and law alone, so the pairs settle one after another,
  // each until nothing of it is due; the whole derivative is taken once they
  // have (before: one change a pass and 8 passes, so that four pairs pressed
  // in at t = 0 could not start).
  sys_.derivative(y_, f_);
  pairs_ = sys_.last_pairs();
  bool changed = false;
  for (const int k : sys_.active()) {
    const auto ku = static_cast<std::size_t>(k);
    for (int changes = 0;; ++changes) {
      const std::optional<Event> due = due_now(k, pairs_[ku]);
      if (!due) break;
      if (changes == kMaxSettleChanges) {
        throw EngineError(fmt::format(
            "reference: contact '{}' does not settle at t = {:.15g} s: its phase changed {} times "
            "at that instant (gap {:.6g} m, law force {:.6g} N)",
            sys_.pair(k).name, t_, changes, pairs_[ku].geometry.gap_m,
            pairs_[ku].unclamped_force_n));
      }
      apply(*due);
      changed = true;
      pairs_[ku] = sys_.evaluate_pair(k, y_, sys_.modes()[ku]);
    }
  }
  if (changed) {
    sys_.derivative(y_, f_);
    pairs_ = sys_.last_pairs();
  }
}

void ReferenceSolver::grow_state() {
  const int n = sys_.state_size();
  auto grow = [n](Eigen::VectorXd& v) {
    const Eigen::Index m = v.size();
    if (m == 0 || m == n) return;
    v.conservativeResize(n);
    v.tail(n - m).setZero();
  };
  for (Eigen::VectorXd* v : {&y_, &f_, &y_out_}) grow(*v);
  // the kept steps: the new pairs' slots were 0 through them, their phase apart
  const auto pairs = static_cast<std::size_t>(sys_.pair_count());
  for (Segment& sg : seg_) {
    for (Eigen::VectorXd* c : {&sg.dense.c0, &sg.dense.c1, &sg.dense.c2, &sg.dense.c3, &sg.dense.c4}) {
      grow(*c);
    }
    sg.modes.resize(pairs);
  }
  out_modes_.resize(pairs);
  out_pairs_.resize(pairs);
  open_.resize(pairs);
  pairs_.resize(pairs);
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
      for (const int ki : sys_.active()) {
        const auto k = static_cast<std::size_t>(ki);
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
      for (const int ki : sys_.active()) {
        const auto k = static_cast<std::size_t>(ki);
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
  // a scene's broad phase: the near group pairs, rebuilt when due
  if (sys_.update_near(y_)) {
    grow_state();
    sys_.derivative(y_, f_);
    pairs_ = sys_.last_pairs();
  }
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
    // a trial that moves a group body past its broad-phase margin could
    // miss a contact (near_pairs.hpp): shorter
    const double excursion = sys_.near_excursion(y1_);
    const bool too_far = excursion >= 1.0;
    if (too_far && kind_ != IntegratorKind::rk45) {
      throw EngineError(fmt::format(
          "reference: a body moved {:.3g} times its broad-phase margin in one {} step of {:.3g} s "
          "at t = {:.15g} s: a contact could be missed; use a shorter dt or integrator rk45",
          excursion, kind_ == IntegratorKind::fixed ? "fixed" : "paper", h, t_));
    }
    if (!too_far && (kind_ != IntegratorKind::rk45 || err <= 1.0)) break;
    ++stats_.rejected;
    rejected = true;
    h *= too_far ? 0.5 : std::max(0.1, 0.9 * std::pow(err, -0.2));
    land.reset();
    if (h < 1e-14 * std::max(1.0, std::abs(t_))) {
      throw EngineError(fmt::format("reference: step size underflow at t = {:.15g} s", t_));
    }
  }
  const double h_tried = h;
  const double err = err1_;

  std::optional<Event> ev = first_event(h);
  // A zero-length event that would undo this pair's last one at this very
  // instant: the pair sits on the boundary of both phases, its gap and rate
  // at the rounding of the state (bodies released touching at rest: a
  // pyramid's bricks fall together, every gap 0 +- 1e-17 m, and press and
  // clamp each found the other due, without end). It keeps its phase for
  // this step; the step's end decides it (settle_grazing). A contact that
  // flips this way is one whose force is 0 either way.
  while (ev && ev->tau == 0.0 && undoes_zero_length_event(*ev)) {
    grazing_.push_back(ev->pair);
    trial(h);  // the located probes moved the trial: the step's end again
    ev = first_event(h);
  }
  if (ev) {
    if (ev->tau > 0.0) {
      accept(ev->tau, std::nullopt);
      zero_length_events_.clear();
    } else {
      count_zero_length_event(*ev);
    }
    const ContactPhase before = sys_.modes()[static_cast<std::size_t>(ev->pair)].phase;
    apply(*ev);
    refresh_and_settle();
    // ... or one the settle undid at once (pressed at a gap of exactly 0
    // with the law's force at -0: clamped back): held the same way
    if (ev->tau == 0.0 && sys_.modes()[static_cast<std::size_t>(ev->pair)].phase == before) {
      grazing_.push_back(ev->pair);
    }
  } else {
    accept(h, land);
    zero_length_events_.clear();
    if (kind_ == IntegratorKind::fixed) ++grid_next_;
  }
  if (!ev || ev->tau > 0.0) record_samples();
  if (!ev || ev->tau > 0.0) settle_grazing();

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

namespace {
// the contact phase an event leads to (slip events keep it)
ContactPhase phase_after(int kind, ContactPhase now) {
  switch (kind) {
    case 0: return ContactPhase::touching;  // declare
    case 1: return ContactPhase::apart;     // release
    case 2:                                 // press
    case 3: return ContactPhase::pressing;  // unclamp
    case 4:                                 // clamp
    case 5: return ContactPhase::touching;  // lift
    default: return now;
  }
}
}  // namespace

bool ReferenceSolver::undoes_zero_length_event(const Event& ev) const {
  const auto it = std::find_if(zero_length_events_.begin(), zero_length_events_.end(),
                               [&](const ZeroLength& z) { return z.pair == ev.pair; });
  if (it == zero_length_events_.end()) return false;
  const ContactPhase now = sys_.modes()[static_cast<std::size_t>(ev.pair)].phase;
  const ContactPhase next = phase_after(static_cast<int>(ev.kind), now);
  return next != now && next == it->phase_before;
}

void ReferenceSolver::settle_grazing() {
  if (grazing_.empty()) return;
  bool changed = false;
  for (const int k : grazing_) {
    const auto ku = static_cast<std::size_t>(k);
    for (int changes = 0; changes < kMaxSettleChanges; ++changes) {
      const std::optional<Event> due = due_now(k, pairs_[ku]);
      if (!due) break;
      apply(*due);
      changed = true;
      pairs_[ku] = sys_.evaluate_pair(k, y_, sys_.modes()[ku]);
    }
  }
  grazing_.clear();
  if (changed) {
    sys_.derivative(y_, f_);
    pairs_ = sys_.last_pairs();
  }
}

void ReferenceSolver::count_zero_length_event(const Event& ev) {
  // per pair: several pairs due at one instant are each one event, not chatter
  auto it = std::find_if(zero_length_events_.begin(), zero_length_events_.end(),
                         [&](const ZeroLength& z) { return z.pair == ev.pair; });
  if (it == zero_length_events_.end()) {
    const PairMode& m = sys_.modes()[static_cast<std::size_t>(ev.pair)];
    zero_length_events_.push_back(ZeroLength{ev.pair, 0, m.phase});
    it = zero_length_events_.end() - 1;
  }
  if (++it->count > kMaxZeroLengthEvents) {
    const PairEvaluation& e = pairs_[static_cast<std::size_t>(ev.pair)];
    throw EngineError(fmt::format(
        "reference: contact '{}' chatters at t = {:.15g} s: {} phase changes in a row without a "
        "step between them (gap {:.6g} m, law force {:.6g} N)",
        sys_.pair(ev.pair).name, t_, it->count, e.geometry.gap_m, e.unclamped_force_n));
  }
}

// ---- episodes ---------------------------------------------------------------

const ReferenceSolver::Segment& ReferenceSolver::segment_at(double t_s) const {
  const Segment& newest = seg_[static_cast<std::size_t>(seg_newest_)];
  const Segment& older = seg_[static_cast<std::size_t>(1 - seg_newest_)];
  return (seg_count_ > 1 && t_s <= older.dense.t1_s()) ? older : newest;
}

void ReferenceSolver::record_samples() {
  for (const int k : sys_.active()) {
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
  for (const int k : sys_.active()) {
    const auto ku = static_cast<std::size_t>(k);
    if (declared(out_modes_[ku])) out_pairs_[ku] = sys_.evaluate_pair(k, y_out_, out_modes_[ku]);
  }
}

BodyState ReferenceSolver::body_state(int body) const { return sys_.body_state(body, y_out_); }

void ReferenceSolver::contacts(std::vector<ContactSample>& out) const {
  out.clear();
  for (std::size_t ku = 0; ku < out_modes_.size(); ++ku) {
    const int k = static_cast<int>(ku);
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
