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

}  // namespace pb
