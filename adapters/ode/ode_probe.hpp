// The contact-free probe run: where and how fast each contact pair first
// touches. The mapping of a nonlinear law to a linear ODE soft contact
// depends on the effective mass and the approach speed of the impact, and
// both depend on the configuration at impact (pendulums); the probe runs the
// same ODE model without contact forces and records the first step at which
// ODE's narrow phase reports each pair.
#pragma once

#include <vector>

#include "planarbench/case.hpp"

namespace pb::internal::ode {

struct FirstTouch {
  bool found = false;
  double time_s = 0.0;              // s, the first step with a contact
  Vec2 point_m = Vec2::Zero();      // m, contact midpoint
  Vec2 normal_ab = Vec2::Zero();    // unit, body_a -> body_b
  double approach_speed_mps = 0.0;  // m/s, > 0 approaching
  std::vector<Vec2> centres_m;      // m, every body's centre at that step
};

// Steps the case's ODE model with dWorldStep at step_s, no contact joints,
// until every pair with a moving body has touched or the case's duration
// has passed. Result index = Case::contacts index.
// steps_taken: the dWorldStep calls the probe made.
[[nodiscard]] std::vector<FirstTouch> probe_first_touches(const Case& c, double step_s,
                                                          long& steps_taken);

}  // namespace pb::internal::ode
