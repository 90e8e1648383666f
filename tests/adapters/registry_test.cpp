// Tests for adapters/registry.cpp: every engine by name, and what every
// engine promises whatever its internals (SPEC §5b): the default mode of each
// runs the engine as its users run it, with no probe or look-ahead run, and
// says whose collision and whose contact force produce its results.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "planarbench/case_loader.hpp"
#include "planarbench/engines.hpp"

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
