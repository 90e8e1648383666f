#include "hybrid_integration.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <functional>
#include <limits>

#include "planarbench/errors.hpp"

namespace pb::independent {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
namespace odeint = boost::numeric::odeint;

// bits of t for Brent's minimiser: 1e-15 relative is below anything the
// dense output resolves, and the peak's value is flat to second order there
constexpr int kBrentBits = 50;

}  // namespace

HybridIntegration::HybridIntegration(const Case& c, const IntegrationSettings& s)
    : case_(c),
      settings_(s),
      model_(c, c.contacts.size()),
      dense_(odeint::make_dense_output(s.abs_tol, s.rel_tol, s.max_step_s,
                                       odeint::runge_kutta_dopri5<State>())) {
  for (const ContactPair& cp : c.contacts) {
    pairs_.emplace_back(cp);
  }
  segment_start_ = model_.initial_state();
  now_ = segment_start_;
  // the first step's size: the controller shrinks it as needed
  dense_.initialize(segment_start_, 0.0, std::min(1e-6, s.max_step_s));
}

PairContact HybridIntegration::contact_at(std::size_t p, const std::vector<BodyMotion>& m) const {
  const auto a = static_cast<std::size_t>(pairs_[p].a);
  const auto b = static_cast<std::size_t>(pairs_[p].b);
  return pair_contact(case_.bodies[a].shape, m[a], case_.bodies[b].shape, m[b]);
}

PairContact HybridIntegration::contact_at(std::size_t p, const State& x) const {
  model_.motions(x, motions_);
  return contact_at(p, motions_);
}

double HybridIntegration::force_n(const Pair& p, const PairContact& c) const {
  if (p.mode != Mode::pressing) return 0.0;
  return std::max(0.0, p.law.unclamped_force_n(c.depth_m, c.depth_rate_mps, p.approach_mps));
}

void HybridIntegration::rhs(const State& x, State& dxdt) const {
  model_.motions(x, motions_);
  forces_.clear();
  const std::size_t first_impulse = model_.first_extra();
  for (std::size_t p = 0; p < pairs_.size(); ++p) {
    double f = 0.0;  // N
    if (pairs_[p].mode == Mode::pressing) {
      const PairContact c = contact_at(p, motions_);
      // unclamped: the smooth law of this mode (the clamp is a mode of its own)
      f = pairs_[p].law.unclamped_force_n(c.depth_m, c.depth_rate_mps, pairs_[p].approach_mps);
      forces_.push_back({pairs_[p].b, f * c.normal, c.point_b_m});
      forces_.push_back({pairs_[p].a, -f * c.normal, c.point_a_m});
    }
    dxdt[first_impulse + p] = f;
  }
  model_.derivative(motions_, forces_, dxdt);
}

bool HybridIntegration::fires(const Pair& p, EventKind kind, const PairContact& c) const {
  switch (kind) {
    case EventKind::onset:
      return c.depth_m > 0.0;
    case EventKind::offset:
      return !(c.depth_m > 0.0);
    case EventKind::clamp:
      return p.law.pushes(c.depth_m, c.depth_rate_mps, p.approach_mps) < 0.0;
    case EventKind::press:
      return p.law.pushes(c.depth_m, c.depth_rate_mps, p.approach_mps) > 0.0;
    case EventKind::second_vertex:
      return c.next_vertex_depth_m > 0.0;
  }
  return false;
}

// the event's time in (lo, hi]: lo is where the mode's expectation held (the
// step's start, or the restart at an event, where the function is ~0 and its
// sign is taken as expected), hi where the event fires; halved to the last
// bit, the first time known to fire is returned
double HybridIntegration::locate(std::size_t p, EventKind kind, double lo_s, double hi_s) const {
  State x(model_.state_size());
  for (int i = 0; i < 200; ++i) {  // 200 halvings exhaust any interval of doubles >= 0
    const double mid = 0.5 * (lo_s + hi_s);
    if (mid <= lo_s || mid >= hi_s) break;
    dense_.calc_state(mid, x);
    if (fires(pairs_[p], kind, contact_at(p, x))) {
      hi_s = mid;
    } else {
      lo_s = mid;
    }
  }
  return hi_s;
}

// the peak force and the largest penetration of every overlapping pair over
// [t0, t1] of the last step's dense output
void HybridIntegration::track_extremes(double t0_s, double t1_s) {
  State x(model_.state_size());
  for (std::size_t p = 0; p < pairs_.size(); ++p) {
    Pair& pr = pairs_[p];
    if (pr.mode == Mode::apart || !pr.open) continue;
    const auto force_at = [&](double t) {
      dense_.calc_state(t, x);
      return force_n(pr, contact_at(p, x));
    };
    const auto depth_at = [&](double t) {
      dense_.calc_state(t, x);
      return contact_at(p, x).depth_m;
    };
    const auto largest = [&](const auto& f) {
      constexpr int kSamples = 6;
      std::array<double, kSamples> t{};
      std::array<double, kSamples> v{};
      int best = 0;
      for (int k = 0; k < kSamples; ++k) {
        t[k] = t0_s + (t1_s - t0_s) * k / (kSamples - 1);
        v[k] = f(t[k]);
        if (v[k] > v[best]) best = k;
      }
      // the largest sample's neighbours bracket the maximum (at an end of the
      // step too: a maximum just inside it would be missed by both steps'
      // samples otherwise)
      const auto r = boost::math::tools::brent_find_minima(
          [&](double s) { return -f(s); }, t[std::max(best - 1, 0)],
          t[std::min(best + 1, kSamples - 1)], kBrentBits);
      return std::max(v[best], -r.second);
    };
    if (pr.mode == Mode::pressing) {
      pr.episode.peak_force_n = std::max(pr.episode.peak_force_n, largest(force_at));
    }
    pr.episode.max_penetration_m = std::max(pr.episode.max_penetration_m, largest(depth_at));
  }
}

void HybridIntegration::step() {
  const auto system = [this](const State& x, State& dxdt, double) { rhs(x, dxdt); };
  const auto [t0, t1] = dense_.do_step(system);
  ++steps_;
  segment_stepped_ = true;
  const State& x1 = dense_.current_state();
  model_.motions(x1, motions_);
  std::optional<Event> first;
  for (std::size_t p = 0; p < pairs_.size(); ++p) {
    const PairContact c = contact_at(p, motions_);
    std::vector<EventKind> kinds;
    switch (pairs_[p].mode) {
      case Mode::apart:
        kinds = {EventKind::onset};
        break;
      case Mode::pressing:
        kinds = {EventKind::offset, EventKind::clamp, EventKind::second_vertex};
        break;
      case Mode::clamped:
        kinds = {EventKind::offset, EventKind::press, EventKind::second_vertex};
        break;
    }
    for (EventKind k : kinds) {
      if (!fires(pairs_[p], k, c)) continue;
      const double te = locate(p, k, t0, t1);
      if (!first || te < first->t_s) first = Event{te, p, k};
    }
  }
  track_extremes(t0, first ? first->t_s : t1);
  pending_ = first;
}

void HybridIntegration::apply(const Event& e) {
  State x(model_.state_size());
  dense_.calc_state(e.t_s, x);
  Pair& p = pairs_[e.pair];
  const PairContact c = contact_at(e.pair, x);
  const double impulse = x[model_.first_extra() + e.pair];  // N s
  switch (e.kind) {
    case EventKind::onset:
      p.approach_mps = c.depth_rate_mps;
      p.mode = p.law.pushes(c.depth_m, c.depth_rate_mps, p.approach_mps) < 0.0 ? Mode::clamped
                                                                               : Mode::pressing;
      p.open = true;
      p.impulse_at_onset_ns = impulse;
      p.episode = ContactEpisode{};
      p.episode.body_a = p.a;
      p.episode.body_b = p.b;
      p.episode.onset_time_s = e.t_s;
      p.episode.offset_time_s = kNaN;
      p.episode.approach_speed_mps = c.depth_rate_mps;
      p.episode.separation_speed_mps = kNaN;
      p.episode.restitution = kNaN;
      p.episode.peak_force_n = force_n(p, c);
      p.episode.impulse_ns = 0.0;
      p.episode.max_penetration_m = std::max(0.0, c.depth_m);
      break;
    case EventKind::offset:
      p.mode = Mode::apart;
      p.open = false;
      p.episode.offset_time_s = e.t_s;
      p.episode.separation_speed_mps = -c.depth_rate_mps;
      p.episode.restitution = p.episode.separation_speed_mps / p.episode.approach_speed_mps;
      p.episode.impulse_ns = impulse - p.impulse_at_onset_ns;
      closed_.push_back(p.episode);
      break;
    case EventKind::clamp:
      p.mode = Mode::clamped;
      break;
    case EventKind::press:
      p.mode = Mode::pressing;
      break;
    case EventKind::second_vertex:
      throw EngineError(fmt::format(
          "independent truth: at t = {:.9g} s a second vertex of pair '{}' reaches the line; "
          "only a single-vertex polygon contact is handled",
          e.t_s, p.name));
  }
  segment_start_ = x;
  dense_.initialize(x, e.t_s, dense_.current_time_step());
  segment_stepped_ = false;
  pending_.reset();
}

void HybridIntegration::advance_to(double t_s) {
  if (!(t_s >= time_s_) || !std::isfinite(t_s)) {
    throw EngineError(
        fmt::format("independent truth: cannot advance from t = {} s to t = {} s", time_s_, t_s));
  }
  while (true) {
    if (pending_ && t_s > pending_->t_s) {
      apply(*pending_);
      continue;
    }
    // how far the states are known: the dense output's end (the restart's
    // time before a step), or a located event's time
    const double reach = pending_ ? pending_->t_s : dense_.current_time();
    if (t_s <= reach) break;
    step();
  }
  time_s_ = t_s;
  if (segment_stepped_) {
    now_.resize(model_.state_size());
    dense_.calc_state(t_s, now_);
  } else {
    now_ = segment_start_;
  }
}

void HybridIntegration::body_states(std::vector<BodyState>& out) const {
  std::vector<BodyMotion> m;
  model_.motions(now_, m);
  out.resize(m.size());
  for (std::size_t i = 0; i < m.size(); ++i) {
    out[i].position_m = m[i].pose.centre_m;
    out[i].angle_rad = m[i].pose.angle_rad;
    out[i].velocity_mps = m[i].velocity_mps;
    out[i].angular_velocity_radps = m[i].angular_velocity_radps;
  }
}

void HybridIntegration::contacts(std::vector<ContactSample>& out) const {
  out.clear();
  for (std::size_t p = 0; p < pairs_.size(); ++p) {
    if (pairs_[p].mode == Mode::apart) continue;
    const PairContact c = contact_at(p, now_);
    if (!(c.depth_m > 0.0)) continue;
    ContactSample s;
    s.body_a = pairs_[p].a;
    s.body_b = pairs_[p].b;
    s.force_n = force_n(pairs_[p], c);
    s.penetration_m = c.depth_m;
    s.normal = c.normal;
    s.point_m = c.point_m();
    out.push_back(s);
  }
}

std::vector<ContactEpisode> HybridIntegration::episodes() const {
  std::vector<ContactEpisode> out = closed_;
  for (std::size_t p = 0; p < pairs_.size(); ++p) {
    if (!pairs_[p].open) continue;
    ContactEpisode ep = pairs_[p].episode;
    ep.impulse_ns = now_[model_.first_extra() + p] - pairs_[p].impulse_at_onset_ns;
    out.push_back(ep);
  }
  std::sort(out.begin(), out.end(), [](const ContactEpisode& x, const ContactEpisode& y) {
    return x.onset_time_s < y.onset_time_s;
  });
  return out;
}

double HybridIntegration::energy() const {
  std::vector<BodyMotion> m;
  model_.motions(now_, m);
  return model_.energy(m);
}

std::vector<std::string> HybridIntegration::laws() const {
  std::vector<std::string> out;
  for (const Pair& p : pairs_) out.push_back(fmt::format("{}: {}", p.name, p.law.describe()));
  return out;
}

}  // namespace pb::independent
