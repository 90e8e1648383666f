// The ode adapter: engine "ode".
#pragma once

#include <memory>

#include "planarbench/engine.hpp"

namespace pb {

[[nodiscard]] std::unique_ptr<Engine> make_ode_engine();

}  // namespace pb
