// A campaign's axis points checked against every case and engine before
// anything runs (campaign_file.cpp calls it once the plan is read): each value
// of each axis alone, and every combination of the values of the axes that
// change the case, since a case's keys constrain one another (issue 35 item
// 11: duration 0.001 with output_interval 0.01 planned, then `campaign run`
// exited 2 naming neither the file nor the axes).
#pragma once

#include <string>
#include <vector>

#include "campaign_plan.hpp"

namespace pb::cli {

// Throws InputError naming plan.file, the axis (its line, plan.axis_lines) or
// axes, the point and the case, with what the loader or the engine said (each
// point with the campaign's `set`). With `quiet` false, a check past a second
// says how far it is on stderr.
void check_axis_points(const CampaignPlan& plan, bool quiet);

// the most combinations of case axes checked one by one; past it, each axis's
// first, last, smallest and largest values are combined (the corners, where
// an order between keys such as output_interval <= duration breaks first)
inline constexpr std::int64_t kMaxCheckedCombinations = 20000;

}  // namespace pb::cli
