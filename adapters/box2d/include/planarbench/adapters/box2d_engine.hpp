// The box2d adapter: engine "box2d".
#pragma once

#include <memory>

#include "planarbench/engine.hpp"

namespace pb {

[[nodiscard]] std::unique_ptr<Engine> make_box2d_engine();

}  // namespace pb
