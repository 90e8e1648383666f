// Whether and how MuJoCo runs a case (Engine::supports): unsupported shapes
// and joints, and the approximations each mode makes.
#pragma once

#include <string>

#include "planarbench/case.hpp"
#include "planarbench/engine.hpp"

namespace pb::internal::mujoco {

// `inject` = mujoco.mode=inject (the case's own force law is applied)
[[nodiscard]] Capability mujoco_capability(const Case& c, bool inject);

}  // namespace pb::internal::mujoco
