// Tests for reports/src/report_validity.cpp (issue 32): the physical-validity
// section's table, per-engine readings and figures on constructed runs whose
// violations are known by construction (a force outside the cone by 10 %, a
// stick that creeps), and that a run without contact rows adds nothing.
#include "report_validity.hpp"

#include <gtest/gtest.h>

#include <string>

#include "body_on_ground.hpp"

namespace pb::internal {
namespace {

constexpr double kDt = 1e-3;  // s, the output interval

Case block_case() {
  return test::body_on_ground(
      "slab", "block", Polygon{{Vec2(-0.1, -0.1), Vec2(0.1, -0.1), Vec2(0.1, 0.1), Vec2(-0.1, 0.1)}},
      0.5, KelvinVoigt{});
}

// 100 rows of F_n = 10 N: sliding at 0.2 m/s with F_t = -mu F_n but one row at
// -1.1 mu F_n (engine "outside"), or held with F_t = 0.45 F_n creeping at
// 5e-5 m/s (engine "creeping")
RunResult run_of(const std::string& engine) {
  RunResult r;
  r.engine_name = engine;
  r.status = RunStatus::ok;
  for (int i = 0; i < 100; ++i) {
    ContactRow row;
    row.time_s = kDt * i;
    row.sample.body_a = 0;
    row.sample.body_b = 1;
    row.sample.force_n = 10.0;
    row.sample.penetration_m = 1e-5;
    row.sample.normal = Vec2(0.0, 1.0);
    const bool outside = engine == "outside";
    row.sample.tangential_force_n = outside ? (i == 40 ? -5.5 : -5.0) : 4.5;
    row.sample.slip_mps = outside ? 0.2 : 5e-5;
    r.contacts.push_back(row);
  }
  return r;
}

TEST(ReportValidity, TabulatesReadsAndPlotsEachRunsViolations) {
  const Case c = block_case();
  ResultsFile results;
  CaseRuns cr;
  cr.case_name = c.name;
  cr.runs = {run_of("outside"), run_of("creeping")};
  results.cases = {cr};
  const ValiditySection s = validity_section({c}, results);
  ASSERT_EQ(s.table.rows.size(), 2u);
  const auto& outside = s.table.rows[0];
  EXPECT_EQ(outside[0], "slab");
  EXPECT_EQ(outside[1], "outside");
  EXPECT_EQ(outside[2], "ground_block");
  EXPECT_EQ(outside[4], "0.1 (0)");   // cone: one row at 10 %, the 99th of 100 at 0
  EXPECT_EQ(outside[5], "0 (0)");     // dissipation: beyond the cone it is -0.1, never above 0
  EXPECT_EQ(outside[6], "-");         // never inside the cone below 1e-3 m/s
  EXPECT_EQ(outside[8], "-");         // a faced pair: no law residual
  const auto& creeping = s.table.rows[1];
  EXPECT_EQ(creeping[4], "0 (0)");
  EXPECT_EQ(creeping[5], "-");        // never sliding
  EXPECT_EQ(creeping[6], "5e-05 (5e-05)");
  ASSERT_EQ(s.readings.size(), 2u);
  EXPECT_NE(s.readings[0].find("outside: Coulomb cone respected to 0.1 of mu F_n (slab)"),
            std::string::npos)
      << s.readings[0];
  EXPECT_NE(s.readings[0].find("dissipates at Coulomb's maximum rate"), std::string::npos);
  EXPECT_NE(s.readings[1].find("creeps up to 5e-05 m/s inside the cone (slab)"), std::string::npos)
      << s.readings[1];
  // the friction case's two figures; no law figure (its one pair has friction)
  ASSERT_EQ(s.figures.size(), 2u);
  EXPECT_EQ(s.figures[0].id, "slab_coulomb");
  EXPECT_EQ(s.figures[1].id, "slab_creep");
  EXPECT_NE(s.figures[0].svg.find("<svg"), std::string::npos);
  EXPECT_FALSE(s.note.empty());
}

TEST(ReportValidity, RunsWithoutContactRowsAddNothing) {
  const Case c = block_case();
  ResultsFile results;
  CaseRuns cr;
  cr.case_name = c.name;
  RunResult empty;
  empty.engine_name = "reference";
  empty.status = RunStatus::ok;
  RunResult unsupported = run_of("outside");
  unsupported.status = RunStatus::unsupported;  // its rows are not read
  cr.runs = {empty, unsupported};
  results.cases = {cr};
  const ValiditySection s = validity_section({c}, results);
  EXPECT_TRUE(s.table.rows.empty());
  EXPECT_TRUE(s.readings.empty());
  EXPECT_TRUE(s.figures.empty());
  EXPECT_TRUE(s.note.empty());  // the report leaves the section out
}

}  // namespace
}  // namespace pb::internal
