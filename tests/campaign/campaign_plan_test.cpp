// Tests for apps/campaign_file.cpp and campaign_plan.cpp: the campaign file read into its runs,
// their order, their settings, the seeded perturbations and the shards.
#include "campaign_plan.hpp"
#include "campaign_shards.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "planarbench/errors.hpp"

namespace {

namespace fs = std::filesystem;
using pb::cli::CampaignPlan;

fs::path write_campaign(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / ("pb_campaign_plan_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path p = dir / name;
  std::ofstream(p) << text;
  return p;
}

const char* kTwoAxes = R"(
[campaign]
cases = ["falling_ball", "head_on"]
engines = ["mujoco", "ode"]
metrics = ["position_error_m", "trace"]

[[axis]]
key = "dt"
values = [1e-3, 5e-4, 1e-4]

[[axis]]
name = "state"
key = "bodies.*.velocity"
perturb = { sigma = 1e-2, samples = 2, seed = 3 }
)";

TEST(CampaignPlan, RunsAreEveryCaseEngineAndAxisPointInThatOrder) {
  const CampaignPlan plan = pb::cli::load_campaign(write_campaign("two.toml", kTwoAxes), "");
  ASSERT_EQ(plan.size(), 2 * 2 * 3 * 2);
  EXPECT_EQ(plan.trace_points, 50);  // the default when "trace" is recorded
  // the case outermost, the last axis innermost (mixed radix 2, 2, 3, 2)
  for (std::int64_t id = 0; id < plan.size(); ++id) {
    const auto r = plan.decode(id);
    const std::int64_t back =
        ((static_cast<std::int64_t>(r.case_index) * 2 + static_cast<std::int64_t>(r.engine_index)) * 3 +
         static_cast<std::int64_t>(r.point[0])) * 2 + static_cast<std::int64_t>(r.point[1]);
    EXPECT_EQ(back, id);
  }
  const auto last = plan.decode(plan.size() - 1);
  EXPECT_EQ(plan.cases[last.case_index].c.name, "head_on");
  EXPECT_EQ(plan.engines[last.engine_index], "ode");
  EXPECT_EQ(plan.describe(7), "run 7: falling_ball x ode, dt=0.001, state=1");
}

TEST(CampaignPlan, AssignmentsSetTheAxisKeyAndPerturbEveryMovingBody) {
  const CampaignPlan plan = pb::cli::load_campaign(write_campaign("two.toml", kTwoAxes), "");
  // head_on has two moving disks: one velocity assignment each, plus dt
  const std::int64_t id = 12 + 2 * 1 + 1;  // head_on x mujoco, dt=5e-4, state=1
  const auto r = plan.decode(id);
  ASSERT_EQ(plan.cases[r.case_index].c.name, "head_on");
  const auto a = plan.assignments(r);
  ASSERT_EQ(a.size(), 1u + plan.cases[r.case_index].moving_bodies.size());
  EXPECT_EQ(a[0].first, "dt");
  EXPECT_EQ(a[0].second, "0.0005");
  for (std::size_t i = 1; i < a.size(); ++i) {
    EXPECT_EQ(a[i].first, "bodies." + plan.cases[r.case_index].moving_bodies[i - 1] + ".velocity");
  }
  // only the perturbation changes the case (and so the truth)
  const auto case_keys = plan.case_assignments(r);
  EXPECT_EQ(case_keys.size(), a.size() - 1);
  // the same run id gives the same settings in a plan loaded again (a shard)
  const CampaignPlan again = pb::cli::load_campaign(write_campaign("two.toml", kTwoAxes), "");
  EXPECT_EQ(again.assignments(again.decode(id)), a);
}

TEST(CampaignPlan, PerturbationsAreNormalWithTheGivenSigma) {
  // 4000 samples of a 2-D velocity: 8000 deviates. Sample mean and standard
  // deviation against N(0, sigma^2): the mean's standard error is
  // sigma / sqrt(8000) = 1.1 % of sigma, the standard deviation's relative
  // standard error 1 / sqrt(2 * 8000) = 0.8 %; the bounds are 5 of them.
  const double sigma = 0.25;
  const CampaignPlan plan = pb::cli::load_campaign(write_campaign("many.toml", R"(
[campaign]
cases = ["falling_ball"]
engines = ["ode"]
[[axis]]
key = "bodies.ball.velocity"
perturb = { sigma = 0.25, samples = 4000, seed = 11 }
)"),
                                                   "");
  const auto& ball = plan.cases[0].c.bodies;
  const auto nominal = std::find_if(ball.begin(), ball.end(), [](const auto& b) { return b.name == "ball"; })
                           ->velocity_mps;
  double sum = 0.0, sum2 = 0.0;
  int n = 0;
  std::set<std::string> distinct;
  for (std::int64_t id = 0; id < plan.size(); ++id) {
    const auto a = plan.assignments(plan.decode(id));
    ASSERT_EQ(a.size(), 1u);
    distinct.insert(a[0].second);
    double vx = 0.0, vy = 0.0;
    ASSERT_EQ(std::sscanf(a[0].second.c_str(), "[%lf,%lf]", &vx, &vy), 2) << a[0].second;
    for (const double d : {vx - nominal.x(), vy - nominal.y()}) {
      sum += d;
      sum2 += d * d;
      ++n;
    }
  }
  EXPECT_EQ(distinct.size(), 4000u);
  const double mean = sum / n;
  const double sd = std::sqrt(sum2 / n - mean * mean);
  EXPECT_LT(std::abs(mean), 5 * sigma / std::sqrt(n));
  EXPECT_LT(std::abs(sd / sigma - 1.0), 5 / std::sqrt(2.0 * n));
}

TEST(CampaignPlan, LogAndLinearRangesEndExactlyWhereGiven) {
  const CampaignPlan plan = pb::cli::load_campaign(write_campaign("ranges.toml", R"(
[campaign]
cases = ["falling_ball"]
engines = ["ode"]
[[axis]]
key = "dt"
log = { from = 1e-3, to = 1e-5, points = 5 }
[[axis]]
key = "contact.stiffness"
linear = { from = 1e5, to = 3e5, points = 3 }
)"),
                                                   "");
  const auto& dt = plan.axes[0].axis.values;
  ASSERT_EQ(dt.size(), 5u);
  EXPECT_EQ(dt.front(), 1e-3);
  EXPECT_EQ(dt.back(), 1e-5);
  // 10^(-3 - k/2): equal ratios of sqrt(10), to rounding (a few ulps)
  for (std::size_t k = 0; k < dt.size(); ++k) {
    EXPECT_NEAR(dt[k], std::pow(10.0, -3.0 - 0.5 * static_cast<double>(k)), 1e-14 * dt[k]);
  }
  EXPECT_EQ(plan.axes[1].axis.values, (std::vector<double>{1e5, 2e5, 3e5}));
  EXPECT_TRUE(plan.axes[1].case_key);
  EXPECT_FALSE(plan.axes[0].case_key);
}

TEST(CampaignPlan, ShardsTakeEveryRunOnceBalancedByCost) {
  const CampaignPlan plan = pb::cli::load_campaign(write_campaign("two.toml", kTwoAxes), "");
  double total = 0.0, largest = 0.0;
  for (std::int64_t id = 0; id < plan.size(); ++id) {
    total += plan.cost(id);
    largest = std::max(largest, plan.cost(id));
  }
  for (int n : {1, 2, 3, 4, 7, 24, 30}) {
    const auto shards = pb::cli::partition(plan, n);
    ASSERT_EQ(shards.size(), static_cast<std::size_t>(n));
    EXPECT_EQ(shards, pb::cli::partition(plan, n)) << "not deterministic at n = " << n;
    std::vector<std::int64_t> all;
    for (const auto& s : shards) {
      EXPECT_TRUE(std::is_sorted(s.begin(), s.end()));
      double load = 0.0;
      for (const auto id : s) load += plan.cost(id);
      // greedy to the least loaded: no shard exceeds the mean by more than
      // one run (Graham, "Bounds on multiprocessing timing anomalies", 1969)
      EXPECT_LE(load, total / n + largest + 1e-12) << n;
      all.insert(all.end(), s.begin(), s.end());
    }
    std::sort(all.begin(), all.end());
    ASSERT_EQ(all.size(), static_cast<std::size_t>(plan.size())) << n;
    for (std::int64_t id = 0; id < plan.size(); ++id) EXPECT_EQ(all[static_cast<std::size_t>(id)], id);
  }
  // a finer step costs more: the estimate scales with default step / step
  EXPECT_NEAR(plan.cost(4) / plan.cost(0), 10.0, 1e-12);  // dt 1e-4 vs 1e-3, same case/engine
}

TEST(CampaignPlan, ShardTextIsKOfNCountedFromZero) {
  EXPECT_EQ(pb::cli::parse_shard("0/1", "--shard"), std::make_pair(0, 1));
  EXPECT_EQ(pb::cli::parse_shard("3/4", "--shard"), std::make_pair(3, 4));
  for (const char* bad : {"4/4", "-1/4", "a/b", "1", "1/0", "1/4x", "", "/4", "0/100001"}) {
    EXPECT_THROW((void)pb::cli::parse_shard(bad, "--shard"), pb::InputError) << bad;
  }
}

TEST(CampaignPlan, CasesResolveByNamePathAndGlob) {
  const fs::path dir = write_campaign("x.toml", "").parent_path() / "globbed";
  fs::create_directories(dir);
  fs::copy_file(fs::path(PB_SOURCE_DIR) / "cases/sliding.toml", dir / "sliding.toml",
                fs::copy_options::overwrite_existing);
  fs::copy_file(fs::path(PB_SOURCE_DIR) / "cases/head_on.toml", dir / "head_on.toml",
                fs::copy_options::overwrite_existing);
  const CampaignPlan plan = pb::cli::load_campaign(write_campaign("glob.toml", R"(
[campaign]
cases = ["falling_ball", "globbed/*.toml"]
engines = "ode"
)"),
                                                   "");
  ASSERT_EQ(plan.cases.size(), 3u);
  EXPECT_EQ(plan.cases[0].c.name, "falling_ball");
  EXPECT_EQ(plan.cases[1].c.name, "head_on");  // a glob's matches sorted
  EXPECT_EQ(plan.cases[2].c.name, "sliding");
  EXPECT_EQ(plan.size(), 3);
  // the same case twice is refused: its runs would be ambiguous
  EXPECT_THROW((void)pb::cli::load_campaign(write_campaign("twice.toml", R"(
[campaign]
cases = ["sliding", "globbed/sliding.toml"]
engines = "ode"
)"),
                                            ""),
               pb::InputError);
}

}  // namespace

// the message load_campaign refuses `text` with, or "(planned)"
std::string refusal(const std::string& name, const std::string& text) {
  try {
    (void)pb::cli::load_campaign(write_campaign(name, text), "", true);
  } catch (const pb::InputError& e) {
    return e.what();
  }
  return "(planned)";
}

TEST(CampaignPlan, AxesThatChangeTheCaseAreCheckedTogether) {
  // issue 35 item 11: each axis alone was fine, duration 0.001 with
  // output_interval 0.01 planned, and `campaign run` then exited 2 naming
  // neither the file nor the axes
  const std::string head = R"(
[campaign]
cases = ["falling_ball"]
engines = ["mujoco"]
metrics = ["position_error_m"]
)";
  // a duration axis and an output_interval axis, each given by its TOML line
  // of points ("values = [...]", "linear = {...}")
  const auto two_axes = [&head](const std::string& durations, const std::string& intervals) {
    return head + "\n[[axis]]\nkey = \"duration\"\n" + durations +
           "\n\n[[axis]]\nkey = \"output_interval\"\n" + intervals + "\n";
  };
  const std::string why =
      refusal("together.toml", two_axes("values = [0.5, 0.001]", "values = [1e-3, 0.01]"));
  EXPECT_NE(why.find("together.toml:7: axis[0], axis[1]: the axes together: at duration = 0.001, "
                     "output_interval = 0.01 on case 'falling_ball'"),
            std::string::npos)
      << why;
  EXPECT_NE(why.find("must be <= duration"), std::string::npos) << why;
  // the same axes with every combination valid plan
  EXPECT_EQ(refusal("together_ok.toml", two_axes("values = [0.5, 0.1]", "values = [1e-3, 0.01]")),
            "(planned)");
  // past kMaxCheckedCombinations the corners are checked: the bad pair is
  // each axis's extreme (300 x 300 values)
  const std::string corner =
      refusal("corners.toml", two_axes("linear = { from = 0.002, to = 1, points = 300 }",
                                       "linear = { from = 1e-3, to = 0.01, points = 300 }"));
  EXPECT_NE(corner.find("at duration = 0.002, output_interval = 0.01"), std::string::npos) << corner;
}
