// The closed-form truth: engine "analytic".
#pragma once

#include <memory>

#include "planarbench/engine.hpp"

namespace pb {

[[nodiscard]] std::unique_ptr<Engine> make_analytic_engine();

}  // namespace pb
