// Tests for reports/src/report_work_precision.cpp
#include "report_work_precision.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using pb::RunStatus;
using pb::internal::Reach;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Hand-computed log-log interpolation. Between (0.2 s, 4e-3 m) and
// (0.8 s, 2.5e-4 m) the error falls by 16 while the time grows by 4, so the
// level 1e-3 m, a factor 4 = 16^(1/2) below 4e-3, is reached half way in log
// time: 0.2 * 4^(1/2) = 0.4 s.
TEST(TimeToReach, InterpolatesLogLogBetweenTheBracketingRungs) {
  const Reach r = pb::internal::time_to_reach({0.2, 0.8}, {4e-3, 2.5e-4}, 1e-3);
  EXPECT_EQ(r.kind, Reach::Kind::interpolated);
  // 1e-12 relative: a few roundings of log and exp
  // by hand: 1e-3 lies halfway (in log) between 4e-3 and 2.5e-4 (factors 4 and
  // 4), so the time is halfway in log between 0.2 and 0.8 s: sqrt(0.16) = 0.4 s;
  // 1e-12 s allows the rounding of the log-log interpolation
  EXPECT_NEAR(r.wall_time_s, 0.4, 1e-12);
  // a decade of time per two of error: 1e-3 m is half way, sqrt(0.1 * 1) s
  EXPECT_NEAR(pb::internal::time_to_reach({0.1, 1.0}, {1e-2, 1e-4}, 1e-3).wall_time_s,
              std::sqrt(0.1), 1e-12);
}

TEST(TimeToReach, SkipsRungsWithoutAnErrorAndUsesTheFirstCrossing) {
  // a diverged coarsest rung, then the crossing above
  const Reach r =
      pb::internal::time_to_reach({0.05, 0.2, 0.8, 3.2}, {kNaN, 4e-3, 2.5e-4, 1e-6}, 1e-3);
  EXPECT_EQ(r.kind, Reach::Kind::interpolated);
  EXPECT_NEAR(r.wall_time_s, 0.4, 1e-12);
}

TEST(TimeToReach, ACheaperFinerRungBoundsTheTime) {
  // wall times are noisy: the third rung reaches the level in 0.3 s < 0.4 s
  const Reach r = pb::internal::time_to_reach({0.2, 0.8, 0.3}, {4e-3, 2.5e-4, 1e-5}, 1e-3);
  EXPECT_EQ(r.wall_time_s, 0.3);
}

TEST(TimeToReach, ExactlyAtTheLevelIsThatRungsTime) {
  const Reach r = pb::internal::time_to_reach({0.2, 0.8}, {4e-3, 1e-3}, 1e-3);
  // 1e-12 s: the rung's own time, up to the interpolation's rounding
  EXPECT_NEAR(r.wall_time_s, 0.8, 1e-12);
  // an error of exactly 0 cannot be put on a log scale: the rung's own time
  EXPECT_EQ(pb::internal::time_to_reach({0.2, 0.8}, {4e-3, 0.0}, 1e-3).wall_time_s, 0.8);
}

TEST(TimeToReach, FirstRungAlreadyBelowIsAnUpperBound) {
  const Reach r = pb::internal::time_to_reach({0.1, 1.0}, {1e-4, 1e-6}, 1e-3);
  EXPECT_EQ(r.kind, Reach::Kind::at_first_rung);
  EXPECT_EQ(r.wall_time_s, 0.1);
  EXPECT_EQ(pb::internal::reach_text(r), "<= 0.1");
}

TEST(TimeToReach, NotReachedAndNoData) {
  const Reach above = pb::internal::time_to_reach({0.1, 1.0}, {1e-2, 5e-3}, 1e-3);
  EXPECT_EQ(above.kind, Reach::Kind::not_reached);
  EXPECT_EQ(pb::internal::reach_text(above), "not reached");
  const Reach none = pb::internal::time_to_reach({0.1, 1.0}, {kNaN, kNaN}, 1e-3);
  EXPECT_EQ(none.kind, Reach::Kind::no_data);
  EXPECT_EQ(pb::internal::reach_text(none), "no data");
  // a wall time of 0 has no logarithm: the rung is skipped
  EXPECT_EQ(pb::internal::time_to_reach({0.0}, {1e-6}, 1e-3).kind, Reach::Kind::no_data);
}

// A case of 2 s swept on the reference's rk45 (default rtol 1e-10 in the
// ladder, 0.1 s there: 0.05 s per simulated s) and mujoco (default dt 1e-4 s,
// 0.4 s there: 0.2 s per simulated s, 4 times the reference), one mujoco rung
// diverged.
pb::SweepCase sample_case() {
  pb::SweepCase c;
  c.case_name = "falling_ball";
  c.duration_s = 2.0;
  c.truth = "analytic";
  pb::SweepSeries rk45;
  rk45.name = "reference_rk45";
  rk45.engine = "reference";
  rk45.knob = "rtol";
  rk45.knob_unit = "1";
  rk45.default_value = 1e-10;
  rk45.rungs = {{1e-6, 0.05, 300, 2e-3, RunStatus::ok, ""},
                {1e-10, 0.1, 400, 1e-9, RunStatus::ok, ""}};
  pb::SweepSeries fixed = rk45;
  fixed.name = "reference_fixed";
  fixed.knob = "dt";
  fixed.default_value = 1e-5;  // not in its ladder below
  fixed.rungs = {{1e-3, 0.2, 2000, 1e-6, RunStatus::ok, ""}};
  pb::SweepSeries mj;
  mj.name = "mujoco";
  mj.engine = "mujoco";
  mj.knob = "dt";
  mj.knob_unit = "s";
  mj.default_value = 1e-4;
  mj.rungs = {{1e-3, 0.02, 2000, kNaN, RunStatus::diverged, "at t = 0.5 s: energy runaway"},
              {1e-4, 0.4, 20000, 7e-3, RunStatus::ok, ""}};
  c.series = {rk45, fixed, mj};
  return c;
}

TEST(WorkPrecisionCase, DefaultRungMatchesRelatively) {
  const auto c = sample_case();
  EXPECT_EQ(pb::internal::default_rung(c.series[0]), 1);
  EXPECT_EQ(pb::internal::default_rung(c.series[1]), -1);
  EXPECT_EQ(pb::internal::default_rung(c.series[2]), 1);
}

TEST(WorkPrecisionCase, PlotSeriesHoldOnlyRungsWithAnError) {
  const auto w = pb::internal::work_precision_case(sample_case());
  EXPECT_EQ(w.id, "falling_ball_work_precision");
  ASSERT_EQ(w.series.size(), 3u);
  EXPECT_FALSE(w.series[0].dashed);
  EXPECT_TRUE(w.series[1].dashed);  // the reference's second integrator
  EXPECT_EQ(w.series[0].default_index, 1);
  EXPECT_EQ(w.series[2].wall_s, (std::vector<double>{0.4}));
  EXPECT_EQ(w.series[2].default_index, 0);
  ASSERT_EQ(w.not_plotted.size(), 1u);
  EXPECT_NE(w.not_plotted[0].find("mujoco dt=1e-3: diverged"), std::string::npos)
      << w.not_plotted[0];
  EXPECT_EQ(w.targets_m, (std::vector<double>{1e-3, 1e-5}));
}

TEST(WorkPrecisionCase, SummaryGivesCostPerSimulatedSecondNextToTheReference) {
  const auto w = pb::internal::work_precision_case(sample_case());
  const auto& t = w.summary;
  ASSERT_EQ(t.columns.size(), 8u);
  EXPECT_EQ(t.columns[6], "time to 1e-3 m, s");
  EXPECT_EQ(t.columns[7], "time to 1e-5 m, s");
  ASSERT_EQ(t.rows.size(), 3u);
  // reference rk45: 0.1 s / 2 s = 0.05 s per simulated s, itself 1x
  EXPECT_EQ(t.rows[0][3], "1e-09");
  EXPECT_EQ(t.rows[0][4], "0.05");
  EXPECT_EQ(t.rows[0][5], "1x");
  // 2e-3 m at 0.05 s, 1e-9 m at 0.1 s: 1e-3 m is log(2)/log(2e6) of the way
  const double f3 = std::log(1e-3 / 2e-3) / std::log(1e-9 / 2e-3);
  EXPECT_EQ(t.rows[0][6],
            pb::internal::reach_text({Reach::Kind::interpolated, 0.05 * std::pow(2.0, f3)}));
  EXPECT_EQ(t.rows[1][3], "default not in ladder");
  EXPECT_EQ(t.rows[1][6], "<= 0.2");
  // mujoco: 0.4 s / 2 s = 0.2 s per simulated s = 4x the reference's
  EXPECT_EQ(t.rows[2][4], "0.2");
  EXPECT_EQ(t.rows[2][5], "4x");
  EXPECT_EQ(t.rows[2][6], "not reached");
  EXPECT_NE(t.note.find("0.05 s per simulated s"), std::string::npos) << t.note;
}

TEST(WorkPrecisionCase, EveryRungIsListedDivergedMarked) {
  const auto w = pb::internal::work_precision_case(sample_case());
  ASSERT_EQ(w.rungs.rows.size(), 5u);
  EXPECT_EQ(w.rungs.rows[3][3], "diverged");
  EXPECT_EQ(w.rungs.rows[3][7], "at t = 0.5 s: energy runaway");
  EXPECT_EQ(w.rungs.row_status[3], "fail");
  EXPECT_EQ(w.rungs.rows[4][2], "1e-4");
}

TEST(WorkPrecisionNote, NamesTheLaddersAndTheRepeats) {
  pb::SweepFile s;
  s.repeat = 3;
  s.dt_ladder = {1e-3, 5e-4};
  s.rtol_ladder = {1e-4};
  const std::string note = pb::internal::work_precision_note(s, "sweep.h5");
  for (const char* word : {"sweep.h5", "1e-3, 5e-4 s", "rtol = 1e-4", "median of 3 runs"}) {
    EXPECT_NE(note.find(word), std::string::npos) << word << "\n" << note;
  }
}

TEST(SweepProvenanceTable, ListsParametersRepeatAndCaseFiles) {
  pb::internal::FileProvenance p;
  p.parameters = {{"host", "vm"}};
  pb::SweepFile s;
  s.repeat = 2;
  auto c = sample_case();
  c.case_path = "cases/falling_ball.toml";
  c.overrides = {{"reference.geometry", "exact"}};
  s.cases = {c};
  const auto t = pb::internal::sweep_provenance_table(p, s);
  ASSERT_EQ(t.rows.size(), 4u);
  EXPECT_EQ(t.rows[0], (std::vector<std::string>{"host", "vm"}));
  EXPECT_EQ(t.rows[1], (std::vector<std::string>{"repeat", "2"}));
  EXPECT_EQ(t.rows[2][1], "cases/falling_ball.toml");
  EXPECT_EQ(t.rows[3][1], "reference.geometry=exact");
}

}  // namespace
