// Tests for core/analytic/two_disks_head_on.cpp
//
// Two disks on the x axis integrated as two bodies in the world frame (RK4 at
// 1e-6 s, each with its own force, nothing reduced to a relative coordinate)
// are the independent truth; the restitution is checked against the closed
// form of the clamped Kelvin-Voigt oscillator without gravity (ENGINES.md):
// e = exp(-zeta (pi - 2 asin zeta) / sqrt(1 - zeta^2)).
#include "two_disks_head_on.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace pb::internal {
namespace {

// head_on.toml: disks R 0.2 m, 1 kg at -0.5 m moving +2 m/s, 2 kg at 0.5 m
// moving -0.5 m/s; K 1e4 N/m, c 10 N s/m; `gravity` optional
Case head_on(const Vec2& gravity) {
  Case c;
  c.name = "head_on";
  c.truth = TruthKind::analytic;
  c.duration_s = 0.5;
  c.gravity_mps2 = gravity;
  Body a;
  a.name = "left";
  a.shape = Circle{0.2};
  a.mass_kg = 1.0;
  a.inertia_kgm2 = 0.02;
  a.position_m = Vec2(-0.5, 0.0);
  a.velocity_mps = Vec2(2.0, 0.0);
  a.angular_velocity_radps = 1.5;  // spins never change: no friction
  Body b;
  b.name = "right";
  b.shape = Circle{0.2};
  b.mass_kg = 2.0;
  b.inertia_kgm2 = 0.04;
  b.position_m = Vec2(0.5, 0.0);
  b.velocity_mps = Vec2(-0.5, 0.0);
  c.bodies = {a, b};
  ContactPair p;
  p.name = "left_right";
  p.body_a = 0;
  p.body_b = 1;
  p.law = KelvinVoigt{1e4, 10.0, 0.0};
  c.contacts = {p};
  return c;
}

// the two bodies along x: state (x_a, v_a, x_b, v_b), classic RK4; the
// onset (where the damping term makes the force jump by c v) is located by
// bisecting the step that crosses it, so that no step straddles the jump
struct TwoBodies {
  std::array<double, 4> y{-0.5, 2.0, 0.5, -0.5};
  static std::array<double, 4> rate(const std::array<double, 4>& s) {
    const double delta = 0.4 - (s[2] - s[0]);      // m, overlap of the two radii
    const double delta_dot = -(s[3] - s[1]);       // m/s
    const double f = delta > 0.0 ? std::max(0.0, 1e4 * delta + 10.0 * delta_dot) : 0.0;  // N
    return {s[1], -f / 1.0, s[3], f / 2.0};
  }
  static double gap(const std::array<double, 4>& s) { return (s[2] - s[0]) - 0.4; }
  static std::array<double, 4> rk4(const std::array<double, 4>& s0, double h) {
    auto add = [](const std::array<double, 4>& a, const std::array<double, 4>& b, double k) {
      return std::array<double, 4>{a[0] + k * b[0], a[1] + k * b[1], a[2] + k * b[2],
                                   a[3] + k * b[3]};
    };
    const auto k1 = rate(s0);
    const auto k2 = rate(add(s0, k1, 0.5 * h));
    const auto k3 = rate(add(s0, k2, 0.5 * h));
    const auto k4 = rate(add(s0, k3, h));
    std::array<double, 4> out = s0;
    for (int i = 0; i < 4; ++i) {
      const auto u = static_cast<std::size_t>(i);
      out[u] += h / 6.0 * (k1[u] + 2.0 * k2[u] + 2.0 * k3[u] + k4[u]);
    }
    return out;
  }
  void step(double h) {
    const auto next = rk4(y, h);
    if (gap(y) > 0.0 && gap(next) <= 0.0) {
      // free flight up to the onset (exact for RK4: constant velocities), then the rest
      double lo = 0.0;
      double hi = h;
      for (int i = 0; i < 200 && hi - lo > 0.0; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (!(mid > lo && mid < hi)) break;
        (gap(rk4(y, mid)) > 0.0 ? lo : hi) = mid;
      }
      y = rk4(y, hi);
      y = rk4(y, h - hi);
      return;
    }
    y = next;
  }
};

TEST(TwoDisksHeadOn, MatchesTwoIndependentlyIntegratedBodies) {
  const Case c = head_on(Vec2::Zero());
  TwoDisksHeadOn d(c, 0, 1, 0);
  d.extend_to(c.duration_s);
  TwoBodies ref;
  std::vector<BodyState> s;
  const double h = 1e-6;  // s
  for (int k = 1; k <= 500; ++k) {
    for (int i = 0; i < 1000; ++i) ref.step(h);  // to t = k ms
    const double t = 1e-3 * k;
    d.body_states(t, s);
    // RK4 at h = 1e-6 s with the onset located: (omega h)^4 ~ 1e-16 per step,
    // and the clamp's kink in the force (continuous value, jumping slope)
    // inside one step: ~c v h^2 / m ~ 1e-11 m; 1e-9 m and 1e-7 m/s leave room
    EXPECT_NEAR(s[0].position_m.x(), ref.y[0], 1e-9) << "t=" << t;
    EXPECT_NEAR(s[0].velocity_mps.x(), ref.y[1], 1e-7) << "t=" << t;
    EXPECT_NEAR(s[1].position_m.x(), ref.y[2], 1e-9) << "t=" << t;
    EXPECT_NEAR(s[1].velocity_mps.x(), ref.y[3], 1e-7) << "t=" << t;
    EXPECT_EQ(s[0].position_m.y(), 0.0);
    EXPECT_EQ(s[0].angular_velocity_radps, 1.5);
  }
}

TEST(TwoDisksHeadOn, MomentumIsExactAndTheImpactIsTheFreeOscillator) {
  const Case c = head_on(Vec2::Zero());
  TwoDisksHeadOn d(c, 0, 1, 0);
  d.extend_to(c.duration_s);
  std::vector<BodyState> s;
  for (int k = 0; k <= 500; ++k) {
    d.body_states(1e-3 * k, s);
    const Vec2 p = 1.0 * s[0].velocity_mps + 2.0 * s[1].velocity_mps;
    // m_a v_a + m_b v_b = M V exactly but for the rounding of a few products
    // of O(1) numbers: 1e-15 kg m/s
    EXPECT_NEAR(p.x(), 1.0, 1e-15);
  }
  const auto eps = d.episodes(c.duration_s);
  ASSERT_EQ(eps.size(), 1u);
  // the gap 0.6 m closed at 2.5 m/s: 0.24 s (one rounding of a quotient)
  EXPECT_NEAR(eps[0].onset_time_s, 0.24, 1e-15);
  const double mu = 2.0 / 3.0;
  const double zeta = 10.0 / (2.0 * std::sqrt(1e4 * mu));
  const double e = std::exp(-zeta * (std::numbers::pi - 2.0 * std::asin(zeta)) /
                            std::sqrt(1.0 - zeta * zeta));
  // the closed form's events are roots found to the last bits: 1e-12
  EXPECT_NEAR(eps[0].restitution, e, 1e-12);
  // the impulse on either disk is mu (1 + e) v_approach
  EXPECT_NEAR(eps[0].impulse_ns, mu * (1.0 + e) * 2.5, 1e-12);
}

TEST(TwoDisksHeadOn, GravityMovesBothAlike) {
  const Case flat = head_on(Vec2::Zero());
  const Case falling = head_on(Vec2(0.0, -9.8066));
  TwoDisksHeadOn a(flat, 0, 1, 0);
  TwoDisksHeadOn b(falling, 0, 1, 0);
  a.extend_to(0.5);
  b.extend_to(0.5);
  std::vector<BodyState> sa, sb;
  for (const double t : {0.1, 0.25, 0.3, 0.5}) {
    a.body_states(t, sa);
    b.body_states(t, sb);
    for (int i = 0; i < 2; ++i) {
      const auto u = static_cast<std::size_t>(i);
      // the same relative motion, shifted by the free fall g t^2 / 2
      EXPECT_NEAR(sb[u].position_m.x(), sa[u].position_m.x(), 1e-15);
      EXPECT_NEAR(sb[u].position_m.y(), -0.5 * 9.8066 * t * t, 1e-15);
      EXPECT_NEAR(sb[u].velocity_mps.y(), -9.8066 * t, 1e-15);
    }
  }
}

TEST(TwoDisksHeadOn, ContactSampleLiesBetweenTheSurfaces) {
  const Case c = head_on(Vec2::Zero());
  TwoDisksHeadOn d(c, 0, 1, 0);
  d.extend_to(c.duration_s);
  std::vector<ContactSample> cs;
  d.contacts(0.25, cs);
  ASSERT_EQ(cs.size(), 1u);
  EXPECT_EQ(cs[0].normal, Vec2(1.0, 0.0));
  EXPECT_GT(cs[0].penetration_m, 0.0);
  std::vector<BodyState> s;
  d.body_states(0.25, s);
  // midway between x_a + R and x_b - R
  EXPECT_NEAR(cs[0].point_m.x(), 0.5 * (s[0].position_m.x() + 0.2 + s[1].position_m.x() - 0.2),
              1e-15);
  d.contacts(0.1, cs);
  EXPECT_TRUE(cs.empty());
}

}  // namespace
}  // namespace pb::internal
