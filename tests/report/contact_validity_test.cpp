// Tests for reports/src/contact_validity.cpp on constructed series whose
// violations are known by construction (issue 32): a force outside the cone by
// 10 %, friction short of the maximum dissipation, a stick that creeps, a
// force at a distance, a frictionless pair with a tangential force, rows
// without the tangential columns, and two pairs interleaved.
#include "planarbench/reports/contact_validity.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "body_on_ground.hpp"

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

// A disk (body 1) on a fixed half-plane (body 0), pressed along +y: the normal
// from the ground to the disk is +y, the penetration rate -v_y.
Case disk_on_ground(const ContactLaw& law) {
  return test::body_on_ground("disk_case", "disk", Circle{0.1}, 0.0, law);
}

// the disk's trajectory and a row per sample: penetration 1e-3 m, the centre
// moving down at `vy` (so the rate is -vy), force `fn(i)`
RunResult disk_run(const std::vector<double>& vy, const std::vector<double>& fn) {
  RunResult r;
  BodyTrajectory t;
  t.name = "disk";
  for (std::size_t i = 0; i < vy.size(); ++i) {
    const double time = kDt * static_cast<double>(i);
    t.time_s.push_back(time);
    t.position_m.emplace_back(0.0, 0.1 - 1e-3);
    t.angle_rad.push_back(0.0);
    t.velocity_mps.emplace_back(0.0, vy[i]);
    t.angular_velocity_radps.push_back(3.0);  // spin: tangential at the point, no normal rate
    ContactRow row;
    row.time_s = time;
    row.sample.body_a = 0;
    row.sample.body_b = 1;
    row.sample.force_n = fn[i];
    row.sample.penetration_m = 1e-3;
    row.sample.normal = Vec2(0.0, 1.0);
    row.sample.point_m = Vec2(0.0, -5e-4);
    row.sample.tangential_force_n = 0.0;
    row.sample.slip_mps = 0.0;
    r.contacts.push_back(row);
  }
  r.bodies = {t};
  return r;
}

TEST(ContactValidity, TheNormalLawResidualReadsTheRateFromTheBodyStates) {
  // Kelvin-Voigt K = 1e4 N/m, c = 10 N s/m: at 1 mm approaching at 0.5 m/s
  // the law gives 10 + 5 = 15 N; separating at 0.5 m/s, 5 N
  const Case c = disk_on_ground(KelvinVoigt{1e4, 10.0, 0.0});
  std::vector<double> vy = {-0.5, -0.5, 0.5, 0.5};
  std::vector<double> fn = {15.0, 15.0, 5.0, 5.0};
  fn[2] = 5.0 + 1.5;  // 10 % of the pair's peak (15 N) off the law on one sample
  const PairValidity v = contact_validity(c, disk_run(vy, fn))[0];
  EXPECT_EQ(v.law_residual.samples, 4);
  EXPECT_NEAR(v.law_residual.max, 0.1, 1e-14);  // 1.5 / 15 after sums of 1e4 * 1e-3: rounding
  EXPECT_DOUBLE_EQ(v.law_residual.fraction_above, 0.25);
  // complementarity: a normal force on a separating contact, F_n (-rate) =
  // 6.5 N x 0.5 m/s = 3.25 W, then 2.5 W; approaching rows give 0
  EXPECT_NEAR(v.complementarity_w.max, 3.25, 1e-15);  // 6.5 x (-(-0.5)): one product, rounding only
  EXPECT_EQ(v.complementarity_w.samples, 4);
  EXPECT_DOUBLE_EQ(v.complementarity_w.fraction_above, 0.5);
}

TEST(ContactValidity, LankaraniNikraveshReadsItsApproachSpeedFromTheRunsEpisode) {
  // F = K delta^1.5 (1 + 0.75 (1 - e^2) rate / approach): K = 1e6, delta =
  // 1e-3: 31.6228 N elastic; e = 0.5, rate 0.5 m/s of an approach at 1 m/s:
  // x (1 + 0.75 * 0.75 * 0.5)
  const Case c = disk_on_ground(LankaraniNikravesh{1e6, 1.5, 0.5, std::nullopt, {}});
  const double law = 1e6 * std::pow(1e-3, 1.5) * (1.0 + 0.75 * 0.75 * 0.5);
  RunResult r = disk_run({-0.5, -0.5}, {law, law});
  ContactEpisode e;
  e.body_a = 0;
  e.body_b = 1;
  e.onset_time_s = 0.0;
  e.offset_time_s = std::nan("");
  e.approach_speed_mps = 1.0;
  r.events = {e};
  const PairValidity v = contact_validity(c, r)[0];
  EXPECT_LT(v.law_residual.max, 1e-15);  // the same law from the same doubles: rounding
  // without the episode the law is its elastic part alone: off by 28 % of it
  r.events.clear();
  // 1e-12: K delta^1.5 through pow, times 1.28125, and a quotient: a few ulp of 1
  EXPECT_NEAR(contact_validity(c, r)[0].law_residual.max, 1.0 - 1.0 / (1.0 + 0.28125), 1e-12);
}

TEST(ContactValidity, AFacedPairHasNoLawResidualAndAMissingBodySampleNone) {
  Case faced = disk_on_ground(KelvinVoigt{1e4, 10.0, 0.0});
  faced.bodies[1].shape = Polygon{{Vec2(-0.1, -0.1), Vec2(0.1, -0.1), Vec2(0.1, 0.1), Vec2(-0.1, 0.1)}};
  const RunResult r = disk_run({-0.5}, {15.0});
  EXPECT_EQ(contact_validity(faced, r)[0].law_residual.samples, 0);
  EXPECT_EQ(contact_validity(faced, r)[0].complementarity_w.samples, 1);  // any shape
  // a row at a time the body was not sampled: no rate, neither series
  RunResult shifted = r;
  shifted.contacts[0].time_s = 0.5 * kDt;
  const PairValidity v = contact_validity(disk_on_ground(KelvinVoigt{1e4, 10.0, 0.0}), shifted)[0];
  EXPECT_EQ(v.law_residual.samples, 0);
  EXPECT_EQ(v.complementarity_w.samples, 0);
}

TEST(ContactValidity, TheGateReadsEachSeriesWorstPairAndLeavesOutWhatNoPairHas) {
  RunResult r;
  for (int i = 0; i < 10; ++i) r.contacts.push_back(row(kDt * i, 0, 1, 10.0, 1e-5, -5.5, 0.2));
  const auto m = validity_metrics(two_pair_case(), r);
  auto find = [&](const char* name) -> const MetricValue* {
    for (const auto& x : m) {
      if (x.metric == name) return &x;
    }
    return nullptr;
  };
  ASSERT_NE(find("cone_violation"), nullptr);
  EXPECT_NEAR(find("cone_violation")->error, 0.1, 1e-15);  // (5.5 - 5) / 5: rounding only
  EXPECT_EQ(find("cone_violation")->against, "self");
  EXPECT_NE(find("cone_violation")->note.find("ground_box"), std::string::npos);
  EXPECT_EQ(find("stick_creep"), nullptr);   // never inside the cone
  EXPECT_EQ(find("law_residual"), nullptr);  // no bodies to read a rate from
}

}  // namespace
}  // namespace pb
