// Tests for the reference's scenes (SPEC §11; core/reference/src/near_pairs.cpp,
// sparse_stick_solve.cpp, the settling of reference_solver.cpp): the shipped
// scenes against arithmetic written here, not the truth engine's code.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "planarbench/case_loader.hpp"
#include "planarbench/reference/reference_engine.hpp"
#include "planarbench/runner.hpp"
#include "scene_cases.hpp"

namespace pb {
namespace {

// the run as `planarbench run` makes it: the case's own [settings] (the
// scenes run the reference at exact geometry)
RunResult run(const Case& c) {
  SettingsOverrides o;
  for (const auto& [key, text] : c.settings) o.set(key, text, SettingSource{c.source_path, 0});
  auto e = make_reference_engine();
  return run_engine(*e, c, o, RunOptions{});
}

// the largest distance any body moved from its start, m
double drift_m(const RunResult& r) {
  double worst = 0.0;
  for (const auto& b : r.bodies) {
    for (const Vec2& p : b.position_m) worst = std::max(worst, (p - b.position_m.front()).norm());
  }
  return worst;
}

TEST(ReferenceScenes, RestingStackOfTenHoldsItsWeightsStill) {
  // ten 1 kg boxes pressed in at rest: interface k from the top carries k m g
  // (statics of a column), and nothing moves
  const Case c = test::scene_case("stack_10");
  const RunResult r = run(c);
  ASSERT_EQ(r.status, RunStatus::ok) << r.reason;
  // 1e-9 m: the bound for 5 s; the start is the law's rest to ~1e-16
  // m, and a stable rest keeps its rounding (measured 7e-16 m over 2 s)
  EXPECT_LE(drift_m(r), 1e-9);
  const double w = 1.0 * 9.8066;  // N, one box
  // each interface's force against the weight above, every stored sample
  double worst = 0.0;
  for (const ContactRow& row : r.contacts) {
    const int lower = row.sample.body_a;  // 0: the ground, k: box_k
    const int above = 10 - lower;         // boxes above the interface
    worst = std::max(worst, std::abs(row.sample.force_n - above * w) / (above * w));
  }
  EXPECT_LE(worst, 1e-6);  // the bound: k m g to 1e-6 relative
  EXPECT_FALSE(r.contacts.empty());
}

TEST(ReferenceScenes, CradleSpeedsFollowTheBinaryRestitution) {
  // equal disks, each impact binary: the struck disk leaves at (1 + e) / 2 of
  // the striker's speed, e the clamped Kelvin-Voigt restitution of the
  // reduced mass m / 2 (ENGINES.md: e = exp(-zeta (pi - 2 asin zeta) / sqrt(1 - zeta^2)))
  const Case c = test::scene_case("cradle_5");
  const RunResult r = run(c);
  ASSERT_EQ(r.status, RunStatus::ok) << r.reason;
  const double mu = 0.5;                          // kg
  const double zeta = 20.0 / (2.0 * std::sqrt(1e5 * mu));
  const double e = std::exp(-zeta * (M_PI - 2.0 * std::asin(zeta)) / std::sqrt(1.0 - zeta * zeta));
  const double last = std::pow(0.5 * (1.0 + e), 4);  // m/s, disk_5 after four impacts from 1 m/s
  const auto& d5 = r.bodies.back();
  ASSERT_EQ(d5.name, "disk_5");
  // 1e-6 relative: the bound (exact geometry, rtol 1e-10)
  EXPECT_NEAR(d5.velocity_mps.back().x(), last, 1e-6 * last);
  // momentum exact: 1 kg m/s throughout
  double p = 0.0;
  for (const auto& b : r.bodies) p += 1.0 * b.velocity_mps.back().x();
  EXPECT_NEAR(p, 1.0, 1e-9);  // rounding of 1e5 steps' sums, far below
  ASSERT_EQ(r.events.size(), 4u);
  for (const ContactEpisode& ep : r.events) EXPECT_NEAR(ep.restitution, e, 1e-6);
}

TEST(ReferenceScenes, PyramidReleasedTouchingCarriesItsWeightOnTheGround) {
  // 15 bricks settle onto compliant contacts; once settled the ground carries
  // N m g (statics), and no brick has slid off (friction holds them)
  // 1 s of the scene's 2 (CI time: the reference's pyramid_5 is ~45 s a
  // simulated second under the sanitizers); settled long before, see below
  const Case c = test::scene_case("pyramid_5", 1.0);
  const RunResult r = run(c);
  ASSERT_EQ(r.status, RunStatus::ok) << r.reason;
  std::map<double, double> ground;  // N at each stored sample
  for (const ContactRow& row : r.contacts) {
    if (row.sample.body_a == 0) ground[row.time_s] += row.sample.force_n;
  }
  ASSERT_FALSE(ground.empty());
  const double weight = 15.0 * 9.8066;
  // 1e-6 relative at the end: the transient (damping ratio 1, ~100 rad/s and
  // faster) has decayed by e^-100 over the 1 s
  EXPECT_NEAR(ground.rbegin()->second, weight, 1e-6 * weight);
  // the top sinks by the bricks' compliance: 4 interfaces of up to ~7 m g / K
  // each, so between one brick's 1e-5 m and 1e-3 m
  const auto& top = r.bodies.back();
  const double sag = top.position_m.front().y() - top.position_m.back().y();
  EXPECT_GT(sag, 1e-5);
  EXPECT_LT(sag, 1e-3);
}

TEST(ReferenceScenes, StartingPressedInAtManyPairsSettles) {
  // before: more than 3 pairs pressed in at t = 0 stopped with "contact phases
  // do not settle"; stack_50 presses 50
  Case c = test::scene_case("stack_50");
  c.duration_s = 0.01;
  const RunResult r = run(c);
  EXPECT_EQ(r.status, RunStatus::ok) << r.reason;
}

}  // namespace
}  // namespace pb
