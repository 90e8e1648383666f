// The mujoco adapter: engine "mujoco".
#pragma once

#include <memory>

#include "planarbench/engine.hpp"

namespace pb {

[[nodiscard]] std::unique_ptr<Engine> make_mujoco_engine();

}  // namespace pb
