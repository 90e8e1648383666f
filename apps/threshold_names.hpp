// The names a thresholds file uses that its own syntax check cannot know:
// cases, engines and baselines, checked against a results file and the
// cases folder by `check` and `report --thresholds` alike.
#pragma once

#include <string>
#include <vector>

#include "planarbench/reports/thresholds.hpp"
#include "planarbench/run_result.hpp"

namespace pb::cli {

// Each threshold's case is in `results` or the cases folder, its engine is an
// engine and its `against` an engine, truth or self; otherwise an InputError
// naming the file, the line and the field, with a "did you mean". A misspelt
// name would otherwise be a breach ("not computed") in `check`, and a check
// silently never made in `report`.
void check_threshold_names(const std::string& file, const std::vector<Threshold>& thresholds,
                           const ResultsFile& results);

}  // namespace pb::cli
