// Tests for reports/src/report.cpp
//
// End to end on a results file of synthetic falling_ball runs
// (report_test_runs.hpp), with a stand-in web folder, so the C++ side is
// tested without npm; tests/report/browser_test.mjs opens the real page.
#include "planarbench/reports/report.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <filesystem>
#include <string>

#include "planarbench/errors.hpp"
#include "planarbench/results_file.hpp"
#include "report_files.hpp"
#include "fake_web_dir.hpp"
#include "report_test_runs.hpp"

namespace pb {
namespace {

namespace fs = std::filesystem;

class ReportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // one folder per test process: CTest runs the tests of this fixture in parallel
    dir_ = fs::temp_directory_path() / (std::string("pb_report_test_") +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    test::write_fake_web_dir(dir_ / "web", "The MIT License (MIT)", "1.6.32");

    const Case c = test::falling_ball_case();
    ResultsFile results;
    results.provenance = {"planarbench run", "2026-01-01T00:00:00Z", "host"};
    results.cases.push_back(test::falling_ball_runs(c));
    write_results_file(dir_ / "r.h5", results);
  }
  void TearDown() override { fs::remove_all(dir_); }

  ReportOptions options(const std::string& out) const {
    ReportOptions o;
    o.results = dir_ / "r.h5";
    o.out_dir = dir_ / out;
    o.web_dir = dir_ / "web";
    return o;
  }

  fs::path dir_;
};

TEST_F(ReportTest, WritesPageMarkdownAndFigures) {
  const ReportSummary s = write_report(options("out"));
  EXPECT_EQ(s.figures, 2u);    // Figs 5 and 6
  // and Fig 5 zoomed on its episode, and the physical-validity section's
  // normal-law residual of the ball (a smooth frictionless pair)
  EXPECT_EQ(s.svg_files, 4u);
  EXPECT_EQ(s.validity_figures, 1u);
  EXPECT_GT(s.metrics, 0u);
  EXPECT_EQ(s.checks, 0u);
  for (const char* f :
       {"report.html", "report.md", "figures/falling_ball_fig5.svg",
        "figures/falling_ball_fig5_episode0.svg", "figures/falling_ball_fig6.svg",
        "figures/falling_ball_law.svg"}) {
    EXPECT_TRUE(fs::is_regular_file(dir_ / "out" / f)) << f;
  }
  const std::string html = internal::read_text_file(dir_ / "out" / "report.html");
  EXPECT_EQ(html.find("@@"), std::string::npos);
  EXPECT_NE(html.find("\"falling_ball_fig5\""), std::string::npos);
  EXPECT_NE(html.find("uPlot 1.6.32 The MIT License (MIT)"), std::string::npos);
  const std::string md = internal::read_text_file(dir_ / "out" / "report.md");
  for (const char* heading : {"## Capability matrix", "## Timings", "## Metrics", "## Provenance",
                              "## Parameter mapping", "## Physical validity"}) {
    EXPECT_NE(md.find(heading), std::string::npos) << heading;
  }
  EXPECT_NE(md.find("mujoco cannot do X"), std::string::npos);  // from the mapping
}

TEST_F(ReportTest, SameInputSameBytes) {
  (void)write_report(options("a"));
  (void)write_report(options("b"));
  for (const char* f : {"report.html", "report.md", "figures/falling_ball_fig5.svg"}) {
    EXPECT_EQ(internal::read_text_file(dir_ / "a" / f), internal::read_text_file(dir_ / "b" / f))
        << f;
  }
}

TEST_F(ReportTest, ThresholdsAddPassFail) {
  internal::write_text_atomically(dir_ / "t.toml", R"(
[[threshold]]
case = "falling_ball"
engine = "mujoco"
against = "truth"
metric = "peak_force"
rtol = 0.05
why = "590 N against 580 N: 1.7 %"

[[threshold]]
case = "falling_ball"
engine = "box2d"
against = "truth"
metric = "peak_force"
rtol = 0.05
why = "impulsive: fails"
)");
  ReportOptions o = options("out");
  o.thresholds = dir_ / "t.toml";
  const ReportSummary s = write_report(o);
  EXPECT_EQ(s.checks, 2u);
  EXPECT_EQ(s.checks_failed, 1u);
  const std::string md = internal::read_text_file(dir_ / "out" / "report.md");
  EXPECT_NE(md.find("**Check:** gate failed: 1 failed; 1 of 2 checks within their bands"),
            std::string::npos);
}

// A band the engine's model cannot meet, declared before the run, is still a
// failure in the counts (issue 16): never among the passed checks.
TEST_F(ReportTest, KnownBreachesAreCountedApartFromPassed) {
  internal::write_text_atomically(dir_ / "t.toml", R"(
[[threshold]]
case = "falling_ball"
engine = "box2d"
against = "truth"
metric = "peak_force"
rtol = 0.05
why = "impulsive: fails"
known_breach = "rigid contact has no stiffness"
expected = [1e3, 1e7]
expected_bound = ["1e3", "1e7"]
expected_why = "one step's impulse over the step"
)");
  ReportOptions o = options("out");
  o.thresholds = dir_ / "t.toml";
  const ReportSummary s = write_report(o);
  EXPECT_EQ(s.checks, 1u);
  EXPECT_EQ(s.checks_failed, 0u);
  EXPECT_EQ(s.checks_known, 1u);
  const std::string md = internal::read_text_file(dir_ / "out" / "report.md");
  // the gate passes: a known breach does not fail it, and is not a pass either
  EXPECT_NE(md.find("**Check:** gate passed: 0 failed; 0 of 1 checks within their bands, 1 "
                    "known breaches"),
            std::string::npos);
}

TEST_F(ReportTest, BadInputIsAnInputError) {
  ReportOptions o = options("out");
  o.results = dir_ / "absent.h5";
  EXPECT_THROW((void)write_report(o), InputError);
  // an HDF5 file that is not a results file
  const fs::path foreign = dir_ / "foreign.h5";
  const hid_t f = H5Fcreate(foreign.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  H5Fclose(f);
  o.results = foreign;
  EXPECT_THROW((void)write_report(o), InputError);
  // missing web assets
  o = options("out");
  o.web_dir = dir_ / "no_web";
  EXPECT_THROW((void)write_report(o), InputError);
  EXPECT_FALSE(fs::exists(dir_ / "out"));  // nothing written before the inputs are known good
}

}  // namespace
}  // namespace pb
