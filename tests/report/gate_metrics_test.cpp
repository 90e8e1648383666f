// Tests of the gate's metrics on damaged runs (issue 25): reports/src/metrics.cpp
// (compare_runs, case_metrics), reports/src/thresholds.cpp (check_thresholds)
// and the verdict's ranking (reports/src/report_verdict.cpp), with runs built
// by hand: NaN samples, a run cut short, and lost or extra contact episodes.
//
// The runs are the synthetic falling_ball runs of report_test_runs.hpp (the
// ball's y = 2 - offset - t on the case's 25001-sample grid, one episode over
// [0.7250, 0.7560] s): box2d follows the truth exactly, mujoco 1 mm below it.
//
// The rules shown here:
// - a NaN sample makes every maximum over the run NaN wherever it sits (first
//   or last sample: std::max(0, NaN) is 0 but std::max(NaN, 0) is NaN), and a
//   NaN metric fails its threshold without any other help;
// - an ok run with fewer rows than its baseline (or without one of its
//   bodies) gets NaN trajectory errors, noted "truncated": never judged on the
//   common prefix; a diverged run keeps its errors up to the divergence (its
//   status fails the gate already), with the same note;
// - episodes are paired by index per body pair (the run's k-th with the
//   baseline's k-th); a baseline episode the run lacks gets every metric its
//   baseline value exists for, with the run's value NaN (the episode's
//   thresholds fail), and episode_count differs; an extra episode of the run
//   has no baseline value and shows in episode_count alone.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "planarbench/reports/metrics.hpp"
#include "planarbench/reports/thresholds.hpp"
#include "report_test_runs.hpp"
#include "report_verdict.hpp"

namespace pb {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

RunResult& run_of(CaseRuns& cr, const std::string& engine) {
  for (auto& r : cr.runs) {
    if (r.engine_name == engine) return r;
  }
  throw std::logic_error("no run " + engine);
}

const MetricValue* find(const std::vector<MetricValue>& ms, const std::string& engine,
                        const std::string& against, const std::string& name, int episode = -1) {
  for (const auto& m : ms) {
    if (m.engine == engine && m.against == against && m.metric == name && m.episode == episode) {
      return &m;
    }
  }
  return nullptr;
}

Threshold band(const std::string& engine, const std::string& metric, double atol, double rtol,
               int episode = -1) {
  Threshold t;
  t.case_name = "falling_ball";
  t.engine = engine;
  t.against = "truth";
  t.metric = metric;
  t.episode = episode;
  t.atol = atol;
  t.rtol = rtol;
  t.why = "test";
  return t;
}

// every outcome of `th` against `metrics` (no run marked invalid: the
// metric's own value must decide), and whether any fails the gate
bool gate_fails(const Threshold& th, const std::vector<MetricValue>& metrics) {
  bool fails = false;
  for (const auto& o : check_thresholds({th}, metrics, {})) fails = fails || fails_gate(o);
  return fails;
}

// a second episode of the ball on the ground, [1.9, 1.93] s, restitution 0.8
ContactEpisode second_bounce(double restitution = 0.8) {
  ContactEpisode e;
  e.body_a = 0;  // ground
  e.body_b = 1;  // ball
  e.onset_time_s = 1.9;
  e.offset_time_s = 1.93;
  e.approach_speed_mps = 5.0;
  e.separation_speed_mps = 5.0 * restitution;
  e.restitution = restitution;
  e.peak_force_n = 580.0;
  e.impulse_ns = 9.0;
  e.max_penetration_m = 0.01;
  return e;
}

// the falling_ball runs with a second bounce in the truth and in mujoco
CaseRuns two_bounce_runs(const Case& c) {
  CaseRuns cr = test::falling_ball_runs(c);
  run_of(cr, "analytic").events.push_back(second_bounce());
  run_of(cr, "mujoco").events.push_back(second_bounce());
  return cr;
}

// (the wide bands below: any finite error of these synthetic runs meets
// them, at most 1 mm and 590 vs 580 N apart, so only the damage can fail one)
constexpr double kWide = 1e3;

// ---- NaN ------------------------------------------------------------------------------

// One NaN at the first and one at the last compared sample: the maximum is
// NaN either way, and fails its threshold with no invalid-data list given.
TEST(GateMetrics, NanAtEitherEndMakesTheMaximumNanAndFails) {
  const Case c = test::falling_ball_case();
  for (const std::size_t row : {std::size_t{0}, std::size_t{25000}}) {
    CaseRuns cr = test::falling_ball_runs(c);
    auto& ball = run_of(cr, "mujoco").bodies.front();
    ASSERT_EQ(ball.time_s.size(), 25001u);
    ball.position_m[row] = Vec2(kNaN, 0.0);
    const auto metrics = case_metrics(c, cr);
    const MetricValue* m = find(metrics, "mujoco", "truth", "position_max");
    ASSERT_NE(m, nullptr) << row;
    EXPECT_TRUE(std::isnan(m->actual)) << row << ": " << m->actual;
    EXPECT_TRUE(gate_fails(band("mujoco", "position_max", kWide, 0.0), metrics)) << row;
    // the engine left alone: finite, and passes the same band
    EXPECT_FALSE(gate_fails(band("box2d", "position_max", kWide, 0.0), metrics)) << row;
  }
}

// A NaN peak force in the second episode: the metric is kept (NaN) and fails
// the every-episode threshold; dropped, the threshold would have seen
// episode 0 alone and passed.
TEST(GateMetrics, NanEpisodeValueIsKeptAndFails) {
  const Case c = test::falling_ball_case();
  CaseRuns cr = two_bounce_runs(c);
  run_of(cr, "mujoco").events[1].peak_force_n = kNaN;
  run_of(cr, "mujoco").events[1].restitution = std::numeric_limits<double>::infinity();
  const auto metrics = case_metrics(c, cr);
  for (const char* name : {"peak_force", "restitution"}) {
    const MetricValue* m = find(metrics, "mujoco", "truth", name, 1);
    ASSERT_NE(m, nullptr) << name;
    EXPECT_TRUE(std::isnan(m->actual)) << name;
    EXPECT_TRUE(std::isnan(m->error)) << name;
    EXPECT_TRUE(gate_fails(band("mujoco", name, kWide, 0.0), metrics)) << name;
    // episode 0 alone is fine
    EXPECT_FALSE(gate_fails(band("mujoco", name, kWide, 0.0, 0), metrics)) << name;
  }
}

// A truth episode still open at the end has no duration or restitution:
// nothing to compare, so no metric (not a NaN failure of the engine).
TEST(GateMetrics, NoBaselineValueNoMetric) {
  const Case c = test::falling_ball_case();
  CaseRuns cr = two_bounce_runs(c);
  run_of(cr, "analytic").events[1].offset_time_s = kNaN;
  run_of(cr, "analytic").events[1].restitution = kNaN;
  const auto metrics = case_metrics(c, cr);
  EXPECT_EQ(find(metrics, "mujoco", "truth", "contact_duration", 1), nullptr);
  EXPECT_EQ(find(metrics, "mujoco", "truth", "restitution", 1), nullptr);
  EXPECT_NE(find(metrics, "mujoco", "truth", "peak_force", 1), nullptr);
}

// ---- truncated runs -------------------------------------------------------------------

// An ok run whose rows stop at t = 1 s (10001 of 25001): its errors on the
// common prefix are 0 (box2d follows the truth exactly), which must not pass.
TEST(GateMetrics, ATruncatedOkRunIsNotJudgedOnItsPrefix) {
  const Case c = test::falling_ball_case();
  CaseRuns cr = test::falling_ball_runs(c);
  auto& ball = run_of(cr, "box2d").bodies.front();
  for (auto* v : {&ball.time_s, &ball.angle_rad, &ball.angular_velocity_radps}) v->resize(10001);
  ball.position_m.resize(10001);
  ball.velocity_mps.resize(10001);
  const auto metrics = case_metrics(c, cr);
  for (const char* name : {"position_max", "position_rms", "velocity_max", "angle_max"}) {
    const MetricValue* m = find(metrics, "box2d", "truth", name);
    ASSERT_NE(m, nullptr) << name;
    EXPECT_TRUE(std::isnan(m->actual)) << name << " = " << m->actual;
    EXPECT_NE(m->note.find("truncated: 10001 rows of body 'ball'"), std::string::npos) << m->note;
    EXPECT_TRUE(gate_fails(band("box2d", name, kWide, 0.0), metrics)) << name;
  }
  // against mujoco (the engine pair) too, in either role
  const MetricValue* pair = find(metrics, "box2d", "mujoco", "position_max");
  ASSERT_NE(pair, nullptr);
  EXPECT_TRUE(std::isnan(pair->actual));

  // the verdict ranks mujoco (1 mm) first, box2d unranked with no error
  ResultsFile results;
  results.cases.push_back(cr);
  const internal::Table t = internal::verdict_table(results, {c}, metrics, {}, {}, {});
  ASSERT_EQ(t.rows.size(), 1u);
  EXPECT_EQ(t.rows[0][2], "mujoco");
  EXPECT_NE(t.rows[0][3].find("box2d no error computed"), std::string::npos) << t.rows[0][3];
}

// The same cut on a diverged run: its errors up to the divergence stay (the
// report shows how far it got), noted; its status fails the gate.
TEST(GateMetrics, ATruncatedDivergedRunKeepsItsPrefixErrorsNoted) {
  const Case c = test::falling_ball_case();
  CaseRuns cr = test::falling_ball_runs(c);
  RunResult& r = run_of(cr, "mujoco");
  r.status = RunStatus::diverged;
  r.diverged_at_s = 1.0;
  auto& ball = r.bodies.front();
  for (auto* v : {&ball.time_s, &ball.angle_rad, &ball.angular_velocity_radps}) v->resize(10001);
  ball.position_m.resize(10001);
  ball.velocity_mps.resize(10001);
  const MetricValue* m = nullptr;
  const auto metrics = case_metrics(c, cr);
  m = find(metrics, "mujoco", "truth", "position_max");
  ASSERT_NE(m, nullptr);
  // 1 mm below the truth: the offset, up to rounding of y ~ 2 m (a few ulp, 1e-15 m)
  EXPECT_NEAR(m->actual, 1e-3, 1e-12);
  EXPECT_NE(m->note.find("truncated"), std::string::npos) << m->note;
}

// A run without the ball at all: NaN errors, not no metric (a threshold of a
// missing metric fails too, but the report would show nothing).
TEST(GateMetrics, AMissingBodyIsTruncation) {
  const Case c = test::falling_ball_case();
  CaseRuns cr = test::falling_ball_runs(c);
  run_of(cr, "box2d").bodies.clear();
  const auto metrics = case_metrics(c, cr);
  const MetricValue* m = find(metrics, "box2d", "truth", "position_max");
  ASSERT_NE(m, nullptr);
  EXPECT_TRUE(std::isnan(m->actual));
  EXPECT_NE(m->note.find("no samples of body 'ball'"), std::string::npos) << m->note;
}

// ---- missing and extra episodes -------------------------------------------------------

// The truth bounces twice, box2d once: episode 1 is lost. Its episode_count
// is 1 against 2, and each of episode 1's metrics is there with the run's
// value NaN: the every-episode band and episode 1's own band fail.
TEST(GateMetrics, ALostEpisodeFailsItsThresholds) {
  const Case c = test::falling_ball_case();
  const CaseRuns cr = two_bounce_runs(c);
  const auto metrics = case_metrics(c, cr);
  const MetricValue* count = find(metrics, "box2d", "truth", "episode_count");
  ASSERT_NE(count, nullptr);
  EXPECT_EQ(count->actual, 1.0);
  EXPECT_EQ(count->desired, 2.0);
  EXPECT_NE(count->note.find("episodes missing in the run"), std::string::npos) << count->note;
  // episode counts are whole numbers: a band below 1 tells 1 from 2
  EXPECT_TRUE(gate_fails(band("box2d", "episode_count", 0.5, 0.0), metrics));
  for (const char* name : {"impact_time", "contact_duration", "peak_force", "impulse",
                           "restitution", "max_penetration"}) {
    const MetricValue* m = find(metrics, "box2d", "truth", name, 1);
    ASSERT_NE(m, nullptr) << name;
    EXPECT_TRUE(std::isnan(m->actual)) << name;
    EXPECT_NE(m->note.find("episode missing in the run"), std::string::npos) << m->note;
    EXPECT_TRUE(gate_fails(band("box2d", name, kWide, kWide), metrics)) << name;
    EXPECT_TRUE(gate_fails(band("box2d", name, kWide, kWide, 1), metrics)) << name;
  }
  // mujoco has both: the same bands pass
  EXPECT_FALSE(gate_fails(band("mujoco", "episode_count", 0.5, 0.0), metrics));
  EXPECT_FALSE(gate_fails(band("mujoco", "restitution", kWide, 0.0), metrics));
}

// mujoco bounces three times against the truth's two: the third has nothing
// to be compared with (no metric of episode 2), and shows in episode_count.
TEST(GateMetrics, AnExtraEpisodeShowsInTheCount) {
  const Case c = test::falling_ball_case();
  CaseRuns cr = two_bounce_runs(c);
  ContactEpisode third = second_bounce();
  third.onset_time_s = 2.3;
  third.offset_time_s = 2.33;
  run_of(cr, "mujoco").events.push_back(third);
  const auto metrics = case_metrics(c, cr);
  const MetricValue* count = find(metrics, "mujoco", "truth", "episode_count");
  ASSERT_NE(count, nullptr);
  EXPECT_EQ(count->actual, 3.0);
  EXPECT_EQ(count->desired, 2.0);
  EXPECT_NE(count->note.find("extra episodes in the run"), std::string::npos) << count->note;
  EXPECT_TRUE(gate_fails(band("mujoco", "episode_count", 0.5, 0.0), metrics));
  for (const auto& m : metrics) {
    EXPECT_FALSE(m.engine == "mujoco" && m.against == "truth" && m.episode == 2) << m.metric;
  }
  // the first two are paired as before, and pass
  EXPECT_FALSE(gate_fails(band("mujoco", "restitution", kWide, 0.0), metrics));
}

// ---- the verdict ----------------------------------------------------------------------

// An ok run with one NaN position is not ranked (its error is no number),
// and the valid one is best; undamaged, box2d (error 0) is best.
TEST(GateMetrics, VerdictRanksOnlyFiniteErrors) {
  const Case c = test::falling_ball_case();
  auto best_of = [&](const CaseRuns& cr) {
    ResultsFile results;
    results.cases.push_back(cr);
    const internal::Table t = internal::verdict_table(results, {c}, case_metrics(c, cr), {}, {}, {});
    return t.rows.at(0).at(2);
  };
  CaseRuns cr = test::falling_ball_runs(c);
  EXPECT_EQ(best_of(cr), "box2d");
  run_of(cr, "box2d").bodies.front().position_m[25000] = Vec2(0.0, kNaN);
  EXPECT_EQ(best_of(cr), "mujoco");
}

// Where the truth run is the converged reference (its mapping's physics
// mode), the verdict says in words that the reference is judged against
// itself; a closed-form truth gets no such caveat.
TEST(GateMetrics, VerdictSaysWhenTheReferenceIsJudgedAgainstItself) {
  const Case c = test::falling_ball_case();
  auto row_of = [&](const CaseRuns& cr) {
    ResultsFile results;
    results.cases.push_back(cr);
    return internal::verdict_table(results, {c}, case_metrics(c, cr), {}, {}, {}).rows.at(0);
  };
  CaseRuns cr = test::falling_ball_runs(c);
  run_of(cr, "analytic").mapping["physics"] = {{"mode", "closed form"}};
  EXPECT_EQ(row_of(cr).at(4).find("judged against itself"), std::string::npos);
  run_of(cr, "analytic").mapping["physics"] = {{"mode", "converged reference"}};
  const auto row = row_of(cr);
  EXPECT_EQ(row.at(1), "converged reference");
  EXPECT_NE(row.at(4).find("the reference is judged against itself"), std::string::npos)
      << row.at(4);
}

}  // namespace
}  // namespace pb
