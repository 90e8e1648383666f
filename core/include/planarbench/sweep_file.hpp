// The HDF5 work-precision file of `planarbench sweep`, readable with h5py
// alone. Written to a temporary name in the target directory and renamed when
// complete, like the results file (results_file.hpp).
//
//   /parameters                       attributes: provenance as in a results file
//                                     (build, host, UTC time, command line), and
//                                     the sweep's repeat, quick, dt_ladder, rtol_ladder,
//                                     ladder_stop_rule (a series has fewer rungs than
//                                     its ladder when it stopped early)
//   /sweep/<case>/                    attributes: case_text, case_sha256, case_path,
//                                     overrides (JSON), duration_s, truth, truth_note
//   /sweep/<case>/<series>/           attributes: engine, knob ("dt" or "rtol"),
//                                     knob_key (the --set key), default_value,
//                                     fixed_settings (JSON), truth
//     value [n]                       the knob's value at each rung (unit s or 1)
//     wall_time_s [n]                 s, median wall time of the repeats
//     steps [n]                       the engine's steps
//     position_error_m [n]            m, max over samples and bodies of |p - p_truth|
//     status [n], reason [n]          ok | diverged | unsupported, and why
// Every dataset carries a `unit` attribute.
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
