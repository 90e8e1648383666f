// Tests for reports/src/friction_metrics.cpp
//
// The truth is the analytic engine's run of the shipped case; the run under
// test is that truth with a known disturbance added here (a creep, an
// acceleration error, a delay), so each metric's value is known from the
// disturbance alone, not from the code under test.
#include "planarbench/reports/friction_metrics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "planarbench/analytic/analytic_engine.hpp"
#include "planarbench/case_loader.hpp"
#include "planarbench/runner.hpp"

namespace pb {
namespace {

Case load(const std::string& name) {
  return load_case(std::string(PB_CASES_DIR) + "/" + name + ".toml");
}

RunResult truth_of(const Case& c) {
  auto e = make_analytic_engine();
  return run_engine(*e, c, {});
}

// the line's unit tangent (the ground's body x axis)
Vec2 tangent_of(const Case& c) {
  const double a = c.bodies.at(0).angle_rad;
  return {std::cos(a), std::sin(a)};
}

const MetricValue* find(const std::vector<MetricValue>& ms, const std::string& name) {
  for (const auto& m : ms) {
    if (m.metric == name) return &m;
  }
  return nullptr;
}

// block_hold: a run that creeps down the incline at v = 2e-6 m/s from t = 0
// drifts v t: hold_drift = v T (T = 1 s), creep = v
TEST(FrictionMetrics, HoldDriftAndCreepOfACreepingRun) {
  const Case c = load("block_hold");
  const RunResult truth = truth_of(c);
  RunResult run = truth;
  run.engine_name = "mujoco";
  const Vec2 t = tangent_of(c);
  const double v = 2e-6;  // m/s
  BodyTrajectory& b = run.bodies.at(0);
  for (std::size_t k = 0; k < b.time_s.size(); ++k) {
    b.position_m[k] += v * b.time_s[k] * t;
    b.velocity_mps[k] += v * t;
  }
  const auto ms = friction_metrics(c, run, truth);
  const MetricValue* drift = find(ms, "hold_drift_m");
  const MetricValue* creep = find(ms, "creep_speed_mps");
  ASSERT_NE(drift, nullptr);
  ASSERT_NE(creep, nullptr);
  // the truth's own position is exact to rounding (1e-19 m): 1e-15 of slack
  EXPECT_NEAR(drift->actual, v * 1.0, 1e-15);
  EXPECT_NEAR(creep->actual, v, 1e-15);
  EXPECT_NEAR(drift->desired, 0.0, 1e-15);
  // no slide, stop, slip or impact in a hold
  EXPECT_EQ(find(ms, "slide_acceleration_mps2"), nullptr);
  EXPECT_EQ(find(ms, "stop_time_s"), nullptr);
  EXPECT_EQ(find(ms, "tangential_impulse_ns"), nullptr);
}

// block_slide: a run sliding 1 % faster than the truth (w scaled by 1.01)
// has a fitted acceleration 1 % above the truth's
TEST(FrictionMetrics, SlideAccelerationOfAFasterRun) {
  const Case c = load("block_slide");
  const RunResult truth = truth_of(c);
  RunResult run = truth;
  run.engine_name = "ode";
  for (auto& v : run.bodies.at(0).velocity_mps) v *= 1.01;
  const auto ms = friction_metrics(c, run, truth);
  const MetricValue* a = find(ms, "slide_acceleration_mps2");
  ASSERT_NE(a, nullptr);
  // the truth: g (sin(theta) - mu cos(theta)), theta = atan(0.55), mu = 0.5
  const double th = std::atan(0.55);
  const double closed = 9.8066 * (std::sin(th) - 0.5 * std::cos(th));
  // a least-squares slope of an exactly linear speed: rounding only
  EXPECT_NEAR(a->desired, closed, 1e-12);
  EXPECT_NEAR(a->error, 0.01, 1e-10);
}

// block_stop: a run 1 ms late in everything (its samples are the truth's one
// millisecond earlier, the first millisecond held at the start) stops 1 ms later
// and as far
TEST(FrictionMetrics, StopTimeAndDistanceOfALateRun) {
  const Case c = load("block_stop");
  const RunResult truth = truth_of(c);
  RunResult run = truth;
  run.engine_name = "box2d";
  BodyTrajectory& b = run.bodies.at(0);
  const BodyTrajectory& tb = truth.bodies.at(0);
  const std::size_t lag = 10;  // samples of 1e-4 s
  for (std::size_t k = 0; k < b.time_s.size(); ++k) {
    const std::size_t j = k >= lag ? k - lag : 0;
    b.position_m[k] = tb.position_m[j];
    b.velocity_mps[k] = tb.velocity_mps[j];
  }
  const auto ms = friction_metrics(c, run, truth);
  const MetricValue* t_stop = find(ms, "stop_time_s");
  const MetricValue* d_stop = find(ms, "stop_distance_m");
  ASSERT_NE(t_stop, nullptr);
  ASSERT_NE(d_stop, nullptr);
  // the truth stops at v0 / (mu g); read where w falls to 1e-3 v0, which is
  // (1 - 1e-3) of it on a linear deceleration
  EXPECT_NEAR(t_stop->desired, (1.0 - 1e-3) * 2.0 / (0.4 * 9.8066), 1e-12);
  EXPECT_NEAR(t_stop->actual - t_stop->desired, 1e-3, 1e-12);
  EXPECT_NEAR(d_stop->actual, d_stop->desired, 1e-12);
}

// disk_throw: slip end and roll speed read alike on a run and its truth
TEST(FrictionMetrics, SlipEndOfTheTruthIsItsClosedForm) {
  const Case c = load("disk_throw");
  const RunResult truth = truth_of(c);
  const auto ms = friction_metrics(c, truth, truth);
  const MetricValue* t_end = find(ms, "slip_end_time_s");
  const MetricValue* v_roll = find(ms, "roll_speed_mps");
  ASSERT_NE(t_end, nullptr);
  ASSERT_NE(v_roll, nullptr);
  // read where the slip falls to 1e-3 of v0 = 3 m/s: on its linear decrease
  // 3 mu g t from 3 m/s, at (1 - 1e-3) t*, t* = v0 / (3 mu g); the centre
  // then moves at v0 - mu g t = 2 + 1e-3 (m/s)
  const double t_star = 3.0 / (3.0 * 0.3 * 9.8066);
  EXPECT_NEAR(t_end->desired, (1.0 - 1e-3) * t_star, 1e-12);
  EXPECT_NEAR(v_roll->desired, 2.0 + 1e-3, 1e-12);
  // friction dissipated a third of m v0^2 / 2 = 4.5 J
  const MetricValue* w = find(ms, "friction_dissipation_j");
  ASSERT_NE(w, nullptr);
  EXPECT_NEAR(w->desired, 1.5, 1e-12);
}

// disk_oblique_roll: a run whose post-impact spin is 10 % low has a tangential
// impulse unchanged (the centre's speed kept) and a spin error of 10 %
TEST(FrictionMetrics, ImpactImpulseAndSpin) {
  const Case c = load("disk_oblique_roll");
  const RunResult truth = truth_of(c);
  RunResult run = truth;
  run.engine_name = "mujoco";
  for (auto& w : run.bodies.at(0).angular_velocity_radps) w *= 0.9;
  const auto ms = friction_metrics(c, run, truth);
  const MetricValue* jt = find(ms, "tangential_impulse_ns");
  const MetricValue* spin = find(ms, "post_impact_spin_radps");
  ASSERT_NE(jt, nullptr);
  ASSERT_NE(spin, nullptr);
  // the closed form: the slip stops inside the contact, m_t v_c0 = (m / 3) 1 m/s
  EXPECT_NEAR(jt->desired, -1.0 / 3.0, 1e-12);
  EXPECT_NEAR(jt->error, 0.0, 1e-12);
  EXPECT_NEAR(spin->error, 0.1, 1e-12);
  EXPECT_EQ(jt->episode, 0);
}

// a frictionless case has no friction metrics
TEST(FrictionMetrics, NoneWithoutFriction) {
  const Case c = load("sliding");
  const RunResult truth = truth_of(c);
  EXPECT_TRUE(friction_metrics(c, truth, truth).empty());
}

// the campaign's steady slide: the truth's slope over the second half
TEST(FrictionMetrics, SteadySlideAccelerationWithoutATruth) {
  const Case c = load("disk_slip");
  const RunResult truth = truth_of(c);
  const double th = std::acos(-1.0) / 6.0;
  EXPECT_NEAR(steady_slide_acceleration_mps2(c, truth),
              9.8066 * (std::sin(th) - 0.1 * std::cos(th)), 1e-12);
}

}  // namespace
}  // namespace pb
