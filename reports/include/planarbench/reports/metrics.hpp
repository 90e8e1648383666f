// The comparison metrics of SPEC §4: one run against a baseline (the truth,
// the reference solver, or another engine) on one time grid.
#pragma once

#include <string>
#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/run_result.hpp"

namespace pb {

// One metric value. `actual` is the run's quantity and `desired` the
// baseline's (numpy assert_allclose semantics: |actual - desired| <= atol +
// rtol |desired|); for error metrics (position_max ...) desired is 0 and
// actual is the error itself. `error` is what a report shows.
struct MetricValue {
  std::string case_name;
  std::string engine;
  std::string against;   // "truth", "reference" or an engine name; "self" for energy etc.
  std::string metric;    // SPEC §4 name
  int episode = -1;      // contact episode index for per-episode metrics, -1 otherwise
  double actual = 0.0;
  double desired = 0.0;
  double error = 0.0;    // abs error, or relative error for relative metrics
  std::string unit;      // of `error` ("1": relative, or a dimensionless quantity)
  std::string value_unit;  // of `actual` and `desired`
  std::string note;      // e.g. "episode missing in run", "compared up to t = 0.4965 s"
};

// One value of metric `name` of `run` against `against`: error = |actual -
// desired|, divided by |desired| when `relative` (its unit is then "1");
// `unit` is the quantity's.
[[nodiscard]] MetricValue metric_value(const Case& c, const RunResult& run,
                                       const std::string& against, const std::string& name,
                                       double actual, double desired, bool relative,
                                       const std::string& unit);

// The metrics of `run` against `baseline`, both runs of case `c`. Trajectories:
// the run's samples, deduplicated by time (an engine with a step coarser than
// the grid repeats its last state), are linearly interpolated onto the
// baseline's sample times inside the run's time span; samples of the baseline
// after `valid_until_s` are left out. A run with fewer rows of a body than
// the baseline, or none, is "truncated" (noted): an ok run's trajectory
// errors are then NaN, never those of the common prefix; a diverged run
// keeps its errors up to the divergence (issue 25). Episodes are matched in
// order per body pair (the run's k-th with the baseline's k-th); the counts
// are metric "episode_count" (noted when episodes are missing or extra); a
// baseline episode the run lacks gets each metric its baseline value exists
// for with the run's value NaN, so its thresholds fail; an extra episode of
// the run has nothing to be compared with and shows in episode_count alone.
// A run's NaN or inf episode value against a finite baseline one is kept as
// NaN (fails); a baseline value that is not finite gives no metric.
// A NaN sample makes a maximum (position_max, velocity_max, angle_max, the
// drifts) NaN, never skipped (issue 24; run_validity.hpp names such runs).
[[nodiscard]] std::vector<MetricValue> compare_runs(const Case& c, const RunResult& run,
                                                    const RunResult& baseline,
                                                    const std::string& against,
                                                    double valid_until_s);

// Metrics of a run on its own: energy_drift (max change of total mechanical
// energy over each contact-free stretch, relative to the run's energy scale
// m g (y_max - y_min) + max kinetic energy), constraint_drift (max distance
// between each revolute joint's anchor on the body and its world pivot),
// momentum_drift (closed systems: free bodies touching only each other,
// max |P(t) - P(0) - M g t| relative to |P(0)|, or to sum m |v(0)| when that
// is 0), wall_per_sim_s.
[[nodiscard]] std::vector<MetricValue> self_metrics(const Case& c, const RunResult& run);

// Every metric of a case: each engine against the truth (analytic where the
// case has one, valid up to its valid_until_s; otherwise the reference), each
// engine against the reference, every pair of engines, and self metrics.
[[nodiscard]] std::vector<MetricValue> case_metrics(const Case& c, const CaseRuns& runs);

}  // namespace pb
