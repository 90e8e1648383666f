// Tests for reports/src/run_validity.cpp and its use by the metrics
// (reports/src/metrics.cpp), the gate (reports/src/thresholds.cpp) and the
// verdict of the report (reports/src/report_verdict.cpp): a run whose samples
// hold NaN or inf fails its checks and is shown failed, never ranked (issue 24).
//
// The runs are the synthetic falling_ball runs of report_test_runs.hpp: box2d
// follows the truth exactly (position error 0), mujoco 1 mm below it.
#include "planarbench/reports/run_validity.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "planarbench/reports/metrics.hpp"
#include "planarbench/reports/report.hpp"
#include "planarbench/reports/thresholds.hpp"
#include "planarbench/results_file.hpp"
#include "report_files.hpp"
#include "fake_web_dir.hpp"
#include "report_test_runs.hpp"

namespace pb {
namespace {

namespace fs = std::filesystem;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

RunResult& run_of(CaseRuns& cr, const std::string& engine) {
  for (auto& r : cr.runs) {
    if (r.engine_name == engine) return r;
  }
  throw std::logic_error("no run " + engine);
}

const MetricValue* find_metric(const std::vector<MetricValue>& metrics, const std::string& engine,
                               const std::string& against, const std::string& name) {
  for (const auto& m : metrics) {
    if (m.engine == engine && m.against == against && m.metric == name && m.episode < 0) return &m;
  }
  return nullptr;
}

// ---- the metrics: NaN is not dropped by a maximum ----------------------------------

// Ten NaN rows among 25001 finite ones: std::max(x, NaN) is x, so the maximum
// used to be taken over the finite rows alone and the run looked fine.
TEST(RunValidity, NanRowsMakeTheMaximumErrorNan) {
  const Case c = test::falling_ball_case();
  CaseRuns cr = test::falling_ball_runs(c);
  auto& ball = run_of(cr, "box2d").bodies.front();
  for (std::size_t i = 100; i < 110; ++i) ball.position_m[i] = Vec2(kNaN, kNaN);
  ball.velocity_mps[200] = Vec2(0.0, kNaN);
  ball.angle_rad[300] = kNaN;
  const auto metrics = case_metrics(c, cr);
  for (const char* name : {"position_max", "position_rms", "velocity_max", "angle_max"}) {
    const MetricValue* m = find_metric(metrics, "box2d", "truth", name);
    ASSERT_NE(m, nullptr) << name;
    EXPECT_TRUE(std::isnan(m->error)) << name << " = " << m->error;
  }
  // the run left alone keeps its finite error
  const MetricValue* mujoco = find_metric(metrics, "mujoco", "truth", "position_max");
  ASSERT_NE(mujoco, nullptr);
  EXPECT_TRUE(std::isfinite(mujoco->error));
}

// ---- which runs are invalid ----------------------------------------------------------

TEST(RunValidity, AValidRunHasNoFault) {
  const Case c = test::falling_ball_case();
  const CaseRuns cr = test::falling_ball_runs(c);
  EXPECT_TRUE(invalid_runs(cr).empty());
}

TEST(RunValidity, EachDamagedDatasetIsNamedWithItsRowsAndFirstRow) {
  const Case c = test::falling_ball_case();
  CaseRuns cr = test::falling_ball_runs(c);
  RunResult& r = run_of(cr, "mujoco");
  auto& ball = r.bodies.front();
  for (std::size_t i = 100; i < 110; ++i) ball.position_m[i].y() = kNaN;
  ball.angular_velocity_radps[7] = std::numeric_limits<double>::infinity();
  r.contacts[3].sample.force_n = kNaN;
  // a NaN penetration is what an engine that does not report it writes
  // (tests/python/README.md): not a fault
  r.contacts[4].sample.penetration_m = kNaN;
  const auto faults = invalid_runs(cr);
  ASSERT_EQ(faults.size(), 3u);
  for (const auto& f : faults) {
    EXPECT_EQ(f.case_name, "falling_ball");
    EXPECT_EQ(f.engine, "mujoco");
  }
  EXPECT_EQ(faults[0].dataset, "/runs/falling_ball/mujoco/bodies/ball/position");
  EXPECT_EQ(faults[0].rows, 10u);
  EXPECT_EQ(faults[0].first_row, 100u);
  EXPECT_EQ(faults[1].dataset, "/runs/falling_ball/mujoco/bodies/ball/angular_velocity");
  EXPECT_EQ(faults[1].first_row, 7u);
  EXPECT_EQ(faults[2].dataset, "/runs/falling_ball/mujoco/contacts");
  EXPECT_EQ(faults[2].field, "force_n");
  EXPECT_EQ(faults[2].first_row, 3u);
  const std::string text = faults[0].describe();
  EXPECT_NE(text.find("falling_ball.mujoco"), std::string::npos) << text;
  EXPECT_NE(text.find("/runs/falling_ball/mujoco/bodies/ball/position"), std::string::npos) << text;
  EXPECT_NE(text.find("row 100"), std::string::npos) << text;
}

// Issue 49: every float of a run's events table set to NaN passed the gate.
// An episode's onset, approach speed, peak force and impulse are numbers once
// it has begun; its offset, separation speed, restitution (an episode still
// open at the end) and deepest penetration (an engine that does not report
// it) may be NaN, never infinite. A contact's normal and point are numbers.
TEST(RunValidity, NanEventsAndContactGeometryAreInvalid) {
  const Case c = test::falling_ball_case();
  CaseRuns cr = test::falling_ball_runs(c);
  RunResult& r = run_of(cr, "box2d");
  ASSERT_FALSE(r.events.empty());
  ContactEpisode open = r.events.front();
  open.offset_time_s = open.separation_speed_mps = open.restitution = kNaN;
  open.max_penetration_m = kNaN;
  r.events.push_back(open);  // an open episode: valid
  EXPECT_TRUE(invalid_runs(cr).empty());

  ContactEpisode& e = r.events.front();
  e.onset_time_s = e.approach_speed_mps = e.peak_force_n = e.impulse_ns = kNaN;
  e.restitution = std::numeric_limits<double>::infinity();
  r.contacts[2].sample.normal.x() = kNaN;
  r.contacts[5].sample.point_m.y() = -std::numeric_limits<double>::infinity();
  r.contacts[6].sample.tangential_force_n = std::numeric_limits<double>::infinity();
  std::vector<std::string> named;
  for (const auto& f : invalid_runs(cr)) {
    EXPECT_EQ(f.engine, "box2d");
    named.push_back(f.dataset.substr(f.dataset.rfind('/') + 1) + "." + f.field);
  }
  const std::vector<std::string> expected = {
      "contacts.normal", "contacts.point_m", "contacts.tangential_force_n",
      "events.onset_time_s", "events.approach_speed_mps", "events.peak_force_n",
      "events.impulse_ns", "events.restitution"};
  EXPECT_EQ(named, expected);
}

TEST(RunValidity, AnUnsupportedRunHasNoDataToCheck) {
  const Case c = test::falling_ball_case();
  const CaseRuns cr = test::falling_ball_runs(c);  // its reference is unsupported
  for (const auto& f : invalid_runs(cr)) EXPECT_NE(f.engine, "reference");
}

// ---- the gate ----------------------------------------------------------------------------

Threshold band(const std::string& engine, const std::string& against, const std::string& metric) {
  Threshold t;
  t.case_name = "falling_ball";
  t.engine = engine;
  t.against = against;
  t.metric = metric;
  // wide on purpose: a band any finite error of these runs meets (the
  // synthetic runs are at most 1 mm apart), so only invalid data can fail it
  t.atol = 1e3;
  t.why = "test";
  return t;
}

// A NaN in a run's velocity fails even a check of its position, and a known
// breach of an invalid run fails the gate too: its values mean nothing.
TEST(RunValidity, EveryCheckOfAnInvalidRunFailsTheGate) {
  const Case c = test::falling_ball_case();
  CaseRuns cr = test::falling_ball_runs(c);
  run_of(cr, "mujoco").bodies.front().velocity_mps[200] = Vec2(kNaN, 0.0);
  const auto metrics = case_metrics(c, cr);
  const auto faults = invalid_runs(cr);
  ASSERT_EQ(faults.size(), 1u);
  Threshold known = band("mujoco", "self", "wall_per_sim_s");
  known.known_breach = "stated before the run";
  const auto outcomes = check_thresholds(
      {band("mujoco", "truth", "position_max"), known, band("box2d", "truth", "position_max")},
      metrics, faults);
  ASSERT_EQ(outcomes.size(), 3u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_FALSE(outcomes[i].passed) << i;
    EXPECT_TRUE(fails_gate(outcomes[i])) << i;
    EXPECT_STREQ(outcome_label(outcomes[i]), "invalid data") << i;
    EXPECT_NE(outcomes[i].message.find("/runs/falling_ball/mujoco/bodies/ball/velocity"),
              std::string::npos)
        << outcomes[i].message;
  }
  // box2d's own data are valid, and its baseline (the truth) too
  EXPECT_TRUE(outcomes[2].passed) << outcomes[2].message;
  EXPECT_FALSE(fails_gate(outcomes[2]));
}

// A check against an invalid baseline fails too: the truth with NaN makes
// every engine's error against it meaningless.
TEST(RunValidity, ChecksAgainstAnInvalidBaselineFail) {
  const Case c = test::falling_ball_case();
  CaseRuns cr = test::falling_ball_runs(c);
  run_of(cr, "analytic").bodies.front().angle_rad[5] = kNaN;
  const auto outcomes = check_thresholds({band("box2d", "truth", "position_max")},
                                         case_metrics(c, cr), invalid_runs(cr));
  ASSERT_EQ(outcomes.size(), 1u);
  EXPECT_TRUE(fails_gate(outcomes[0]));
  EXPECT_NE(outcomes[0].message.find("falling_ball.analytic"), std::string::npos)
      << outcomes[0].message;
}

// ---- the report ----------------------------------------------------------------------

class InvalidRunReport : public ::testing::Test {
 protected:
  void SetUp() override {
    // one folder per test: CTest runs the tests of this fixture in parallel
    dir_ = fs::temp_directory_path() /
           (std::string("pb_run_validity_test_") +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    test::write_fake_web_dir(dir_ / "web", "stand-in", "0.0.0");
  }
  void TearDown() override { fs::remove_all(dir_); }

  // the verdict row of report.md for `cr`, split into its cells
  std::vector<std::string> verdict_row(const CaseRuns& cr) {
    ResultsFile results;
    results.provenance = {"planarbench run", "2026-01-01T00:00:00Z", "host"};
    results.cases.push_back(cr);
    write_results_file(dir_ / "r.h5", results);
    ReportOptions o;
    o.results = dir_ / "r.h5";
    o.out_dir = dir_ / "out";
    o.web_dir = dir_ / "web";
    (void)write_report(o);
    const std::string md = internal::read_text_file(dir_ / "out" / "report.md");
    const auto at = md.find("## Verdict");
    EXPECT_NE(at, std::string::npos);
    std::istringstream lines(md.substr(at));
    std::string line;
    while (std::getline(lines, line)) {
      // a row with a failed run is marked bold: | **falling_ball** |
      if (line.rfind("| falling_ball |", 0) != 0 && line.rfind("| **falling_ball** |", 0) != 0) {
        continue;
      }
      std::vector<std::string> cells;
      std::string cell;
      std::istringstream parts(line.substr(1));
      while (std::getline(parts, cell, '|')) {
        const auto a = cell.find_first_not_of(' ');
        const auto b = cell.find_last_not_of(' ');
        std::string text = a == std::string::npos ? "" : cell.substr(a, b - a + 1);
        if (text.size() > 4 && text.rfind("**", 0) == 0) text = text.substr(2, text.size() - 4);
        cells.push_back(text);
      }
      return cells;  // case, truth, best, engines, caveats
    }
    ADD_FAILURE() << "no verdict row in\n" << md;
    return {};
  }

  fs::path dir_;
};

// All of box2d's positions NaN: it used to rank first with error 0.
TEST_F(InvalidRunReport, AllNanPositionsAreShownFailedNotRankedFirst) {
  const Case c = test::falling_ball_case();
  const auto valid = verdict_row(test::falling_ball_runs(c));
  ASSERT_EQ(valid.size(), 5u);
  ASSERT_EQ(valid[2], "box2d");  // the control: box2d follows the truth exactly

  CaseRuns cr = test::falling_ball_runs(c);
  for (auto& p : run_of(cr, "box2d").bodies.front().position_m) p = Vec2(kNaN, kNaN);
  const auto row = verdict_row(cr);
  ASSERT_EQ(row.size(), 5u);
  EXPECT_EQ(row[2], "mujoco");  // the one valid engine left (the reference is unsupported)
  EXPECT_NE(row[3].find("box2d FAILED"), std::string::npos) << row[3];
  EXPECT_NE(row[4].find("box2d FAILED: invalid data"), std::string::npos) << row[4];
  EXPECT_NE(row[4].find("/runs/falling_ball/box2d/bodies/ball/position"), std::string::npos)
      << row[4];
}

TEST_F(InvalidRunReport, TenNanRowsAreShownFailedNotRankedFirst) {
  const Case c = test::falling_ball_case();
  CaseRuns cr = test::falling_ball_runs(c);
  auto& ball = run_of(cr, "box2d").bodies.front();
  for (std::size_t i = 100; i < 110; ++i) ball.position_m[i] = Vec2(kNaN, kNaN);
  const auto row = verdict_row(cr);
  ASSERT_EQ(row.size(), 5u);
  EXPECT_EQ(row[2], "mujoco");
  EXPECT_NE(row[3].find("box2d FAILED"), std::string::npos) << row[3];
}

}  // namespace
}  // namespace pb
