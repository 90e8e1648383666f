// The slip of a contact (issue 32): the velocity of body_b's material point
// at the contact point relative to body_a's, along t = n rotated by +90 deg,
// v(p) = v + omega x (p - x) for each body (a fixed body does not move). One
// definition for every engine: the runner fills ContactSample::slip_mps from
// the engine's own body states at the sample's time.
#pragma once

#include <cmath>
#include <limits>
#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/engine.hpp"

namespace pb {

// m/s, the velocity of body `i`'s material point at `p`
[[nodiscard]] inline Vec2 material_point_velocity(const Case& c, const std::vector<BodyState>& states,
                                                  int i, const Vec2& p) {
  const auto k = static_cast<std::size_t>(i);
  if (i < 0 || k >= states.size() || k >= c.bodies.size()) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return Vec2(nan, nan);
  }
  if (c.bodies[k].fixed) return Vec2::Zero();
  const BodyState& s = states[k];
  const Vec2 r = p - s.position_m;
  return s.velocity_mps + s.angular_velocity_radps * Vec2(-r.y(), r.x());
}

// sets each sample's slip_mps from `states` (index = Case::bodies index)
inline void fill_slip(const Case& c, const std::vector<BodyState>& states,
                      std::vector<ContactSample>& samples) {
  for (ContactSample& s : samples) {
    const Vec2 rel = material_point_velocity(c, states, s.body_b, s.point_m) -
                     material_point_velocity(c, states, s.body_a, s.point_m);
    s.slip_mps = rel.dot(contact_tangent(s.normal));
  }
}

}  // namespace pb
