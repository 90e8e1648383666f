// A campaign's runs dealt to shards: `campaign run --shard K/N` runs shard K,
// `campaign plan --shards N` shows their balance, `campaign merge` names the
// shards of missing runs.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "campaign_plan.hpp"

namespace pb::cli {

// "K/N" (0 <= K < N <= 100000) as {K, N}; InputError naming `option` otherwise.
[[nodiscard]] std::pair<int, int> parse_shard(const std::string& text, const std::string& option);

// The ids of shard k of n, ascending: the runs dealt longest first to the
// shard with the least estimated cost so far (ties to the lowest shard, runs
// of equal cost by id): deterministic, and balanced by estimated cost. Takes
// up to kPlanBytesPerRun bytes per run (campaign_size.hpp); with `quiet`
// false, says how far it is on stderr once it has taken a second.
[[nodiscard]] std::vector<std::vector<std::int64_t>> partition(const CampaignPlan& plan, int n,
                                                               bool quiet = true);

}  // namespace pb::cli
