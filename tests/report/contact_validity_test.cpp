// Tests for reports/src/contact_validity.cpp on constructed series whose
// violations are known by construction (issue 32): a force outside the cone by
// 10 %, friction short of the maximum dissipation, a stick that creeps, a
// force at a distance, a frictionless pair with a tangential force, rows
// without the tangential columns, and two pairs interleaved.
#include "planarbench/reports/contact_validity.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pb {
namespace {

constexpr double kMu = 0.5;
constexpr double kDt = 1e-3;  // s, the output interval

Case two_pair_case() {
  Case c;
  c.output_interval_s = kDt;
  ContactPair ground;
  ground.name = "ground_box";
  ground.body_a = 0;
  ground.body_b = 1;
  ground.friction = kMu;
  ContactPair smooth;
  smooth.name = "wall_box";
  smooth.body_a = 2;
  smooth.body_b = 1;
  smooth.friction = 0.0;
  c.contacts = {ground, smooth};
  return c;
}

ContactRow row(double t, int a, int b, double fn, double pen, double ft, double slip) {
  ContactRow r;
  r.time_s = t;
  r.sample.body_a = a;
  r.sample.body_b = b;
  r.sample.force_n = fn;
  r.sample.penetration_m = pen;
  r.sample.normal = Vec2(0.0, 1.0);
  r.sample.tangential_force_n = ft;
  r.sample.slip_mps = slip;
  return r;
}

TEST(ContactValidity, AForceOutsideTheConeBy10PercentIsMeasured) {
  RunResult r;
  // 100 samples sliding at 0.2 m/s with F_t = -mu F_n, one at -1.1 mu F_n
  for (int i = 0; i < 100; ++i) {
    r.contacts.push_back(row(kDt * i, 0, 1, 10.0, 1e-5, i == 40 ? -5.5 : -5.0, 0.2));
  }
  const PairValidity v = contact_validity(two_pair_case(), r)[0];
  EXPECT_EQ(v.pair, "ground_box");
  EXPECT_EQ(v.samples, 100);
  EXPECT_EQ(v.cone.samples, 100);
  EXPECT_NEAR(v.cone.max, 0.1, 1e-15);  // (5.5 - 5) / 5, rounding only
  EXPECT_EQ(v.cone.p99, 0.0);           // the 99th smallest of 99 zeros and one 0.1
  EXPECT_DOUBLE_EQ(v.cone.fraction_above, 0.01);
  // beyond the cone the friction over-dissipates: 1 - 1.1 = -0.1, never above 0
  EXPECT_EQ(v.dissipation.max, 0.0);
  EXPECT_EQ(v.stick_creep_mps.samples, 0);  // always sliding
}

TEST(ContactValidity, FrictionShortOfTheMaximumDissipationIsItsDeficit) {
  RunResult r;
  // F_t = -0.8 mu F_n against a 0.2 m/s slip for 1 s: 1 + (-0.8) = 0.2, and
  // the deficit is 0.2 mu F_n |v| T = 0.2 * 5 N * 0.2 m/s * 1 s = 0.2 J
  for (int i = 0; i <= 1000; ++i) r.contacts.push_back(row(kDt * i, 0, 1, 10.0, 1e-5, -4.0, 0.2));
  const PairValidity v = contact_validity(two_pair_case(), r)[0];
  // 1e-15: 1 - 4 / 5 in doubles, rounding only
  EXPECT_NEAR(v.dissipation.max, 0.2, 1e-15);
  EXPECT_NEAR(v.dissipation.p99, 0.2, 1e-15);
  EXPECT_EQ(v.dissipation.fraction_above, 1.0);
  EXPECT_NEAR(v.power_deficit_j, 0.2, 1e-12);  // 1000 trapezoids of 2e-4 J: rounding
  EXPECT_EQ(v.cone.max, 0.0);
  // a gap of 10 output intervals between two sliding samples is not integrated
  RunResult gap;
  gap.contacts = {row(0.0, 0, 1, 10.0, 1e-5, -4.0, 0.2), row(10 * kDt, 0, 1, 10.0, 1e-5, -4.0, 0.2)};
  EXPECT_TRUE(std::isnan(contact_validity(two_pair_case(), gap)[0].power_deficit_j));
}

TEST(ContactValidity, AStickThatCreepsIsToldFromATrueStick) {
  RunResult creeping, sticking;
  for (int i = 0; i < 50; ++i) {
    // F_t = 0.45 F_n: inside the cone mu = 0.5
    creeping.contacts.push_back(row(kDt * i, 0, 1, 10.0, 1e-5, 4.5, 5e-5));
    sticking.contacts.push_back(row(kDt * i, 0, 1, 10.0, 1e-5, 4.5, i % 2 ? 1e-12 : -1e-12));
  }
  const PairValidity c = contact_validity(two_pair_case(), creeping)[0];
  EXPECT_EQ(c.stick_creep_mps.samples, 50);
  EXPECT_EQ(c.stick_creep_mps.max, 5e-5);
  EXPECT_EQ(c.stick_creep_mps.fraction_above, 1.0);  // floor 1e-6 m/s
  const PairValidity s = contact_validity(two_pair_case(), sticking)[0];
  EXPECT_EQ(s.stick_creep_mps.max, 1e-12);
  EXPECT_EQ(s.stick_creep_mps.fraction_above, 0.0);
  EXPECT_EQ(s.dissipation.samples, 0);  // never sliding
  // at the cone's edge (F_t = mu F_n) the load is not strictly inside it: no creep read
  RunResult edge;
  edge.contacts = {row(0.0, 0, 1, 10.0, 1e-5, 5.0, 5e-5)};
  EXPECT_EQ(contact_validity(two_pair_case(), edge)[0].stick_creep_mps.samples, 0);
}

TEST(ContactValidity, AForceAtADistanceAndATangentOnAFrictionlessPairAreMeasured) {
  RunResult r;
  r.contacts = {row(0.0, 0, 1, 3.0, -1e-6, 0.0, 0.0),   // open by 1 um, pushed with 3 N
                row(kDt, 0, 1, 2.0, 1e-6, 0.0, 0.0),     // pressed: no violation
                row(0.0, 1, 2, 8.0, 1e-6, 0.8, 0.1)};    // frictionless wall, F_t = 0.1 F_n (either order of bodies)
  const auto v = contact_validity(two_pair_case(), r);
  ASSERT_EQ(v.size(), 2u);
  EXPECT_EQ(v[0].force_at_distance_n.samples, 1);
  EXPECT_EQ(v[0].force_at_distance_n.max, 3.0);
  EXPECT_EQ(v[1].pair, "wall_box");
  EXPECT_EQ(v[1].samples, 1);
  EXPECT_NEAR(v[1].frictionless_tangent.max, 0.1, 1e-16);  // 0.8 / 8 in doubles: rounding only
  EXPECT_EQ(v[1].cone.samples, 0);  // no cone without friction
}

TEST(ContactValidity, RowsWithoutTheTangentialColumnsAreNotRecordedNotZero) {
  RunResult r;
  const double nan = std::nan("");
  for (int i = 0; i < 10; ++i) r.contacts.push_back(row(kDt * i, 0, 1, 10.0, 1e-5, nan, nan));
  r.contacts.push_back(row(10 * kDt, 0, 1, 10.0, 1e-5, -5.0, nan));  // slip alone missing
  const PairValidity v = contact_validity(two_pair_case(), r)[0];
  EXPECT_EQ(v.samples, 11);
  EXPECT_EQ(v.not_recorded, 11);
  EXPECT_EQ(v.cone.samples, 0);
  EXPECT_TRUE(std::isnan(v.cone.max));
  EXPECT_TRUE(std::isnan(v.cone.fraction_above));
  EXPECT_TRUE(std::isnan(v.power_deficit_j));
  // a run without contacts: every pair, nothing measured
  const auto none = contact_validity(two_pair_case(), RunResult{});
  ASSERT_EQ(none.size(), 2u);
  EXPECT_EQ(none[1].samples, 0);
}

}  // namespace
}  // namespace pb
