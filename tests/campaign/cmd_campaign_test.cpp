// Tests for apps/cmd_campaign.cpp, run as a user runs it: the real binary's
// campaign plan / run / merge, its shards, a shard killed with SIGKILL and
// resumed, merges that must fail, and the merged file read with h5py alone
// (tests/campaign/read_campaign.py).
#include <gtest/gtest.h>

#include "planarbench/results_file.hpp"

#include <unistd.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <thread>

#include "child_process.hpp"

namespace {

using namespace pb::test;

// 2 cases x 3 engines x 2 steps x 3 perturbed initial velocities = 36 runs.
// The analytic engine is one of them: its error against the truth of its own
// (perturbed) initial state is zero, whatever the perturbation.
const char* kCampaign = R"(
[campaign]
cases = ["falling_ball", "head_on"]
engines = ["analytic", "mujoco", "ode"]
metrics = ["position_error_m", "events", "first_restitution", "trace"]
trace_points = 11

[[axis]]
key = "dt"
values = [1e-4, 5e-5]

[[axis]]
name = "state"
key = "bodies.*.velocity"
perturb = { sigma = 1e-2, samples = 3, seed = 5 }
)";
constexpr int kRuns = 36;

fs::path campaign_file(const fs::path& dir, const std::string& text = kCampaign) {
  const fs::path p = dir / "study.toml";
  std::ofstream(p) << text;
  return p;
}

// planarbench campaign ARGS..., run to its end
Finished campaign(std::vector<std::string> args) {
  args.insert(args.begin(), "campaign");
  return run_planarbench(args);
}

nlohmann::json read_with_h5py(const fs::path& file) {
  const Finished f = run_shell(std::string(PB_PYTHON) + " " + PB_SOURCE_DIR +
                               "/tests/campaign/read_campaign.py " + file.string());
  EXPECT_EQ(f.exit.code, 0) << f.err;
  return f.exit.code == 0 ? nlohmann::json::parse(f.err) : nlohmann::json::object();
}

// the one-machine run of kCampaign, made once per test process (CTest runs
// the tests of this file in parallel processes: each has its own)
const fs::path& one_shard_file() {
  static const fs::path file = [] {
    const fs::path dir = fresh_dir("one_" + std::to_string(::getpid()));
    const fs::path toml = campaign_file(dir);
    const Finished r = campaign({"run", toml.string(), "--out", (dir / "parts").string(), "-q"});
    EXPECT_EQ(r.exit.code, 0) << r.err;
    const Finished m = campaign({"merge", (dir / "parts").string(), "--out", (dir / "one.h5").string(), "-q"});
    EXPECT_EQ(m.exit.code, 0) << m.err;
    return dir / "one.h5";
  }();
  return file;
}

TEST(CmdCampaign, PlanCountsTheRunsAndEstimatesTheirCost) {
  const fs::path dir = fresh_dir("plan");
  const Finished f = run_shell(std::string(PB_EXE) + " campaign plan " + campaign_file(dir).string() +
                               " --shards 4");
  ASSERT_EQ(f.exit.code, 0) << f.err;
  EXPECT_NE(f.err.find("36 runs = 2 case(s) x 3 engine(s) x 2 (dt) x 3 (state)"), std::string::npos) << f.err;
  EXPECT_NE(f.err.find("truth runs: 6"), std::string::npos) << f.err;
  // balanced by estimated cost, not by count: the costliest within one run of the mean
  EXPECT_NE(f.err.find("4 shards: "), std::string::npos) << f.err;
}

// A plan that takes more than a second says how far it is on stderr (issue
// 24): 1,000,000 runs of one case and engine (nothing runs; the plan costs
// each run and deals them to 4 shards), about 1.5 s on the 2-core machine of
// the README, 12 s under the sanitizers (CI).
TEST(CmdCampaign, ALongPlanPrintsProgressOnStderr) {
  const fs::path dir = fresh_dir("plan_progress");
  const fs::path toml = campaign_file(dir, R"(
[campaign]
cases = ["falling_ball"]
engines = ["analytic"]
metrics = ["events"]

[[axis]]
key = "output_interval"
values = [1e-3, 2e-3, 3e-3, 4e-3]

[[axis]]
name = "state"
key = "bodies.*.velocity"
perturb = { sigma = 1e-2, samples = 250000, seed = 7 }
)");
  const auto t0 = std::chrono::steady_clock::now();
  const Finished f = campaign({"plan", toml.string(), "--shards", "4"});
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_EQ(f.exit.code, 0) << f.err;
  // progress is promised past a second: 1.5 s leaves half a second for the
  // start of the process and the line's one-second clock to disagree
  if (wall_s < 1.5) GTEST_SKIP() << "the plan took " << wall_s << " s: too fast to need progress";
  EXPECT_NE(f.err.find("campaign plan: "), std::string::npos) << f.err;
  EXPECT_NE(f.err.find(" of 1000000 runs"), std::string::npos) << f.err;
  EXPECT_NE(f.err.find("planned in"), std::string::npos) << f.err;
}

// Each run of a campaign is a process of its own (apps/run_isolation.hpp,
// issue 24): a spin of 1e200 rad/s trips libode's dIASSERT (SIGABRT), which
// ended the whole shard before; now that run is diverged naming the signal
// and the other runs are written (a campaign's diverged runs are rows of its
// table: the shard exits 0, as for any diverged run).
TEST(CmdCampaign, AnAbortInOneRunLosesOnlyThatRun) {
  const fs::path dir = fresh_dir("abort");
  const fs::path toml = campaign_file(dir, R"(
[campaign]
cases = ["falling_ball"]
engines = ["analytic", "ode"]
metrics = ["events"]
set = { duration = 0.01 }

[[axis]]
key = "bodies.ball.angular_velocity"
values = [0.0, 1e200]
)");
  const Finished r = campaign({"run", toml.string(), "--out", (dir / "parts").string(), "-q"});
  EXPECT_EQ(r.exit.code, 0) << r.err;
  const Finished m = campaign({"merge", (dir / "parts").string(), "--out", (dir / "c.h5").string(), "-q"});
  ASSERT_EQ(m.exit.code, 0) << m.err;
  const pb::ResultsFile f = pb::read_results_file(dir / "c.h5");
  ASSERT_TRUE(f.campaign.has_value());
  ASSERT_EQ(f.campaign->runs.size(), 4u);
  int diverged = 0;
  for (const auto& run : f.campaign->runs) {
    const bool spun = run.axis_values.at(0) > 1.0;
    if (run.engine == "ode" && spun) {
      ++diverged;
      EXPECT_EQ(run.status, pb::RunStatus::diverged);
      EXPECT_NE(run.reason.find("SIGABRT"), std::string::npos) << run.reason;
    } else {
      EXPECT_EQ(run.status, pb::RunStatus::ok) << run.engine << ": " << run.reason;
    }
  }
  EXPECT_EQ(diverged, 1);
}

TEST(CmdCampaign, ThreeShardsMergeToTheSameDatasetsAsOne) {
  const fs::path dir = fresh_dir("three");
  const fs::path toml = campaign_file(dir);
  for (int k = 0; k < 3; ++k) {
    // small checkpoints: each shard writes several files; one thread or two
    const Finished r = campaign({"run", toml.string(), "--shard", std::to_string(k) + "/3",
                                          "--out", (dir / "parts").string(), "--checkpoint-runs", "2",
                                          "--jobs", k == 1 ? "1" : "2", "-q"});
    ASSERT_EQ(r.exit.code, 0) << r.err;
  }
  EXPECT_GT(dir_entries(dir / "parts").size(), 6u);
  const Finished m = campaign({"merge", (dir / "parts").string(), "--out", (dir / "three.h5").string()});
  ASSERT_EQ(m.exit.code, 0) << m.err;
  const Finished same = dataset_hashes("same " + one_shard_file().string() + " " + (dir / "three.h5").string());
  EXPECT_EQ(same.exit.code, 0) << same.err;
}

TEST(CmdCampaign, MergedFileReadsWithH5pyAndHoldsEveryRunInOrder) {
  const auto j = read_with_h5py(one_shard_file());
  ASSERT_TRUE(j.contains("runs")) << j.dump();
  EXPECT_EQ(j["runs"], kRuns);
  EXPECT_EQ(j["planned_runs"], kRuns);
  EXPECT_EQ(j["axes"], nlohmann::json::array({"dt", "state"}));
  // the head-on closed form needs velocities along the line of centres: the
  // perturbed ones are not, so the analytic engine is unsupported there (its
  // 6 runs), and the truth of head_on is the reference
  EXPECT_EQ(j["status"]["ok"], kRuns - 6);
  EXPECT_EQ(j["status"]["unsupported"], 6);
  // every run says whose physics made it: the engines as their users run them
  // by default (SPEC §5b), the closed form for the truth engine
  EXPECT_EQ(j["physics"]["mujoco"], nlohmann::json::array({"native: force by engine"}));
  EXPECT_EQ(j["physics"]["ode"], nlohmann::json::array({"native: force by engine"}));
  EXPECT_EQ(j["physics"]["analytic"], nlohmann::json::array({"closed form: force by closed form"}));
  // the analytic engine against the truth of its own initial state: exactly 0
  // (a truth taken at the nominal state would be off by ~ 1e-2 m/s x 2.5 s)
  ASSERT_EQ(j["analytic_position_error_m"].size(), 6u);
  for (const auto& e : j["analytic_position_error_m"]) EXPECT_EQ(e.get<double>(), 0.0);
  // the engines are close to it: a falling ball to ~1e-2 m at these steps
  // (the sweep's errors, README), a head-on pair far closer
  for (const auto& e : j["engine_position_error_m"]) EXPECT_LT(e.get<double>(), 0.05);
  // each run starts where its overrides put it: the trace at t = 0 is the
  // case's initial position (velocity was perturbed, position not)
  EXPECT_EQ(j["trace_starts_at_initial_position"], true);
}

// The block family's metrics (issue 30), read with h5py: each run's SPEC §7
// friction error against its own case's closed form, NaN where the truth has
// no such figure. Two members on the reference and on the analytic engine
// itself: a held block (hold_drift_m, the drift of its contact point) and a
// thrown one (stop_time_error, relative). The analytic engine is its own
// truth: exactly 0; the reference holds to the state's error of rk45 at
// rtol 1e-10 over <= 1e4 steps (1e-6 relative, positions within 0.1 m of the
// origin: 1e-7 m) and stops within 1e-6 of t_stop
// (tests/reference/friction_on_faces_test.cpp derives both).
TEST(CmdCampaign, TheBlockFamilysMetricsAreFrictionErrorsAgainstTheTruth) {
  const fs::path dir = fresh_dir("family");
  const std::string family = std::string(PB_SOURCE_DIR) + "/cases/family/";
  const fs::path toml = campaign_file(dir, "[campaign]\ncases = [\"" + family +
                                               "hold_a1_s25_r0.98.toml\", \"" + family +
                                               "stop_a1_v5_mu0.6.toml\"]\n"
                                               "engines = [\"analytic\", \"reference\"]\n"
                                               "metrics = [\"hold_drift_m\", \"stop_time_error\", "
                                               "\"slide_acceleration_error\"]\n");
  const Finished r = campaign({"run", toml.string(), "--out", (dir / "parts").string(), "-q"});
  ASSERT_EQ(r.exit.code, 0) << r.err;
  const fs::path merged = dir / "family.h5";
  ASSERT_EQ(campaign({"merge", (dir / "parts").string(), "--out", merged.string(), "-q"}).exit.code, 0);
  const Finished py = run_shell(std::string(PB_PYTHON) + " -c '"
                                "import h5py, json, sys; g = h5py.File(sys.argv[1])[\"campaign/runs\"]; "
                                "d = lambda b: b.decode() if isinstance(b, bytes) else b; "
                                "n = lambda x: None if x != x else float(x); "
                                "print(json.dumps([[d(c), d(e)] + [n(x) for x in "
                                "(g[\"metric/hold_drift_m\"][i], g[\"metric/stop_time_error\"][i], "
                                "g[\"metric/slide_acceleration_error\"][i])] for i, (c, e) in "
                                "enumerate(zip(g[\"case\"][:], g[\"engine\"][:]))]), file=sys.stderr)' " +
                                merged.string());
  ASSERT_EQ(py.exit.code, 0) << py.err;
  const auto rows = nlohmann::json::parse(py.err);
  ASSERT_EQ(rows.size(), 4u);
  for (const auto& row : rows) {
    // NaN (no such figure in the truth) comes through JSON as null
    const std::string c = row[0], e = row[1];
    EXPECT_TRUE(row[4].is_null()) << c << " " << e;  // neither truth slides steadily
    if (c.starts_with("hold")) {
      EXPECT_TRUE(row[3].is_null()) << e;
      ASSERT_FALSE(row[2].is_null()) << e;
      EXPECT_LE(row[2].get<double>(), e == "analytic" ? 0.0 : 1e-7) << e;
    } else {
      EXPECT_TRUE(row[2].is_null()) << e;
      ASSERT_FALSE(row[3].is_null()) << e;
      EXPECT_LE(row[3].get<double>(), e == "analytic" ? 0.0 : 1e-6) << e;
    }
  }
}

TEST(CmdCampaign, TheReportOfACampaignHasItsSection) {
  const fs::path dir = fresh_dir("report");
  const Finished r = run_planarbench({"report", one_shard_file().string(), "--out", (dir / "r").string()});
  ASSERT_EQ(r.exit.code, 0) << r.err;
  const std::string md = file_bytes(dir / "r" / "report.md");
  EXPECT_NE(md.find("## Campaign"), std::string::npos);
  EXPECT_NE(md.find("36 of 36 planned runs"), std::string::npos);
  // per case: error and wall time against dt, and the spread at each dt
  for (const char* f : {"falling_ball_dt_position_error_m.svg", "falling_ball_dt_wall_time.svg",
                        "falling_ball_state_spread_0.svg", "head_on_state_spread_1.svg"}) {
    EXPECT_TRUE(fs::exists(dir / "r" / "figures" / f)) << f;
    EXPECT_NE(md.find(std::string("figures/") + f), std::string::npos) << f;
  }
  // nothing of a run matrix: no verdict, no mapping
  EXPECT_EQ(md.find("## Parameter mapping"), std::string::npos);
}

// Issue 49: an axis's name is the user's text; in report.md it is text, not
// markup (an axis named <img src=x onerror=...> reached it as HTML)
TEST(CmdCampaign, AnAxisNameIsShownAsTextInTheReport) {
  const fs::path dir = fresh_dir("markup");
  const fs::path toml = campaign_file(dir, R"(
[campaign]
cases = ["falling_ball"]
engines = ["analytic"]
metrics = ["events"]

[[axis]]
name = "<img src=x onerror=alert(1)> *b*"
key = "output_interval"
values = [1e-3, 2e-3]
)");
  ASSERT_EQ(campaign({"run", toml.string(), "--out", (dir / "parts").string(), "-q"}).exit.code, 0);
  ASSERT_EQ(campaign({"merge", (dir / "parts").string(), "--out", (dir / "m.h5").string(), "-q"})
                .exit.code,
            0);
  const Finished r = run_planarbench({"report", (dir / "m.h5").string(), "--out", (dir / "r").string()});
  ASSERT_EQ(r.exit.code, 0) << r.err;
  const std::string md = file_bytes(dir / "r" / "report.md");
  EXPECT_NE(md.find("## Campaign"), std::string::npos);
  EXPECT_EQ(md.find("<img"), std::string::npos) << md.substr(0, 2000);
  EXPECT_NE(md.find("&lt;img src=x onerror=alert(1)&gt; \\*b\\*"), std::string::npos)
      << md.substr(0, 2000);
}

TEST(CmdCampaign, MergeWithAMissingShardExitsTwoNamingTheRuns) {
  const fs::path dir = fresh_dir("missing");
  const fs::path toml = campaign_file(dir);
  const Finished r = campaign({"run", toml.string(), "--shard", "1/3", "--out", (dir / "parts").string(), "-q"});
  ASSERT_EQ(r.exit.code, 0) << r.err;
  const Finished m = campaign({"merge", (dir / "parts").string(), "--out", (dir / "m.h5").string()});
  EXPECT_EQ(m.exit.code, 2) << m.err;
  EXPECT_NE(m.err.find("24 of 36 runs are missing"), std::string::npos) << m.err;
  EXPECT_NE(m.err.find("shard(s) 0,2 of 3"), std::string::npos) << m.err;
  EXPECT_NE(m.err.find("sbatch --array=0,2"), std::string::npos) << m.err;
  // the first 20 named, with case, engine and axis points
  EXPECT_NE(m.err.find("x analytic, dt=0.0001, state="), std::string::npos) << m.err;
  EXPECT_NE(m.err.find("... and 4 more"), std::string::npos) << m.err;
  EXPECT_EQ(std::count(m.err.begin(), m.err.end(), '\n'), 1) << m.err;  // one line (issue 24)
  EXPECT_FALSE(fs::exists(dir / "m.h5"));
}

TEST(CmdCampaign, ARunInTwoFilesIsRefused) {
  const fs::path dir = fresh_dir("duplicate");
  const fs::path toml = campaign_file(dir);
  const Finished r = campaign({"run", toml.string(), "--out", (dir / "parts").string(), "-q"});
  ASSERT_EQ(r.exit.code, 0) << r.err;
  const auto parts = dir_entries(dir / "parts");
  ASSERT_EQ(parts.size(), 1u);
  fs::copy_file(dir / "parts" / parts[0], dir / "parts" / ("copy-" + parts[0]));
  const Finished m = campaign({"merge", (dir / "parts").string(), "--out", (dir / "m.h5").string()});
  EXPECT_EQ(m.exit.code, 2) << m.err;
  EXPECT_NE(m.err.find("36 run(s) are in two files"), std::string::npos) << m.err;
  // one line, like every error (issue 24): the pairs follow on it, "; "-separated
  EXPECT_EQ(std::count(m.err.begin(), m.err.end(), '\n'), 1) << m.err;
  EXPECT_NE(m.err.find("remove one of each pair: run 0: "), std::string::npos) << m.err;
  EXPECT_NE(m.err.find("; run 1: "), std::string::npos) << m.err;
  EXPECT_FALSE(fs::exists(dir / "m.h5"));
}

TEST(CmdCampaign, AFolderOfAnotherCampaignIsRefused) {
  const fs::path dir = fresh_dir("other");
  const fs::path toml = campaign_file(dir);
  ASSERT_EQ(campaign({"run", toml.string(), "--shard", "0/9", "--out", (dir / "parts").string(), "-q"}).exit.code, 0);
  std::string other = kCampaign;
  other.replace(other.find("seed = 5"), 8, "seed = 6");
  const fs::path toml2 = dir / "other.toml";
  std::ofstream(toml2) << other;
  const Finished r = campaign({"run", toml2.string(), "--out", (dir / "parts").string(), "-q"});
  EXPECT_EQ(r.exit.code, 2) << r.err;
  EXPECT_NE(r.err.find("belongs to another campaign"), std::string::npos) << r.err;
}

TEST(CmdCampaign, ACaseFileEditedBetweenShardsIsRefused) {
  const fs::path dir = fresh_dir("edited");
  fs::copy_file(fs::path(PB_SOURCE_DIR) / "cases/head_on.toml", dir / "head_on.toml");
  std::string text = kCampaign;
  text.replace(text.find("\"head_on\""), 9, "\"head_on.toml\"");
  const fs::path toml = campaign_file(dir, text);
  ASSERT_EQ(campaign({"run", toml.string(), "--shard", "0/2", "--out", (dir / "parts").string(), "-q"}).exit.code, 0);
  // an edit that changes nothing of the physics still changes the case's text
  std::ofstream(dir / "head_on.toml", std::ios::app) << "# edited\n";
  const Finished r = campaign({"run", toml.string(), "--shard", "1/2", "--out", (dir / "parts").string(), "-q"});
  EXPECT_EQ(r.exit.code, 2) << r.err;
  EXPECT_NE(r.err.find("case 'head_on' was run from another text"), std::string::npos) << r.err;
}

TEST(CmdCampaign, AShardKilledMidRunResumesWithNoDuplicateAndNoLostRun) {
  const fs::path dir = fresh_dir("killed");
  const fs::path toml = campaign_file(dir);
  const fs::path parts = dir / "parts";
  // one run per file, one thread: the kill lands between two checkpoints
  const pid_t pid = spawn_planarbench(words("campaign run " + toml.string() + " --out " + parts.string() +
                                            " --checkpoint-runs 1 --jobs 1 -q"));
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < deadline &&
         (!fs::exists(parts) || dir_entries(parts).size() < 3)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ::kill(pid, SIGKILL);
  const ChildExit e = wait_child(pid);
  ASSERT_TRUE(e.signaled) << "the shard ended before it was killed (exit " << e.code << ")";
  const std::size_t kept = dir_entries(parts).size();  // finished runs, and maybe a temporary
  ASSERT_LT(kept, static_cast<std::size_t>(kRuns));
  // merging now names what is missing
  const Finished early = campaign({"merge", parts.string(), "--out", (dir / "m.h5").string()});
  EXPECT_EQ(early.exit.code, 2) << early.err;
  // resubmitted: only what is missing runs
  const Finished again = campaign({"run", toml.string(), "--out", parts.string()});
  ASSERT_EQ(again.exit.code, 0) << again.err;
  EXPECT_NE(again.err.find("already in"), std::string::npos) << again.err;
  const Finished m = campaign({"merge", parts.string(), "--out", (dir / "m.h5").string()});
  ASSERT_EQ(m.exit.code, 0) << m.err;
  const Finished same = dataset_hashes("same " + one_shard_file().string() + " " + (dir / "m.h5").string());
  EXPECT_EQ(same.exit.code, 0) << same.err;
}

}  // namespace
