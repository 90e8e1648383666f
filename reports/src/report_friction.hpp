// The friction section of a report (SPEC §7, issue 22):
//  - per case whose truth holds a body at rest (block_hold): the drift of its
//    contact point over time, one line per engine, on a log scale
//    (friction_metrics.hpp, hold_drift_series);
//  - the friction curve, from a campaign whose axis sets a pair's friction
//    and which records slide_acceleration_mps2 (campaigns/friction_curve.toml):
//    each engine's steady acceleration against tan(theta) / mu, with the
//    closed form a = g (sin(theta) - mu cos(theta)) where tan(theta) > mu, 0
//    where it holds: the stick-slip threshold at 1.0;
//  - a table of the curve: per point, the closed form and each engine's value;
//  - the block family (issue 30), from a campaign that records hold_drift_m,
//    slide_acceleration_error or stop_time_error (campaigns/block_family.toml):
//    each engine's error per member against tan(theta) / mu (held, sliding)
//    or v0 (stopping), log scale, and a table per engine: members, worst error.
#pragma once

#include <vector>

#include "planarbench/campaign_table.hpp"
#include "planarbench/case.hpp"
#include "planarbench/run_result.hpp"
#include "report_model.hpp"

namespace pb::internal {

// a campaign table and the file it came from
struct NamedCampaign {
  const CampaignTable* table = nullptr;
  std::string file;
};

// cases and results: the report's (index-aligned); campaigns: the tables
// beside them (the curve's and the family's found among them). Empty (no
// figure) when none has anything of friction.
[[nodiscard]] FrictionSection friction_section(const std::vector<Case>& cases,
                                               const ResultsFile& results,
                                               const std::vector<NamedCampaign>& campaigns);

}  // namespace pb::internal
