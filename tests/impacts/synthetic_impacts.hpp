// Impacts made up for the tests, stored as the MCube file stores them (angle
// and angular velocity clockwise-positive, y twice the centre's height): the
// pre-impact states drawn over the dataset's ranges (its README), the
// post-impact ones from a law the test chooses.
#pragma once

#include <cmath>
#include <functional>
#include <random>

#include "planarbench/impacts/impact_data.hpp"
#include "planarbench/impacts/impact_object.hpp"

namespace pb::test {

// a state at the touch: angle (rad, counter-clockwise), x', y' (m/s), theta' (rad/s)
inline ImpactState impact_state(double angle, double vx, double vy, double w) {
  ImpactState s;
  s.angle_rad = angle;
  s.velocity_mps = Vec2(vx, vy);
  s.angular_velocity_radps = w;
  return s;
}

// n impacts; `law` maps a pre-impact state (the project's convention) to
// the post-impact one. Stored with AngleConvention{-1, -1} (the MCube file's).
inline ImpactSet synthetic_impacts(std::size_t n, unsigned seed,
                                   const std::function<ImpactState(const ImpactState&)>& law) {
  const ImpactObject o;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> angle(-3.1, 3.1), vx(0.1, 1.1), vy(-2.9, -2.2), w(-14.0, 25.0);
  ImpactSet set;
  set.path = "synthetic";
  while (set.size() < n) {
    ImpactState pre;
    pre.angle_rad = angle(rng);
    pre.velocity_mps = Vec2(vx(rng), vy(rng));
    pre.angular_velocity_radps = w(rng);
    const Vec2 r = lowest_point_offset(o, pre.angle_rad);
    // the lowest point must approach the ground
    if (pre.velocity_mps.y() + pre.angular_velocity_radps * r.x() > -0.5) continue;
    const ImpactState post = law(pre);
    const double y2 = 2.0 * touching_height(o, pre.angle_rad);  // stored y: twice the height
    set.pre.push_back({0.2, y2, -pre.angle_rad, pre.velocity_mps.x(), pre.velocity_mps.y(),
                       -pre.angular_velocity_radps});
    set.post.push_back({0.2, y2, -pre.angle_rad, post.velocity_mps.x(), post.velocity_mps.y(),
                        -post.angular_velocity_radps});
    set.drop.push_back(static_cast<double>(set.size()));
  }
  return set;
}

}  // namespace pb::test
