// Tests for the momentum_drift self metric of reports/src/metrics.cpp
//
// head_on.toml has two free disks (1 kg and 2 kg) touching only each other
// and no gravity: total momentum P = 1 * 2 + 2 * (-0.5) = 1 kg m/s is exact.
// A synthetic run that trades momentum between the disks exactly has no
// drift; one sample with 1e-3 m/s added to the 2 kg disk has 2e-3 kg m/s,
// i.e. 2e-3 of |P(0)|. falling_ball's ball touches the fixed ground: no
// momentum metric at all.
#include <gtest/gtest.h>

#include <filesystem>

#include <string>

#include "planarbench/case_loader.hpp"
#include "planarbench/reports/metrics.hpp"

namespace pb {
namespace {

Case head_on() { return load_case(std::string(PB_CASES_DIR) + "/head_on.toml"); }

// the disks exchange momentum q(t) = 3 t (kg m/s) at every output sample
RunResult exchanging_run(const Case& c, double kick_mps, int kick_sample) {
  RunResult r;
  r.case_name = c.name;
  r.engine_name = "mujoco";
  r.body_names = {"left", "right"};
  BodyTrajectory left, right;
  left.name = "left";
  right.name = "right";
  for (int k = 0; k < c.output_samples(); ++k) {
    const double t = c.output_time(k);
    const double q = 3.0 * t;  // kg m/s from left to right
    for (auto* b : {&left, &right}) {
      b->time_s.push_back(t);
      b->angle_rad.push_back(0.0);
      b->angular_velocity_radps.push_back(0.0);
    }
    left.position_m.emplace_back(-0.5 + 2.0 * t, 0.0);
    right.position_m.emplace_back(0.5 - 0.5 * t, 0.0);
    left.velocity_mps.emplace_back(2.0 - q / 1.0, 0.0);
    right.velocity_mps.emplace_back(-0.5 + q / 2.0 + (k == kick_sample ? kick_mps : 0.0), 0.0);
  }
  r.bodies = {left, right};
  return r;
}

const MetricValue* find(const std::vector<MetricValue>& ms, const std::string& name) {
  for (const auto& m : ms) {
    if (m.metric == name) return &m;
  }
  return nullptr;
}

TEST(MomentumDrift, ExactExchangeHasNone) {
  const Case c = head_on();
  const auto ms = self_metrics(c, exchanging_run(c, 0.0, -1));
  const MetricValue* m = find(ms, "momentum_drift");
  ASSERT_NE(m, nullptr);
  // q / 1 and q / 2 * 2 round differently: a few ulp of the 2 kg m/s terms
  EXPECT_LT(m->actual, 1e-14);
}

TEST(MomentumDrift, OneKickIsSeenRelativeToTheInitialMomentum) {
  const Case c = head_on();
  const auto ms = self_metrics(c, exchanging_run(c, 1e-3, 1234));
  const MetricValue* m = find(ms, "momentum_drift");
  ASSERT_NE(m, nullptr);
  // 2 kg * 1e-3 m/s over |P(0)| = 1 kg m/s
  EXPECT_NEAR(m->actual, 2e-3, 1e-12);
}

TEST(MomentumDrift, NotForBodiesTouchingTheGround) {
  const Case c = load_case(std::filesystem::path(PB_CASES_DIR) / "falling_ball.toml");
  RunResult r;
  r.case_name = c.name;
  r.engine_name = "mujoco";
  r.body_names = {"ground", "ball"};
  BodyTrajectory b;
  b.name = "ball";
  for (int k = 0; k < 10; ++k) {
    b.time_s.push_back(c.output_time(k));
    b.position_m.emplace_back(0.0, 1.0);
    b.angle_rad.push_back(0.0);
    b.velocity_mps.emplace_back(0.0, 0.0);
    b.angular_velocity_radps.push_back(0.0);
  }
  r.bodies = {b};
  EXPECT_EQ(find(self_metrics(c, r), "momentum_drift"), nullptr);
}

}  // namespace
}  // namespace pb
