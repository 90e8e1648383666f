// The metrics of a scene (SPEC §11), beside the trajectory and episode
// metrics every case has (metrics.hpp):
//   stacks and pyramids (the bodies of a [[generate]] standing on a support):
//     lateral_drift_m      max over its bodies and samples of the displacement
//                          along the support's surface, m (truth 0: nothing
//                          pushes them sideways)
//     sag_m                the top body's sink along the support's normal at
//                          the end, m (a resting stack: 0; a pyramid released
//                          touching sinks by its compliance)
//     settled_creep_mps    the top body's mean speed over the run's second
//                          half, m/s (settled: 0)
//     ground_force_error   |mean support force over the second half - the
//                          weight W| / W (statics: the support carries it all)
//     interface_force_error (against the truth) max over samples and
//                          interfaces of |F - F_truth| / F_truth
//   every scene:
//     energy_ratio         max over samples of KE / (KE(0) + U_c(0) + W_g(t)):
//                          passive contacts keep it <= 1 (energy_budget.hpp)
//     deepest_penetration_m  max penetration over the contacts table, m
//                          (SimBenchmark's measure of a pile)
#pragma once

#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/reports/metrics.hpp"
#include "planarbench/run_result.hpp"

namespace pb {

// the scene metrics of `run`; `truth` (nullable) an ok truth run of the case
[[nodiscard]] std::vector<MetricValue> scene_metrics(const Case& c, const RunResult& run,
                                                     const RunResult* truth);

// the names scene_metrics can give (thresholds check them)
[[nodiscard]] const std::vector<const char*>& scene_metric_names();

}  // namespace pb
