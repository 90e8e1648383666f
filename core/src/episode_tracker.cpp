#include "planarbench/episode_tracker.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pb {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// fraction in [0, 1] where a linear function from a (at 0) to b (at 1) is 0
double zero_fraction(double a, double b) {
  if (a == b) return 1.0;
  return std::clamp(a / (a - b), 0.0, 1.0);
}
}  // namespace

void EpisodeTracker::observe(double t_s, int body_a, int body_b, double penetration_m,
                             double normal_speed_mps, double force_n) {
  const auto key = std::make_pair(body_a, body_b);
  Last& last = last_[key];
  auto it = open_.find(key);
  const bool touching = penetration_m > 0.0;

  if (touching && it == open_.end()) {
    // onset: interpolate between the last observation at or below zero and now
    Open o;
    o.ep.body_a = body_a;
    o.ep.body_b = body_b;
    double onset = t_s;
    double speed = normal_speed_mps;
    if (last.valid && last.penetration_m <= 0.0 && std::isfinite(penetration_m) &&
        std::isfinite(last.penetration_m)) {
      const double f = zero_fraction(last.penetration_m, penetration_m);
      onset = last.t_s + f * (t_s - last.t_s);
      speed = last.speed_mps + f * (normal_speed_mps - last.speed_mps);
    }
    o.ep.onset_time_s = onset;
    o.ep.offset_time_s = kNaN;
    o.ep.approach_speed_mps = speed;
    o.ep.separation_speed_mps = kNaN;
    o.ep.restitution = kNaN;
    o.ep.peak_force_n = force_n;
    o.ep.impulse_ns = 0.5 * force_n * (t_s - onset);
    o.ep.max_penetration_m = penetration_m;
    o.last_t_s = t_s;
    o.last_force_n = force_n;
    it = open_.emplace(key, o).first;
  } else if (touching) {
    // inside the episode: trapezoid impulse, peaks
    Open& o = it->second;
    o.ep.impulse_ns += 0.5 * (o.last_force_n + force_n) * (t_s - o.last_t_s);
    o.ep.peak_force_n = std::max(o.ep.peak_force_n, force_n);
    o.ep.max_penetration_m = std::max(o.ep.max_penetration_m, penetration_m);
    o.last_t_s = t_s;
    o.last_force_n = force_n;
  } else if (it != open_.end()) {
    // offset: interpolate where the penetration returned to zero
    Open& o = it->second;
    double offset = t_s;
    double speed = normal_speed_mps;
    if (last.valid && std::isfinite(penetration_m)) {
      const double f = zero_fraction(last.penetration_m, penetration_m);
      offset = last.t_s + f * (t_s - last.t_s);
      speed = last.speed_mps + f * (normal_speed_mps - last.speed_mps);
    }
    o.ep.impulse_ns += 0.5 * (o.last_force_n + force_n) * (t_s - o.last_t_s);
    o.ep.peak_force_n = std::max(o.ep.peak_force_n, force_n);
    o.ep.offset_time_s = offset;
    o.ep.separation_speed_mps = -speed;
    o.ep.restitution =
        o.ep.approach_speed_mps > 0.0 ? o.ep.separation_speed_mps / o.ep.approach_speed_mps : kNaN;
    closed_.push_back(o.ep);
    open_.erase(it);
  }
  last = Last{t_s, penetration_m, normal_speed_mps, true};
}

void EpisodeTracker::observe_separated(double t_s, int body_a, int body_b,
                                       double normal_speed_mps) {
  // no geometry known: the episode closes at this step
  const auto key = std::make_pair(body_a, body_b);
  if (auto it = open_.find(key); it != open_.end()) {
    Open& o = it->second;
    o.ep.impulse_ns += 0.5 * o.last_force_n * (t_s - o.last_t_s);
    o.ep.offset_time_s = t_s;
    o.ep.separation_speed_mps = -normal_speed_mps;
    o.ep.restitution =
        o.ep.approach_speed_mps > 0.0 ? o.ep.separation_speed_mps / o.ep.approach_speed_mps : kNaN;
    closed_.push_back(o.ep);
    open_.erase(it);
  }
  last_[key] = Last{t_s, kNaN, normal_speed_mps, false};
}

void EpisodeTracker::record_within_step(double t0_s, double t1_s, int body_a, int body_b,
                                        double gap0_m, double approach_mps, double separation_mps,
                                        double impulse_ns) {
  const double dt = t1_s - t0_s;
  double at = t0_s;
  if (std::isfinite(gap0_m) && approach_mps > 0.0) at += std::clamp(gap0_m / approach_mps, 0.0, dt);
  ContactEpisode ep;
  ep.body_a = body_a;
  ep.body_b = body_b;
  ep.onset_time_s = at;
  ep.offset_time_s = at;
  ep.approach_speed_mps = approach_mps;
  ep.separation_speed_mps = separation_mps;
  ep.restitution = approach_mps > 0.0 ? separation_mps / approach_mps : kNaN;
  ep.peak_force_n = dt > 0.0 ? impulse_ns / dt : kNaN;
  ep.impulse_ns = impulse_ns;
  ep.max_penetration_m = 0.0;
  closed_.push_back(ep);
}

bool EpisodeTracker::in_contact(int body_a, int body_b) const {
  return open_.count(std::make_pair(body_a, body_b)) != 0;
}

std::vector<ContactEpisode> EpisodeTracker::episodes() const {
  std::vector<ContactEpisode> all = closed_;
  for (const auto& [key, o] : open_) all.push_back(o.ep);
  std::stable_sort(all.begin(), all.end(), [](const ContactEpisode& a, const ContactEpisode& b) {
    return a.onset_time_s < b.onset_time_s;
  });
  return all;
}

}  // namespace pb
