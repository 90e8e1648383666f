// Tests for core/src/settings.cpp
#include "planarbench/settings.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "planarbench/errors.hpp"

namespace pb {
namespace {

struct DemoSettings {
  double dt_s = 1e-3;
  int iterations = 8;
  bool warm = true;
  std::string solver = "pgs";
  std::vector<double> solimp = {0.9, 0.95, 0.001, 0.5, 2.0};
};

SettingsBinder bind(DemoSettings& s) {
  SettingsBinder b("demo");
  b.real("dt", &s.dt_s, 1e-7, 0.1, "step, s")
      .integer("iterations", &s.iterations, 1, 1000, "solver iterations")
      .boolean("warm", &s.warm, "warm start")
      .choice("solver", &s.solver, {"pgs", "cg"}, "solver")
      .reals("solimp", &s.solimp, 5, "solimp");
  return b;
}

TEST(Settings, PrefixedKeyWinsOverShared) {
  DemoSettings s;
  SettingsOverrides o;
  o.set("dt", "1e-4", {"--set", 0});
  o.set("demo.dt", "2e-4", {"--set", 0});
  o.set("demo.solimp", "[0.99, 0.99, 0.001, 0.5, 2]", {"--set", 0});
  o.set("iterations", "50", {"--set", 0});
  bind(s).apply(o);
  EXPECT_EQ(s.dt_s, 2e-4);
  EXPECT_EQ(s.iterations, 50);
  EXPECT_EQ(s.solimp[0], 0.99);
}

TEST(Settings, BadValuesNameTheKeyAndTheRange) {
  DemoSettings s;
  auto expect_error = [&](const std::string& key, const std::string& text,
                          const std::string& fragment) {
    SettingsOverrides o;
    o.set(key, text, {"--set", 0});
    try {
      bind(s).apply(o);
      FAIL() << key << "=" << text << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  };
  expect_error("demo.dt", "abc", "finite number in [1e-07, 0.1]");
  expect_error("dt", "nan", "finite number");
  expect_error("dt", "1", "[1e-07, 0.1]");
  expect_error("iterations", "2.5", "integer in [1, 1000]");
  expect_error("warm", "maybe", "true or false");
  expect_error("solver", "newton", "one of: pgs, cg");
  expect_error("solimp", "1 2 3", "list of 5 finite numbers");
}

TEST(Settings, ASharedKeysRefusalNamesTheEngineWhoseRangeItBroke) {
  // issue 35 item 16: `--set dt=0.1 --engine all` gave a range without saying
  // which engine's it was (each engine has its own)
  DemoSettings s;
  SettingsOverrides o;
  o.set("dt", "1", {"--set", 0});
  try {
    bind(s).apply(o);
    FAIL() << "dt=1 accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("dt (for demo; demo.dt sets demo's alone): must be a "
                                         "finite number in [1e-07, 0.1]"),
              std::string::npos)
        << e.what();
  }
}

TEST(Settings, KnowsAndJson) {
  DemoSettings s;
  const auto b = bind(s);
  EXPECT_TRUE(b.knows("dt"));
  EXPECT_TRUE(b.knows("demo.dt"));
  EXPECT_FALSE(b.knows("other.dt"));
  EXPECT_EQ(b.to_json()["solver"], "pgs");
}

}  // namespace
}  // namespace pb
