// MuJoCo 2.2.2 and 3.3.8 side by side (issue 33): engine "mujoco" (Debian's
// native 2.2.2) and engine "mujoco3" (MuJoCo's WebAssembly build of 3.3.8)
// run the same plan, MJCF and contact rule, so every difference between their
// metrics is MuJoCo's own change between the versions.
#pragma once

#include <vector>

#include "planarbench/reports/metrics.hpp"
#include "planarbench/reports/thresholds.hpp"
#include "report_model.hpp"

namespace pb::internal {

// One row per case with both engines' metrics: how many were compared, how
// many agree to 1e-9 (relative), the largest change (metric, 2.2.2 -> 3.3.8)
// and each metric whose verdict differs between the versions. Empty (no rows)
// when no case has both engines.
[[nodiscard]] Table mujoco_versions_table(const std::vector<MetricValue>& metrics,
                                          const std::vector<CheckOutcome>& outcomes);

}  // namespace pb::internal
