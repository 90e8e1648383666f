// The ODE library's process-wide state: initialisation, per-thread data,
// the global random seed of dWorldQuickStep, and the version it reports.
#pragma once

#include <mutex>
#include <string>

namespace pb::internal::ode {

// dInitODE2(0) once per process (ODE manual, "Initialization"), then
// dAllocateODEDataForThread(dAllocateMaskAll) for the calling thread; cheap
// when both were done already. Call before any ODE use in a thread.
// Throws EngineError when ODE refuses.
void ensure_ode_ready_in_this_thread();

// dWorldQuickStep draws its row order from a process-global seed
// (misc.cpp: one std::atomic<uint32_t> for the whole process). Engines that
// reseed and quick-step hold this lock, so that two engines on two threads
// do not interleave their draws and each run stays reproducible.
[[nodiscard]] std::mutex& quickstep_random_lock();

// ODE's non-fatal messages (dMessage: e.g. "LCP internal error, s <= 0"),
// which ODE prints to stderr by default: the adapter's handler counts them
// per thread instead, with the first one's text, so that a run can record
// what ODE said during it (installed by ensure_ode_ready_in_this_thread)
struct OdeMessages {
  long count = 0;
  std::string last;  // "ODE message <num>: <text>" of the latest one on this thread
};
[[nodiscard]] const OdeMessages& ode_messages_on_this_thread();

// dODE_VERSION from <ode/version.h> (the headers compiled against)
[[nodiscard]] std::string ode_header_version();
// ODE_VERSION of pkg-config at build time (compile definition)
[[nodiscard]] std::string ode_pkgconfig_version();
// dGetConfiguration(): the library's build options, e.g. ODE_double_precision
[[nodiscard]] std::string ode_configuration();

}  // namespace pb::internal::ode
