// Issue 24, point 5: no command overwrites one of its own inputs, whichever
// input option names it and whichever output would replace it: the report's
// pages and figures inside --out, a sweep's or a merge's --out, the files of
// an impacts --work folder. Each case is refused with exit 2 and one line on
// stderr before anything is written, and the input keeps its bytes. The real
// planarbench binary, run as a user runs it.
#include <gtest/gtest.h>

#include <cctype>
#include <string>
#include <vector>

#include "child_process.hpp"

namespace {

using namespace pb::test;

// a valid results file, made once per test process
const fs::path& results_file() {
  static const fs::path file = [] {
    const fs::path dir = fresh_dir("results_" + std::to_string(::getpid()));
    const Finished r = run_planarbench({"run", "--case", "falling_ball", "--engine", "analytic",
                                        "--set", "duration=0.8", "--out",
                                        (dir / "good.h5").string(), "--quiet"});
    EXPECT_EQ(r.exit.code, 0) << r.err;
    return dir / "good.h5";
  }();
  return file;
}

std::size_t lines(const std::string& s) { return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n')); }

// `f` is a refusal: exit 2, one line naming `option` and the input's file
void expect_refused(const Finished& f, const std::string& option, const fs::path& input) {
  EXPECT_EQ(f.exit.code, 2) << f.err;
  EXPECT_EQ(lines(f.err), 1u) << f.err;
  EXPECT_EQ(f.err.rfind("planarbench: error: " + option, 0), 0u) << f.err;
  EXPECT_NE(f.err.find("names a file this command also reads or writes"), std::string::npos) << f.err;
  EXPECT_NE(f.err.find(input.filename().string()), std::string::npos) << f.err;
}

// ---- report: results, --thresholds, --sweep, --campaign, --impacts --------------

struct ReportClash {
  const char* option;  // "" for the results file
  const char* page;    // the output inside --out that would replace it
};

class ReportKeepsItsInputs : public ::testing::TestWithParam<ReportClash> {};

// "thresholds_report_html": a name for the test and its folder (CTest runs
// the tests in parallel: each has its own)
std::string clash_name(const ReportClash& c) {
  std::string name = std::string(*c.option ? c.option + 2 : "results") + "_" + c.page;
  for (char& ch : name) {
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  }
  return name;
}

TEST_P(ReportKeepsItsInputs, AnInputAtAnOutputOfTheFolderIsRefused) {
  const ReportClash& c = GetParam();
  const fs::path dir = fresh_dir("report_" + clash_name(c));
  const fs::path out = dir / "out";
  const fs::path input = out / c.page;
  fs::create_directories(input.parent_path());
  // the input is a file the option takes: thresholds text, else a results file
  if (std::string(c.option) == "--thresholds") {
    fs::copy_file(fs::path(PB_SOURCE_DIR) / "cases/thresholds.toml", input);
  } else {
    fs::copy_file(results_file(), input);
  }
  const std::string before = file_bytes(input);
  std::vector<std::string> args = {"report"};
  if (*c.option) {
    args.push_back(results_file().string());
    args.push_back(c.option);
  }
  args.push_back(input.string());
  args.push_back("--out");
  args.push_back(out.string());
  const Finished f = run_planarbench(args);
  expect_refused(f, "--out", input);
  EXPECT_EQ(file_bytes(input), before) << "the input was overwritten";
  EXPECT_FALSE(fs::exists(out / (c.page == std::string("report.md") ? "report.html" : "report.md")))
      << "a page was written";
}

INSTANTIATE_TEST_SUITE_P(
    EveryInputOption, ReportKeepsItsInputs,
    ::testing::Values(ReportClash{"", "report.md"}, ReportClash{"", "report.html"},
                      ReportClash{"", "figures/falling_ball_fig5.svg"},
                      ReportClash{"--thresholds", "report.html"},
                      ReportClash{"--thresholds", "report.md"},
                      ReportClash{"--sweep", "report.md"}, ReportClash{"--campaign", "report.html"},
                      ReportClash{"--impacts", "report.md"},
                      ReportClash{"--impacts", "figures/impacts_error.svg"}),
    [](const ::testing::TestParamInfo<ReportClash>& p) { return clash_name(p.param); });

// report.md is a symbolic link to the results file elsewhere: writing the
// page through the link would replace the file it names
TEST(ReportKeepsItsInputsThroughLinks, APageLinkedToAnInputIsRefused) {
  const fs::path dir = fresh_dir("report_link");
  const fs::path input = dir / "mine.h5";
  fs::copy_file(results_file(), input);
  fs::create_directories(dir / "out");
  fs::create_symlink(input, dir / "out" / "report.md");
  const std::string before = file_bytes(input);
  const Finished f = run_planarbench({"report", input.string(), "--out", (dir / "out").string()});
  expect_refused(f, "--out", input);
  EXPECT_EQ(file_bytes(input), before);
}

// inputs inside the report folder that no output replaces are fine
TEST(ReportKeepsItsInputsThroughLinks, AnInputBesideThePagesIsAllowed) {
  const fs::path dir = fresh_dir("report_beside");
  fs::copy_file(results_file(), dir / "results.h5");
  fs::create_directories(dir / "figures");
  fs::copy_file(results_file(), dir / "figures" / "results.h5");
  const Finished f = run_planarbench({"report", (dir / "figures" / "results.h5").string(), "--out",
                                      dir.string(), "--quiet"});
  EXPECT_EQ(f.exit.code, 0) << f.err;
  EXPECT_TRUE(fs::is_regular_file(dir / "report.md"));
}

// ---- sweep -----------------------------------------------------------------------

TEST(SweepKeepsItsInputs, OutLinkedToTheCaseFileIsRefused) {
  const fs::path dir = fresh_dir("sweep_link");
  fs::copy_file(fs::path(PB_SOURCE_DIR) / "cases/falling_ball.toml", dir / "ball.toml");
  fs::create_symlink(dir / "ball.toml", dir / "out.h5");
  const std::string before = file_bytes(dir / "ball.toml");
  const Finished f = run_planarbench({"sweep", "--case", (dir / "ball.toml").string(), "--engine",
                                      "box2d", "--quick", "--out", (dir / "out.h5").string()});
  expect_refused(f, "--out", dir / "ball.toml");
  EXPECT_EQ(file_bytes(dir / "ball.toml"), before);
}

// ---- campaign merge: the campaign file and the case files its parts name ----------

// a campaign of 2 short runs of a case file of its own folder, run into parts/
fs::path two_run_campaign(const fs::path& dir) {
  fs::copy_file(fs::path(PB_SOURCE_DIR) / "cases/falling_ball.toml", dir / "ball.toml");
  const fs::path toml = dir / "study.toml";
  std::ofstream(toml) << "[campaign]\ncases = [\"ball.toml\"]\nengines = [\"analytic\"]\n"
                         "metrics = [\"events\"]\nset = { duration = 0.01 }\n\n"
                         "[[axis]]\nkey = \"output_interval\"\nvalues = [1e-3, 2e-3]\n";
  const Finished r = run_planarbench({"campaign", "run", toml.string(), "--out",
                                      (dir / "parts").string(), "-q"});
  EXPECT_EQ(r.exit.code, 0) << r.err;
  return toml;
}

TEST(CampaignMergeKeepsItsInputs, OutNamingTheCampaignFileIsRefused) {
  const fs::path dir = fresh_dir("merge_campaign_file");
  const fs::path toml = two_run_campaign(dir);
  const std::string before = file_bytes(toml);
  const Finished f = run_planarbench(
      {"campaign", "merge", (dir / "parts").string(), "--out", toml.string(), "-q"});
  expect_refused(f, "--out", toml);
  EXPECT_EQ(file_bytes(toml), before) << "the campaign file was overwritten";
}

TEST(CampaignMergeKeepsItsInputs, OutNamingACaseFileOfTheCampaignIsRefused) {
  const fs::path dir = fresh_dir("merge_case_file");
  (void)two_run_campaign(dir);
  const std::string before = file_bytes(dir / "ball.toml");
  const Finished f = run_planarbench({"campaign", "merge", (dir / "parts").string(), "--out",
                                      (dir / "ball.toml").string(), "-q"});
  expect_refused(f, "--out", dir / "ball.toml");
  EXPECT_EQ(file_bytes(dir / "ball.toml"), before) << "the case file was overwritten";
}

TEST(CampaignMergeKeepsItsInputs, OutLinkedToAShardFileIsRefused) {
  const fs::path dir = fresh_dir("merge_part_link");
  (void)two_run_campaign(dir);
  const auto parts = dir_entries(dir / "parts");
  ASSERT_EQ(parts.size(), 1u);
  fs::create_symlink(dir / "parts" / parts[0], dir / "merged.h5");
  const std::string before = file_bytes(dir / "parts" / parts[0]);
  const Finished f = run_planarbench({"campaign", "merge", (dir / "parts").string(), "--out",
                                      (dir / "merged.h5").string(), "-q"});
  expect_refused(f, "--out", dir / "parts" / parts[0]);
  EXPECT_EQ(file_bytes(dir / "parts" / parts[0]), before);
}

// ---- impacts: --data, --params and the --work folder -------------------------------

TEST(ImpactsKeepsItsInputs, MergeOutNamingTheStudyOfItsWorkFolderIsRefused) {
  const fs::path dir = fresh_dir("impacts_merge_study");
  std::ofstream(dir / "study.json") << "{}\n";
  std::ofstream(dir / "data.mat") << "not read\n";
  const Finished f = run_planarbench({"impacts", "merge", dir.string(), "--data",
                                      (dir / "data.mat").string(), "--out",
                                      (dir / "study.json").string()});
  expect_refused(f, "--out", dir / "study.json");
  EXPECT_EQ(file_bytes(dir / "study.json"), "{}\n");
}

TEST(ImpactsKeepsItsInputs, FitDataInsideTheTasksOfItsWorkFolderIsRefused) {
  const fs::path dir = fresh_dir("impacts_fit_data_task");
  fs::create_directories(dir / "tasks");
  std::ofstream(dir / "tasks" / "box2d.all.json") << "{}\n";
  const Finished f = run_planarbench({"impacts", "fit", "--data",
                                      (dir / "tasks" / "box2d.all.json").string(), "--work",
                                      dir.string(), "--shard", "0/1"});
  EXPECT_EQ(f.exit.code, 2) << f.err;
  EXPECT_EQ(lines(f.err), 1u) << f.err;
  EXPECT_NE(f.err.find("--data"), std::string::npos) << f.err;
  EXPECT_NE(f.err.find("names a file this command also reads or writes"), std::string::npos) << f.err;
  EXPECT_EQ(file_bytes(dir / "tasks" / "box2d.all.json"), "{}\n");
}

}  // namespace
