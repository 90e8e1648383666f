// Drives an engine through a case onto the common output grid.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>

#include "planarbench/case.hpp"
#include "planarbench/engine.hpp"
#include "planarbench/run_result.hpp"
#include "planarbench/settings.hpp"

namespace pb {

struct RunOptions {
  // called now and then with the fraction of simulated time done, [0, 1]
  std::function<void(double fraction)> progress;
  // when set, the samples go to a RunSpool in this folder as the run
  // proceeds (memory bounded whatever the run's length; run_spool.hpp);
  // empty: they are kept in RunResult's vectors
  std::filesystem::path spool_dir;
};

// Builds `engine` for case `c`, advances it to every output time, samples body
// states and contacts, and returns the result. Unsupported cases give status
// unsupported with the engine's reason; an EngineError, a non-finite state or
// an energy runaway (planarbench/energy_budget.hpp) gives status diverged with
// the time and the reason. InputError (bad settings) propagates.
[[nodiscard]] RunResult run_engine(Engine& engine, const Case& c,
                                   const SettingsOverrides& engine_overrides,
                                   const RunOptions& options = {});

}  // namespace pb
