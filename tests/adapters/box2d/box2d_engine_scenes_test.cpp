// Tests for adapters/box2d/box2d_engine.cpp on scenes (SPEC §11): contact
// groups through Box2D's own broad phase, the case files of cases/scenes run
// on the real library.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "box2d_test_cases.hpp"
#include "planarbench/adapters/box2d_engine.hpp"
#include "planarbench/case_loader.hpp"
#include "planarbench/runner.hpp"
#include "scene_cases.hpp"

namespace pb {
namespace {

using box2d_test::overrides;

// stack_10 (ten 1 kg boxes at their resting pose): Box2D's rigid contact
// holds it, interface k from the top carries k m g (SPEC §11), and nothing
// moves. Box2D collides the case's faces exactly (the adapter insets each
// box by the skin, box2d_geometry.hpp), so each interface starts at a
// separation within the slop, where the position solver does not act, and
// warm-started impulses hold the weights. Tolerances: the force, float
// impulses summed over 8 iterations, 1e-5 relative (measured 6e-8); the
// drift, 1e-5 m (measured 7e-7 m, ~10 float ulps at 1 m; a stack built from
// b2PolygonShape::SetAsBox, skin outside the faces, rises 0.15 m).
TEST(Box2dScenes, StackHoldsAndCarriesTheWeights) {
  Case c = test::scene_case("stack_10");
  c.duration_s = 0.5;
  auto e = make_box2d_engine();
  const RunResult r = run_engine(*e, c, {});
  ASSERT_EQ(r.status, RunStatus::ok) << r.reason;
  const double g = c.gravity_mps2.norm();
  const double t_end = r.contacts.back().time_s;
  int interfaces = 0;
  for (const ContactRow& row : r.contacts) {
    if (row.time_s != t_end) continue;
    const ContactSample& s = row.sample;
    // interface below box_i carries the 11 - i boxes from box_i up
    const std::string upper = c.bodies[static_cast<std::size_t>(s.body_b)].name;
    const int i = std::stoi(upper.substr(upper.find('_') + 1));
    const double weight = (11 - i) * 1.0 * g;  // N
    EXPECT_NEAR(s.force_n, weight, 1e-5 * weight) << upper;
    ++interfaces;
  }
  EXPECT_EQ(interfaces, 10);
  for (const BodyTrajectory& b : r.bodies) {
    for (const Vec2& p : b.position_m) EXPECT_LT((p - b.position_m.front()).norm(), 1e-5) << b.name;
  }
}

// cradle_5: five 1 kg disks with gaps, the striker at 1 m/s, no gravity.
// Each binary impact of equal masses with restitution e sends the struck
// disk on at u (1 + e) / 2 and leaves the striker u (1 - e) / 2 (closed
// form), e of the clamped Kelvin-Voigt law at the reduced mass 0.5 kg, so
// the row ends at v (1 - e) / 2 x ((1 + e) / 2)^(i - 1), the last disk at
// v ((1 + e) / 2)^4. Momentum is exact. Tolerances: float32 velocities,
// 1e-6 m/s (six roundings of ~1 m/s at 6e-8; measured 2e-8).
TEST(Box2dScenes, CradleChainsBinaryImpactsAndKeepsMomentum) {
  const Case c = test::scene_case("cradle_5");
  auto e = make_box2d_engine();
  const RunResult r = run_engine(*e, c, {});
  ASSERT_EQ(r.status, RunStatus::ok) << r.reason;
  ASSERT_EQ(r.bodies.size(), 5u);
  const double rest = box2d_test::clamped_kv_restitution(1e5, 20.0, 0.5);
  double u = 1.0;  // m/s, the moving disk's speed before its impact
  for (std::size_t i = 0; i < 5; ++i) {
    const double expected = i < 4 ? u * (1.0 - rest) / 2.0 : u;
    EXPECT_NEAR(r.bodies[i].velocity_mps.back().x(), expected, 1e-6) << r.bodies[i].name;
    u *= (1.0 + rest) / 2.0;
  }
  for (std::size_t k = 0; k < r.bodies[0].time_s.size(); ++k) {
    double momentum = 0.0;  // kg m/s
    for (const BodyTrajectory& b : r.bodies) momentum += b.velocity_mps[k].x();
    ASSERT_NEAR(momentum, 1.0, 1e-6) << r.bodies[0].time_s[k];
  }
  EXPECT_EQ(r.events.size(), 4u);  // one episode per binary impact
}

// pile_100 for 1 s (100 disks fall 0.07-1.3 m into a box and pile up): no
// disk leaves the box or sinks into the ground beyond 1 mm (Box2D holds
// circles on chains within float, measured 7e-5 m; a disk through the ground
// falls on), the energy never exceeds its start (rigid impacts with e < 1,
// friction: passive; 1e-6 relative for float positions), and the pairs
// indexed are those Box2D's broad phase paired (measured 952 of the 5250
// the group allows: the pairs that came within Box2D's fat AABBs, 0.1 m
// margin), not all.
TEST(Box2dScenes, PileStaysInItsBoxAndIndexesOnlyNearPairs) {
  Case c = test::scene_case("pile_100");
  c.duration_s = 1.0;
  auto e = make_box2d_engine();
  const RunResult r = run_engine(*e, c, {});
  ASSERT_EQ(r.status, RunStatus::ok) << r.reason;
  const double radius = 0.05, mass = 0.1, g = c.gravity_mps2.norm();
  auto energy = [&](std::size_t k) {
    double j = 0.0;
    for (const BodyTrajectory& b : r.bodies) {
      j +=
          0.5 * mass * b.velocity_mps[k].squaredNorm() + mass * g * b.position_m[k].y() +
          0.25 * mass * radius * radius * b.angular_velocity_radps[k] * b.angular_velocity_radps[k];
    }
    return j;
  };
  const double e0 = energy(0);
  for (std::size_t k = 0; k < r.bodies[0].time_s.size(); ++k) {
    ASSERT_LE(energy(k), e0 * (1.0 + 1e-6)) << r.bodies[0].time_s[k];
  }
  for (const BodyTrajectory& b : r.bodies) {
    for (const Vec2& p : b.position_m) {
      ASSERT_GT(p.y(), radius - 1e-3) << b.name;
      ASSERT_LT(std::abs(p.x()), 0.65 - radius + 1e-3) << b.name;
    }
  }
  const int bodies = static_cast<int>(c.bodies.size());
  const int possible = bodies * (bodies - 1) / 2 - 3;  // the three half-planes never pair
  const int indexed = r.extra.at("contact_pairs_indexed").get<int>();
  EXPECT_GT(indexed, 100);  // the disks did meet
  EXPECT_LT(indexed, possible / 4);
}

// A disk dropped 0.2 m onto flat ground, ground and disk one contact group,
// sampled every 1e-3 s at dt 1e-4 s. The contacts table's force is the mean
// over each output interval (box2d.reported_force = auto, a case with
// groups): summed over the samples x 1e-3 s it is the impulse the solver
// gave, which the episodes also sum (1e-9 relative: the same impulses added
// in another order). The last step's impulse / dt alone (reported_force =
// step) samples one step in ten: a bounce's one-step impulse counts ten
// times when it lands on a sample and not at all when it does (measured:
// 6.0 times the impulse here).
TEST(Box2dScenes, ReportedForceIsTheIntervalsMeanImpulse) {
  Case c = box2d_test::make_case("drop_group", 1.0);
  c.output_interval_s = 1e-3;
  c.bodies = {box2d_test::ground_body(), box2d_test::disk_body("disk", 0.1, 0.1, Vec2(0.0, 0.3))};
  ContactGroup g;
  g.name = "all";
  g.bodies = {0, 1};
  g.law = KelvinVoigt{1e4, 4.0, 0.0};  // zeta 0.063 at 0.1 kg: e = 0.82, several bounces
  c.contact_groups = {g};
  for (const char* mode : {"auto", "step"}) {
    auto e = make_box2d_engine();
    e->build(c, overrides({{"box2d.reported_force", mode}}));
    double table_ns = 0.0;  // N s
    std::vector<ContactSample> cs;
    for (int k = 1; k <= 1000; ++k) {
      e->advance_to(k * 1e-3);
      e->contacts(cs);
      for (const ContactSample& s : cs) table_ns += s.force_n * 1e-3;
    }
    double episodes_ns = 0.0;  // N s
    for (const ContactEpisode& ep : e->episodes()) episodes_ns += ep.impulse_ns;
    EXPECT_GT(episodes_ns, 0.5) << mode;  // the bounces and 0.6 s at rest
    if (std::string(mode) == "auto") {
      EXPECT_NEAR(table_ns, episodes_ns, 1e-9 * episodes_ns);
    } else {
      EXPECT_GT(std::abs(table_ns - episodes_ns), 0.01 * episodes_ns);
    }
  }
}

// On a case of declared pairs whose dt is its output interval (block_slide:
// 1e-4 s, a slab sliding to rest with friction), the interval's mean is the
// last step's impulse / dt: every row of the table the same, bit for bit,
// whichever reported_force.
TEST(Box2dScenes, IntervalForceIsTheStepForceWhenDtIsTheInterval) {
  const Case c = load_case(PB_CASES_DIR "/block_slide.toml");
  auto e = make_box2d_engine();
  const RunResult a = run_engine(*e, c, overrides({{"box2d.reported_force", "step"}}));
  const RunResult b = run_engine(*e, c, overrides({{"box2d.reported_force", "interval"}}));
  ASSERT_EQ(a.contacts.size(), b.contacts.size());
  ASSERT_GT(a.contacts.size(), 100u);
  for (std::size_t k = 0; k < a.contacts.size(); ++k) {
    ASSERT_EQ(a.contacts[k].sample.force_n, b.contacts[k].sample.force_n) << k;
    ASSERT_EQ(a.contacts[k].sample.tangential_force_n, b.contacts[k].sample.tangential_force_n);
  }
}

// A declared pair inside a group keeps its own law (SPEC §11): two 1 kg
// disks dropped 0.3 m, side by side, the group's Kelvin-Voigt c = 10 N s/m
// (e = 0.859), the declared ground-right pair's c = 100 N s/m (e = 0.30).
// Each first onset takes its rule's restitution at m_eff = 1 kg (1e-6: the
// float normal and mass data in m_eff), the group pair named by its group,
// and each disk's first bounce has it (gravity acts over the episode's
// steps, impulse step and interpolated onset and offset: 3 (1 + e) g dt / v;
// measured 1.1e-3 at e = 0.30, where 2 of them, box2d_engine_test's bound
// for e = 0.86, is 1.05e-3).
TEST(Box2dScenes, DeclaredPairInAGroupKeepsItsLaw) {
  Case c = box2d_test::make_case("group_and_pair", 0.5);
  c.bodies = {box2d_test::ground_body(), box2d_test::disk_body("left", 0.1, 1.0, Vec2(-1.0, 0.4)),
              box2d_test::disk_body("right", 0.1, 1.0, Vec2(1.0, 0.4))};
  ContactGroup grp;
  grp.name = "all";
  grp.bodies = {0, 1, 2};
  grp.law = KelvinVoigt{1e4, 10.0, 0.0};
  c.contact_groups = {grp};
  c.contacts = {box2d_test::kv_pair(0, 2, 1e4, 100.0)};
  auto e = make_box2d_engine();
  const RunResult r = run_engine(*e, c, {});
  ASSERT_EQ(r.status, RunStatus::ok) << r.reason;
  bool group_seen = false, pair_seen = false;
  for (const auto& onset : r.mapping.at("onsets")) {
    const std::string name = onset.at("contact").get<std::string>();
    const double rest = onset.at("restitution").get<double>();
    if (name == "all:ground-left" && !group_seen) {
      EXPECT_NEAR(rest, box2d_test::clamped_kv_restitution(1e4, 10.0, 1.0), 1e-6);
      group_seen = true;
    } else if (name == "pair" && !pair_seen) {
      EXPECT_NEAR(rest, box2d_test::clamped_kv_restitution(1e4, 100.0, 1.0), 1e-6);
      pair_seen = true;
    }
  }
  EXPECT_TRUE(group_seen);
  EXPECT_TRUE(pair_seen);
  const double g = c.gravity_mps2.norm(), v = std::sqrt(2.0 * g * 0.3), dt = 1e-4;
  for (const int disk : {1, 2}) {
    const double rest = box2d_test::clamped_kv_restitution(1e4, disk == 1 ? 10.0 : 100.0, 1.0);
    for (const ContactEpisode& ep : r.events) {
      if (ep.body_b != disk) continue;
      EXPECT_NEAR(ep.restitution, rest, 3.0 * (1.0 + rest) * g * dt / v) << disk;
      break;
    }
  }
}

// Force injection applies the law to declared pairs only: a case with groups
// is refused there, not run with its group pairs left out.
TEST(Box2dScenes, InjectModeRefusesContactGroups) {
  const Case c = test::scene_case("stack_2");
  auto e = make_box2d_engine();
  const RunResult r = run_engine(*e, c, overrides({{"box2d.mode", "inject"}}));
  EXPECT_EQ(r.status, RunStatus::unsupported);
  EXPECT_NE(r.reason.find("contact groups"), std::string::npos) << r.reason;
}

}  // namespace
}  // namespace pb
