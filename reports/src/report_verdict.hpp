// The verdict at the top of a report (issue 13): per case, which engine is
// closest to the truth at its default settings, how much worse the others
// are, what each costs, and the caveats a reader needs before trusting the
// ranking (whose truth, runs that failed, bands an engine cannot meet).
#pragma once

#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/reports/metrics.hpp"
#include "planarbench/reports/thresholds.hpp"
#include "planarbench/run_result.hpp"
#include "report_model.hpp"

namespace pb::internal {

// One row per case of `results` (cases[i] is the case of results.cases[i]):
// the engines (and the reference, when a truth exists) ranked by
// position_max against the truth, or against the reference where the case
// has no truth (flagged: the ranking then measures agreement with the
// reference, not accuracy); each with its error, the ratio to the best, the
// run's wall time per simulated second, and the sweep's time to 1e-3 m when
// `work_precision` has the case. Caveats list runs that are not ok, known
// breaches and failed checks of `outcomes`, and unresolved impacts from the
// mappings.
[[nodiscard]] Table verdict_table(const ResultsFile& results, const std::vector<Case>& cases,
                                  const std::vector<MetricValue>& metrics,
                                  const std::vector<CheckOutcome>& outcomes,
                                  const std::vector<MappingEntry>& mappings,
                                  const std::vector<WorkPrecisionCase>& work_precision);

}  // namespace pb::internal
