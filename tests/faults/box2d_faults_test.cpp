// Tests for adapters/box2d/box2d_faults.cpp: inputs that would trip one of
// Box2D's asserts (kept in Debian's libbox2d: b2Assert is assert) are refused
// with an EngineError naming the body, so the process does not abort; a
// runaway is caught at Box2D's per-step clamps (b2_maxTranslation = 2 m,
// b2_maxRotation = pi/2), where it would otherwise look like a body leaving
// the scene at 2 m per step.
#include <gtest/gtest.h>

#include <cmath>

#include "fault_runs.hpp"

namespace pb {
namespace {

using faults_test::run_shipped;

// Each of these inputs aborted the process before (measured with
// libbox2d 2.4.1: "b2Body::b2Body: Assertion `bd->linearVelocity.IsValid()'
// failed", "b2Body::SetMassData: Assertion `m_I > 0.0f' failed" when 1e39
// kg becomes inf in float), or ran a body Box2D cannot represent; now each is
// a diverged run at t = 0 with the reason.
TEST(Box2dFaults, InputsBox2dCannotTakeAreRefused) {
  const struct {
    faults_test::Sets sets;
    const char* names;
  } refused[] = {
      {{{"bodies.ball.mass", "1e39"}}, "mass 1e+39 kg"},
      {{{"bodies.ball.mass", "1e-39"}}, "normal floats"},
      {{{"bodies.ball.velocity", "[1e39, 0.0]"}}, "initial speed 1e+39 m/s"},
      // a speed whose square overflows double is still said as written (issue 24: was "inf")
      {{{"bodies.ball.velocity", "[1e308, 0.0]"}}, "initial speed 1e+308 m/s covers 1e+304 m"},
      {{{"bodies.ball.velocity", "[1.5e308, -1.5e308]"}}, "initial velocity (1.5e+308, -1.5e+308) m/s"},
      {{{"bodies.ball.angular_velocity", "1e5"}}, "b2_maxRotation"},
      // 1e5 m/s^2 moves a body 10 m in a 0.01 s step
      {{{"gravity", "[0.0, -1e5]"}, {"dt", "1e-2"}}, "gravity 1e+05 m/s^2"},
  };
  for (const auto& x : refused) {
    faults_test::Sets sets = x.sets;
    sets.emplace_back("duration", "0.1");
    const RunResult r = run_shipped("falling_ball", "box2d", sets);
    EXPECT_EQ(r.status, RunStatus::diverged) << x.names;
    EXPECT_NE(r.reason.find("box2d: refused"), std::string::npos) << r.reason;
    EXPECT_NE(r.reason.find(x.names), std::string::npos) << r.reason;
    EXPECT_EQ(r.steps, 0) << x.names;
  }
}

// falling_ball with the case's law applied by the adapter (box2d.mode=inject)
// at K = 1e12 N/m: at the first step in contact (delta ~ v h = 7e-4 m) the
// force K delta = 7e8 N would change the 1 kg ball's speed by F h / m = 7e4
// m/s, 7 m in one step: beyond b2_maxTranslation. The adapter stops before
// the step (t = 0.72501 s in closed form, the case's header) rather than let
// Box2D clamp it.
TEST(Box2dFaults, ExplicitStiffForceIsStoppedBeforeBox2dClampsIt) {
  const faults_test::Sets sets = {
      {"box2d.mode", "inject"}, {"contact.stiffness", "1e12"}, {"duration", "0.8"}};
  const RunResult r = run_shipped("falling_ball", "box2d", sets);
  ASSERT_EQ(r.status, RunStatus::diverged) << r.reason;
  EXPECT_NE(r.reason.find("body 'ball' diverged"), std::string::npos) << r.reason;
  EXPECT_NE(r.reason.find("b2_maxTranslation"), std::string::npos) << r.reason;
  // 2e-4 s: the onset resolved to one step plus Euler's lead (5e-5 s)
  EXPECT_NEAR(r.diverged_at_s, 0.72501, 2e-4);
}

// A disk falling from rest at dt = 0.01 s reaches |v| h = 2 m per step, where
// Box2D clamps, when n h g h > 2 m: n > 2 / (g h^2) = 2039.4, i.e. at step
// 2040, t = 20.40 s. The run is diverged there, naming the clamp: a speed this
// step cannot carry, which Box2D would silently cap at 200 m/s.
TEST(Box2dFaults, VelocityAtTheClampIsDivergedWhereFreeFallReachesIt) {
  Case c;
  c.name = "long_fall";
  c.duration_s = 30.0;
  c.output_interval_s = 0.01;
  Body disk;
  disk.name = "disk";
  disk.shape = Circle{0.5};
  disk.mass_kg = 1.0;
  disk.inertia_kgm2 = 0.125;
  c.bodies = {disk};
  auto e = make_engine("box2d");
  const RunResult r = run_engine(*e, c, faults_test::engine_keys({{"dt", "1e-2"}}));
  ASSERT_EQ(r.status, RunStatus::diverged) << r.reason;
  EXPECT_NE(r.reason.find("clamped its translation"), std::string::npos) << r.reason;
  // 0.02 s: two steps; Box2D sums g h in float (relative 6e-8 per step, 1e-4 in all)
  EXPECT_NEAR(r.diverged_at_s, 2040 * 0.01, 0.02);
}

// issue 35: disk_backspin spun at 1e4 rad/s with mu 10 rolls off the end of
// Box2D's ground box (the case's half-plane has none) and falls; its centre
// ends 2.46 m below the ground. A body cannot be inside a half-plane it
// touches: the run is diverged, naming body, half-plane and depth, at the
// first sample past the surface
TEST(Box2dFaults, ABodyBelowTheHalfPlaneItTouchesIsDiverged) {
  const RunResult r = faults_test::run_shipped(
      "disk_backspin", "box2d",
      {{"bodies.disk.angular_velocity", "1e4"}, {"contact.friction", "10"}});
  ASSERT_EQ(r.status, RunStatus::diverged) << r.reason;
  EXPECT_NE(r.reason.find("the centre of mass of body 'disk' is"), std::string::npos) << r.reason;
  EXPECT_NE(r.reason.find("below half-plane 'ground'"), std::string::npos) << r.reason;
  // the shipped case as it is stays ok
  EXPECT_EQ(faults_test::run_shipped("disk_backspin", "box2d", {}).status, RunStatus::ok);
}

}  // namespace
}  // namespace pb
