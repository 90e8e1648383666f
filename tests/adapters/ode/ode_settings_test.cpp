// Tests for adapters/ode/ode_settings.cpp
#include "ode_settings.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "planarbench/errors.hpp"

namespace pb::internal::ode {
namespace {

// the stated defaults (the brief and ENGINES.md): dt 1e-4 s, ODE at that step
// (no sub-steps: SPEC §5b, the step the user gives), the stepper by the case
// (auto: direct for declared pairs, quick for a scene), the corrected damping
// mapping, native contacts
TEST(OdeSettings, DefaultsAreTheStatedOnes) {
  OdeSettings s;
  const nlohmann::json j = bind_ode_settings(s).to_json();
  EXPECT_EQ(j.at("dt").get<double>(), 1e-4);
  EXPECT_EQ(j.at("substeps").get<int>(), 1);
  EXPECT_EQ(j.at("contact_steps").get<int>(), 20);
  EXPECT_EQ(j.at("stepper").get<std::string>(), "auto");
  EXPECT_EQ(j.at("quick_iterations").get<int>(), 20);
  EXPECT_EQ(j.at("damping_mapping").get<std::string>(), "corrected");
  EXPECT_EQ(j.at("mode").get<std::string>(), "native");
}

// "dt" is shared with the other engines; "ode.dt" wins over it
TEST(OdeSettings, SharedAndPrefixedKeys) {
  OdeSettings s;
  const SettingsBinder b = bind_ode_settings(s);
  SettingsOverrides o;
  o.set("dt", "1e-3", {"--set", 0});
  b.apply(o);
  EXPECT_EQ(s.dt_s, 1e-3);
  o.set("ode.dt", "2e-5", {"--set", 0});
  o.set("ode.stepper", "quick", {"--set", 0});
  o.set("ode.damping_mapping", "textbook", {"--set", 0});
  o.set("ode.mode", "inject", {"--set", 0});
  b.apply(o);
  EXPECT_EQ(s.dt_s, 2e-5);
  EXPECT_EQ(s.stepper, "quick");
  EXPECT_EQ(s.damping_mapping, "textbook");
  EXPECT_EQ(s.mode, "inject");
  EXPECT_TRUE(b.knows("ode.quick_iterations"));
  EXPECT_FALSE(b.knows("mujoco.solimp"));
}

// bad values are input errors naming the key
TEST(OdeSettings, BadValuesAreInputErrors) {
  OdeSettings s;
  const SettingsBinder b = bind_ode_settings(s);
  for (const auto& [key, value] :
       std::vector<std::pair<std::string, std::string>>{{"ode.stepper", "pgs"},
                                                        {"ode.damping_mapping", "exact"},
                                                        {"ode.mode", "both"},
                                                        {"ode.dt", "0"},
                                                        {"ode.substeps", "-1"},
                                                        {"ode.quick_iterations", "2.5"}}) {
    SettingsOverrides o;
    o.set(key, value, {"--set", 0});
    try {
      b.apply(o);
      ADD_FAILURE() << key << "=" << value << " was accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), key);
    }
  }
}

}  // namespace
}  // namespace pb::internal::ode
