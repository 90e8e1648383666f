// The work-precision section of a report, from a `planarbench sweep` file:
// per case, each series' error against wall time (a log-log plot, see
// report_work_precision_svg.hpp), the wall time each series needs to reach a
// position error of 1e-3 m and 1e-5 m, and its cost per simulated second at the
// engine's default setting next to the reference's.
#pragma once

#include <string>
#include <vector>

#include "planarbench/sweep_file.hpp"
#include "report_model.hpp"
#include "report_provenance.hpp"

namespace pb::internal {

// m, the error levels each case's table gives the wall time for
[[nodiscard]] const std::vector<double>& work_precision_targets();

// The wall time a series needs to reach `target_m`. Its rungs are walked in
// ladder order (coarse to fine), skipping rungs without a finite error >= 0
// and a positive finite wall time (diverged, unsupported, no truth). At the
// first crossing, between the last rung above the level (t_a, e_a) and the
// first at or below it (t_b, e_b), the time is interpolated linearly in log-log,
//   log t = log t_a + (log target - log e_a) (log t_b - log t_a) / (log e_b - log e_a),
// as on a work-precision diagram (Hairer, Norsett & Wanner, Solving ODEs I,
// §II.1: error against work, both logarithmic). The result is the least of
// that time and the wall time of every rung at or below the level (a finer
// rung can be cheaper when wall times are noisy). When the first usable rung
// is already at or below the level, the result is an upper bound
// (at_first_rung: a coarser setting might do). An error of exactly 0 gives t_b.
[[nodiscard]] Reach time_to_reach(const std::vector<double>& wall_s,
                                  const std::vector<double>& error_m, double target_m);

// "0.1234", "<= 0.0213" (at_first_rung), "not reached", "no data"
[[nodiscard]] std::string reach_text(const Reach& r);

// the index of the rung at the series' default setting (relative match
// 1e-9), -1 when the ladder does not hold it
[[nodiscard]] int default_rung(const SweepSeries& s);

// The section of one case: plot series, what is not plotted, the summary
// table (per series: knob, default, error and wall per simulated second at the
// default, ratio to the reference rk45's, time to each target) and every rung.
[[nodiscard]] WorkPrecisionCase work_precision_case(const SweepCase& c);

// the plot's file in the report folder: "figures/<id>.svg"
[[nodiscard]] std::string work_precision_file(const WorkPrecisionCase& c);

// What the section says about how the sweep was made and how to read it.
[[nodiscard]] std::string work_precision_note(const SweepFile& sweep, const std::string& path);

// /parameters of the sweep file, then its ladders and each case's digest.
[[nodiscard]] Table sweep_provenance_table(const FileProvenance& provenance,
                                           const SweepFile& sweep);

}  // namespace pb::internal
