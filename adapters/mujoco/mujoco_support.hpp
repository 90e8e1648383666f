// Whether and how MuJoCo runs a case (Engine::supports): unsupported shapes
// and joints, and the approximations each mode makes.
#pragma once

#include <string>

#include "planarbench/case.hpp"
#include "planarbench/engine.hpp"

namespace pb::internal::mujoco {

// `mode` = mujoco.mode: "native", "oracle" or "inject"
[[nodiscard]] Capability mujoco_capability(const Case& c, const std::string& mode);

}  // namespace pb::internal::mujoco
