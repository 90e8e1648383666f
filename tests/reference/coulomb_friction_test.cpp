// Tests for core/reference/src/coulomb_friction.cpp, and the reference
// solver's friction (SPEC §7) on the shipped friction cases at its defaults,
// against closed forms written here (a rigid body on a line with Coulomb
// friction: Marion & Thornton, Classical Dynamics, §7-§12 style).
#include "planarbench/reference/coulomb_friction.hpp"

#include <gtest/gtest.h>

#include "planarbench/reference/contact_dynamics.hpp"

#include <cmath>
#include <string>

#include "planarbench/analytic/analytic_engine.hpp"
#include "planarbench/case_loader.hpp"
#include "planarbench/reference/reference_engine.hpp"
#include "planarbench/reference/reference_solver.hpp"
#include "planarbench/runner.hpp"

namespace pb {
namespace {

constexpr double kG = 9.8066;  // m/s^2, SPEC §2

Case load(const std::string& name) {
  return load_case(std::string(PB_CASES_DIR) + "/" + name + ".toml");
}

// ---- the stick solve -----------------------------------------------------------

// one free body (m = 2 kg, I = 0.5 kg m^2) at rest, one sticking row at
// r = (0, -0.5) from its centre along t = (1, 0): J M^-1 J^T = 1/m + r_y^2 / I
// = 0.5 + 0.5 = 1 kg^-1, so the force is -(a_free + beta v)
TEST(StickSolve, OneRowIsTheLoadOverTheEffectiveInverseMass) {
  Case c;
  Body ground;
  ground.name = "ground";
  ground.fixed = true;
  ground.shape = HalfPlane{};
  Body b;
  b.name = "b";
  b.shape = Circle{0.5};
  b.mass_kg = 2.0;
  b.inertia_kgm2 = 0.5;
  b.position_m = Vec2(0.0, 0.5);
  c.bodies = {ground, b};
  const PlanarModel model(c);
  Eigen::VectorXd q, u;
  model.initial_state(q, u);
  u[0] = 1e-3;  // a residual slip of 1 mm/s, damped at beta
  Eigen::VectorXd u_dot_free(3);
  u_dot_free << 3.0, -9.0, 0.0;  // a tangential pull of 3 m/s^2
  StickSolve solve(3, 1);
  std::vector<StickRow> rows = {
      StickRow{0, 1, Vec2(0.0, 0.0), Vec2(0.0, 0.0), Vec2(1.0, 0.0), u[0]}};
  std::vector<double> f;
  solve.solve(model, q, u, u_dot_free, rows, f);
  ASSERT_EQ(f.size(), 1u);
  // J M^-1 J^T = 1 kg^-1: f = -(3 + 100 x 1e-3) N; exact arithmetic on these numbers
  EXPECT_NEAR(f[0], -(3.0 + kStickRate_per_s * 1e-3), 1e-14);
}

// two rows on one body, at (-0.5, -0.5) and (0.5, -0.5) from its centre,
// both along t = (1, 0): both rows are J = (1, 0, 0.5) (v_x - omega r_y), so
// A = J M^-1 J^T = 1/m + 0.5^2 / I = 1 + 1.5 = 2.5 in every entry, singular;
// the solve must still stop both points: 2 + 2.5 (f_1 + f_2) = 0
TEST(StickSolve, TwoCoupledRowsHoldTheBodyTogether) {
  Case c;
  Body ground;
  ground.name = "ground";
  ground.fixed = true;
  ground.shape = HalfPlane{};
  Body b;
  b.name = "b";
  b.shape = Polygon{{Vec2(-0.5, -0.5), Vec2(0.5, -0.5), Vec2(0.5, 0.5), Vec2(-0.5, 0.5)}};
  b.mass_kg = 1.0;
  b.inertia_kgm2 = 1.0 / 6.0;
  b.position_m = Vec2(0.0, 0.5);
  c.bodies = {ground, b};
  const PlanarModel model(c);
  Eigen::VectorXd q, u;
  model.initial_state(q, u);
  Eigen::VectorXd u_dot_free(3);
  u_dot_free << 2.0, 0.0, 0.0;
  StickSolve solve(3, 2);
  std::vector<StickRow> rows = {
      StickRow{0, 1, Vec2(-0.5, 0.0), Vec2(-0.5, 0.0), Vec2(1.0, 0.0), 0.0},
      StickRow{0, 1, Vec2(0.5, 0.0), Vec2(0.5, 0.0), Vec2(1.0, 0.0), 0.0}};
  std::vector<double> f;
  solve.solve(model, q, u, u_dot_free, rows, f);
  ASSERT_EQ(f.size(), 2u);
  // f_1 + f_2 = -2 / 2.5 = -0.8 N (a few ulps of the factorisation)
  EXPECT_NEAR(f[0] + f[1], -0.8, 1e-12);
}

// ---- the reference at its defaults on the shipped cases -----------------------

// the case run as shipped: with its own [settings] (the disks' exact geometry)
RunResult run(const std::string& name) {
  const Case c = load(name);
  SettingsOverrides o;
  for (const auto& [key, text] : c.settings) o.set(key, text, SettingSource{c.source_path, 0});
  auto e = make_reference_engine();
  return run_engine(*e, c, o);
}

// the body's speed along the line (tangent t) at output sample k
double along_speed(const RunResult& r, std::size_t k, const Vec2& t) {
  return r.bodies.at(0).velocity_mps[k].dot(t);
}

// block_hold: tan(theta) = 0.9 mu, at rest: the contact point must not move
// more than 1e-6 m over the 1 s (issue 22); its centre may tilt about it
TEST(ReferenceFriction, HoldingBlockDriftsUnderAMicrometre) {
  const RunResult r = run("block_hold");
  ASSERT_EQ(r.status, RunStatus::ok) << r.reason;
  const double theta = std::atan(0.45);
  const Vec2 t(std::cos(theta), -std::sin(theta));
  const Vec2 n(std::sin(theta), std::cos(theta));
  const BodyTrajectory& b = r.bodies.at(0);
  double worst = 0.0;
  for (std::size_t k = 0; k < b.time_s.size(); ++k) {
    // the material point 0.02 m below the centre along -n at t = 0
    const double turn = b.angle_rad[k] - b.angle_rad[0];
    const Vec2 arm = -0.02 * n;
    const Vec2 rotated(std::cos(turn) * arm.x() - std::sin(turn) * arm.y(),
                       std::sin(turn) * arm.x() + std::cos(turn) * arm.y());
    const Vec2 p = b.position_m[k] + rotated - (b.position_m[0] + arm);
    worst = std::max(worst, std::abs(p.dot(t)));
  }
  EXPECT_LT(worst, 1e-6);
}

// disk_roll: mu = 0.3 >= tan(30 deg) / 3: a = (2/3) g sin(30 deg), omega = -v / R
TEST(ReferenceFriction, DiskRollsAtTwoThirdsGSinTheta) {
  const RunResult r = run("disk_roll");
  ASSERT_EQ(r.status, RunStatus::ok) << r.reason;
  const double th = std::acos(-1.0) / 6.0;
  const Vec2 t(std::cos(th), -std::sin(th));
  const std::size_t last = r.bodies.at(0).time_s.size() - 1;
  const double tl = r.bodies.at(0).time_s[last];
  // exact circle, rk45 rtol 1e-10: the velocity to ~1e-9 relative; 1e-4 is issue 22's band
  EXPECT_NEAR(along_speed(r, last, t), 2.0 / 3.0 * kG * std::sin(th) * tl,
              1e-4 * 2.0 / 3.0 * kG * std::sin(th) * tl);
  EXPECT_NEAR(r.bodies.at(0).angular_velocity_radps[last] * 0.25, -along_speed(r, last, t), 1e-8);
}

// disk_throw: slip ends at t* = v0 / (3 mu g), then it rolls at (2/3) v0
TEST(ReferenceFriction, ThrownDiskRollsAtTwoThirdsV0) {
  const RunResult r = run("disk_throw");
  ASSERT_EQ(r.status, RunStatus::ok) << r.reason;
  const BodyTrajectory& b = r.bodies.at(0);
  const double t_star = 3.0 / (3.0 * 0.3 * kG);
  // first sample with the contact point's slip below 1e-9 m/s: within one
  // output interval (1e-4 s) of t*, i.e. 0.03 % (issue 22: 0.5 %)
  double t_end = -1.0;
  for (std::size_t k = 0; k < b.time_s.size(); ++k) {
    if (std::abs(b.velocity_mps[k].x() + 0.25 * b.angular_velocity_radps[k]) <= 1e-9) {
      t_end = b.time_s[k];
      break;
    }
  }
  EXPECT_NEAR(t_end, t_star, 1e-4);
  EXPECT_NEAR(b.velocity_mps.back().x(), 2.0, 1e-4 * 2.0);
}

// the integrated friction dissipation equals the mechanical energy lost:
// m v0^2 / 6 = 1.5 J for the thrown disk (its normal motion rests, so friction
// is all that dissipates)
TEST(ReferenceFriction, DissipationIsTheEnergyLost) {
  const Case c = load("disk_throw");
  ReferenceSettings s;
  s.geometry = "exact";
  ReferenceSolver solver(c, s);
  const double e0 = solver.energy_j();
  solver.advance_to(1.0);
  // rk45 at rtol 1e-10 over ~100 steps: 1e-8 J of 4.5 J
  EXPECT_NEAR(solver.friction_dissipation_j(), 1.5, 1e-8);
  EXPECT_NEAR(e0 - solver.energy_j(), solver.friction_dissipation_j(), 1e-8);
  // its tangential impulse on the disk: m (2/3 v0 - v0) = -1 N s
  EXPECT_NEAR(solver.tangential_impulse_ns(0), -1.0, 1e-8);
}

// sliding_friction starts touching at zero penetration: the normal force
// oscillates and the disk slips and sticks by turns before it rolls for good.
// The closed form (core/analytic/tangential_motion.cpp, written from the rigid
// body's equations) and the reference (its rigid stick with located events)
// share no code: their trajectories must agree. Bound: rk45 at rtol 1e-10
// over ~800 steps, 800 x 1e-10 = 8e-8 of the ~2.3 m travelled (2e-7 m),
// the closed form's events bisected to the last bit: 1e-6 m
TEST(ReferenceFriction, StickSlipSequenceMatchesTheClosedForm) {
  const Case c = load("sliding_friction");
  SettingsOverrides o;
  for (const auto& [key, text] : c.settings) o.set(key, text, SettingSource{c.source_path, 0});
  auto ref = make_reference_engine();
  auto truth = make_analytic_engine();
  const RunResult a = run_engine(*ref, c, o);
  const RunResult b = run_engine(*truth, c, o);
  ASSERT_EQ(a.status, RunStatus::ok) << a.reason;
  ASSERT_EQ(b.status, RunStatus::ok) << b.reason;
  // the closed form has at least one slip, one stick and a final roll
  const auto& phases = b.mapping.at("friction").at("phases");
  ASSERT_GE(phases.size(), 3u);
  EXPECT_EQ(phases.back().at("kind"), "stick");
  double worst = 0.0;
  for (std::size_t k = 0; k < a.bodies.at(0).time_s.size(); ++k) {
    worst = std::max(worst, (a.bodies.at(0).position_m[k] - b.bodies.at(0).position_m[k]).norm());
  }
  EXPECT_LT(worst, 1e-6);
}

// a frictionless case keeps the state it always had, [q, u, J]; friction
// appends each pair's tangential impulse and dissipation
TEST(ReferenceFriction, StateGrowsOnlyWithFriction) {
  Case c = load("sliding_friction");
  const ContactDynamics with(c, GeometryMode::exact);
  EXPECT_EQ(with.state_size(), 2 * 3 + 3 * 1);
  c.contacts[0].friction = 0.0;
  const ContactDynamics without(c, GeometryMode::exact);
  EXPECT_EQ(without.state_size(), 2 * 3 + 1);
}

}  // namespace
}  // namespace pb
