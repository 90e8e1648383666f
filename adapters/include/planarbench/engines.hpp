// The registry of every engine by name (SPEC §5 engine names).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "planarbench/engine.hpp"

namespace pb {

// every engine name, in report order: analytic, reference, mujoco, box2d, ode
[[nodiscard]] const std::vector<std::string>& engine_names();

// Creates an engine by name. Throws InputError listing the allowed names.
[[nodiscard]] std::unique_ptr<Engine> make_engine(const std::string& name);

// NAME|all -> engine names; throws InputError for an unknown name.
[[nodiscard]] std::vector<std::string> resolve_engines(const std::string& spec);

// true when some engine binds `key` (as "key" or "engine.key")
[[nodiscard]] bool is_engine_setting_key(const std::string& key);

}  // namespace pb
