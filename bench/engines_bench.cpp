// The cost of one simulated second: every case of cases/ x every engine that
// supports it, registered at run time as engines/<case>/<engine>.
//
// One iteration = one fresh engine built for the case (not timed) and advanced
// from the case's start over the window min(1 s, case duration) along the
// case's output grid, reading the body states and contacts at every grid time
// exactly as pb::run_engine does (runner.cpp) but without storing them. The
// window is 1 s for every case in cases/ (all last >= 1 s). So the figure is
// what one simulated second of `planarbench run` costs in the engine, without
// the build, the results storage and the file output.
//
// Timing: the build (MuJoCo's XML compile, ODE's world, the reference's
// outlines) and the destruction of the previous iteration's engine happen
// between PauseTiming and ResumeTiming, so that both the real and the CPU
// time cover the advance loop only. UseRealTime makes the iteration count and
// the rate counters follow wall time (sim_s_per_wall_s); the CPU column is the
// thread's CPU time of the same loop, which a busy shared machine inflates far
// less than the wall time (bench/README.md). One Pause/Resume pair costs
// ~0.7 us of CPU with Debian's libbenchmark (measured on this machine), below
// 0.2 % of the cheapest iteration here (~0.4 ms). Manual time was not used:
// its CPU column would include the build.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "bench_errors.hpp"
#include "deferred_registration.hpp"
#include "planarbench/case.hpp"
#include "planarbench/case_loader.hpp"
#include "planarbench/engine.hpp"
#include "planarbench/engines.hpp"
#include "planarbench/settings.hpp"

namespace pb::bench {

namespace {

// simulated time of one iteration, s: one second, or the whole case if shorter
constexpr double kWindowS = 1.0;

struct EngineCase {
  Case c;
  SettingsOverrides settings;  // the case's own [settings] table
  std::string engine;
  std::string support;  // "native" or "mapped"
  int grid_points = 0;  // output times after t = 0 inside the window
};

// the case's [settings] table as overrides, as `planarbench run` passes them
// without --set (apps/cli_common.cpp engine_settings_for)
SettingsOverrides case_settings(const Case& c) {
  SettingsOverrides o;
  for (const auto& [key, text] : c.settings) o.set(key, text, SettingSource{c.source_path, 0});
  return o;
}

void simulated_second(benchmark::State& state, const EngineCase& ec) {
  std::vector<BodyState> states;
  std::vector<ContactSample> contacts;
  double simulated_s = 0.0;  // s, summed over iterations
  double steps = 0.0;        // engine steps, summed over iterations
  std::unique_ptr<Engine> engine;
  for (auto _ : state) {
    try {
      // not timed: a fresh engine (the previous one is destroyed here) and its build
      state.PauseTiming();
      engine = make_engine(ec.engine);
      // settings applied before the build, as pb::run_engine does
      engine->settings().apply(ec.settings);
      engine->build(ec.c, ec.settings);
      const double t0_s = engine->time();
      const long steps0 = engine->steps();
      state.ResumeTiming();
      // timed: the runner's loop, advance to each grid time, read states and contacts
      for (int k = 1; k <= ec.grid_points; ++k) {
        engine->advance_to(ec.c.output_time(k));
        engine->body_states(states);
        engine->contacts(contacts);
      }
      benchmark::DoNotOptimize(states.data());
      benchmark::DoNotOptimize(contacts.data());
      simulated_s += engine->time() - t0_s;
      steps += static_cast<double>(engine->steps() - steps0);
    } catch (const std::exception& e) {
      // SkipWithError stops the timer whether or not it is running
      skip_with_error(state, ec.engine + " on " + ec.c.name + ": " + e.what());
      break;
    }
  }
  // kIsRate divides by the real (wall) time of all iterations (UseRealTime)
  state.counters["sim_s_per_wall_s"] = benchmark::Counter(simulated_s, benchmark::Counter::kIsRate);
  state.counters["steps_per_s"] = benchmark::Counter(steps, benchmark::Counter::kIsRate);
  state.counters["window_s"] = ec.grid_points * ec.c.output_interval_s;
  state.SetLabel(ec.support);
}

void register_engine_benchmarks() {
  for (const auto& path : resolve_cases("all", PB_CASES_DIR)) {
    const Case c = load_case(path);
    const double window_s = std::min(kWindowS, c.duration_s);
    // grid times k * output_interval <= window (1e-9 relative slack for rounding)
    const int grid_points = std::min(
        c.output_samples() - 1,
        static_cast<int>(window_s / c.output_interval_s * (1.0 + 1e-9)));
    for (const auto& name : engine_names()) {
      const Capability cap = make_engine(name)->supports(c);
      if (cap.support == Support::unsupported) continue;
      auto ec = std::make_shared<const EngineCase>(
          EngineCase{c, case_settings(c), name, support_name(cap.support), grid_points});
      benchmark::RegisterBenchmark(("engines/" + c.name + "/" + name).c_str(),
                                   [ec](benchmark::State& state) { simulated_second(state, *ec); })
          ->UseRealTime()
          ->Unit(benchmark::kMillisecond);
    }
  }
}

const DeferredRegistration kRegistration(register_engine_benchmarks);

}  // namespace

}  // namespace pb::bench
