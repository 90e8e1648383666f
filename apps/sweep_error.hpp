// The error of one sweep rung: SPEC §4 position_max of the run against the
// case's truth (reports/metrics.hpp), taken at the output samples the engine
// really reached.
//
// An engine whose step is coarser than the output interval repeats its last
// state on the grid (runner.hpp); compare_runs would then interpolate linearly
// between its steps, and that interpolation error (about a dt^2 / 8: 7e-5 m at
// dt = 1 ms through the falling ball's 580 m/s^2 impact) would hide the
// integration error the sweep measures. So the truth is restricted to the grid
// samples where the run's time is the grid time (within kSameTimeFraction of
// the output interval); a run that reaches no grid time after t = 0 (a step
// incommensurate with the grid) is compared on every sample, interpolated.
#pragma once

#include "planarbench/case.hpp"
#include "planarbench/run_result.hpp"

namespace pb::cli {

// a run's sample is at grid time t_k when |t - t_k| <= this * output interval
inline constexpr double kSameTimeFraction = 1e-6;

// m; NaN unless both runs are ok and share at least one body
[[nodiscard]] double sweep_position_error(const Case& c, const RunResult& run,
                                          const RunResult& truth);

// the number of grid samples of `run` (after t = 0) at which its time is the grid time
[[nodiscard]] std::size_t samples_on_grid(const Case& c, const RunResult& run);

}  // namespace pb::cli
