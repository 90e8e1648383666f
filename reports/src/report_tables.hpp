// The report's tables (SPEC §6): capability matrix, timings, every metric with
// its pass/fail against the thresholds, thresholds without a metric, and
// provenance.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/reports/metrics.hpp"
#include "planarbench/reports/thresholds.hpp"
#include "planarbench/run_result.hpp"
#include "report_model.hpp"
#include "report_provenance.hpp"

namespace pb::internal {

// cases x engines: the status of each run, with the reason when not ok
[[nodiscard]] Table capability_table(const ResultsFile& results);

// per run: status, wall time, steps, simulated time, wall per simulated second
[[nodiscard]] Table timings_table(const ResultsFile& results, const std::vector<Case>& cases);
// whose physics produced each run (SPEC §5b: the mapping's "physics"):
// mode, whose collision, whose contact force, how the law's parameters were
// set, and whether any came from the run's future (an oracle run: failing row)
[[nodiscard]] Table physics_table(const ResultsFile& results);

// Every metric: case, engine, against, metric, episode, value, desired, error,
// unit, and with `with_checks` (a thresholds file was given) the limit and
// pass / fail of each checked metric (a metric no threshold covers has an
// empty result).
[[nodiscard]] Table metrics_table(const std::vector<MetricValue>& metrics,
                                  const std::vector<CheckOutcome>& outcomes, bool with_checks);

// thresholds that matched no computed metric (each fails: "not computed")
[[nodiscard]] Table unmatched_thresholds_table(const std::vector<CheckOutcome>& outcomes);

// /parameters, then each case's sha256 and --set overrides, then each run's
// engine version
[[nodiscard]] Table provenance_table(const FileProvenance& provenance, const ResultsFile& results);

// numbers as the tables print them: 4 significant digits, "" for NaN
[[nodiscard]] std::string format_number(double v);

// how many wall times a run's cost is the median of (1 for a single run), and
// their range: s (NaN, NaN for a single run), or as text "min - max" ("")
[[nodiscard]] std::string wall_runs(const RunResult& r);
[[nodiscard]] std::pair<double, double> wall_time_range(const RunResult& r);
[[nodiscard]] std::string wall_range(const RunResult& r);

}  // namespace pb::internal
