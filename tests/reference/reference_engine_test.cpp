// Tests for core/reference/src/reference_engine.cpp: the engine interface.
#include "planarbench/reference/reference_engine.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "planarbench/analytic/analytic_engine.hpp"
#include "planarbench/case_loader.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/runner.hpp"

namespace pb {
namespace {

Case load(const std::string& name) {
  return load_case(std::string(PB_CASES_DIR) + "/" + name + ".toml");
}

SettingsOverrides with(std::initializer_list<std::pair<std::string, std::string>> kv) {
  SettingsOverrides o;
  for (const auto& [k, v] : kv) o.set(k, v, SettingSource{"test", 0});
  return o;
}

TEST(ReferenceEngine, NameVersionSettings) {
  auto e = make_reference_engine();
  EXPECT_EQ(e->name(), "reference");
  EXPECT_FALSE(e->version().empty());
  EXPECT_TRUE(e->settings().knows("reference.geometry"));
  EXPECT_TRUE(e->settings().knows("dt"));
  EXPECT_EQ(e->settings().engine(), "reference");
}

TEST(ReferenceEngine, SupportsEveryShippedCaseNatively) {
  for (const char* name : {"falling_ball", "dual_pendulum", "sliding", "falling_ball_paper",
                           "sliding_paper"}) {
    auto e = make_reference_engine();
    const Capability cap = e->supports(load(name));
    EXPECT_EQ(cap.support, Support::native) << name << ": " << cap.reason;
  }
}

TEST(ReferenceEngine, ExactGeometryRefusesPairsWithoutARoutine) {
  // two ellipses have no exact routine; outline points handle them
  Case c = load("dual_pendulum");
  c.bodies[1].shape = Ellipse{0.5, 0.3};
  auto e = make_reference_engine();
  EXPECT_EQ(e->supports(c).support, Support::native);
  e->settings().apply(with({{"geometry", "exact"}}));
  const Capability cap = e->supports(c);
  EXPECT_EQ(cap.support, Support::unsupported);
  EXPECT_NE(cap.reason.find("ellipse"), std::string::npos);
  EXPECT_THROW(e->build(c, with({{"geometry", "exact"}})), EngineError);
}

TEST(ReferenceEngine, RunsThroughTheRunner) {
  // the runner drives the engine onto the common grid; a short falling_ball
  Case c = load("falling_ball");
  c.duration_s = 0.8;
  auto e = make_reference_engine();
  const RunResult r = run_engine(*e, c, with({{"integrator", "paper"}, {"geometry", "exact"}}));
  ASSERT_EQ(r.status, RunStatus::ok) << r.reason;
  EXPECT_EQ(r.bodies.size(), 1u);  // the moving ball only
  EXPECT_EQ(r.bodies[0].time_s.size(), static_cast<std::size_t>(c.output_samples()));
  EXPECT_EQ(r.bodies[0].time_s.back(), c.output_time(c.output_samples() - 1));
  ASSERT_EQ(r.events.size(), 1u);
  EXPECT_FALSE(std::isnan(r.events[0].offset_time_s));
  // contact rows exist during the impact only, with a unit normal a -> b
  ASSERT_FALSE(r.contacts.empty());
  // rows sit on the output grid (falling_ball: output_interval = 1e-4 s), so
  // the first and last may lie up to one interval outside the episode; a unit
  // normal to 1e-12 (rounding of a normalisation, 1e-16, with margin)
  const double interval_s = 1e-4;  // cases/falling_ball.toml output_interval
  for (const auto& row : r.contacts) {
    EXPECT_GE(row.time_s, r.events[0].onset_time_s - interval_s);
    EXPECT_LE(row.time_s, r.events[0].offset_time_s + interval_s);
    EXPECT_NEAR(row.sample.normal.norm(), 1.0, 1e-12);
    EXPECT_GE(row.sample.force_n, 0.0);
  }
  EXPECT_EQ(r.settings.at("integrator"), "paper");
  EXPECT_EQ(r.mapping.at("contact_law").at("ground_ball"), "kelvin_voigt");
  EXPECT_EQ(r.extra.at("integrator"), "paper");
  EXPECT_EQ(r.extra.at("constraint_drift_m").get<double>(), 0.0);
  EXPECT_GT(r.steps, 0);
}

// issue 35: head_on's disks with Coulomb friction (mu 0.3) meet head on, so
// friction has nothing to do: the run takes the frictionless run's steps, not
// 4e6 (the slip direction flipped with the outline's normal at every step,
// each flip located as an event); its tangential impulse is rounding
TEST(ReferenceEngine, HeadOnWithFrictionTakesTheFrictionlessSteps) {
  Case c = load_case(PB_CASES_DIR "/head_on.toml");
  auto e = make_reference_engine();
  const RunResult plain = run_engine(*e, c, {});
  ASSERT_EQ(plain.status, RunStatus::ok) << plain.reason;
  c.contacts[0].friction = 0.3;
  auto f = make_reference_engine();
  const RunResult rough = run_engine(*f, c, {});
  ASSERT_EQ(rough.status, RunStatus::ok) << rough.reason;
  // 2x: the friction pair's extra events (press, stick) and their steps
  EXPECT_LE(rough.steps, 2 * plain.steps) << rough.steps << " vs " << plain.steps;
  // the disks keep moving along the x axis: no spin from a tangential impulse
  // (1e-12 rad/s: rounding of the contact's lever on the 3 N s impulse)
  for (const auto& b : rough.bodies) {
    EXPECT_NEAR(b.angular_velocity_radps.back(), 0.0, 1e-12) << b.name;
  }
}

TEST(ReferenceEngine, BodyStatesIncludeFixedBodies) {
  auto e = make_reference_engine();
  const Case c = load("sliding");
  e->build(c, with({{"geometry", "exact"}}));
  e->advance_to(0.01);
  std::vector<BodyState> s;
  e->body_states(s);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].position_m, c.bodies[0].position_m);
  EXPECT_EQ(s[0].angle_rad, c.bodies[0].angle_rad);  // a fixed body is copied, not integrated
  std::vector<ContactSample> cs;
  e->contacts(cs);
  ASSERT_EQ(cs.size(), 1u);  // touching from t = 0
  EXPECT_EQ(cs[0].body_a, 0);
  EXPECT_EQ(cs[0].body_b, 1);
  // an open episode has no offset yet
  ASSERT_EQ(e->episodes().size(), 1u);
  EXPECT_TRUE(std::isnan(e->episodes()[0].offset_time_s));
}

// The default outline search (detection=fast) against the brute force
// (detection=brute) over a whole run: falling_ball through its first impact
// (0.725 .. 0.757 s) and sliding pressed onto its incline for 0.1 s (1.6
// periods of its normal oscillation), both with the
// default rk45 at rtol 1e-10 and the 180-point outlines of the cases.
// Tolerance 1e-9 m: the two searches give the same contact geometry to
// 1e-12 (fast_outline_contact_test.cpp; on this machine to the last bit), so
// the trajectories can differ only through that difference amplified by the
// step-size control: a perturbation of 1e-12 m can at worst flip an
// accept/reject decision, after which both runs are still rk45 solutions
// within their global error, < 1e-9 m at rtol 1e-10 (README: within 1.4e-10 m
// of the converged state at t = 2 s). Observed on x86-64: 0 (identical runs).
TEST(ReferenceEngine, FastDetectionFollowsTheBruteForceOverWholeRuns) {
  for (const auto& [name, duration_s] : {std::pair<const char*, double>{"falling_ball", 0.8},
                                         std::pair<const char*, double>{"sliding", 0.1}}) {
    Case c = load(name);
    c.duration_s = duration_s;
    auto fast_engine = make_reference_engine();
    auto brute_engine = make_reference_engine();
    const RunResult fast = run_engine(*fast_engine, c, with({{"detection", "fast"}}));
    const RunResult brute = run_engine(*brute_engine, c, with({{"detection", "brute"}}));
    ASSERT_EQ(fast.status, RunStatus::ok) << fast.reason;
    ASSERT_EQ(brute.status, RunStatus::ok) << brute.reason;
    EXPECT_EQ(fast.extra.at("detection"), "fast");
    EXPECT_EQ(brute.extra.at("detection"), "brute");
    ASSERT_EQ(fast.bodies.size(), 1u);
    ASSERT_EQ(fast.bodies[0].position_m.size(), brute.bodies[0].position_m.size());
    double worst_m = 0.0;
    for (std::size_t k = 0; k < fast.bodies[0].position_m.size(); ++k) {
      worst_m = std::max(worst_m, (fast.bodies[0].position_m[k] - brute.bodies[0].position_m[k]).norm());
    }
    EXPECT_LE(worst_m, 1e-9) << name;
    // the run went through contact: one episode, the same in both
    ASSERT_EQ(fast.events.size(), 1u) << name;
    ASSERT_EQ(brute.events.size(), 1u) << name;
    EXPECT_NEAR(fast.events[0].onset_time_s, brute.events[0].onset_time_s, 1e-9) << name;
  }
}

// One force per pair (SPEC §1) on face contacts: the square of
// square_landing.toml lands flat and the arch of concave_arch.toml on its two
// feet; the penetration is symmetric about the centre of mass, so the law's
// force must act on the vertical through it and nothing turns. A line of
// action 1 mm off centre would turn the square at ~1 rad/s by the end of the
// first impact (300 N * 1e-3 m * 0.04 s / 0.01 kg m^2); the bound 1e-8 rad
// is 4x the worst observed over 1.2 s (outline points, 2.5e-9 rad: the
// rounding of a sampled face's depth-weighted centroid; exact: 4.5e-11 rad).
// Their bounces are the translating body's closed form (the analytic engine):
// restitution to 1e-6, the rk45 tolerance's effect on an event's velocities.
TEST(ReferenceEngine, FaceContactsLandFlatWithTheClosedFormBounce) {
  for (const char* name : {"square_landing", "concave_arch"}) {
    const Case c = load(name);
    auto truth_engine = make_analytic_engine();
    const RunResult truth = run_engine(*truth_engine, c, SettingsOverrides{});
    ASSERT_EQ(truth.status, RunStatus::ok) << truth.reason;
    ASSERT_GE(truth.events.size(), 2u) << name;
    for (const char* geometry : {"exact", "outline"}) {
      auto e = make_reference_engine();
      const RunResult r = run_engine(*e, c, with({{"geometry", geometry}}));
      ASSERT_EQ(r.status, RunStatus::ok) << name << " " << geometry << ": " << r.reason;
      ASSERT_EQ(r.bodies.size(), 1u);
      double worst_rad = 0.0;
      for (const double a : r.bodies[0].angle_rad) worst_rad = std::max(worst_rad, std::abs(a));
      EXPECT_LT(worst_rad, 1e-8) << name << " " << geometry;
      ASSERT_EQ(r.events.size(), truth.events.size()) << name << " " << geometry;
      for (std::size_t k = 0; k < r.events.size(); ++k) {
        EXPECT_NEAR(r.events[k].restitution, truth.events[k].restitution, 1e-6)
            << name << " " << geometry << " episode " << k;
      }
    }
  }
}

TEST(ReferenceEngine, AdvanceBeforeBuildIsAnEngineError) {
  auto e = make_reference_engine();
  EXPECT_THROW(e->advance_to(1.0), EngineError);
}

// Issue 15: a state the geometry cannot represent is `diverged` with the
// reason, never `ok`. Dropped at 1e4 m/s the ball's centre goes under the
// ground line within the first contact (the Kelvin-Voigt truth's maximum
// depth is v / omega = 8660 / 100 = 87 m against a 0.5 m radius); on sliding
// at 3 s the disk has slid g sin45 t^2 / 2 = 31 m, past the 20 m segment of
// outline points that represents the ground (extent 20 m, centred on 0).
TEST(ReferenceEngine, StatesPastTheGeometryAreDivergedWithTheReason) {
  Case fast = load("falling_ball");
  fast.bodies[1].velocity_mps = Vec2(0.0, -1e4);
  auto e = make_reference_engine();
  const RunResult r = run_engine(*e, fast, SettingsOverrides{});
  EXPECT_EQ(r.status, RunStatus::diverged);
  EXPECT_NE(r.reason.find("penetration beyond what the geometry represents"), std::string::npos)
      << r.reason;
  EXPECT_NE(r.reason.find("'ball'"), std::string::npos) << r.reason;
  EXPECT_LT(r.diverged_at_s, 0.01) << "within the first contact";

  Case slide = load("sliding");
  slide.duration_s = 3.0;
  auto e2 = make_reference_engine();
  const RunResult r2 = run_engine(*e2, slide, SettingsOverrides{});
  EXPECT_EQ(r2.status, RunStatus::diverged);
  EXPECT_NE(r2.reason.find("past the end of the 20 m segment"), std::string::npos) << r2.reason;
  // 10 m along the slope (half the segment) is reached at sqrt(2 10 / (g sin45)) = 1.70 s
  EXPECT_GT(r2.diverged_at_s, 1.7);
}

}  // namespace
}  // namespace pb
