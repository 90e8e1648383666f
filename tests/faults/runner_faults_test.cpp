// Tests for core/src/runner.cpp: its fault checks (non-finite state, energy
// runaway, an engine's EngineError), with scripted engines defined here whose
// motions are closed forms: passive ones the runner must leave alone, and a
// runaway whose detection time follows from its formula.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

#include "planarbench/energy_budget.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/runner.hpp"

namespace pb {
namespace {

constexpr double kG = 9.8066;  // m/s^2

// One moving body (index 1) whose state is a closed form of t, stepped at
// 1e-3 s; reports `initial_contacts` at t = 0 and throws EngineError once its
// time reaches fail_at_s.
class ScriptedEngine final : public Engine {
 public:
  using Motion = std::function<BodyState(double t_s)>;
  explicit ScriptedEngine(Motion motion, std::vector<ContactSample> initial_contacts = {},
                          double fail_at_s = std::numeric_limits<double>::infinity())
      : motion_(std::move(motion)), initial_(std::move(initial_contacts)), fail_at_s_(fail_at_s) {}

  std::string name() const override { return "scripted"; }
  std::string version() const override { return "test"; }
  Physics physics() const override { return Physics{"test", "test", "", "test", "", "", false}; }
  Capability supports(const Case&) const override { return {Support::native, ""}; }
  const SettingsBinder& settings() const override { return binder_; }
  void build(const Case& c, const SettingsOverrides&) override { bodies_ = c.bodies.size(); }
  void advance_to(double t) override {
    while (static_cast<double>(steps_ + 1) * kStep <= t + 1e-9 * kStep) {
      ++steps_;
      if (time() >= fail_at_s_) throw EngineError("scripted: the solver gave up");
    }
  }
  double time() const override { return static_cast<double>(steps_) * kStep; }
  void body_states(std::vector<BodyState>& out) const override {
    out.assign(bodies_, BodyState{});
    out[1] = motion_(time());
  }
  void contacts(std::vector<ContactSample>& out) const override {
    out.clear();
    if (steps_ == 0) out = initial_;
  }
  std::vector<ContactEpisode> episodes() const override { return {}; }
  long steps() const override { return steps_; }
  nlohmann::json mapping() const override { return nlohmann::json::object(); }

 private:
  static constexpr double kStep = 1e-3;  // s
  Motion motion_;
  std::vector<ContactSample> initial_;
  double fail_at_s_;
  SettingsBinder binder_{"scripted"};
  std::size_t bodies_ = 0;
  long steps_ = 0;
};

// a fixed ground and a 1 kg disk (I = 0.125 kg m^2), sampled every 0.01 s
Case disk_case(const Vec2& gravity_mps2, double duration_s) {
  Case c;
  c.name = "scripted_case";
  c.gravity_mps2 = gravity_mps2;
  c.duration_s = duration_s;
  c.output_interval_s = 0.01;
  Body ground;
  ground.name = "ground";
  ground.fixed = true;
  ground.shape = HalfPlane{};
  Body disk;
  disk.name = "disk";
  disk.shape = Circle{0.5};
  disk.mass_kg = 1.0;
  disk.inertia_kgm2 = 0.125;
  disk.position_m = Vec2(0.0, 2.0);
  c.bodies = {ground, disk};
  ContactPair p;
  p.name = "ground_disk";
  p.body_a = 0;
  p.body_b = 1;
  p.law = KelvinVoigt{1e4, 10.0, 0.0};
  c.contacts = {p};
  return c;
}

// A ball dropped from 2 m bouncing elastically off y = 0 forever: period
// T = 2 sqrt(2 h / g), y = h - g s^2 / 2 with s the time from the last apex.
// Energy is conserved exactly, so the kinetic energy never exceeds the work
// gravity has done: the run is ok.
TEST(RunnerFaults, ElasticBouncingIsNotARunaway) {
  const Case c = disk_case(Vec2(0.0, -kG), 3.0);
  const double h = 2.0;                         // m, apex height
  const double half = std::sqrt(2.0 * h / kG);  // s, apex to floor
  ScriptedEngine e([=](double t) {
    // time from the nearest apex, in [-half, half]
    const double s = std::remainder(t, 2.0 * half);
    BodyState b;
    b.position_m = Vec2(0.0, h - 0.5 * kG * s * s);
    b.velocity_mps = Vec2(0.0, -kG * s);
    return b;
  });
  const RunResult r = run_engine(e, c, {});
  EXPECT_EQ(r.status, RunStatus::ok) << r.reason;
  EXPECT_EQ(r.bodies.at(0).time_s.size(), 301u);  // every sample of 3 s kept
}

// A disk whose speed doubles every 0.1 s without gravity, v = 2^(t / 0.1)
// m/s: its kinetic energy is 4^(t / 0.1) times the initial one and passes 10
// times at t = 0.1 log 10 / log 4 = 0.1661 s; the first sample after that is
// 0.17 s, where the run stops as diverged, keeping the 17 samples before.
TEST(RunnerFaults, ExponentialEnergyGrowthIsARunawayAtItsClosedFormTime) {
  const Case c = disk_case(Vec2::Zero(), 1.0);
  ScriptedEngine e([](double t) {
    BodyState b;
    const double rate = std::log(2.0) / 0.1;  // 1/s
    b.position_m = Vec2((std::exp(rate * t) - 1.0) / rate, 2.0);
    b.velocity_mps = Vec2(std::exp(rate * t), 0.0);
    return b;
  });
  const RunResult r = run_engine(e, c, {});
  ASSERT_EQ(r.status, RunStatus::diverged);
  // 1e-9 s: the grid time 0.17 s up to the summed steps' rounding; a sample
  // early (0.16 s, ratio 9.19) or late (0.18 s) fails
  EXPECT_NEAR(r.diverged_at_s, 0.17, 1e-9);
  EXPECT_NE(r.reason.find("energy runaway at t = 0.17 s"), std::string::npos) << r.reason;
  // 4^1.7 = 10.56 times the 0.5 J it started with
  EXPECT_NE(r.reason.find("10.56 times"), std::string::npos) << r.reason;
  EXPECT_EQ(r.bodies.at(0).time_s.size(), 17u);
}

// A disk 0.1 m deep in a K = 1e4 N/m contact at t = 0 holds K d^2 / 2 = 50 J;
// released without gravity it leaves at sqrt(2 * 50 / 1) = 10 m/s. The
// runner counts the contact's elastic energy from the engine's penetration
// at t = 0: ok. The same motion from an engine that gives no penetration
// (NaN) has no energy to come from: a runaway.
TEST(RunnerFaults, InitialContactEnergyIsAllowed) {
  const Case c = disk_case(Vec2::Zero(), 0.5);
  const auto release = [](double t) {
    BodyState b;
    b.position_m = Vec2(0.0, 0.4 + 10.0 * t);
    b.velocity_mps = Vec2(0.0, t > 0.0 ? 10.0 : 0.0);
    return b;
  };
  ContactSample deep;
  deep.body_a = 0;
  deep.body_b = 1;
  deep.penetration_m = 0.1;
  ScriptedEngine known(release, {deep});
  const RunResult ok = run_engine(known, c, {});
  EXPECT_EQ(ok.status, RunStatus::ok) << ok.reason;

  deep.penetration_m = std::numeric_limits<double>::quiet_NaN();
  ScriptedEngine unknown(release, {deep});
  const RunResult bad = run_engine(unknown, c, {});
  EXPECT_EQ(bad.status, RunStatus::diverged);
  EXPECT_NEAR(bad.diverged_at_s, 0.01, 1e-12);  // the first sample after t = 0
}

// An engine's own EngineError while stepping (a MuJoCo warning, an ODE or
// Box2D blow-up) ends the run as diverged at the engine's time, with its text.
TEST(RunnerFaults, EngineErrorIsDivergedAtTheEnginesTime) {
  const Case c = disk_case(Vec2(0.0, -kG), 1.0);
  ScriptedEngine e(
      [](double t) {
        BodyState b;
        b.position_m = Vec2(0.0, 2.0 - 0.5 * kG * t * t);
        b.velocity_mps = Vec2(0.0, -kG * t);
        return b;
      },
      {}, 0.305);
  const RunResult r = run_engine(e, c, {});
  ASSERT_EQ(r.status, RunStatus::diverged);
  EXPECT_EQ(r.reason, "scripted: the solver gave up");
  // the engine's 1e-3 s step that reached 0.305 s, not the 0.31 s sample asked for
  EXPECT_NEAR(r.diverged_at_s, 0.305, 1e-12);
  EXPECT_EQ(r.bodies.at(0).time_s.size(), 31u);  // 0 ... 0.30 s
}

}  // namespace
}  // namespace pb
