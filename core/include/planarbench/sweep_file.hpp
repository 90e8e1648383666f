// The work-precision file of `planarbench sweep`: a results file (SPEC §5,
// results_file.hpp) whose /campaign table (campaign_table.hpp, kind "sweep")
// has one row per rung, written and read by the results file's own writer
// and reader, readable with h5py alone:
//
//   /campaign@description          JSON: repeat, quick, dt_ladder, rtol_ladder,
//                                  ladder_stop_rule (a series has fewer rungs than its
//                                  ladder when it stopped early)
//   /campaign/axes/dt, rtol        the ladders
//   /campaign/cases/<case>         case_text, ..., truth, truth_note; extra (JSON):
//                                  "series", each {name, engine, knob ("dt" | "rtol"),
//                                  knob_key, knob_unit, default_value, fixed_settings}
//   /campaign/runs/                a row per rung: case, engine, series, axis/dt or
//                                  axis/rtol (NaN on the other), steps, status, reason,
//                                  metric/position_error_m [m]; attribute wall_time_s [s]
//                                  (median of the repeats)
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "planarbench/run_result.hpp"

namespace pb {

// one rung of a ladder: one setting of the knob
struct SweepRung {
  double value = 0.0;        // the knob's value (dt in s, or rtol)
  double wall_time_s = 0.0;  // s, median over the repeats
  long steps = 0;
  double position_error_m = 0.0;  // m; NaN when not ok or without a truth
  RunStatus status = RunStatus::ok;
  std::string reason;  // empty when ok
};

// one engine (or one integrator of the reference) over its ladder
struct SweepSeries {
  std::string name;            // group name: "mujoco", "reference_rk45", "reference_fixed"
  std::string engine;          // engine name: "mujoco", "reference"
  std::string knob;            // "dt" or "rtol"
  std::string knob_key;        // the engine setting it drives: "mujoco.dt", "reference.rtol"
  std::string knob_unit;       // "s" for dt, "1" for rtol
  double default_value = 0.0;  // the knob at the engine's default settings
  std::string
      fixed_settings;  // JSON object: settings every rung shares, e.g. {"integrator":"fixed"}
  std::vector<SweepRung> rungs;
};

struct SweepCase {
  std::string case_name;
  std::string case_text;
  std::string case_path;
  std::vector<std::pair<std::string, std::string>> overrides;  // --set given
  double duration_s = 0.0;                                     // s, simulated time of every run
  std::string truth;       // what errors are measured against, e.g. "analytic"
  std::string truth_note;  // why that truth, and how far it is trusted
  std::vector<SweepSeries> series;
};

struct SweepFile {
  ResultsProvenance provenance;
  int repeat = 1;                   // runs per rung (wall time = median)
  bool quick = false;               // --quick: two rungs per series
  std::vector<double> dt_ladder;    // s
  std::vector<double> rtol_ladder;  // 1
  std::string ladder_stop_rule;     // when a series stops before its finest rung
  std::vector<SweepCase> cases;
};

// Writes the whole file atomically. Throws InputError when the target
// directory is missing or not writable (nothing is left behind), and
// std::runtime_error on an HDF5 failure (the temporary file is removed).
void write_sweep_file(const std::filesystem::path& path, const SweepFile& sweep);

// Reads a file written by write_sweep_file. Throws InputError naming the file
// and the missing or malformed object for a truncated or foreign file.
[[nodiscard]] SweepFile read_sweep_file(const std::filesystem::path& path);

}  // namespace pb
