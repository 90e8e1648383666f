#include "ode_library.hpp"

#include <ode/ode.h>
#include <ode/version.h>

#include <cstdarg>
#include <cstdio>
#include <string>

#include "planarbench/errors.hpp"

#ifndef PB_ODE_PKGCONFIG_VERSION
#define PB_ODE_PKGCONFIG_VERSION "unknown"
#endif

namespace pb::internal::ode {

namespace {
// the adapter uses double-precision ODE only (Debian's libode-dev is dDOUBLE)
static_assert(sizeof(dReal) == sizeof(double), "the ODE adapter needs double-precision ODE");

thread_local OdeMessages t_messages;

// dMessageFunction: counted, not printed (ode_library.hpp)
void count_message(int num, const char* msg, va_list ap) {
  ++t_messages.count;
  char text[256];
  std::vsnprintf(text, sizeof text, msg, ap);
  t_messages.last = "ODE message " + std::to_string(num) + ": " + text;
}
}  // namespace

void ensure_ode_ready_in_this_thread() {
  // the library's collider tables are global: initialise them once; the
  // process never calls dCloseODE (engines may live until exit)
  static std::once_flag once;
  static int init_ok = 0;
  std::call_once(once, [] {
    init_ok = dInitODE2(0);
    dSetMessageHandler(&count_message);
  });
  if (init_ok == 0) throw EngineError("ODE: dInitODE2(0) failed");
  // per-thread caches (ODE manual: dAllocateODEDataForThread in every thread)
  thread_local bool thread_ready = false;
  if (!thread_ready) {
    if (dAllocateODEDataForThread(dAllocateMaskAll) == 0) {
      throw EngineError("ODE: dAllocateODEDataForThread failed");
    }
    thread_ready = true;
  }
}

const OdeMessages& ode_messages_on_this_thread() { return t_messages; }

std::mutex& quickstep_random_lock() {
  static std::mutex m;
  return m;
}

std::string ode_header_version() {
  return dODE_VERSION;
}

std::string ode_pkgconfig_version() {
  return PB_ODE_PKGCONFIG_VERSION;
}

std::string ode_configuration() {
  ensure_ode_ready_in_this_thread();
  return dGetConfiguration();
}

}  // namespace pb::internal::ode
