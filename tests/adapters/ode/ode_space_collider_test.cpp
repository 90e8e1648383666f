// Tests for adapters/ode/ode_space_collider.cpp
#include "ode_space_collider.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include "ode_library.hpp"
#include "ode_test_cases.hpp"
#include "planarbench/contact_pairs.hpp"

namespace pb::internal::ode {
namespace {

using ode_test::disk_body;
using ode_test::ground_body;
using ode_test::pair;

const ContactLaw kKv = KelvinVoigt{1e4, 10.0, 0.0};

ContactGroup group(const std::string& name, std::vector<int> bodies, double friction = 0.0) {
  ContactGroup g;
  g.name = name;
  g.bodies = std::move(bodies);
  g.law = kKv;
  g.friction = friction;
  return g;
}

// Disk A (R = 0.1 m) 1 mm into the ground, disk B 2 mm into A from above,
// disk C far up in the air; one group holds all four bodies. The ground is a
// plane (an infinite box in ODE's broad phase), so ODE hands the near
// callback every disk against it, but only the two pairs dCollide reports
// are registered: ground-A and A-B, not ground-B, ground-C, A-C or B-C (the
// pairs ContactPairs would list up front: 6). Normals from body_a to body_b,
// body_a the fixed body, else the lower index: both up. 1e-12 m: rounding
// of sums of 0.1 m lengths; 1e-15 on unit normals.
TEST(OdeSpaceCollider, RegistersOnlyThePairsOdeReports) {
  ensure_ode_ready_in_this_thread();
  Case c;
  c.bodies = {ground_body(), disk_body("a", 0.1, 1.0, Vec2(0.0, 0.099)),
              disk_body("b", 0.1, 1.0, Vec2(0.0, 0.297)),
              disk_body("c", 0.1, 1.0, Vec2(5.0, 5.0))};
  c.contact_groups = {group("all", {0, 1, 2, 3})};
  OdeWorld world(c);
  ContactPairs pairs(c);
  SpaceCollider collider(c, world, pairs);
  StepContacts out;
  collider.collide(out);
  ASSERT_EQ(pairs.size(), 2);
  ASSERT_EQ(out.pairs.size(), 2u);
  for (const PairContact& pc : out.pairs) {
    const ContactPair& cp = pairs[pc.pair];
    EXPECT_NEAR(pc.normal_ab.y(), 1.0, 1e-15) << cp.name;
    if (cp.body_a == 0) {
      EXPECT_EQ(cp.body_b, 1);
      EXPECT_NEAR(pc.depth_m, 1e-3, 1e-12);
    } else {
      EXPECT_EQ(cp.body_a, 1);
      EXPECT_EQ(cp.body_b, 2);
      EXPECT_NEAR(pc.depth_m, 2e-3, 1e-12);
    }
    // g1 has a body (a joint on (0, body) is stored reversed by ODE)
    EXPECT_NE(dGeomGetBody(out.geom(pc, 0).g1), nullptr);
  }
  EXPECT_LT(out.pairs[0].pair, out.pairs[1].pair);  // ascending pair index
}

// A declared pair takes precedence for its two bodies and a body outside
// every group touches only through its declared pairs: disks 1 and 2 in the
// group with the ground, disk 3 in no group but declared against disk 1
// (its own law). All three disks overlap each other and press into the
// ground; ODE's bits keep disk 3 from the ground and from disk 2.
TEST(OdeSpaceCollider, GroupsBitsAndDeclaredPairs) {
  ensure_ode_ready_in_this_thread();
  Case c;
  c.bodies = {ground_body(), disk_body("d1", 0.1, 1.0, Vec2(0.0, 0.099)),
              disk_body("d2", 0.1, 1.0, Vec2(0.19, 0.099)),
              disk_body("d3", 0.1, 1.0, Vec2(0.095, 0.099))};
  c.contacts = {pair(3, 1, KelvinVoigt{5e4, 1.0, 0.0}, "declared")};
  c.contact_groups = {group("g", {0, 1, 2})};
  OdeWorld world(c);
  ContactPairs pairs(c);
  EXPECT_EQ(rule_bits(pairs, c, 0), 1UL);
  EXPECT_EQ(rule_bits(pairs, c, 1), 1UL | (1UL << 63U));
  EXPECT_EQ(rule_bits(pairs, c, 3), 1UL << 63U);
  SpaceCollider collider(c, world, pairs);
  StepContacts out;
  collider.collide(out);
  std::vector<std::pair<int, int>> seen;
  for (const PairContact& pc : out.pairs) {
    seen.emplace_back(pairs[pc.pair].body_a, pairs[pc.pair].body_b);
  }
  // the declared pair keeps index 0 and its own order (d3 -> d1), then the
  // group's ground-d1, ground-d2, d1-d2 in the order ODE found them
  ASSERT_EQ(out.pairs.size(), 4u);
  EXPECT_EQ(out.pairs[0].pair, 0);
  EXPECT_EQ(seen[0], std::make_pair(3, 1));
  EXPECT_EQ(pairs.size(), 4);
  for (const auto& p : seen) {
    EXPECT_NE(p, std::make_pair(0, 3));
    EXPECT_NE(p, std::make_pair(2, 3));
  }
  EXPECT_TRUE(std::holds_alternative<KelvinVoigt>(pairs[0].law));
  EXPECT_EQ(std::get<KelvinVoigt>(pairs[0].law).stiffness_n_per_m, 5e4);
  // d3 -> d1: the normal points from d3 to d1, along -x
  EXPECT_NEAR(out.pairs[0].normal_ab.x(), -1.0, 1e-15);
}

// Two fixed bodies never touch, even overlapping in one group: a fixed disk
// sunk into the ground gives no pair.
TEST(OdeSpaceCollider, TwoFixedBodiesNeverCollide) {
  ensure_ode_ready_in_this_thread();
  Case c;
  c.bodies = {ground_body(), disk_body("post", 0.1, 1.0, Vec2(0.0, 0.05)),
              disk_body("free", 0.1, 1.0, Vec2(3.0, 0.099))};
  c.bodies[1].fixed = true;
  c.bodies[1].mass_kg = 0.0;
  c.bodies[1].inertia_kgm2 = 0.0;
  c.contact_groups = {group("all", {0, 1, 2})};
  OdeWorld world(c);
  ContactPairs pairs(c);
  SpaceCollider collider(c, world, pairs);
  StepContacts out;
  collider.collide(out);
  ASSERT_EQ(out.pairs.size(), 1u);
  EXPECT_EQ(pairs[out.pairs[0].pair].body_b, 2);
}

// A pair keeps its index once registered: colliding the same state again
// gives the same pairs, contacts and bits, and adds nothing.
TEST(OdeSpaceCollider, SameStateSameContacts) {
  ensure_ode_ready_in_this_thread();
  Case c;
  c.bodies = {ground_body()};
  std::vector<int> members = {0};
  for (int k = 0; k < 12; ++k) {
    c.bodies.push_back(disk_body(fmt::format("d{}", k), 0.1, 1.0,
                                 Vec2(0.19 * (k % 4), 0.099 + 0.19 * (k / 4))));
    members.push_back(k + 1);
  }
  c.contact_groups = {group("all", members, 0.5)};
  OdeWorld world(c);
  ContactPairs pairs(c);
  SpaceCollider collider(c, world, pairs);
  StepContacts first;
  StepContacts again;
  collider.collide(first);
  const int registered = pairs.size();
  collider.collide(again);
  EXPECT_EQ(pairs.size(), registered);
  // 4 on the ground, 3 x 3 side by side, 4 x 2 one above the other
  EXPECT_EQ(registered, 4 + 9 + 8);
  ASSERT_EQ(first.pairs.size(), again.pairs.size());
  for (std::size_t e = 0; e < first.pairs.size(); ++e) {
    EXPECT_EQ(first.pairs[e].pair, again.pairs[e].pair);
    EXPECT_EQ(first.pairs[e].depth_m, again.pairs[e].depth_m);
    EXPECT_EQ(first.pairs[e].point_m, again.pairs[e].point_m);
  }
}

}  // namespace
}  // namespace pb::internal::ode
