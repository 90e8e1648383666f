#include "planarbench/engine.hpp"

#include "planarbench/run_result.hpp"

namespace pb {

const char* support_name(Support s) {
  switch (s) {
    case Support::native: return "native";
    case Support::mapped: return "mapped";
    case Support::unsupported: return "unsupported";
  }
  return "unsupported";
}

const char* run_status_name(RunStatus s) {
  switch (s) {
    case RunStatus::ok: return "ok";
    case RunStatus::diverged: return "diverged";
    case RunStatus::unsupported: return "unsupported";
  }
  return "unsupported";
}

nlohmann::json physics_json(const Physics& p) {
  return {{"mode", p.mode},
          {"collision_by", p.collision_by},
          {"collision", p.collision},
          {"contact_force_by", p.contact_force_by},
          {"contact_force", p.contact_force},
          {"parameters", p.parameters},
          {"foreknowledge", p.foreknowledge}};
}

}  // namespace pb
