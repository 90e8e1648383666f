// Tests for reports/src/report_campaign.cpp: the spread of a random axis, the
// medians and bands against an axis, and the plots, on tables whose numbers
// are known by construction.
#include "report_campaign.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "planarbench/run_result.hpp"

namespace {

using pb::CampaignRun;
using pb::CampaignTable;

TEST(ReportCampaign, RmsSpreadIsTheRootMeanSquareDistanceFromTheMean) {
  // four points at the corners of a square of side 2 about (1, -1): each is
  // sqrt(2) from the centre
  EXPECT_DOUBLE_EQ(pb::internal::rms_spread({0, 2, 0, 2}, {0, 0, -2, -2}), std::sqrt(2.0));
  // one point: no spread; NaN points are left out
  EXPECT_EQ(pb::internal::rms_spread({3}, {4}), 0.0);
  EXPECT_DOUBLE_EQ(pb::internal::rms_spread({0, std::nan(""), 2}, {0, 5, 0}), 1.0);
  EXPECT_TRUE(std::isnan(pb::internal::rms_spread({}, {})));
}

// one case, two engines, a dt axis of 2 points and a random axis of 3 samples;
// the metric is 10 * dt (+ the sample index for "b"); the trace of one body is
// x = sample * t, y = 0 at t = 0, 1, 2
CampaignTable table() {
  CampaignTable t;
  t.planned_runs = 12;
  t.engines = {"a", "b"};
  pb::CampaignCase c;
  c.name = "toy";
  c.truth = "analytic";
  c.moving_bodies = {"body"};
  t.cases = {c};
  t.axes = {{"dt", "dt", "values", "s", {}, {1e-3, 1e-4}}, {"state", "bodies.*.position", "perturb", "1", {}, {0, 1, 2}}};
  t.metrics = {{"position_error_m", "m", ""}};
  t.trace_points = 3;
  t.trace_bodies = 1;
  std::int64_t id = 0;
  for (const std::string e : {"a", "b"}) {
    for (const double dt : {1e-3, 1e-4}) {
      for (int s = 0; s < 3; ++s) {
        CampaignRun r;
        r.id = id++;
        r.case_name = "toy";
        r.engine = e;
        r.status = pb::RunStatus::ok;
        r.wall_time_s = 1e-6 / dt;
        r.axis_values = {dt, static_cast<double>(s)};
        r.metrics = {10 * dt + (e == "b" ? s : 0)};
        r.trace_time_s = {0, 1, 2};
        r.trace_position_m = {0, 0, 1.0 * s, 0, 2.0 * s, 0};
        if (e == "a") {
          r.physics = R"({"mode":"native","collision_by":"engine","contact_force_by":"engine","foreknowledge":false})";
        }
        t.runs.push_back(r);
      }
    }
  }
  return t;
}

TEST(ReportCampaign, AxisTableHasTheMedianAndRangeOfEachPoint) {
  const auto sec = pb::internal::campaign_section(table(), "toy.h5");
  ASSERT_EQ(sec.cases.size(), 1u);
  const auto& tables = sec.cases[0].tables;
  ASSERT_EQ(tables.size(), 3u);  // runs, the dt axis, the spread
  EXPECT_EQ(tables[0].rows[0],
            (std::vector<std::string>{"a", "6", "6", "0", "0", "0.0055", "0.033", "native: collision by engine, force by engine"}));
  // b's runs say nothing of their physics: the table says so, it does not guess
  EXPECT_EQ(tables[0].rows[1].back(), "not recorded");
  EXPECT_EQ(tables[0].row_status[0], "");
  const auto& axis = tables[1];
  ASSERT_EQ(axis.rows.size(), 4u);
  // engine a at dt 1e-4: the metric is 1e-3 for every sample; b: 1e-3 + {0, 1, 2}
  EXPECT_EQ(axis.rows[0][0], "a");
  EXPECT_EQ(axis.rows[0][1], "1e-4");
  EXPECT_EQ(axis.rows[0][3], "0.001");
  EXPECT_EQ(axis.rows[2][0], "b");
  EXPECT_EQ(axis.rows[2][3], "1.001 (0.001..2.001)");
}

TEST(ReportCampaign, ARunWithForeknowledgeIsMarked) {
  CampaignTable t = table();
  t.runs[0].physics = R"({"mode":"oracle","collision_by":"engine","contact_force_by":"engine","foreknowledge":true})";
  const auto sec = pb::internal::campaign_section(t, "toy.h5");
  const auto& runs = sec.cases[0].tables[0];
  EXPECT_EQ(runs.row_status[0], "fail");
  EXPECT_NE(runs.rows[0].back().find("oracle: collision by engine, force by engine, WITH FOREKNOWLEDGE"),
            std::string::npos)
      << runs.rows[0].back();
  EXPECT_NE(runs.rows[0].back().find("; native: "), std::string::npos) << runs.rows[0].back();
}

TEST(ReportCampaign, SpreadGrowsAsTheSamplesFanOut) {
  const auto sec = pb::internal::campaign_section(table(), "toy.h5");
  const auto& spread = sec.cases[0].tables[2];
  ASSERT_EQ(spread.rows.size(), 4u);  // 2 engines x 2 points of dt
  // samples at x = 0, s, 2s for s = 0, 1, 2 at t = 0, 1, 2: the rms distance
  // from the mean of {0, 1, 2} is sqrt(2/3), of {0, 2, 4} 2 sqrt(2/3)
  for (const auto& row : spread.rows) {
    EXPECT_EQ(row[2], "3");
    EXPECT_EQ(row[3], "0");
    EXPECT_EQ(row[4], fmt::format("{:.4g}", 2 * std::sqrt(2.0 / 3.0)));
    EXPECT_EQ(row[6], "-");  // no growth ratio from a zero start
  }
  // figures: the metric and the wall time against dt, one spread per dt point
  ASSERT_EQ(sec.cases[0].figures.size(), 4u);
  EXPECT_EQ(sec.cases[0].figures[0].id, "toy_dt_position_error_m");
}

TEST(ReportCampaign, PlotsAreTheSameBytesEachTime) {
  const auto a = pb::internal::campaign_section(table(), "toy.h5");
  const auto b = pb::internal::campaign_section(table(), "toy.h5");
  for (std::size_t i = 0; i < a.cases[0].figures.size(); ++i) {
    EXPECT_EQ(a.cases[0].figures[i].svg, b.cases[0].figures[i].svg);
    EXPECT_NE(a.cases[0].figures[i].svg.find("<path d=\"M"), std::string::npos) << i;
  }
}

TEST(ReportCampaign, AnEmptyPlotSaysSo) {
  pb::internal::LinePlot p;
  p.title = "nothing";
  const std::string svg = pb::internal::line_plot_svg(p);
  EXPECT_NE(svg.find("no point to plot"), std::string::npos);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
}

}  // namespace
