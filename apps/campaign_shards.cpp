#include "campaign_shards.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <queue>
#include <stdexcept>

#include "campaign_size.hpp"
#include "planarbench/errors.hpp"

namespace pb::cli {

std::pair<int, int> parse_shard(const std::string& text, const std::string& option) {
  const auto slash = text.find('/');
  int k = -1;
  int n = 0;
  try {
    std::size_t used_k = 0;
    std::size_t used_n = 0;
    if (slash != std::string::npos) {
      k = std::stoi(text.substr(0, slash), &used_k);
      n = std::stoi(text.substr(slash + 1), &used_n);
    }
    if (slash == std::string::npos || used_k != slash || used_n != text.size() - slash - 1) n = 0;
  } catch (const std::exception&) {
    n = 0;
  }
  if (n < 1 || n > 100000 || k < 0 || k >= n) {
    throw InputError(option, 0, text,
                     "expected K/N with 0 <= K < N <= 100000, e.g. 0/4 (Slurm: "
                     "$SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT)");
  }
  return {k, n};
}

std::vector<std::vector<std::int64_t>> partition(const CampaignPlan& plan, int n, bool quiet) {
  const std::int64_t total = plan.size();
  std::vector<std::pair<double, std::int64_t>> runs;
  runs.reserve(static_cast<std::size_t>(total));
  PlanProgress costing("costing the runs for the shards", total, quiet);
  for (std::int64_t id = 0; id < total; ++id) {
    runs.emplace_back(plan.cost(id), id);
    costing.tick(id + 1);
  }
  costing.say(fmt::format("sorting {} runs by estimated cost", total));
  std::sort(runs.begin(), runs.end(), [](const auto& a, const auto& b) {
    return a.first != b.first ? a.first > b.first : a.second < b.second;
  });
  using Load = std::pair<double, int>;  // (estimated cost so far, shard)
  std::priority_queue<Load, std::vector<Load>, std::greater<>> least;
  for (int k = 0; k < n; ++k) least.emplace(0.0, k);
  std::vector<std::vector<std::int64_t>> shards(static_cast<std::size_t>(n));
  PlanProgress dealing(fmt::format("dealing the runs to {} shards", n), total, quiet);
  std::int64_t dealt = 0;
  for (const auto& [c, id] : runs) {
    dealing.tick(++dealt);
    auto [load, k] = least.top();
    least.pop();
    shards[static_cast<std::size_t>(k)].push_back(id);
    least.emplace(load + c, k);
  }
  for (auto& s : shards) std::sort(s.begin(), s.end());
  return shards;
}

}  // namespace pb::cli
