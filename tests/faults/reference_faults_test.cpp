// Tests for the reference solver's progress guard (core/reference/src/
// reference_solver.cpp, issue 24): a run that cannot advance ends `diverged`
// with a reason, at once, instead of spinning at t = 0 for minutes (a speed
// of 1e308 m/s took 695 s to fail with the step limit alone; a spin of
// 1e20 rad/s ~5 min). Inputs a user can give: the case format allows them.
#include <gtest/gtest.h>

#include <string>

#include "fault_runs.hpp"

namespace pb {
namespace {

bool contains(const std::string& s, const std::string& what) { return s.find(what) != std::string::npos; }

// 1e308 m/s: steps of ~1e-300 s, or none at all, leave t where it was
TEST(ReferenceFaults, AHopelessSpeedEndsAtOnceNamingNoProgress) {
  const RunResult r = faults_test::run_shipped(
      "falling_ball", "reference", {{"bodies.ball.velocity", "[0.0, -1e308]"}});
  ASSERT_EQ(r.status, RunStatus::diverged) << r.reason;
  EXPECT_TRUE(contains(r.reason, "reference: no progress")) << r.reason;
  // the stall rule: 100 steps in a row that leave t unchanged (and not 2e8)
  EXPECT_LE(r.steps, 101) << r.reason;
}

// 1e20 rad/s: t advances, by ~5e-12 s a step: after one window of 1e5 steps
// the rate, ~2e11 steps per simulated second, is beyond the bound 1e8 (issue
// 35: the stiffest shipped contact takes 4e5), before the projection of the
// 2.5 s left (4.8e11 steps, beyond 100 x the limit) is even needed
TEST(ReferenceFaults, AHopelessSpinEndsAfterOneWindow) {
  const RunResult r = faults_test::run_shipped(
      "falling_ball", "reference", {{"bodies.ball.angular_velocity", "1e20"}});
  ASSERT_EQ(r.status, RunStatus::diverged) << r.reason;
  EXPECT_TRUE(contains(r.reason, "reference: too many steps per simulated second")) << r.reason;
  EXPECT_LE(r.steps, 100000) << r.reason;  // one window of the guard
}

// a fast launch away from the ground (1e3 m/s up: 500 m in 0.5 s, steps set
// by the error control, not stalled) still runs, ok
TEST(ReferenceFaults, AFastLaunchIsNotCalledNoProgress) {
  const RunResult r = faults_test::run_shipped(
      "falling_ball", "reference", {{"bodies.ball.velocity", "[0.0, 1e3]"}, {"duration", "0.5"}});
  EXPECT_FALSE(contains(r.reason, "no progress")) << r.reason;
  EXPECT_EQ(r.status, RunStatus::ok) << r.reason;
}

}  // namespace
}  // namespace pb
