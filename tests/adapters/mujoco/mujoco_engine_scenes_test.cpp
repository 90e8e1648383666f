// Tests for adapters/mujoco/mujoco_engine.cpp on scenes (SPEC §11): the
// contact groups run through MuJoCo 2.2.2's own broad phase, on the real
// case files of cases/scenes. Each test states the physics it checks and why
// its tolerance is that number; durations are cut where the figure is
// reached earlier (CI runs these under AddressSanitizer, 3-5x slower).
#include "planarbench/adapters/mujoco_engine.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "planarbench/case_loader.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/runner.hpp"
#include "scene_cases.hpp"

namespace pb {
namespace {

constexpr double kG = 9.8066;  // m/s^2, SPEC §2

SettingsOverrides given(std::initializer_list<std::pair<std::string, std::string>> kv) {
  SettingsOverrides o;
  for (const auto& [k, v] : kv) o.set(k, v, SettingSource{"--set", 0});
  return o;
}

RunResult run(const Case& c, const SettingsOverrides& o = {}) {
  auto e = make_mujoco_engine();
  return run_engine(*e, c, o);
}

// Ten boxes stacked at their resting pose. MuJoCo finds the ten pairs itself
// (no <pair> written) and, with multiccd (on for a group of polygons), holds
// each face at both corners: the stack stands. Interface k from the top
// carries k m g. At d = 0.9999 MuJoCo's contact carries gravity's share d of
// the load by the constraint and the law's spring on top, so the case's
// pressed start hops first (ENGINES.md): the drift is that hop, not a creep.
TEST(MujocoScenes, StackOfTenStandsOnItsFaces) {
  const Case c = test::scene_case("stack_10", 0.5);
  const RunResult r = run(c);
  ASSERT_EQ(r.status, RunStatus::ok) << r.reason;
  const nlohmann::json& cap = r.extra.at("mujoco_capacity");
  EXPECT_EQ(cap.at("group_pairs_found"), 10);  // ground-box_1 and nine interfaces
  EXPECT_LE(cap.at("most_contacts").get<int>(), cap.at("nconmax").get<int>());
  EXPECT_EQ(r.mapping.at("groups").size(), 1u);
  double drift = 0.0;
  for (const BodyTrajectory& b : r.bodies) {
    for (const Vec2& p : b.position_m) drift = std::max(drift, (p - b.position_m.front()).norm());
  }
  // 5 mm: the hop releases the pressed interfaces (measured 2.6 mm at the
  // top box); a stack that topples or slides moves its boxes by 0.1 m and more
  EXPECT_LT(drift, 5e-3);
  const double t = c.duration_s;
  for (int k = 1; k <= 10; ++k) {
    const std::string below = k == 10 ? "ground" : "box_" + std::to_string(10 - k);
    const double f = test::pair_force_at(r, c, below, "box_" + std::to_string(11 - k), t);
    // 20 %: measured 1.00-1.14 k m g at 0.5 s (the contacts multiccd finds,
    // two or three a face, share the load unevenly while the hop rings
    // down); a face held at one corner carries tens of times the weight
    EXPECT_NEAR(f / (k * kG), 1.0, 0.2) << "interface " << k << " from the top";
  }
}

// Without multiccd MuJoCo's convex collider reports one contact per two
// boxes, at a support vertex (a corner, first in the mesh's vertex order on
// a tie): each box stands on one corner of the one below and the stack is
// kicked apart in the first millisecond (the energy budget ends it).
TEST(MujocoScenes, StackOfTenOnOneCornerEachIsKickedApart) {
  const Case c = test::scene_case("stack_10", 0.01);
  const RunResult r = run(c, given({{"mujoco.multiccd", "off"}}));
  ASSERT_EQ(r.status, RunStatus::diverged);
  EXPECT_NE(r.reason.find("energy runaway"), std::string::npos) << r.reason;
  // 2 ms: the budget's first output samples after the kick (measured 1 ms)
  EXPECT_LE(r.diverged_at_s, 2e-3);
  const int ground = c.body_index("ground");
  for (const ContactRow& row : r.contacts) {
    if (row.time_s > 0.0) break;
    if (row.sample.body_a == ground) continue;
    // at t = 0 each interface's one contact sits at a corner (x = +-0.2 m)
    EXPECT_NEAR(std::abs(row.sample.point_m.x()), 0.2, 1e-6);
  }
}

// Fifty boxes at their resting pose, on their faces: the per-pair solref
// rule sets each interface's reference acceleration to K delta / m_set with
// m_set the pair's own effective mass (m for the ground, m / 2 for two
// boxes), and MuJoCo's soft contact near d = 1 follows it: along the column
// those accelerations add (box k's is the sum of the k interfaces below), so
// the ground carries sum_k m a_k + N m g, about 1700 times the weight, not N m
// g. The first sample shows it; the kick ends the run by the energy budget.
TEST(MujocoScenes, StackOfFiftyIsLaunchedByThePerPairRule) {
  const Case c = test::scene_case("stack_50", 2e-4);
  const RunResult r = run(c);
  const int n = 50;
  const double m = 1.0;
  const double k_law = 1e6;
  double sum = 0.0;       // m/s^2, sum over the boxes of their accelerations
  double a = 0.0;         // m/s^2, box k's: the interfaces below it
  for (int k = 1; k <= n; ++k) {
    const double delta = (n - k + 1) * m * kG / k_law;  // m, its interface's compression
    a += k_law * delta / (k == 1 ? m : m / 2.0);
    sum += a;
  }
  const double predicted = m * sum + n * m * kG;  // N, ~8.2e5 against 490
  const double f = test::pair_force_at(r, c, "ground", "box_1", 0.0);
  // 3 %: the constraint's regulariser at d = 0.9999 softens the column's
  // response a little (measured 1.0 % below); the weight is 0.06 % of it
  EXPECT_NEAR(f / predicted, 1.0, 0.03) << f << " N against " << predicted;
}

// Newton's cradle with gaps, no gravity: four binary sphere-sphere impacts
// down the row. Momentum is exact (the contact forces are equal and
// opposite: MuJoCo's solver applies J^T f to both bodies); the struck disk
// leaves with most of it, each impact passing on (1 + e) / 2 of the speed.
TEST(MujocoScenes, CradleConservesMomentum) {
  const Case c = test::scene_case("cradle_5", 0.4);
  const RunResult r = run(c);
  ASSERT_EQ(r.status, RunStatus::ok) << r.reason;
  ASSERT_EQ(r.bodies.size(), 5u);
  double largest = 0.0;
  for (std::size_t i = 0; i < r.bodies[0].time_s.size(); ++i) {
    double p = 0.0;  // kg m/s, all disks are 1 kg
    for (const BodyTrajectory& b : r.bodies) p += b.velocity_mps[i].x();
    largest = std::max(largest, std::abs(p - 1.0));
  }
  // 1e-12 kg m/s: the rounding of 4000 steps' velocity updates of ~1 m/s
  EXPECT_LT(largest, 1e-12);
  EXPECT_EQ(r.events.size(), 4u);  // each neighbour pair once
  // e of the clamped oscillator for the reduced mass 0.5 kg: 0.86-0.87, so
  // (1 + e)^4 / 16 = 0.76; MuJoCo measured 0.7666 m/s. 0.02 m/s: the speed
  // of a cradle whose impacts are not binary, or lose momentum, is far off
  EXPECT_NEAR(r.bodies[4].velocity_mps.back().x(), 0.7666, 0.02);
}

// 100 disks dropped into a box of three half-planes: MuJoCo's broad phase
// pairs them as they meet; no disk leaves the box or sinks into the ground.
TEST(MujocoScenes, PileStaysInItsBox) {
  const Case c = test::scene_case("pile_100", 0.4);
  const RunResult r = run(c);
  ASSERT_EQ(r.status, RunStatus::ok) << r.reason;
  ASSERT_EQ(r.bodies.size(), 100u);
  for (const BodyTrajectory& b : r.bodies) {
    for (const Vec2& p : b.position_m) {
      // a disk's centre stays a radius (0.05 m) inside each wall, less the
      // law's deepest penetration (measured below 2 mm)
      EXPECT_GT(p.y(), 0.05 - 5e-3) << b.name;
      EXPECT_LT(std::abs(p.x()), 0.65 - 0.05 + 5e-3) << b.name;
    }
  }
  double deepest = 0.0;
  for (const ContactRow& row : r.contacts) deepest = std::max(deepest, row.sample.penetration_m);
  // K = 1e4 N/m: a disk of 0.1 kg landing at ~3 m/s presses
  // v sqrt(m / K) = 1 cm at most; a contact MuJoCo lost lets disks overlap
  EXPECT_GT(deepest, 0.0);
  EXPECT_LT(deepest, 0.01);
}

// MuJoCo's broad phase finds the pairs; nothing is declared pair by pair.
TEST(MujocoScenes, NoPairIsDeclaredForAGroup) {
  auto e = make_mujoco_engine();
  const Case c = test::scene_case("pyramid_5", 1e-3);
  e->build(c, {});
  const nlohmann::json m = e->mapping();
  EXPECT_TRUE(m.at("pairs").empty());
  EXPECT_EQ(m.at("groups").at(0).at("bodies"), 16);  // the ground and 15 bricks
  EXPECT_TRUE(m.at("capacity").at("written").get<bool>());
  // oracle and inject calibrate or apply declared pairs one by one
  EXPECT_EQ(e->supports(c).support, Support::mapped);
  auto oracle = make_mujoco_engine();
  EXPECT_THROW(oracle->build(c, given({{"mujoco.mode", "oracle"}})), EngineError);
  EXPECT_THROW(e->build(c, given({{"mujoco.integrator", "RK4"}})), EngineError);
}

}  // namespace
}  // namespace pb
