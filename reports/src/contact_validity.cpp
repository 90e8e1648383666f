#include "planarbench/reports/contact_validity.hpp"

#include <algorithm>
#include <cmath>

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

bool same_pair(const ContactSample& s, const ContactPair& p) {
  return (s.body_a == p.body_a && s.body_b == p.body_b) ||
         (s.body_a == p.body_b && s.body_b == p.body_a);
}

}  // namespace

std::vector<PairValidity> contact_validity(const Case& c, const RunResult& r) {
  std::vector<PairValidity> out;
  for (const ContactPair& p : c.contacts) {
    PairValidity v;
    v.pair = p.name;
    v.body_a = p.body_a;
    v.body_b = p.body_b;
    v.mu = p.friction;
    std::vector<double> cone, tangent, dissipation, creep, distance;
    double deficit = 0.0;
    bool any_sliding_interval = false;
    const ContactRow* previous = nullptr;  // the pair's last recorded row
    double previous_power = 0.0;
    bool previous_sliding = false;
    for (const ContactRow& row : r.contacts) {
      const ContactSample& s = row.sample;
      if (!same_pair(s, p)) continue;
      ++v.samples;
      if (s.force_n > 0.0 && s.penetration_m < -kOpenGap_m) distance.push_back(s.force_n);
      if (!std::isfinite(s.tangential_force_n) || !std::isfinite(s.slip_mps)) {
        ++v.not_recorded;
        previous = nullptr;
        continue;
      }
      const double fn = s.force_n;
      const double ft = s.tangential_force_n;
      const double vt = s.slip_mps;
      const bool pressed = fn > 0.0;
      const bool sliding = std::abs(vt) > kSlidingSpeed_mps;
      double power = 0.0;  // W, F_t v_t + mu F_n |v_t|
      if (pressed && p.has_friction()) {
        const double limit = p.friction * fn;
        cone.push_back(std::max(0.0, std::abs(ft) - limit) / limit);
        if (sliding) {
          dissipation.push_back(1.0 + (vt > 0.0 ? 1.0 : -1.0) * ft / limit);
          power = ft * vt + limit * std::abs(vt);
        } else if (std::abs(ft) <= (1.0 - kInsideCone) * limit) {
          creep.push_back(std::abs(vt));
        }
      } else if (pressed) {
        tangent.push_back(std::abs(ft) / fn);
      }
      const bool now_sliding = pressed && p.has_friction() && sliding;
      if (previous != nullptr && previous_sliding && now_sliding) {
        const double dt = row.time_s - previous->time_s;
        if (dt > 0.0 && dt <= 1.5 * c.output_interval_s) {
          deficit += 0.5 * (previous_power + power) * dt;
          any_sliding_interval = true;
        }
      }
      previous = &row;
      previous_power = power;
      previous_sliding = now_sliding;
    }
    v.cone = summarise(std::move(cone), kRelativeFloor);
    v.frictionless_tangent = summarise(std::move(tangent), kRelativeFloor);
    v.dissipation = summarise(std::move(dissipation), kRelativeFloor);
    v.stick_creep_mps = summarise(std::move(creep), kCreepFloor_mps);
    v.force_at_distance_n = summarise(std::move(distance), 0.0);
    if (any_sliding_interval) v.power_deficit_j = deficit;
    out.push_back(std::move(v));
  }
  return out;
}

}  // namespace pb
