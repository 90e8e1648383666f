// How MuJoCo's warnings end a run: the reason of a diverged run names the
// warning, what MuJoCo did about it, how often it was raised, where (the case
// body and coordinate of the DOF) and when it first occurred.
#pragma once

#include <mujoco/mujoco.h>

#include <string>

#include "mujoco_model.hpp"
#include "mujoco_stepping.hpp"
#include "planarbench/case.hpp"

namespace pb::internal::mujoco {

// "slide x of body 'ball' (the case's x)" for a DOF (or qpos index: the
// adapter's slide and hinge joints have one coordinate each, in the same
// order), "DOF 7" for one it did not make
[[nodiscard]] std::string describe_dof(const Case& c, const ModelLayout& layout, int dof);

// The reason of a run ended by warning w, first raised in the step at t_s
// (the adapter looks at the counters after every half step). `mujoco_text`
// is MuJoCo's own message (last_warning_text()), quoted when not empty.
[[nodiscard]] std::string fault_reason(const Case& c, const ModelLayout& layout,
                                       const RaisedWarning& w, double t_s,
                                       const std::string& mujoco_text);

}  // namespace pb::internal::mujoco
