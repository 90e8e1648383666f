// The registry: the one place that knows every engine.
#include "planarbench/engines.hpp"

#include <fmt/format.h>

#include "planarbench/adapters/box2d_engine.hpp"
#include "planarbench/adapters/mujoco3_engine.hpp"
#include "planarbench/adapters/mujoco_engine.hpp"
#include "planarbench/adapters/ode_engine.hpp"
#include "planarbench/analytic/analytic_engine.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/reference/reference_engine.hpp"

namespace pb {

namespace {
std::string joined_names() {
  std::string s;
  for (const auto& n : engine_names()) s += (s.empty() ? "" : ", ") + n;
  return s;
}
}  // namespace

const std::vector<std::string>& engine_names() {
  static const std::vector<std::string> names = {"analytic", "reference", "mujoco", "mujoco3",
                                                 "box2d",    "ode"};
  return names;
}

std::unique_ptr<Engine> make_engine(const std::string& name) {
  if (name == "analytic") return make_analytic_engine();
  if (name == "reference") return make_reference_engine();
  if (name == "mujoco") return make_mujoco_engine();
  if (name == "mujoco3") return make_mujoco3_engine();
  if (name == "box2d") return make_box2d_engine();
  if (name == "ode") return make_ode_engine();
  throw InputError(fmt::format("--engine: unknown engine '{}'; allowed: {}, all", name,
                               joined_names()));
}

std::vector<std::string> resolve_engines(const std::string& spec) {
  if (spec == "all") return engine_names();
  std::vector<std::string> out;
  // comma-separated list is accepted too: --engine reference,mujoco
  std::size_t start = 0;
  while (start <= spec.size()) {
    const auto comma = spec.find(',', start);
    const auto item = spec.substr(start, comma == std::string::npos ? std::string::npos
                                                                    : comma - start);
    (void)make_engine(item);  // validates the name
    out.push_back(item);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

bool is_engine_setting_key(const std::string& key) {
  for (const auto& n : engine_names()) {
    if (make_engine(n)->settings().knows(key)) return true;
  }
  return false;
}

}  // namespace pb
