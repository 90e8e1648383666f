// A contact-free run of the case (every pair inactive) up to each pair's first
// touch: where a pair will first meet, how fast, and with what effective mass.
// This calibrates the solref of each pair at the configuration of its first
// impact rather than at t = 0, where the bodies may be far apart and, for
// pendulums, in another pose (m_eff = 1/(J M^-1 J^T) depends on both).
#pragma once

#include <mujoco/mujoco.h>

#include <vector>

#include "mujoco_model.hpp"
#include "planarbench/case.hpp"

namespace pb::internal::mujoco {

struct FirstTouch {
  bool found = false;
  double time_s = 0.0;              // s, the first state whose distance is <= the pair's threshold
  double effective_mass_kg = 0.0;   // kg, along the contact normal at that state
  double approach_speed_mps = 0.0;  // m/s, normal approach speed there (>= 0)
  Vec2 point_m = Vec2::Zero();      // m
  Vec2 normal_ab = Vec2::Zero();
};

// Runs `m` (a model whose pairs are all inactive) from the case's initial
// state with MuJoCo's own stepping until every present pair has touched or
// until `until_s`. Throws EngineError when MuJoCo raises a warning.
// steps_taken: the steps the probe integrated.
[[nodiscard]] std::vector<FirstTouch> probe_first_touch(const mjModel* m, const Case& c,
                                                        const ModelLayout& layout, double until_s,
                                                        long& steps_taken);

}  // namespace pb::internal::mujoco
