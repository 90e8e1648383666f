// What every engine promises about friction (SPEC §7, issue 22), whatever its
// internals: each is given exactly the pair's coefficient and its mapping
// says so and which model it runs; a force-injection mode, which has no
// friction, refuses a case with friction instead of running it frictionless.
#include <gtest/gtest.h>

#include <string>

#include "planarbench/case_loader.hpp"
#include "planarbench/engines.hpp"
#include "planarbench/runner.hpp"

namespace pb {
namespace {

Case block_hold() { return load_case(std::string(PB_CASES_DIR) + "/block_hold.toml"); }

SettingsOverrides with(const std::string& key = "", const std::string& value = "") {
  SettingsOverrides o;
  if (!key.empty()) o.set(key, value, SettingSource{"test", 0});
  return o;
}

class FrictionEngine : public testing::TestWithParam<std::string> {};

TEST_P(FrictionEngine, MappingStatesTheCoefficientAndTheModel) {
  Case c = block_hold();
  c.duration_s = 0.01;  // the mapping is made at build; a few steps suffice
  auto e = make_engine(GetParam());
  const RunResult r = run_engine(*e, c, with());
  ASSERT_EQ(r.status, RunStatus::ok) << r.reason;
  // the pair's entry in the mapping (MuJoCo, Box2D: "pairs"/"contacts"; ODE: "contacts")
  const nlohmann::json& m = r.mapping;
  const nlohmann::json* pairs = m.contains("pairs") ? &m["pairs"] : &m["contacts"];
  ASSERT_TRUE(pairs->is_array());
  ASSERT_EQ(pairs->size(), 1u);
  const nlohmann::json& f = (*pairs)[0].at("friction");
  EXPECT_EQ(f.at("coefficient").get<double>(), 0.5);
  EXPECT_FALSE(f.at("expressed_as").get<std::string>().empty());
}

TEST_P(FrictionEngine, InjectRefusesFriction) {
  auto e = make_engine(GetParam());
  Case c = block_hold();
  const RunResult r = run_engine(*e, c, with(GetParam() + ".mode", "inject"));
  EXPECT_EQ(r.status, RunStatus::unsupported);
  EXPECT_NE(r.reason.find("pair 'ground_slab' has friction"), std::string::npos) << r.reason;
}

INSTANTIATE_TEST_SUITE_P(Engines, FrictionEngine, testing::Values("mujoco", "box2d", "ode"),
                         [](const testing::TestParamInfo<std::string>& i) { return i.param; });

}  // namespace
}  // namespace pb
