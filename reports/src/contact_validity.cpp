#include "planarbench/reports/contact_validity.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <variant>

#include "planarbench/contact_force.hpp"
#include "planarbench/contact_slip.hpp"

namespace pb {

namespace {

// relative floors of the fractions: a violation this small is rounding
constexpr double kRelativeFloor = 1e-6;
constexpr double kCreepFloor_mps = 1e-6;

// max, nearest-rank 99th percentile, fraction above `floor`
ValiditySeries summarise(std::vector<double> v, double floor) {
  ValiditySeries s;
  s.floor = floor;
  s.samples = static_cast<int>(v.size());
  if (v.empty()) return s;
  std::sort(v.begin(), v.end());
  s.max = v.back();
  // nearest rank: the ceil(0.99 n)-th smallest
  const auto rank = static_cast<std::size_t>(std::ceil(0.99 * static_cast<double>(v.size())));
  s.p99 = v[std::max<std::size_t>(rank, 1) - 1];
  const auto above = std::count_if(v.begin(), v.end(), [floor](double x) { return x > floor; });
  s.fraction_above = static_cast<double>(above) / static_cast<double>(v.size());
  return s;
}

// a contact sample or an episode of the pair, its bodies either way round
template <class Touch>
bool same_pair(const Touch& s, const ContactPair& p) {
  return (s.body_a == p.body_a && s.body_b == p.body_b) ||
         (s.body_a == p.body_b && s.body_b == p.body_a);
}

// s: a body sample counts as the row's when this close in time (both are the
// engine's time at the same output sample, written from the same double)
constexpr double kSameTime_s = 1e-12;

// The run's body states at a row's time (index = Case::bodies index; a fixed
// body's is never read), or false when a moving body has no sample then.
class StatesAt {
 public:
  StatesAt(const Case& c, const RunResult& r) : states_(c.bodies.size()) {
    for (std::size_t i = 0; i < c.bodies.size(); ++i) {
      const BodyTrajectory* t = nullptr;
      for (const auto& b : r.bodies) {
        if (b.name == c.bodies[i].name) t = &b;
      }
      trajectories_.push_back(c.bodies[i].fixed ? nullptr : t);
      moving_.push_back(!c.bodies[i].fixed);
    }
  }

  [[nodiscard]] bool at(double time_s) {
    for (std::size_t i = 0; i < trajectories_.size(); ++i) {
      if (!moving_[i]) continue;
      const BodyTrajectory* t = trajectories_[i];
      if (t == nullptr) return false;
      const auto it = std::lower_bound(t->time_s.begin(), t->time_s.end(), time_s - kSameTime_s);
      if (it == t->time_s.end() || std::abs(*it - time_s) > kSameTime_s) return false;
      const auto k = static_cast<std::size_t>(it - t->time_s.begin());
      if (k >= t->position_m.size() || k >= t->angle_rad.size() || k >= t->velocity_mps.size() ||
          k >= t->angular_velocity_radps.size()) {
        return false;
      }
      states_[i] = BodyState{t->position_m[k], t->angle_rad[k], t->velocity_mps[k],
                             t->angular_velocity_radps[k]};
    }
    return true;
  }

  [[nodiscard]] const std::vector<BodyState>& states() const { return states_; }

 private:
  std::vector<BodyState> states_;
  std::vector<const BodyTrajectory*> trajectories_;
  std::vector<bool> moving_;
};

// a pair whose law one contact point carries: neither body has faces
bool smooth_pair(const Case& c, const ContactPair& p) {
  const auto n = static_cast<int>(c.bodies.size());
  if (p.body_a < 0 || p.body_a >= n || p.body_b < 0 || p.body_b >= n) return false;
  return !std::holds_alternative<Polygon>(c.bodies[static_cast<std::size_t>(p.body_a)].shape) &&
         !std::holds_alternative<Polygon>(c.bodies[static_cast<std::size_t>(p.body_b)].shape);
}

// m/s, the approach speed of the run's episode of the pair holding time t
// (Lankarani-Nikravesh's latched delta_dot), 0 when none holds it
double approach_at(const RunResult& r, const ContactPair& p, double t) {
  for (const ContactEpisode& e : r.events) {
    const double off = std::isfinite(e.offset_time_s) ? e.offset_time_s : INFINITY;
    if (same_pair(e, p) && t >= e.onset_time_s && t <= off) return e.approach_speed_mps;
  }
  return 0.0;
}

// the gate's metrics: name, unit and the series whose largest max they are
struct GateMetric {
  const char* name;
  const char* unit;
  ValiditySeries PairValidity::*series;
};
constexpr GateMetric kGateMetrics[] = {
    {"cone_violation", "1", &PairValidity::cone},
    {"dissipation_deficit", "1", &PairValidity::dissipation},
    {"stick_creep", "m/s", &PairValidity::stick_creep_mps},
    {"force_at_distance", "N", &PairValidity::force_at_distance_n},
    {"law_residual", "1", &PairValidity::law_residual},
    {"complementarity", "W", &PairValidity::complementarity_w}};

}  // namespace

const std::vector<const char*>& validity_metric_names() {
  static const std::vector<const char*> names = [] {
    std::vector<const char*> n;
    for (const GateMetric& m : kGateMetrics) n.push_back(m.name);
    return n;
  }();
  return names;
}

std::vector<ValiditySample> validity_samples(const Case& c, const RunResult& r, std::size_t pair) {
  std::vector<ValiditySample> out;
  if (pair >= c.contacts.size()) return out;
  const ContactPair& p = c.contacts[pair];
  const bool smooth = smooth_pair(c, p);
  StatesAt states(c, r);
  double peak_n = 0.0;  // N, the pair's largest normal force: the law residual's scale
  for (const ContactRow& row : r.contacts) {
    const ContactSample& s = row.sample;
    if (!same_pair(s, p)) continue;
    ValiditySample v;
    v.time_s = row.time_s;
    if (s.force_n > 0.0 && s.penetration_m < -kOpenGap_m) v.force_at_distance_n = s.force_n;
    const bool touching = s.force_n > 0.0 || s.penetration_m > 0.0;
    if (touching && std::isfinite(s.force_n) && std::isfinite(s.penetration_m) &&
        states.at(row.time_s)) {
      const double rate = penetration_rate_mps(c, states.states(), s);  // m/s
      peak_n = std::max(peak_n, s.force_n);
      if (smooth) {
        const double law = contact_force_n(p.law, s.penetration_m, rate, approach_at(r, p, row.time_s));
        v.law_residual = std::abs(s.force_n - law);  // N until scaled below
      }
      if (s.force_n > 0.0) v.complementarity_w = s.force_n * std::max(0.0, -rate);
    }
    v.recorded = std::isfinite(s.tangential_force_n) && std::isfinite(s.slip_mps);
    if (v.recorded) {
      const double fn = s.force_n;
      const double ft = s.tangential_force_n;
      const double vt = s.slip_mps;
      const bool pressed = fn > 0.0;
      const bool sliding = std::abs(vt) > kSlidingSpeed_mps;
      if (pressed && p.has_friction()) {
        const double limit = p.friction * fn;
        v.cone = std::max(0.0, std::abs(ft) - limit) / limit;
        if (sliding) {
          v.sliding = true;
          v.dissipation = 1.0 + (vt > 0.0 ? 1.0 : -1.0) * ft / limit;
          v.power_w = ft * vt + limit * std::abs(vt);
        } else if (std::abs(ft) <= (1.0 - kInsideCone) * limit) {
          v.stick_creep_mps = std::abs(vt);
        }
      } else if (pressed) {
        v.frictionless_tangent = std::abs(ft) / fn;
      }
    }
    out.push_back(v);
  }
  for (ValiditySample& v : out) {
    if (!std::isnan(v.law_residual)) v.law_residual = peak_n > 0.0 ? v.law_residual / peak_n : 0.0;
  }
  return out;
}

PairValidity pair_validity(const Case& c, std::size_t pair,
                           const std::vector<ValiditySample>& samples) {
  const ContactPair& p = c.contacts[pair];
  PairValidity v;
  v.pair = p.name;
  v.body_a = p.body_a;
  v.body_b = p.body_b;
  v.mu = p.friction;
  std::vector<double> cone, tangent, dissipation, creep, distance, law, complementarity;
  auto keep = [](std::vector<double>& into, double x) {
    if (!std::isnan(x)) into.push_back(x);
  };
  double deficit = 0.0;
  bool any_sliding_interval = false;
  const ValiditySample* previous = nullptr;  // the pair's last recorded sample
  for (const ValiditySample& s : samples) {
    ++v.samples;
    keep(distance, s.force_at_distance_n);
    keep(law, s.law_residual);
    keep(complementarity, s.complementarity_w);
    if (!s.recorded) {
      ++v.not_recorded;
      previous = nullptr;
      continue;
    }
    keep(cone, s.cone);
    keep(tangent, s.frictionless_tangent);
    keep(dissipation, s.dissipation);
    keep(creep, s.stick_creep_mps);
    if (previous != nullptr && previous->sliding && s.sliding) {
      const double dt = s.time_s - previous->time_s;
      if (dt > 0.0 && dt <= 1.5 * c.output_interval_s) {
        deficit += 0.5 * (previous->power_w + s.power_w) * dt;
        any_sliding_interval = true;
      }
    }
    previous = &s;
  }
  v.cone = summarise(std::move(cone), kRelativeFloor);
  v.frictionless_tangent = summarise(std::move(tangent), kRelativeFloor);
  v.dissipation = summarise(std::move(dissipation), kRelativeFloor);
  v.stick_creep_mps = summarise(std::move(creep), kCreepFloor_mps);
  v.force_at_distance_n = summarise(std::move(distance), 0.0);
  v.law_residual = summarise(std::move(law), kRelativeFloor);
  v.complementarity_w = summarise(std::move(complementarity), 0.0);
  if (any_sliding_interval) v.power_deficit_j = deficit;
  return v;
}

std::vector<PairValidity> contact_validity(const Case& c, const RunResult& r) {
  std::vector<PairValidity> out;
  for (std::size_t k = 0; k < c.contacts.size(); ++k) {
    out.push_back(pair_validity(c, k, validity_samples(c, r, k)));
  }
  return out;
}

std::vector<MetricValue> validity_metrics(const Case& c, const RunResult& r) {
  std::vector<MetricValue> out;
  if (r.status == RunStatus::unsupported) return out;
  const std::vector<PairValidity> pairs = contact_validity(c, r);
  for (const GateMetric& k : kGateMetrics) {
    const PairValidity* worst = nullptr;
    for (const PairValidity& v : pairs) {
      const ValiditySeries& s = v.*k.series;
      if (s.samples == 0) continue;
      // NaN wins: a maximum is never one that skips a NaN
      if (worst == nullptr || std::isnan(s.max) || (s.max > (worst->*k.series).max)) worst = &v;
    }
    if (worst == nullptr) continue;
    const ValiditySeries& s = worst->*k.series;
    auto m = metric_value(c, r, "self", k.name, s.max, 0.0, false, k.unit);
    m.note = fmt::format("pair {}: max over {} samples (p99 {:.3g}, {:.3g} of them above {:g})",
                         worst->pair, s.samples, s.p99, s.fraction_above, s.floor);
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace pb
