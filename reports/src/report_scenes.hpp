// The scenes section of a report (SPEC §11, issue 44): per scene family
// (stacks, pyramids, rows, piles) a table of every scene on every engine,
// with the figures that matter for the family (scene_metrics.hpp): a stack's
// and a pyramid's sag, sideways drift and settled creep, the support's force
// against the weight and the interfaces' against k m g, a pile's energy
// ratio and deepest penetration, and each run's cost per simulated second;
// and, for a family shipped at several sizes, the sag and the cost against
// the number of bodies on log axes, one line per engine.
#pragma once

#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/run_result.hpp"
#include "report_model.hpp"

namespace pb::internal {

// cases and results: the report's (index-aligned); empty without scenes
[[nodiscard]] ScenesSection scenes_section(const std::vector<Case>& cases,
                                           const ResultsFile& results);

}  // namespace pb::internal
