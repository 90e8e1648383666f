// The truth run of a case, shared by `sweep` and `campaign`.
#pragma once

#include <string>

#include "planarbench/case.hpp"
#include "planarbench/run_result.hpp"
#include "planarbench/settings.hpp"
#include "sweep_plan.hpp"

namespace pb::cli {

// The truth run of a case (sweep and campaign): `plan` (truth_for) at the
// case's engine settings `base` under the truth's own; a closed form that
// does not run falls back to the reference (reference_truth). The note says
// why that truth, how far the reference agrees with the closed form up to
// the first contact where the case has one, and when the truth did not run.
struct TruthRun {
  RunResult result;
  std::string label;
  std::string note;
};
[[nodiscard]] TruthRun run_truth(const Case& c, const TruthPlan& plan, const SettingsOverrides& base);

}  // namespace pb::cli
