// What every engine promises about friction (SPEC §7, issue 22), whatever its
// internals: each is given exactly the pair's coefficient and its mapping
// says so and which model it runs; a force-injection mode, which has no
// friction, refuses a case with friction instead of running it frictionless.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

// Issue 32: every engine's contacts carry the tangential force on body_b and
// the slip along t = n rotated by +90 deg. Closed forms (SPEC §7): on
// block_slide (tan theta = 0.55 > mu = 0.5) the slab slides, so Coulomb's
// force is mu F_n against the slip; on block_hold (tan theta = 0.45 < mu) it
// holds, so the friction carries the slope's share, F_t = tan(theta) F_n,
// inside the cone, and the slip is ~0. Samples after 0.05 s (past the release
// transient) with a normal force.
class TangentialForce : public testing::TestWithParam<std::string> {};

struct Ratios {
  double min = 1e300, max = -1e300;
  int samples = 0, along_the_slip = 0;
  double largest_slip_mps = 0.0;
};

Ratios ratios(const std::string& engine, const std::string& case_name) {
  const Case c = load_case(std::string(PB_CASES_DIR) + "/" + case_name + ".toml");
  auto e = make_engine(engine);
  const RunResult r = run_engine(*e, c, with());
  EXPECT_EQ(r.status, RunStatus::ok) << r.reason;
  Ratios q;
  for (const ContactRow& row : r.contacts) {
    const ContactSample& s = row.sample;
    if (row.time_s < 0.05 || !(s.force_n > 0.0)) continue;
    EXPECT_TRUE(std::isfinite(s.tangential_force_n) && std::isfinite(s.slip_mps)) << row.time_s;
    const double k = s.tangential_force_n / s.force_n;
    q.min = std::min(q.min, k);
    q.max = std::max(q.max, k);
    ++q.samples;
    if (s.tangential_force_n * s.slip_mps > 0.0) ++q.along_the_slip;
    q.largest_slip_mps = std::max(q.largest_slip_mps, std::abs(s.slip_mps));
  }
  return q;
}

TEST_P(TangentialForce, ASlidingSlabFeelsMuTimesTheNormalForceAgainstItsSlip) {
  const Ratios q = ratios(GetParam(), "block_slide");
  ASSERT_GT(q.samples, 100);
  // 1e-4: Box2D's impulses are floats, its sequential-impulse clamp |t| <= mu n
  // per point and iteration meets the cone to float rounding of the step's
  // impulses (measured 0.49995 to 0.50004); the others hold mu exactly to 2e-8
  EXPECT_NEAR(q.min, 0.5, 1e-4);
  EXPECT_NEAR(q.max, 0.5, 1e-4);
  EXPECT_EQ(q.along_the_slip, 0);  // always against the slip (dissipative)
  // sliding: the slab reaches 0.43 m/s down the slope within the run
  EXPECT_GT(q.largest_slip_mps, 0.1);
}

TEST_P(TangentialForce, AHeldSlabFeelsTheSlopesShareInsideTheCone) {
  const Ratios q = ratios(GetParam(), "block_hold");
  ASSERT_GT(q.samples, 100);
  // tan(theta) = 0.45; 2e-5: MuJoCo's soft friction rows ring to 0.450015
  // after the release (measured), the others are within 4e-7
  EXPECT_NEAR(q.min, 0.45, 2e-5);
  EXPECT_NEAR(q.max, 0.45, 2e-5);
  EXPECT_LT(q.max, 0.5);  // inside the cone mu = 0.5
  // 1e-6 m/s: MuJoCo's soft friction creeps at 5.3e-7 m/s inside the cone
  // (its known breach on block_hold), the others stick to 2e-10 m/s
  EXPECT_LT(q.largest_slip_mps, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(Engines, TangentialForce,
                         testing::Values("reference", "mujoco", "mujoco3", "box2d", "ode"),
                         [](const testing::TestParamInfo<std::string>& i) { return i.param; });

}  // namespace
}  // namespace pb
