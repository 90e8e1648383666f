// Tests for core/src/runner.cpp
//
// The runner is tested with a small engine defined here: a body in free fall,
// in closed form. It stands in for no real engine; it exercises the runner's
// grid, sampling, angle unwrapping and divergence handling.
#include "planarbench/runner.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "planarbench/errors.hpp"

namespace pb {
namespace {

// Free fall x(t) = x0 + v0 t + g t^2 / 2, spinning at 5 rad/s with its angle
// wrapped to (-pi, pi] as some engines report it; steps of 1e-3 s; reports a
// NaN state from `nan_after_s` on.
class FreeFallEngine final : public Engine {
 public:
  explicit FreeFallEngine(double nan_after_s = 1e9) : nan_after_s_(nan_after_s) {}
  std::string name() const override { return "freefall"; }
  std::string version() const override { return "test"; }
  Physics physics() const override { return Physics{"test", "test", "", "test", "", "", false}; }
  Capability supports(const Case&) const override { return {Support::native, ""}; }
  const SettingsBinder& settings() const override { return binder_; }
  void build(const Case& c, const SettingsOverrides&) override { c_ = &c; }
  void advance_to(double t) override {
    while (t_ + h_ <= t + 1e-9 * h_) {
      t_ += h_;
      ++steps_;
    }
  }
  double time() const override { return t_; }
  void body_states(std::vector<BodyState>& out) const override {
    out.assign(c_->bodies.size(), BodyState{});
    const Body& b = c_->bodies[0];
    out[0].position_m = b.position_m + b.velocity_mps * t_ + 0.5 * c_->gravity_mps2 * t_ * t_;
    out[0].velocity_mps = b.velocity_mps + c_->gravity_mps2 * t_;
    out[0].angle_rad = std::remainder(5.0 * t_, 2.0 * M_PI);
    out[0].angular_velocity_radps = t_ >= nan_after_s_ ? std::nan("") : 5.0;
  }
  void contacts(std::vector<ContactSample>& out) const override { out.clear(); }
  std::vector<ContactEpisode> episodes() const override { return {}; }
  long steps() const override { return steps_; }
  nlohmann::json mapping() const override { return {{"law", "none"}}; }

 private:
  double nan_after_s_;
  SettingsBinder binder_{"freefall"};
  const Case* c_ = nullptr;
  double t_ = 0.0;
  double h_ = 1e-3;
  long steps_ = 0;
};

Case one_body_case() {
  Case c;
  c.name = "fall";
  c.duration_s = 2.0;
  c.output_interval_s = 0.01;
  Body b;
  b.name = "ball";
  b.shape = Circle{0.5};
  b.mass_kg = 1.0;
  b.inertia_kgm2 = 0.125;
  b.position_m = Vec2(0.0, 10.0);
  b.velocity_mps = Vec2(1.0, 0.0);
  c.bodies.push_back(b);
  Body g;
  g.name = "ground";
  g.fixed = true;
  g.shape = HalfPlane{};
  c.bodies.push_back(g);
  return c;
}

TEST(Runner, SamplesEveryGridPointOfMovingBodies) {
  const Case c = one_body_case();
  FreeFallEngine e;
  const RunResult r = run_engine(e, c, {});
  EXPECT_EQ(r.status, RunStatus::ok);
  ASSERT_EQ(r.bodies.size(), 1u);  // the fixed ground has no trajectory
  const auto& tr = r.bodies[0];
  ASSERT_EQ(tr.time_s.size(), 201u);  // 0, 0.01, ..., 2.0
  // 2000 summed steps of 1e-3 s drift by ~2000 ulps (~1e-13 s); 1e-9 s is the
  // engine's own step-landing slack (1e-9 h) scaled up, far below one step
  EXPECT_NEAR(tr.time_s.back(), 2.0, 1e-9);
  // y(2) = 10 - 9.8066 * 2 = -9.6132; the engine's 1e-3 steps land on the grid
  EXPECT_NEAR(tr.position_m.back().y(), 10.0 - 0.5 * 9.8066 * 4.0, 1e-9);
  // the wrapped angle comes back continuous: 5 rad/s for 2 s = 10 rad
  EXPECT_NEAR(tr.angle_rad.back(), 10.0, 1e-9);
  EXPECT_EQ(r.steps, 2000);
  EXPECT_EQ(r.body_names.size(), 2u);
}

TEST(Runner, NonFiniteStateIsDivergedWithTime) {
  const Case c = one_body_case();
  FreeFallEngine e(0.5);
  const RunResult r = run_engine(e, c, {});
  EXPECT_EQ(r.status, RunStatus::diverged);
  // the first NaN sample is the grid point 0.5 s; 1e-9 s: summed-step rounding only,
  // one output interval (0.01 s) off would fail
  EXPECT_NEAR(r.diverged_at_s, 0.5, 1e-9);
  EXPECT_NE(r.reason.find("ball"), std::string::npos) << r.reason;
  EXPECT_EQ(r.bodies[0].time_s.size(), 50u);  // samples before the divergence are kept
}

}  // namespace
}  // namespace pb
