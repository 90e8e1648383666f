// Tests for reports/src/report_versions.cpp: the MuJoCo 2.2.2 vs 3.3.8 table
// on constructed metrics, every count by hand.
#include "report_versions.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace pb::internal {
namespace {

struct Row {
  const char* engine;
  const char* name;
  double actual;
  int episode;
};

std::vector<MetricValue> metrics_of(const std::vector<Row>& rows) {
  std::vector<MetricValue> out;
  for (const Row& r : rows) {
    MetricValue m;
    m.case_name.assign("c");
    m.engine.assign(r.engine);
    m.against.assign("truth");
    m.metric.assign(r.name);
    m.episode = r.episode;
    m.actual = r.actual;
    out.push_back(std::move(m));
  }
  return out;
}

TEST(MujocoVersions, CountsTheSameFiguresAndNamesTheLargestChange) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<MetricValue> metrics = metrics_of({
      {"mujoco", "restitution", 0.8575, -1}, {"mujoco3", "restitution", 0.8575, -1},
      // rounding on both sides: the same figure whatever its relative change
      {"mujoco", "cone_violation", 2.3e-16, -1}, {"mujoco3", "cone_violation", 2.0e-16, -1},
      // neither has it (a missing episode): the same
      {"mujoco", "impulse", nan, 0}, {"mujoco3", "impulse", nan, 0},
      // a change: 0.3656 -> 0.01148
      {"mujoco", "velocity_max", 0.3656, -1}, {"mujoco3", "velocity_max", 0.01148, -1},
      // a cost is no physics: left out
      {"mujoco", "wall_per_sim_s", 0.02, -1}, {"mujoco3", "wall_per_sim_s", 0.35, -1},
      // one engine only: not compared
      {"mujoco", "peak_force", 500.0, -1}, {"box2d", "peak_force", 400.0, -1}});
  const Table t = mujoco_versions_table(metrics, {});
  ASSERT_EQ(t.rows.size(), 1u);
  EXPECT_EQ(t.rows[0][0], "c");
  EXPECT_EQ(t.rows[0][1], "4");  // restitution, cone_violation, impulse, velocity_max
  EXPECT_EQ(t.rows[0][2], "3");
  EXPECT_NE(t.rows[0][3].find("velocity_max vs truth: 0.3656 -> 0.01148"), std::string::npos)
      << t.rows[0][3];
  EXPECT_EQ(t.rows[0][4], "none");
}

TEST(MujocoVersions, NoRowsWithoutBothEngines) {
  EXPECT_TRUE(
      mujoco_versions_table(metrics_of({{"mujoco", "restitution", 0.8, -1}}), {}).rows.empty());
}

}  // namespace
}  // namespace pb::internal
