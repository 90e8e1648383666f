// Tests for apps/sweep_error.cpp
//
// The fixture is a body moving along x(t) = t^2 (m, t in s) on an output grid
// of 0.1 s over 1 s. The truth samples it exactly. A "coarse" run steps every
// 0.2 s, so on the grid it repeats its last state (runner.hpp: a fixed-step
// engine stops at its last step not after the output time), and each of its
// states is off by a known integration error d = 1e-3 m. At its own steps the
// error is exactly d. Interpolating linearly between its steps instead adds,
// at each midpoint a + 0.1, the chord error of t^2 over [a, a + 0.2]:
//   (a^2 + (a + 0.2)^2) / 2 - (a + 0.1)^2 = 0.01 m,
// so an interpolated comparison reports 0.011 m.
#include "sweep_error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "planarbench/reports/metrics.hpp"

namespace {

constexpr double kInterval = 0.1;  // s, the output grid
constexpr double kOffset = 1e-3;   // m, the coarse run's integration error
constexpr int kSamples = 11;       // t = 0, 0.1, ..., 1 s

pb::Case grid_case() {
  pb::Case c;
  c.name = "parabola";
  c.duration_s = 1.0;
  c.output_interval_s = kInterval;
  return c;
}

// one body sampled at engine times time_of(k) on the grid k = 0..10
template <typename TimeOf>
pb::RunResult run_of(const std::string& engine, TimeOf time_of, double offset_m) {
  pb::RunResult r;
  r.engine_name = engine;
  r.body_names = {"ball"};
  pb::BodyTrajectory b;
  b.name = "ball";
  for (int k = 0; k < kSamples; ++k) {
    const double t = time_of(k);
    b.time_s.push_back(t);
    b.position_m.emplace_back(t * t + offset_m, 0.0);
    b.angle_rad.push_back(0.0);
    b.velocity_mps.emplace_back(2.0 * t, 0.0);
    b.angular_velocity_radps.push_back(0.0);
  }
  r.bodies.push_back(b);
  return r;
}

pb::RunResult truth() {
  return run_of(
      "analytic", [](int k) { return k * kInterval; }, 0.0);
}

// a step of 0.2 s: at grid k the engine is at its last step 0.2 * floor(k / 2)
pb::RunResult coarse() {
  return run_of(
      "engine", [](int k) { return 0.2 * (k / 2); }, kOffset);
}

// SPEC §4 position_max as the report computes it, interpolating
double interpolated_error(const pb::RunResult& run, const pb::RunResult& base) {
  for (const auto& m :
       pb::compare_runs(grid_case(), run, base, "truth", std::numeric_limits<double>::infinity())) {
    if (m.metric == "position_max") return m.error;
  }
  return std::nan("");
}

TEST(SweepError, CoarseStepIsComparedAtItsOwnStepsOnly) {
  // 1e-12 m: sums and squares of numbers below 1 in double precision
  EXPECT_NEAR(pb::cli::sweep_position_error(grid_case(), coarse(), truth()), kOffset, 1e-12);
  // the report's interpolated metric would add the 0.01 m chord error
  EXPECT_NEAR(interpolated_error(coarse(), truth()), kOffset + 0.01, 1e-12);
}

TEST(SweepError, StepOnTheGridIsComparedAtEverySample) {
  const auto fine = run_of(
      "engine", [](int k) { return k * kInterval; }, kOffset);
  EXPECT_EQ(pb::cli::samples_on_grid(grid_case(), fine), static_cast<std::size_t>(kSamples - 1));
  // 1e-12 m: the offset is added to exact grid positions; only rounding differs
  EXPECT_NEAR(pb::cli::sweep_position_error(grid_case(), fine, truth()), kOffset, 1e-12);
}

TEST(SweepError, SamplesOnGridCountsTheEngineStepsThatLandOnIt) {
  // k = 2, 4, 6, 8, 10 after t = 0
  EXPECT_EQ(pb::cli::samples_on_grid(grid_case(), coarse()), 5u);
}

TEST(SweepError, StepOffTheGridFallsBackToInterpolation) {
  // every sample 0.03 s early: no grid time is ever reached after t = 0
  const auto off = run_of(
      "engine", [](int k) { return k == 0 ? 0.0 : k * kInterval - 0.03; }, kOffset);
  EXPECT_EQ(pb::cli::samples_on_grid(grid_case(), off), 0u);
  const double e = pb::cli::sweep_position_error(grid_case(), off, truth());
  EXPECT_TRUE(std::isfinite(e));
  EXPECT_EQ(e, interpolated_error(off, truth()));
}

TEST(SweepError, NoErrorUnlessBothRunsAreOk) {
  auto bad = coarse();
  bad.status = pb::RunStatus::diverged;
  EXPECT_TRUE(std::isnan(pb::cli::sweep_position_error(grid_case(), bad, truth())));
  auto no_truth = truth();
  no_truth.status = pb::RunStatus::unsupported;
  EXPECT_TRUE(std::isnan(pb::cli::sweep_position_error(grid_case(), coarse(), no_truth)));
}

}  // namespace
