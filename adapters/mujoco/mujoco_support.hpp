// Whether and how MuJoCo runs a case (Engine::supports): unsupported shapes
// and joints, and the approximations each mode makes.
#pragma once

#include <string>

#include "planarbench/case.hpp"
#include "mujoco_settings.hpp"
#include "planarbench/engine.hpp"

namespace pb::internal::mujoco {

// `mode` = mujoco.mode: "native", "oracle" or "inject"; `line`: which MuJoCo
// (3.3.8 collides convex shapes with its native collider, not libccd's MPR)
[[nodiscard]] Capability mujoco_capability(const Case& c, const std::string& mode,
                                           MujocoLine line = MujocoLine::v2);

}  // namespace pb::internal::mujoco
