// Tests for reports/src/report_figures.cpp
//
// The fixture is the falling_ball case (a disk dropped on a 30 degree
// incline, paper Figs 5-6) with synthetic runs whose values are known in
// closed form (report_test_runs.hpp): y = 2 - offset - t, a contact force
// constant over [0.7250, 0.7560] s and zero elsewhere.
#include "report_figures.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "planarbench/case_loader.hpp"
#include "report_test_runs.hpp"
#include "file_id.hpp"

namespace pb::internal {
namespace {

const PlotSeries* series_of(const Figure& f, const std::string& engine) {
  for (const auto& s : f.series) {
    if (s.engine == engine) return &s;
  }
  return nullptr;
}

TEST(CaseFigures, FallingBallHasThePapersFigures5And6) {
  const Case c = test::falling_ball_case();
  const auto figures = case_figures(c, test::falling_ball_runs(c), FigureLimits{});
  ASSERT_EQ(figures.size(), 2u);
  EXPECT_EQ(figures[0].id, "falling_ball_fig5");
  EXPECT_EQ(figures[0].title, "Fig. 5 Contact force");
  EXPECT_EQ(figures[0].quantity, Quantity::force);
  EXPECT_EQ(figures[1].id, "falling_ball_fig6");
  EXPECT_EQ(figures[1].paper_figure, "Fig. 6");
  EXPECT_EQ(figures[1].quantity, Quantity::y);
  // one series per ok run, in report order (the truth first); the
  // unsupported reference has none
  for (const auto& f : figures) {
    ASSERT_EQ(f.series.size(), 3u);
    EXPECT_EQ(f.series[0].engine, "analytic");
    EXPECT_EQ(f.series[1].engine, "mujoco");
    EXPECT_EQ(f.series[2].engine, "box2d");
  }
}

TEST(CaseFigures, ForceIsZeroOutsideContactAndKeepsEveryContactSample) {
  const Case c = test::falling_ball_case();
  const auto figures = case_figures(c, test::falling_ball_runs(c), FigureLimits{});
  const PlotSeries* truth = series_of(figures[0], "analytic");
  ASSERT_NE(truth, nullptr);
  EXPECT_EQ(truth->full_points, 25001u);  // 2.5 s at 1e-4 s, t = 0 included
  EXPECT_LT(truth->time_s.size(), 25001u);
  std::size_t in_contact = 0;
  for (std::size_t i = 0; i < truth->time_s.size(); ++i) {
    const double t = truth->time_s[i];
    const bool contact = t >= 0.7250 - 1e-12 && t <= 0.7560 + 1e-12;
    EXPECT_DOUBLE_EQ(truth->value[i], contact ? 580.0 : 0.0) << "t = " << t;
    in_contact += contact ? 1 : 0;
  }
  EXPECT_EQ(in_contact, 311u);  // (0.7560 - 0.7250) / 1e-4 + 1 grid samples
  // thinned outside the windows to the budget (5000), plus the first and last
  // samples and the contact window's padding of 2 output intervals each side
  // (4 samples kept in the window but outside [0.7250, 0.7560])
  EXPECT_LE(truth->time_s.size() - in_contact, 5000u + 2u + 4u);
}

TEST(CaseFigures, ImpulsiveEngineIsOffTheDefaultScale) {
  const Case c = test::falling_ball_case();
  const auto figures = case_figures(c, test::falling_ball_runs(c), FigureLimits{});
  const Figure& force = figures[0];
  // box2d peaks at 1e5 N against the truth's 580 N; mujoco's 590 N sets the axis
  EXPECT_DOUBLE_EQ(force.y_clip, 1.1 * 590.0);
  EXPECT_TRUE(series_of(force, "box2d")->off_scale);
  EXPECT_FALSE(series_of(force, "mujoco")->off_scale);
  EXPECT_NE(series_of(force, "box2d")->note.find("off the default scale"), std::string::npos);
  // the trajectory figure has no clip
  EXPECT_TRUE(std::isnan(figures[1].y_clip));
}

TEST(CaseFigures, TrajectoryValuesAndEpisodeZoom) {
  const Case c = test::falling_ball_case();
  const auto figures = case_figures(c, test::falling_ball_runs(c), FigureLimits{});
  const PlotSeries* mujoco = series_of(figures[1], "mujoco");
  for (std::size_t i = 0; i < mujoco->time_s.size(); ++i) {
    // y = 2 - 1e-3 - t for the run with a 1 mm offset (exact to rounding)
    EXPECT_NEAR(mujoco->value[i], 2.0 - 1e-3 - mujoco->time_s[i], 1e-12);
  }
  // one episode, 31 ms long: the zoom pads half its length on each side
  // (1e-12 s: rounding of sums of O(1) s times)
  ASSERT_EQ(figures[0].episodes.size(), 1u);
  EXPECT_EQ(figures[0].episodes[0].label, "episode 0");
  EXPECT_NEAR(figures[0].episodes[0].t0_s, 0.7250 - 0.0155, 1e-12);
  EXPECT_NEAR(figures[0].episodes[0].t1_s, 0.7560 + 0.0155, 1e-12);
}

TEST(CaseFigures, TruthIsCutWhereItStopsBeingValid) {
  const Case c = test::falling_ball_case();
  CaseRuns runs = test::falling_ball_runs(c);
  for (auto& r : runs.runs) {
    if (r.engine_name == "analytic") r.extra["valid_until_s"] = 1.0;
  }
  const auto figures = case_figures(c, runs, FigureLimits{});
  const PlotSeries* truth = series_of(figures[1], "analytic");
  // the last kept sample is within one output interval (1e-4 s) of the cut
  EXPECT_LE(truth->time_s.back(), 1.0);
  EXPECT_GE(truth->time_s.back(), 1.0 - 1e-4);
  EXPECT_NE(truth->note.find("valid until t = 1 s"), std::string::npos);
}

TEST(CaseFigures, OtherCasesGetGenericPlots) {
  const Case base = test::falling_ball_case();
  const Case c = parse_case(base.source_text, "my_case.toml", "my_case");
  CaseRuns runs = test::falling_ball_runs(c);
  const auto figures = case_figures(c, runs, FigureLimits{});
  ASSERT_EQ(figures.size(), 5u);  // one contact pair, one moving body x 4 quantities
  EXPECT_EQ(figures[0].id, "my_case_force_ground_ball");
  EXPECT_EQ(figures[1].id, "my_case_ball_x");
  EXPECT_EQ(figures[2].id, "my_case_ball_y");
  EXPECT_EQ(figures[3].id, "my_case_ball_vx");
  EXPECT_EQ(figures[4].id, "my_case_ball_vy");
  EXPECT_TRUE(figures[4].paper_figure.empty());
  EXPECT_DOUBLE_EQ(series_of(figures[4], "analytic")->value[0], -1.0);
}

TEST(FileId, ReplacesAnythingButWordCharacters) {
  EXPECT_EQ(file_id("a b/c.d-e_f"), "a_b_c_d-e_f");
  EXPECT_EQ(file_id(""), "_");
}

// Issue 49: a case file name of 244 bytes (legal: 249 with ".toml") gave
// figure files past a file name's 255 bytes. A long name is cut to
// kMaxFileIdBytes, its tail a hash of the whole: two names differing only
// past the cut stay two files, the same name is the same file.
TEST(FileId, ALongNameFitsAFileNameAndStaysDistinct) {
  const std::string a(244, 'a');
  const std::string b = a.substr(0, 243) + "b";
  EXPECT_EQ(file_id(a).size(), internal::kMaxFileIdBytes);
  EXPECT_NE(file_id(a), file_id(b));
  EXPECT_EQ(file_id(a), file_id(std::string(244, 'a')));
  EXPECT_EQ(file_id(a).substr(0, 100), a.substr(0, 100));
  EXPECT_EQ(file_id(std::string(120, 'c')), std::string(120, 'c'));  // at the limit: kept
}

}  // namespace
}  // namespace pb::internal
