// The paper's algorithm: engine "reference".
#pragma once

#include <memory>

#include "planarbench/engine.hpp"

namespace pb {

[[nodiscard]] std::unique_ptr<Engine> make_reference_engine();

}  // namespace pb
