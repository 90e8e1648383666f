// Tests for adapters/registry.cpp: every engine by name, and what every
// engine promises whatever its internals (SPEC §5b): the default mode of each
// runs the engine as its users run it, with no probe or look-ahead run, and
// says whose collision and whose contact force produce its results.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "planarbench/case_loader.hpp"
#include "planarbench/engines.hpp"
#include "planarbench/runner.hpp"

namespace pb {
namespace {

std::vector<Case> shipped_cases() {
  std::vector<Case> out;
  for (const auto& entry : std::filesystem::directory_iterator(PB_CASES_DIR)) {
    const auto& p = entry.path();
    if (p.extension() != ".toml" || p.stem() == "thresholds") continue;
    out.push_back(load_case(p));
  }
  EXPECT_GE(out.size(), 11u);
  return out;
}

SettingsOverrides settings_of(const Case& c, const std::string& key = "",
                              const std::string& value = "") {
  SettingsOverrides o;
  for (const auto& [k, v] : c.settings) o.set(k, v, SettingSource{c.source_path, 0});
  if (!key.empty()) o.set(key, value, SettingSource{"--set", 0});
  return o;
}

// The engines count every step their own integrator takes on this thread
// (mj_Euler / mj_RungeKutta, dWorldStep / dWorldQuickStep, b2World::Step),
// whoever asks for it; the steps taken while building, before t = 0, are
// steps_before_start(). By default there are none, for every shipped case:
// no engine looks into the run's future. The oracle modes do (a probe run up
// to each pair's first touch), which shows the trace is real.
TEST(Registry, DefaultModesTakeNoStepBeforeTheRunStarts) {
  for (const Case& c : shipped_cases()) {
    for (const std::string name : {"mujoco", "box2d", "ode"}) {
      auto e = make_engine(name);
      if (e->supports(c).support == Support::unsupported) continue;
      e->build(c, settings_of(c));
      EXPECT_EQ(e->steps_before_start(), 0) << c.name << " x " << name;
      EXPECT_FALSE(e->physics().foreknowledge) << c.name << " x " << name;
      EXPECT_EQ(e->physics().collision_by, "engine") << c.name << " x " << name;
      EXPECT_EQ(e->physics().contact_force_by, "engine") << c.name << " x " << name;
    }
  }
}

TEST(Registry, OracleModesAreNamedAndLookAhead) {
  const Case c = load_case(std::string(PB_CASES_DIR) + "/falling_ball.toml");
  for (const std::string name : {"mujoco", "ode"}) {
    auto e = make_engine(name);
    e->build(c, settings_of(c, name + ".mode", "oracle"));
    // the probe stepped to the first touch at t = 0.725 s: 7250 steps of 1e-4 s
    EXPECT_GT(e->steps_before_start(), 7000) << name;
    EXPECT_TRUE(e->physics().foreknowledge) << name;
    EXPECT_EQ(e->physics().mode, "oracle") << name;
  }
}

// A deliberately looking-ahead use of a real engine: before the run, it
// builds a second engine of the same library and steps it through the case's
// first `ahead_s` (what an oracle calibration or a peek at the first touch
// does), then builds the engine that runs. Everything else is the real
// engine's. Its own steps_before_start() says 0: only the library's counter,
// read by run_engine around build, can see the look-ahead.
class LookingAhead final : public Engine {
 public:
  LookingAhead(std::string name, double ahead_s)
      : name_(std::move(name)), ahead_s_(ahead_s), inner_(make_engine(name_)) {}
  std::string name() const override { return inner_->name(); }
  std::string version() const override { return inner_->version(); }
  Capability supports(const Case& c) const override { return inner_->supports(c); }
  const SettingsBinder& settings() const override { return inner_->settings(); }
  void build(const Case& c, const SettingsOverrides& o) override {
    auto peek = make_engine(name_);
    peek->build(c, o);
    peek->advance_to(ahead_s_);
    inner_->build(c, o);
  }
  void advance_to(double t_s) override { inner_->advance_to(t_s); }
  double time() const override { return inner_->time(); }
  void body_states(std::vector<BodyState>& out) const override { inner_->body_states(out); }
  void contacts(std::vector<ContactSample>& out) const override { inner_->contacts(out); }
  std::vector<ContactEpisode> episodes() const override { return inner_->episodes(); }
  long steps() const override { return inner_->steps(); }
  nlohmann::json mapping() const override { return inner_->mapping(); }
  Physics physics() const override { return inner_->physics(); }
  long library_steps_on_this_thread() const override {
    return inner_->library_steps_on_this_thread();
  }

 private:
  std::string name_;
  double ahead_s_;
  std::unique_ptr<Engine> inner_;
};

// The no-look-ahead guard fires for every engine: run as users run them, the
// runner records steps_before_start = 0; looking 0.05 s ahead before the run
// records the library's steps of that peek (a fixed step of 1e-4 s: 500 steps;
// the reference's adaptive rk45 takes at least one), so a look-ahead cannot
// pass unseen. Box2D's counter (b2World::Step) fires as well as the others.
TEST(Registry, NoLookAheadGuardFiresForEveryEngine) {
  Case c = load_case(std::string(PB_CASES_DIR) + "/falling_ball.toml");
  c.duration_s = 0.1;  // s: the guard is about build; a short run keeps the test cheap
  constexpr double kAhead_s = 0.05;
  for (const std::string name : {"mujoco", "box2d", "ode", "reference"}) {
    auto plain = make_engine(name);
    const RunResult honest = run_engine(*plain, c, settings_of(c));
    ASSERT_EQ(honest.status, RunStatus::ok) << name << ": " << honest.reason;
    EXPECT_EQ(honest.extra.value("steps_before_start", -1L), 0) << name;
    LookingAhead peeking(name, kAhead_s);
    const RunResult peeked = run_engine(peeking, c, settings_of(c));
    ASSERT_EQ(peeked.status, RunStatus::ok) << name << ": " << peeked.reason;
    EXPECT_EQ(peeking.steps_before_start(), 0) << name << ": the wrapper reports nothing itself";
    const long seen = peeked.extra.value("steps_before_start", -1L);
    if (name == "reference") {
      EXPECT_GT(seen, 0) << name;
    } else {
      // 0.05 s / 1e-4 s = 500 steps of the library's fixed step
      EXPECT_EQ(seen, 500) << name;
    }
  }
}

TEST(Registry, InjectModesSayTheAdapterAppliesTheLaw) {
  const Case c = load_case(std::string(PB_CASES_DIR) + "/falling_ball.toml");
  for (const std::string name : {"mujoco", "box2d", "ode"}) {
    auto e = make_engine(name);
    e->build(c, settings_of(c, name + ".mode", "inject"));
    EXPECT_EQ(e->physics().contact_force_by, "adapter (case law)") << name;
    EXPECT_EQ(e->steps_before_start(), 0) << name;
  }
}

TEST(Registry, UnknownEngineNamesEveryAllowedOne) {
  try {
    (void)make_engine("bullet");
    FAIL() << "no error";
  } catch (const std::exception& e) {
    const std::string what = e.what();
    for (const auto& n : engine_names()) EXPECT_NE(what.find(n), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace pb
