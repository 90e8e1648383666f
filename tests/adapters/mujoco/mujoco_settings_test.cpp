// Tests for adapters/mujoco/mujoco_settings.cpp
#include "mujoco_settings.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "planarbench/errors.hpp"

namespace pb::internal::mujoco {
namespace {

SettingsOverrides given(std::initializer_list<std::pair<std::string, std::string>> kv) {
  SettingsOverrides o;
  for (const auto& [k, v] : kv) o.set(k, v, SettingSource{"--set", 0});
  return o;
}

TEST(MujocoSettings, DefaultsAreStated) {
  MujocoSettings s;
  const SettingsBinder b = bind_mujoco_settings(s);
  const nlohmann::json j = b.to_json();
  EXPECT_EQ(j.at("dt"), 1e-4);
  EXPECT_EQ(j.at("integrator"), "Euler");
  EXPECT_EQ(j.at("solver"), "Newton");
  EXPECT_EQ(j.at("iterations"), 100);
  EXPECT_EQ(j.at("tolerance"), 1e-8);
  EXPECT_EQ(j.at("mode"), "native");
  EXPECT_EQ(j.at("solimp"), nlohmann::json({0.9999, 0.9999, 0.001, 0.5, 2.0}));
  EXPECT_NO_THROW(validate_mujoco_settings(s, {}));
}

TEST(MujocoSettings, SharedDtAndPrefixedKeyWins) {
  MujocoSettings s;
  const SettingsBinder b = bind_mujoco_settings(s);
  b.apply(given({{"dt", "2e-4"}}));
  EXPECT_EQ(s.dt_s, 2e-4);
  b.apply(given({{"dt", "2e-4"}, {"mujoco.dt", "5e-5"}}));
  EXPECT_EQ(s.dt_s, 5e-5);
  EXPECT_TRUE(b.knows("mujoco.mode"));
  EXPECT_TRUE(b.knows("dt"));
  EXPECT_FALSE(b.knows("box2d.dt"));
}

TEST(MujocoSettings, ChoicesAndListsParse) {
  MujocoSettings s;
  const SettingsBinder b = bind_mujoco_settings(s);
  b.apply(given({{"mujoco.integrator", "RK4"},
                 {"mujoco.mode", "inject"},
                 {"mujoco.solimp", "[0.9, 0.95, 0.001, 0.5, 2]"}}));
  EXPECT_EQ(s.integrator, "RK4");
  EXPECT_EQ(s.mode, "inject");
  EXPECT_EQ(s.solimp, (std::vector<double>{0.9, 0.95, 0.001, 0.5, 2.0}));
  EXPECT_THROW(b.apply(given({{"mujoco.integrator", "implicit"}})), InputError);
  EXPECT_THROW(b.apply(given({{"mujoco.solimp", "0.9 0.9"}})), InputError);
}

TEST(MujocoSettings, SolimpOutsideMujocoRangeNamesTheKey) {
  MujocoSettings s;
  const SettingsBinder b = bind_mujoco_settings(s);
  const auto o = given({{"mujoco.solimp", "1.0 0.9999 0.001 0.5 2"}});
  b.apply(o);
  try {
    validate_mujoco_settings(s, o);
    FAIL() << "d = 1 is outside [mjMINIMP, mjMAXIMP]";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "mujoco.solimp");
    EXPECT_EQ(e.file(), "--set");
  }
}

}  // namespace
}  // namespace pb::internal::mujoco
