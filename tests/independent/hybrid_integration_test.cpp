// Tests for core/independent/hybrid_integration.cpp: the independent truth's
// integration against closed forms (free flight, the analytic engine's
// closed forms) and conservation laws.
#include "hybrid_integration.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "planarbench/analytic/analytic_engine.hpp"
#include "planarbench/case_loader.hpp"
#include "planarbench/errors.hpp"

namespace pb::independent {
namespace {

constexpr double kG = 9.8066;  // m/s^2

Case load(const char* name) {
  return load_case(std::string(PB_CASES_DIR) + "/" + name + ".toml");
}

Body ground(double angle_rad) {
  Body g;
  g.name = "ground";
  g.shape = HalfPlane{};
  g.fixed = true;
  g.angle_rad = angle_rad;
  return g;
}

// an ellipse of ellipse_incline's size, thrown and spinning
Body ellipse(Vec2 at, Vec2 v, double w) {
  Body b;
  b.name = "ellipse";
  b.shape = Ellipse{0.3, 0.15};
  b.mass_kg = 1.0;
  b.inertia_kgm2 = (0.3 * 0.3 + 0.15 * 0.15) / 4.0;
  b.position_m = at;
  b.angle_rad = 0.3;
  b.velocity_mps = v;
  b.angular_velocity_radps = w;
  return b;
}

// Free flight has a closed form: x(t) = x0 + v0 t + g t^2 / 2, theta(t) =
// theta0 + w t. Dormand-Prince's 5th-order solution is exact for a
// polynomial of degree 2 in t, so what is left is rounding: at most one ulp of
// the O(10 m) coordinates per step, steps x 2e-15 m.
TEST(HybridIntegration, FreeFlightIsTheParabola) {
  Case c;
  c.name = "flight";
  c.bodies = {ellipse(Vec2(0.0, 2.0), Vec2(1.5, 3.0), 4.0)};
  HybridIntegration run(c, IntegrationSettings{});
  const double e0 = run.energy();
  std::vector<BodyState> s;
  for (const double t : {0.1, 0.5, 1.0}) {
    run.advance_to(t);
    run.body_states(s);
    const Vec2 x = Vec2(0.0, 2.0) + t * Vec2(1.5, 3.0) + 0.5 * t * t * Vec2(0.0, -kG);
    const double bound = static_cast<double>(run.steps()) * 2e-15;
    EXPECT_NEAR((s[0].position_m - x).norm(), 0.0, bound) << t;
    EXPECT_NEAR(s[0].angle_rad, 0.3 + 4.0 * t, bound) << t;
    // energy: O(10 J) terms, rounded: the same per-step bound times m g (10 J/m)
    EXPECT_NEAR(run.energy(), e0, 10.0 * bound) << t;
  }
  EXPECT_TRUE(run.episodes().empty());
}

// A frictionless undamped (Hertz) contact is conservative (F = -dV/dq with
// V = K delta^(n+1) / (n+1): the support point's force along the normal is
// the gradient by the envelope theorem), so a spinning ellipse bouncing on a
// 15 deg incline keeps its energy through the impact. The integration errs
// by at most its local tolerance per step, 1e-12 (abs) + 1e-12 x O(10) (rel)
// per state component, summed over the steps without cancellation and
// weighted by the energy's sensitivity (m |v| ~ 5 N s, m g ~ 10 N, I w ~ 0.1):
// steps x 1e-11 x 15 J.
TEST(HybridIntegration, HertzBounceConservesEnergy) {
  Case c;
  c.name = "hertz_bounce";
  c.bodies = {ground(-15.0 * std::numbers::pi / 180.0),
              ellipse(Vec2(0.0, 0.75), Vec2::Zero(), 4.0)};
  ContactPair p;
  p.name = "ground_ellipse";
  p.body_a = 0;
  p.body_b = 1;
  p.law = Hertz{1e6, 1.5, std::nullopt};
  c.contacts = {p};
  HybridIntegration run(c, IntegrationSettings{});
  const double e0 = run.energy();
  run.advance_to(0.8);
  const auto eps = run.episodes();
  ASSERT_GE(eps.size(), 1u);
  EXPECT_FALSE(std::isnan(eps[0].offset_time_s));
  const double bound = static_cast<double>(run.steps()) * 1e-11 * 15.0;
  EXPECT_NEAR(run.energy(), e0, bound);
  std::printf("Hertz bounce: %zu episodes, energy change %.3g J (bound %.3g J, %ld steps)\n",
              eps.size(), run.energy() - e0, bound, run.steps());
}

// A pendulum (pinned, written in its angle): energy constant over its swing,
// the pivot fixed by construction. Same bound as above with the pendulum's
// O(10 J) energy scale.
TEST(HybridIntegration, PendulumSwingConservesEnergyAndKeepsItsPivot) {
  Case c = load("pendulum_wall");
  c.contacts.clear();  // the swing alone
  HybridIntegration run(c, IntegrationSettings{});
  const double e0 = run.energy();
  std::vector<BodyState> s;
  for (const double t : {0.3, 0.9, 2.0}) {
    run.advance_to(t);
    run.body_states(s);
    EXPECT_NEAR(run.energy(), e0, static_cast<double>(run.steps()) * 1e-11 * 15.0) << t;
    // |centre - pivot| = 0.6 m: one rotation's rounding
    EXPECT_NEAR((s[1].position_m - c.joints[0].anchor_world_m).norm(), 0.6, 1e-15) << t;
  }
}

// The analytic engine's closed forms are code that shares nothing with this
// integration: falling_ball (a disk on a declined line, Kelvin-Voigt with the
// clamp: piecewise damped oscillator, events by root finding) must come out
// the same. Bound: this integration's local tolerance 1e-12 + 1e-12 |x|
// (|x| <= 8 in m, m/s) per step, summed over the steps: steps x 1e-11 in
// m, m/s and N s; the onset and offset times in s are that over the normal
// speed (>= 5 m/s): steps x 2e-12 s; restitution a speed ratio: steps x 1e-11
// / 5 m/s; the peak force (K ~ 1e4 N/m times the depth's error, plus the
// search's 1e-15 relative in t): steps x 1e-7 N.
TEST(HybridIntegration, FallingBallIsTheClosedForm) {
  const Case c = load("falling_ball");
  HybridIntegration run(c, IntegrationSettings{});
  auto truth = make_analytic_engine();
  truth->build(c, {});
  run.advance_to(c.duration_s);
  truth->advance_to(c.duration_s);
  const auto ei = run.episodes();
  const auto et = truth->episodes();
  ASSERT_EQ(ei.size(), et.size());
  const double n = static_cast<double>(run.steps());
  for (std::size_t k = 0; k < ei.size(); ++k) {
    EXPECT_NEAR(ei[k].onset_time_s, et[k].onset_time_s, n * 2e-12) << k;
    EXPECT_NEAR(ei[k].offset_time_s, et[k].offset_time_s, n * 2e-12) << k;
    EXPECT_NEAR(ei[k].restitution, et[k].restitution, n * 2e-12) << k;
    EXPECT_NEAR(ei[k].impulse_ns, et[k].impulse_ns, n * 1e-11) << k;
    EXPECT_NEAR(ei[k].peak_force_n, et[k].peak_force_n, n * 1e-7) << k;
    EXPECT_NEAR(ei[k].max_penetration_m, et[k].max_penetration_m, n * 1e-11) << k;
    std::printf(
        "falling_ball episode %zu: onset %.3g s, offset %.3g s, restitution %.3g, "
        "impulse %.3g N s, peak %.3g N off the closed form (%ld steps)\n",
        k, ei[k].onset_time_s - et[k].onset_time_s, ei[k].offset_time_s - et[k].offset_time_s,
        ei[k].restitution - et[k].restitution, ei[k].impulse_ns - et[k].impulse_ns,
        ei[k].peak_force_n - et[k].peak_force_n, run.steps());
  }
  std::vector<BodyState> si;
  std::vector<BodyState> st;
  run.body_states(si);
  truth->body_states(st);
  EXPECT_NEAR((si[1].position_m - st[1].position_m).norm(), 0.0, n * 1e-11);
}

// The pendulums up to their first contact have a closed form (elliptic
// integrals, the analytic engine): the independent truth, run from t = 0,
// agrees with it at the last output time before the touch, and its first
// onset is the closed form's touch (whose hand-over time the mapping gives).
// Bound: steps x 1e-11 as above in rad; the onset that over the touch's
// angular speed (>= 1 rad/s).
TEST(HybridIntegration, PendulumsAreTheClosedFormUpToTheTouch) {
  for (const char* name : {"dual_pendulum", "pendulum_wall"}) {
    const Case c = load(name);
    HybridIntegration run(c, IntegrationSettings{});
    auto truth = make_analytic_engine();
    truth->build(c, {});
    const double touch = truth->mapping().at("numerical_from_s").get<double>();
    const double before = std::floor(touch / c.output_interval_s) * c.output_interval_s;
    run.advance_to(before);
    truth->advance_to(before);
    std::vector<BodyState> si;
    std::vector<BodyState> st;
    run.body_states(si);
    truth->body_states(st);
    const double n = static_cast<double>(run.steps());
    for (std::size_t i = 0; i < c.bodies.size(); ++i) {
      EXPECT_NEAR(si[i].angle_rad, st[i].angle_rad, n * 1e-11) << name << " body " << i;
      EXPECT_NEAR((si[i].position_m - st[i].position_m).norm(), 0.0, n * 1e-11) << name;
    }
    run.advance_to(touch + 1e-6);
    const auto eps = run.episodes();
    ASSERT_EQ(eps.size(), 1u) << name;
    EXPECT_NEAR(eps[0].onset_time_s, touch, n * 1e-11) << name;
    std::printf("%s: angle %.3g rad before the touch, onset %.3g s off the closed form\n", name,
                si[0].angle_rad - st[0].angle_rad + si[1].angle_rad - st[1].angle_rad,
                eps[0].onset_time_s - touch);
  }
}

// A square landing flat brings two vertices to the line at once: more than
// the single-vertex contact this truth handles, so it stops with the reason.
TEST(HybridIntegration, SecondVertexOnTheLineIsAnError) {
  Case c;
  c.name = "flat_square";
  Body sq;
  sq.name = "square";
  sq.shape = Polygon{{Vec2(-0.1, -0.1), Vec2(0.1, -0.1), Vec2(0.1, 0.1), Vec2(-0.1, 0.1)}};
  sq.mass_kg = 1.0;
  sq.inertia_kgm2 = 1.0 * 0.04 / 6.0;
  sq.position_m = Vec2(0.0, 0.3);
  c.bodies = {ground(0.0), sq};
  ContactPair p;
  p.name = "ground_square";
  p.body_a = 0;
  p.body_b = 1;
  p.law = KelvinVoigt{1e4, 10.0, 0.0};
  c.contacts = {p};
  HybridIntegration run(c, IntegrationSettings{});
  try {
    run.advance_to(0.5);
    FAIL() << "no error";
  } catch (const EngineError& e) {
    EXPECT_NE(std::string(e.what()).find("second vertex"), std::string::npos) << e.what();
  }
}

TEST(HybridIntegration, TimeOnlyForward) {
  Case c;
  c.bodies = {ellipse(Vec2(0.0, 2.0), Vec2::Zero(), 0.0)};
  HybridIntegration run(c, IntegrationSettings{});
  run.advance_to(0.2);
  EXPECT_THROW(run.advance_to(0.1), EngineError);
}

}  // namespace
}  // namespace pb::independent
