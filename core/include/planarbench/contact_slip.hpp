// The slip of a contact (issue 32): the velocity of body_b's material point
// at its contact point relative to body_a's at its own, along t = n rotated
// by +90 deg, v(p) = v + omega x (p - x) for each body (a fixed body does not
// move). A sample's point is the midpoint of the two bodies' contact points,
// which lie half the penetration from it along -n (body_b's, the deepest of b
// inside a) and +n (body_a's): at the midpoint itself a disk rolling without
// slip on a soft contact would show omega delta / 2 of slip (1e-3 m/s on
// sliding_friction). One definition for every engine: the runner fills
// ContactSample::slip_mps from the engine's own body states at the sample's
// time; a penetration the engine does not give (NaN) leaves the midpoint.
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
  return point_velocity(states[k], p);
}

// m/s, body_b's material point's velocity relative to body_a's at a
// sample's contact: each at its own point, half the penetration from the
// midpoint (above); a penetration the engine does not give leaves the midpoint
[[nodiscard]] inline Vec2 contact_relative_velocity(const Case& c,
                                                    const std::vector<BodyState>& states,
                                                    const ContactSample& s) {
  const double half = std::isfinite(s.penetration_m) ? 0.5 * s.penetration_m : 0.0;  // m
  return material_point_velocity(c, states, s.body_b, s.point_m - half * s.normal) -
         material_point_velocity(c, states, s.body_a, s.point_m + half * s.normal);
}

// m/s, the penetration rate delta_dot = -n . (v_b(p_b) - v_a(p_a)), > 0
// approaching: the rate the reference's contact law reads
// (core/reference/include/planarbench/reference/contact_dynamics.hpp)
[[nodiscard]] inline double penetration_rate_mps(const Case& c, const std::vector<BodyState>& states,
                                                 const ContactSample& s) {
  return -contact_relative_velocity(c, states, s).dot(s.normal);
}

// sets each sample's slip_mps from `states` (index = Case::bodies index)
inline void fill_slip(const Case& c, const std::vector<BodyState>& states,
                      std::vector<ContactSample>& samples) {
  for (ContactSample& s : samples) {
    s.slip_mps = contact_relative_velocity(c, states, s).dot(contact_tangent(s.normal));
  }
}

}  // namespace pb
