// Tests for core/analytic/normal_contact_motion.cpp
#include "normal_contact_motion.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "independent_integrators.hpp"

namespace pb::internal {
namespace {

using testing::DiskLineIntegrator;
using testing::DiskLineProblem;

// The normal motion of a body above a line: the body is a disk of radius 1 m
// above the horizontal line y = 0, gravity a along y, so the gap u = y - 1.
// Each scenario is integrated independently in x-y (RK4, h = 2e-6 s, every
// switch of the clamped force located by bisection) and compared with the
// closed form: event times and the state on a 1 ms grid.
struct Scenario {
  const char* name;
  double stiffness;  // N/m
  double damping;    // N s/m
  double gravity;    // m/s^2 along the normal
  double gap0;       // m
  double rate0;      // m/s
  double duration;   // s
};

NormalContactParams params_of(const Scenario& s) {
  return NormalContactParams{1.0, s.stiffness, s.damping, s.gravity, s.gap0, s.rate0};
}

DiskLineProblem problem_of(const Scenario& s) {
  DiskLineProblem p;
  p.mass_kg = 1.0;
  p.radius_m = 1.0;
  p.stiffness_n_per_m = s.stiffness;
  p.damping_ns_per_m = s.damping;
  p.gravity_mps2 = testing::V2(0.0, s.gravity);
  p.line_point_m = testing::V2::Zero();
  p.line_normal = testing::V2(0.0, 1.0);
  p.position0_m = testing::V2(0.0, 1.0 + s.gap0);
  p.velocity0_mps = testing::V2(0.0, s.rate0);
  return p;
}

// event times of the closed form by the kind of transition
struct Events {
  std::vector<double> onsets, clamps, recontacts, offsets;
};
Events events_of(const NormalContactMotion& m, double until) {
  Events e;
  const auto& ph = m.phases();
  // a run that starts in contact has its onset at t = 0
  if (ph[0].kind != NormalPhaseKind::separated) e.onsets.push_back(0.0);
  for (std::size_t i = 1; i < ph.size() && ph[i].start_s <= until; ++i) {
    const auto from = ph[i - 1].kind;
    const auto to = ph[i].kind;
    const double t = ph[i].start_s;
    if (from == NormalPhaseKind::separated) e.onsets.push_back(t);
    if (from == NormalPhaseKind::pressed) {
      e.clamps.push_back(t);
      if (to == NormalPhaseKind::separated) e.offsets.push_back(t);
    }
    if (from == NormalPhaseKind::clamped) {
      (to == NormalPhaseKind::pressed ? e.recontacts : e.offsets).push_back(t);
    }
  }
  return e;
}

class NormalContactScenarios : public ::testing::TestWithParam<Scenario> {};

TEST_P(NormalContactScenarios, MatchesIndependentIntegration) {
  const Scenario& s = GetParam();
  NormalContactMotion m(params_of(s));
  m.extend_to(s.duration);
  DiskLineIntegrator ref(problem_of(s), 2e-6);

  // scales of the motion: gap ~ max(|u0|, v^2 / (2 g), v / w0); speed ~ sqrt(v0^2 + 2 g |u0|)
  const double w0 = std::sqrt(s.stiffness);
  const double speed = std::sqrt(s.rate0 * s.rate0 + 2.0 * std::abs(s.gravity * s.gap0));
  const double length = std::max({std::abs(s.gap0), speed / w0, 1e-3});
  double worst_gap = 0.0;
  double worst_rate = 0.0;
  double worst_force = 0.0;
  for (int k = 0; k * 1e-3 <= s.duration + 1e-12; ++k) {
    const double t = k * 1e-3;
    ref.advance_to(t);
    const NormalState ns = m.state_at(t);
    worst_gap = std::max(worst_gap, std::abs(ns.gap_m - (ref.position().y() - 1.0)));
    worst_rate = std::max(worst_rate, std::abs(ns.gap_rate_mps - ref.velocity().y()));
    worst_force = std::max(worst_force, std::abs(ns.force_n - ref.force()));
  }
  // 1e-9 of each scale: the acceptance criterion of issue 2. Measured: the
  // two agree to 1e-12 relative or better (RK4 at w0 h <= 2e-4 with
  // compensated sums, switches located to the last bit by both).
  EXPECT_LE(worst_gap, 1e-9 * length) << s.name;
  EXPECT_LE(worst_rate, 1e-9 * std::max(speed, 1e-2)) << s.name;
  EXPECT_LE(worst_force, 1e-9 * s.stiffness * length) << s.name;

  // every event, in the same order: located to ~1e-12 s by both
  const Events e = events_of(m, s.duration);
  auto same = [&](const std::vector<double>& a, const std::vector<double>& b, const char* what) {
    ASSERT_EQ(a.size(), b.size()) << s.name << " " << what;
    for (std::size_t i = 0; i < a.size(); ++i) {
      // 1e-12 s: the two locations agree to ~1e-14 s (the RK4 state error
      // divided by the rate of the switching function, plus rounding)
      EXPECT_NEAR(a[i], b[i], 1e-12) << s.name << " " << what << " #" << i;
    }
  };
  same(e.onsets, ref.onsets, "onsets");
  same(e.clamps, ref.clamps, "clamps");
  same(e.recontacts, ref.recontacts, "recontacts");
  same(e.offsets, ref.offsets, "offsets");
}

INSTANTIATE_TEST_SUITE_P(Scenarios, NormalContactScenarios,
                         ::testing::Values(
                             // the falling ball's normal motion: two bounces, zeta = 0.05
                             Scenario{"falling_ball", 1e4, 10.0, -8.492764724752476,
                                      2.232050807568877, 0.0, 2.5},
                             // a soft, lightly damped contact just hard enough to clamp: the force
                             // turns positive again before the body leaves (clamped -> pressed)
                             Scenario{"recontact", 100.0, 2.0, -9.8066, 0.0, -1.42, 1.0},
                             // no damping: force and gap reach zero together
                             Scenario{"undamped", 1e4, 0.0, -9.8066, 0.1, 0.0, 1.0},
                             // over-damped (zeta = 1.5): the body sinks in and stays
                             Scenario{"overdamped", 1e4, 300.0, -9.8066, 0.05, -2.0, 0.5},
                             // gravity away from the line: pushed in, thrown out, gone
                             Scenario{"gravity_away", 1e4, 10.0, 5.0, 0.0, -1.0, 0.3}),
                         [](const auto& p) { return std::string(p.param.name); });

// Free fall from rest at height h onto the line: onset at sqrt(2 h / g).
TEST(NormalContactMotion, FreeFallOnset) {
  NormalContactMotion m({1.0, 1e4, 10.0, -9.8066, 2.0, 0.0});
  m.extend_to(1.0);
  ASSERT_GE(m.phases().size(), 2u);
  EXPECT_EQ(m.phases()[1].kind, NormalPhaseKind::pressed);
  EXPECT_NEAR(m.phases()[1].start_s, std::sqrt(2.0 * 2.0 / 9.8066), 1e-15);  // rounding
  EXPECT_EQ(m.phases()[1].gap0_m, 0.0);
  EXPECT_NEAR(m.phases()[1].gap_rate0_mps, -std::sqrt(2.0 * 9.8066 * 2.0), 1e-14);
}

// Without gravity the clamped Kelvin-Voigt collision has the closed form of
// ENGINES.md: the force phase lasts (pi - 2 asin zeta) / w_d and the body
// leaves with e v, e = exp(-zeta (pi - 2 asin zeta) / sqrt(1 - zeta^2)).
TEST(NormalContactMotion, WithoutGravityTheClampedOscillatorClosedForm) {
  const double k = 1e4;
  const double c = 10.0;
  const double v = 3.0;
  NormalContactMotion m({1.0, k, c, 0.0, 0.0, -v});
  m.extend_to(1.0);
  const auto& ph = m.phases();
  ASSERT_EQ(ph.size(), 3u);  // pressed, clamped, separated
  EXPECT_EQ(ph[0].kind, NormalPhaseKind::pressed);
  EXPECT_EQ(ph[1].kind, NormalPhaseKind::clamped);
  EXPECT_EQ(ph[2].kind, NormalPhaseKind::separated);
  const double zeta = c / (2.0 * std::sqrt(k));
  const double wd = std::sqrt(k) * std::sqrt(1.0 - zeta * zeta);
  const double arc = std::numbers::pi - 2.0 * std::asin(zeta);
  EXPECT_NEAR(ph[1].start_s, arc / wd, 1e-16);  // the last bits of a 31 ms time
  const double e = std::exp(-zeta * arc / std::sqrt(1.0 - zeta * zeta));
  EXPECT_NEAR(ph[1].gap_rate0_mps, e * v, 1e-14);  // rounding of the exponential
  EXPECT_NEAR(ph[2].gap_rate0_mps, e * v, 1e-14);  // free flight out at constant speed
  // no further event, ever: the body flies away
  EXPECT_TRUE(std::isinf(m.known_until_s()));
}

// Undamped: the half period pi / w0 in contact, and the body leaves at the
// speed it came (elastic).
TEST(NormalContactMotion, UndampedContactIsAHalfPeriod) {
  NormalContactMotion m({1.0, 1e4, 0.0, 0.0, 0.0, -2.0});
  m.extend_to(1.0);
  const auto& ph = m.phases();
  ASSERT_EQ(ph.size(), 2u);
  EXPECT_EQ(ph[1].kind, NormalPhaseKind::separated);
  EXPECT_NEAR(ph[1].start_s, std::numbers::pi / 100.0, 1e-16);
  EXPECT_NEAR(ph[1].gap_rate0_mps, 2.0, 1e-14);
}

// Starting at rest exactly touching, pressed by gravity (the sliding case):
// the contact starts at t = 0, oscillates about the static gap m a / K and,
// with zeta = 0.05, never releases: no event is left to find.
TEST(NormalContactMotion, RestingStartSettlesWithoutRelease) {
  const double a = -6.934313360383997;
  NormalContactMotion m({1.0, 1e4, 10.0, a, 0.0, 0.0});
  m.extend_to(1.0);
  ASSERT_EQ(m.phases().size(), 1u);
  EXPECT_EQ(m.phases()[0].kind, NormalPhaseKind::pressed);
  EXPECT_TRUE(std::isinf(m.known_until_s()));
  EXPECT_DOUBLE_EQ(m.equilibrium_gap_m(), a / 1e4);
  // settled after 10 s: e^(-5 * 10) of the initial offset is below rounding
  const NormalState late = m.state_at(10.0);
  EXPECT_NEAR(late.gap_m, a / 1e4, 1e-18);
  EXPECT_NEAR(late.force_n, -a, 1e-13);
}

// Events found while extending in pieces are bitwise those found in one go.
TEST(NormalContactMotion, ExtendingInPiecesIsDeterministic) {
  const NormalContactParams p{1.0, 1e4, 10.0, -8.492764724752476, 2.232050807568877, 0.0};
  NormalContactMotion whole(p);
  whole.extend_to(2.5);
  NormalContactMotion pieces(p);
  for (double t : {0.3, 0.74, 0.75, 1.0, 2.0, 2.5}) pieces.extend_to(t);
  ASSERT_EQ(whole.phases().size(), pieces.phases().size());
  for (std::size_t i = 0; i < whole.phases().size(); ++i) {
    EXPECT_EQ(whole.phases()[i].start_s, pieces.phases()[i].start_s);
    EXPECT_EQ(whole.phases()[i].gap_rate0_mps, pieces.phases()[i].gap_rate0_mps);
  }
}

// Peak force and penetration of a pressed phase: the stationary points of
// the closed form beat any sample of it (dense sampling from below).
TEST(NormalContactMotion, MaximaAreAtLeastEverySample) {
  NormalContactMotion m({1.0, 1e4, 10.0, -8.49, 0.0, -6.0});
  m.extend_to(0.1);
  ASSERT_GE(m.phases().size(), 2u);
  const double end = m.phases()[0].end_s;
  const double peak_force = m.max_force_n(0, 0.0, end);
  const double peak_pen = m.max_penetration_m(0, 0.0, end);
  double sampled_force = 0.0;
  double sampled_pen = 0.0;
  for (int i = 0; i <= 100000; ++i) {
    const NormalState s = m.state_at(end * i / 100000.0);
    sampled_force = std::max(sampled_force, s.force_n);
    sampled_pen = std::max(sampled_pen, -s.gap_m);
  }
  EXPECT_GE(peak_force, sampled_force - 1e-12);
  EXPECT_GE(peak_pen, sampled_pen - 1e-18);
  // and the sampling comes close: a 3e-7 s grid misses ~ (w h)^2 / 8 relative
  EXPECT_NEAR(peak_force, sampled_force, 1e-8 * peak_force);
  EXPECT_NEAR(peak_pen, sampled_pen, 1e-8 * peak_pen);
}

}  // namespace
}  // namespace pb::internal
