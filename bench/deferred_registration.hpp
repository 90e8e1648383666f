// Benchmarks registered from main() rather than from static initialisers.
// The engine and force-law benchmarks are made from the case files at run
// time; loading a case can throw, which a static initialiser cannot report.
// Each benchmark file queues its registration function with a static
// DeferredRegistration; bench_main.cpp runs the queue after
// benchmark::Initialize and reports any error with the file that failed.
#pragma once

#include <functional>
#include <utility>
#include <vector>

namespace pb::bench {

using RegistrationFunction = std::function<void()>;

// the queue; function-local so it exists before any static initialiser uses it
inline std::vector<RegistrationFunction>& registration_queue() {
  static std::vector<RegistrationFunction> queue;
  return queue;
}

// queues `register_fn` to be run by run_deferred_registrations()
struct DeferredRegistration {
  explicit DeferredRegistration(RegistrationFunction register_fn) {
    registration_queue().push_back(std::move(register_fn));
  }
};

// runs every queued registration once, in queue order
inline void run_deferred_registrations() {
  for (const auto& register_fn : registration_queue()) register_fn();
  registration_queue().clear();
}

}  // namespace pb::bench
