// Tests for reports/src/report_tables.cpp
#include "report_tables.hpp"

#include <gtest/gtest.h>

#include "report_test_runs.hpp"

namespace pb::internal {
namespace {

MetricValue metric(const std::string& engine, const std::string& name, int episode, double actual,
                   double desired, double error) {
  MetricValue m;
  m.case_name = "falling_ball";
  m.engine = engine;
  m.against = "truth";
  m.metric = name;
  m.episode = episode;
  m.actual = actual;
  m.desired = desired;
  m.error = error;
  m.unit.assign(1, '1');  // not = "1": GCC 12 warns falsely (-Wstringop-overflow) when inlined
  return m;
}

CheckOutcome outcome(const MetricValue& m, bool passed, double limit) {
  CheckOutcome o;
  o.threshold.case_name = m.case_name;
  o.threshold.engine = m.engine;
  o.threshold.against = m.against;
  o.threshold.metric = m.metric;
  o.value = m;
  o.limit = limit;
  o.passed = passed;
  o.message = passed ? "" : "too far";
  return o;
}

TEST(MetricsTable, PassFailFromTheOutcomesOfEachMetric) {
  const auto a = metric("mujoco", "peak_force", 0, 582.0, 581.2, 0.0014);
  const auto b = metric("box2d", "peak_force", 0, 1.145e5, 581.2, 196.0);
  const auto c = metric("ode", "peak_force", 0, 581.0, 581.2, 0.0003);
  auto oa = outcome(a, true, 29.06);
  oa.threshold.why = "phase error 1.2 %";
  const Table t = metrics_table({a, b, c}, {oa, outcome(b, false, 29.06)}, true);
  ASSERT_EQ(t.rows.size(), 3u);
  ASSERT_EQ(t.columns.size(), 14u);
  EXPECT_EQ(t.columns[10], "limit");
  EXPECT_EQ(t.columns[11], "result");
  EXPECT_EQ(t.rows[0][11], "pass");
  EXPECT_EQ(t.rows[0][12], "phase error 1.2 %");  // the threshold's why beside its limit
  EXPECT_EQ(t.rows[1][11], "fail");
  EXPECT_EQ(t.rows[1][13], "too far");
  EXPECT_EQ(t.rows[2][11], "");  // no threshold covers it
  EXPECT_EQ(t.row_status, (std::vector<std::string>{"pass", "fail", ""}));
  EXPECT_EQ(t.rows[1][5], "1.145e+05");
  EXPECT_EQ(t.rows[0][4], "0");
}

TEST(MetricsTable, GatedFirstThenTruthThenTheRest) {
  auto self = metric("ode", "energy_drift", -1, 0.1, 0.0, 0.1);
  self.against = "self";
  auto vs_ref = metric("ode", "position_max", -1, 0.2, 0.0, 0.2);
  vs_ref.against = "reference";
  const auto truth = metric("ode", "position_max", -1, 0.3, 0.0, 0.3);
  const auto gated = metric("mujoco", "restitution", 0, 0.8, 0.8, 1e-3);
  const Table t = metrics_table({self, vs_ref, truth, gated}, {outcome(gated, true, 1e-2)}, true);
  ASSERT_EQ(t.rows.size(), 4u);
  EXPECT_EQ(t.rows[0][1], "mujoco");    // the gated check
  EXPECT_EQ(t.rows[1][2], "truth");     // then the truth comparison
  EXPECT_EQ(t.rows[2][2], "self");      // then the rest, in the metrics' order
  EXPECT_EQ(t.rows[3][2], "reference");
}

TEST(MetricsTable, UnitsOfTheValueAndOfTheError) {
  auto a = metric("ode", "peak_force", 0, 582.0, 581.2, 0.0014);
  a.unit = "1";  // a relative error ...
  a.value_unit = "N";  // ... of a force
  auto b = metric("ode", "restitution", 0, 0.80, 0.81, 0.01);
  b.unit = "1";  // a dimensionless quantity, its error absolute
  b.value_unit = "1";
  const Table t = metrics_table({a, b}, {}, false);
  EXPECT_EQ(t.columns[7], "unit");
  EXPECT_EQ(t.columns[9], "error unit");
  EXPECT_EQ(t.rows[0][7], "N");
  EXPECT_EQ(t.rows[0][9], "relative");
  EXPECT_EQ(t.rows[1][7], "1");
  EXPECT_EQ(t.rows[1][9], "1");
}

TEST(MetricsTable, NoCheckColumnsWithoutThresholds) {
  const auto a = metric("mujoco", "position_max", -1, 1e-3, 0.0, 1e-3);
  const Table t = metrics_table({a}, {}, false);
  EXPECT_EQ(t.columns.size(), 11u);
  EXPECT_EQ(t.rows[0][4], "");  // not a per-episode metric
}

TEST(UnmatchedThresholds, ListsThresholdsWithoutAValue) {
  CheckOutcome o;
  o.threshold.case_name = "falling_ball";
  o.threshold.metric = "restitution";
  o.threshold.line = 17;
  o.message = "not computed";
  const auto matched = outcome(metric("ode", "impulse", 0, 1, 1, 0), true, 1.0);
  const Table t = unmatched_thresholds_table({o, matched});
  ASSERT_EQ(t.rows.size(), 1u);
  EXPECT_EQ(t.rows[0][5], "17");
  EXPECT_EQ(t.row_status[0], "fail");
}

TEST(CapabilityAndTimings, OneRowPerCaseAndPerRun) {
  const Case c = test::falling_ball_case();
  ResultsFile results;
  results.cases.push_back(test::falling_ball_runs(c));
  const Table cap = capability_table(results);
  // engines in report order, whatever order the file has them in
  EXPECT_EQ(cap.columns,
            (std::vector<std::string>{"case", "analytic", "reference", "mujoco", "box2d"}));
  ASSERT_EQ(cap.rows.size(), 1u);
  EXPECT_EQ(cap.rows[0][1], "ok");
  EXPECT_EQ(cap.rows[0][2], "unsupported: cannot run this case");

  Table tim = timings_table(results, {c});
  ASSERT_EQ(tim.rows.size(), 4u);
  EXPECT_EQ(tim.rows[0][1], "analytic");
  // 0.5 s of wall time over 2.5 simulated seconds
  EXPECT_EQ(tim.rows[0][8], "0.2");
  EXPECT_EQ(tim.rows[1][7], "0");  // the unsupported reference simulated nothing
  EXPECT_EQ(tim.rows[0][4], "1");  // one run, no range
  EXPECT_EQ(tim.rows[0][5], "");

  // a repeated run: its median and the range of its wall times
  results.cases[0].runs[2].wall_time_repeats_s = {0.6, 0.5, 0.9};  // analytic, first in the table
  tim = timings_table(results, {c});
  EXPECT_EQ(tim.rows[0][4], "3");
  EXPECT_EQ(tim.rows[0][5], "0.5 - 0.9");
}

TEST(FormatNumber, FourDigitsAndBlankNaN) {
  EXPECT_EQ(format_number(581.2149), "581.2");
  EXPECT_EQ(format_number(std::nan("")), "");
}

}  // namespace
}  // namespace pb::internal
