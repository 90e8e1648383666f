// Runs whose samples are not numbers (issue 24): a NaN or an infinity in a
// run's sample times, positions, angles, velocities or contact forces makes
// every metric of it meaningless (a maximum would silently skip the NaN, a
// mean would be NaN). The gate fails every check of such a run and of every
// run compared against it (thresholds.hpp), `check` names each one, and the
// report shows the run failed instead of ranking it.
//
// NaN is allowed where the layout gives it a meaning (tests/python/README.md):
// an episode still open at the end has no offset_time, separation_speed or
// restitution, and an engine that does not report penetration writes NaN.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "planarbench/run_result.hpp"

namespace pb {

// one dataset (or table field) of one run holding NaN or an infinity
struct InvalidRun {
  std::string case_name;
  std::string engine;
  std::string dataset;         // its path in the results file, /runs/<case>/<engine>/...
  std::string field;           // the table's field ("force_n"); "" for a body's dataset
  std::size_t rows = 0;        // rows holding a non-finite value
  std::size_t total_rows = 0;  // rows of the dataset
  std::size_t first_row = 0;   // the first of them (0-based)
  double first_value = 0.0;    // its non-finite value (nan, inf or -inf)

  // "falling_ball.mujoco": the run, as `check` names runs
  [[nodiscard]] std::string run() const;
  // the dataset and what is wrong with it, without the run:
  // "/runs/c/e/bodies/ball/position: 10 of 25001 rows hold NaN or inf (the first: row 100, nan)"
  [[nodiscard]] std::string what() const;
  // run() + ": " + what()
  [[nodiscard]] std::string describe() const;
};

// Every dataset of every run of `cr` with a non-finite value, in the file's
// order: runs as stored, each body's time, position, angle, velocity and
// angular_velocity, the contacts table's time, force_n, normal and point_m
// (and an infinity in its penetration_m, tangential_force_n or slip_mps),
// then the events table's onset_time_s, approach_speed_mps, peak_force_n and
// impulse_ns (and an infinity in the rest). Unsupported runs have no samples
// to check.
[[nodiscard]] std::vector<InvalidRun> invalid_runs(const CaseRuns& cr);

// the first entry of `invalid` about run (case_name, engine); null when none
[[nodiscard]] const InvalidRun* find_invalid(const std::vector<InvalidRun>& invalid,
                                             const std::string& case_name,
                                             const std::string& engine);

}  // namespace pb
