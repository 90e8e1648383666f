// Tests for adapters/box2d/box2d_settings.cpp
#include "box2d_settings.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "box2d_test_cases.hpp"
#include "planarbench/errors.hpp"

namespace pb::internal::box2d {
namespace {

using box2d_test::overrides;

// the documented defaults: dt on the 1e-4 s output grid, the Box2D manual's
// iteration counts, automatic restitution threshold, engine mode
TEST(Box2dSettings, DefaultsAreTheDocumentedOnes) {
  Box2dSettings s;
  SettingsBinder binder("box2d");
  bind_settings(binder, &s);
  const nlohmann::json j = binder.to_json();
  EXPECT_EQ(j.at("dt").get<double>(), 1e-4);
  EXPECT_EQ(j.at("velocity_iterations").get<int>(), 8);
  EXPECT_EQ(j.at("position_iterations").get<int>(), 3);
  EXPECT_EQ(j.at("restitution_threshold").get<double>(), 0.0);
  EXPECT_EQ(j.at("mode").get<std::string>(), "native");
  EXPECT_TRUE(j.at("warm_starting").get<bool>());
  EXPECT_TRUE(j.at("continuous_physics").get<bool>());
}

// "dt" is shared by every engine; "box2d.dt" wins over it
TEST(Box2dSettings, SharedKeyAndPrefixedKey) {
  Box2dSettings s;
  SettingsBinder binder("box2d");
  bind_settings(binder, &s);
  binder.apply(overrides({{"dt", "2e-4"}}));
  EXPECT_EQ(s.dt_s, 2e-4);
  binder.apply(overrides({{"dt", "2e-4"}, {"box2d.dt", "5e-5"}}));
  EXPECT_EQ(s.dt_s, 5e-5);
  binder.apply(overrides({{"box2d.mode", "inject"}, {"box2d.velocity_iterations", "20"}}));
  EXPECT_EQ(s.mode, "inject");
  EXPECT_EQ(s.velocity_iterations, 20);
  EXPECT_TRUE(binder.knows("box2d.restitution_threshold"));
  EXPECT_FALSE(binder.knows("box2d.substeps"));
}

// values outside their range are input errors naming the key
TEST(Box2dSettings, BadValuesAreInputErrors) {
  Box2dSettings s;
  SettingsBinder binder("box2d");
  bind_settings(binder, &s);
  EXPECT_THROW(binder.apply(overrides({{"box2d.mode", "soft"}})), InputError);
  EXPECT_THROW(binder.apply(overrides({{"dt", "0"}})), InputError);
  EXPECT_THROW(binder.apply(overrides({{"box2d.velocity_iterations", "2.5"}})), InputError);
  EXPECT_THROW(binder.apply(overrides({{"box2d.restitution_threshold", "-1"}})), InputError);
  try {
    binder.apply(overrides({{"box2d.position_iterations", "-3"}}));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "box2d.position_iterations");
  }
}

}  // namespace
}  // namespace pb::internal::box2d
