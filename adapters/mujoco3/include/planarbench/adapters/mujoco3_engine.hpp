// The mujoco3 adapter: engine "mujoco3", MuJoCo 3.3.8 from its official
// WebAssembly build (npm mujoco-js 0.0.7) in a Node process.
#pragma once

#include <memory>

#include "planarbench/engine.hpp"

namespace pb {

[[nodiscard]] std::unique_ptr<Engine> make_mujoco3_engine();

}  // namespace pb
