// The measured-impacts section of a report (SPEC §8, issue 23), from the
// table of `planarbench impacts fit` (cross-validated predictions) or
// `impacts score` (frozen parameters on another file):
//  - the convention check: the angular momentum about the contact point,
//    post against pre, for each sign pair of the stored angles;
//  - per model: its fitted parameters, eps median / mean / 90th percentile of
//    the judged predictions, the median absolute error of x', y' and theta',
//    failures and wall time; per fit (fold) its parameters and objective;
//  - figures: the CDF of eps per model, and predicted against measured for
//    x', y' and theta' (engines and the rigid baseline).
#pragma once

#include <string>

#include "planarbench/campaign_table.hpp"
#include "report_model.hpp"

namespace pb::internal {

// true for the tables `planarbench impacts` writes
[[nodiscard]] bool is_impacts_table(const CampaignTable& t);

[[nodiscard]] ImpactsSection impacts_section(const CampaignTable& t, const std::string& file);

}  // namespace pb::internal
