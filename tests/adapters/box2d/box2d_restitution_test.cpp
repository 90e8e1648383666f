// Tests for adapters/box2d/box2d_restitution.cpp
#include "box2d_restitution.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "box2d_test_cases.hpp"
#include "planarbench/contact_law_response.hpp"

namespace pb::internal::box2d {
namespace {

// Kelvin-Voigt maps to the clamped oscillator's restitution, which depends on
// m_eff through zeta: the formula is written out again in the test header;
// 1e-12 covers the different evaluation order.
TEST(Box2dRestitution, KelvinVoigtIsTheClampedClosedForm) {
  const ContactLaw kv = KelvinVoigt{1e4, 10.0, 0.0};
  for (const double m : {0.25, 1.0, 4.0}) {
    EXPECT_NEAR(law_restitution(kv, m, 6.0), box2d_test::clamped_kv_restitution(1e4, 10.0, m),
                1e-12)
        << m;
  }
  // zeta = 0.05 at m = 1 kg: e = 0.8588 (SPEC §2: without gravity 0.8588)
  // 1e-4: SPEC prints 4 decimals (+-5e-5), rounded up
  EXPECT_NEAR(law_restitution(kv, 1.0, 6.0), 0.8588, 1e-4);
  EXPECT_TRUE(restitution_depends_on_state(kv));
  EXPECT_NE(law_restitution_method(kv).find("kelvin_voigt_response"), std::string::npos);
}

// An overdamped Kelvin-Voigt contact (zeta >= 1: a brick pyramid's 1e6 N/m,
// 2000 N s/m at m_eff 0.3-0.5 kg) takes the closed form of the clamped
// overdamped oscillator (box2d_restitution.hpp), checked against
// simulate_collision's RK4 of the same law (20000 steps, 1e-8 relative:
// tolerance 1e-6); e^-2 at zeta = 1 exactly, and continuous with the
// underdamped closed form there (1e-3: zeta = 1 - 1e-6 moves e by ~1e-4
// through the square root of 1 - zeta^2).
TEST(Box2dRestitution, OverdampedKelvinVoigtIsItsClosedForm) {
  const double k = 1e6;  // N/m
  for (const double zeta : {1.0, 1.0001, 1.3, 1.79, 3.0, 10.0}) {
    const double m = 0.3;                              // kg
    const double c = 2.0 * zeta * std::sqrt(k * m);    // N s/m
    const ContactLaw kv = KelvinVoigt{k, c, 0.0};
    const double e = law_restitution(kv, m, 0.5);
    EXPECT_NEAR(e, simulate_collision(kv, m, 0.5).restitution, 1e-6) << zeta;
    EXPECT_NEAR(e, overdamped_kv_restitution(k, c, m), 1e-15) << zeta;
    EXPECT_GT(e, 0.0) << zeta;  // the clamp releases while the mass still moves out
  }
  EXPECT_NEAR(overdamped_kv_restitution(1e6, 2e3, 1.0), std::exp(-2.0), 1e-15);
  EXPECT_NEAR(box2d_test::clamped_kv_restitution(1e6, 2e3, 1.0 + 1e-6), std::exp(-2.0), 1e-3);
  // more damping, less restitution
  EXPECT_GT(overdamped_kv_restitution(1e6, 3e3, 1.0), overdamped_kv_restitution(1e6, 6e3, 1.0));
}

// Lankarani-Nikravesh's restitution is not its nominal e, and it does not
// depend on the effective mass or the approach speed: the law is scale
// invariant (delta = D x, t = (D / v) tau removes K, m and v). 1e-7: the
// accuracy of simulate_collision's RK4 (1e-8 relative) with margin.
TEST(Box2dRestitution, LankaraniNikraveshIsScaleInvariantAndNotNominal) {
  LankaraniNikravesh ln;
  ln.stiffness = 1.0242e10;
  ln.exponent = 1.5;
  ln.restitution = 0.7;
  const ContactLaw law = ln;
  const double e1 = law_restitution(law, 0.63, 1.78);
  const double e2 = law_restitution(law, 5.0, 0.1);
  const double e3 = law_restitution(law, 0.01, 20.0);
  EXPECT_NEAR(e1, e2, 1e-7);
  EXPECT_NEAR(e1, e3, 1e-7);
  // the value itself, from an independent RK4 of the dimensionless law
  // x'' = -x^1.5 (1 + 0.75 (1 - e^2) x'), x(0) = 0, x'(0) = 1 (delta = D x,
  // t = (D / v) tau, D = (m v^2 / K)^(2/5)), run until x returns to 0; 1e-6:
  // simulate_collision's 1e-8 relative with margin for this RK4's
  // interpolated exit (2e5 steps of 1.5e-5, error ~1e-9)
  const double c_ln = 0.75 * (1.0 - 0.7 * 0.7);
  auto acc = [&](double x, double xd) {
    return -std::pow(std::max(x, 0.0), 1.5) * (1.0 + c_ln * xd);
  };
  double x = 0.0, xd = 1.0, e_rk4 = std::numeric_limits<double>::quiet_NaN();
  const double h = 1.5e-5;
  for (int i = 0; i < 1'000'000; ++i) {
    const double k1x = xd, k1v = acc(x, xd);
    const double k2x = xd + 0.5 * h * k1v, k2v = acc(x + 0.5 * h * k1x, xd + 0.5 * h * k1v);
    const double k3x = xd + 0.5 * h * k2v, k3v = acc(x + 0.5 * h * k2x, xd + 0.5 * h * k2v);
    const double k4x = xd + h * k3v, k4v = acc(x + h * k3x, xd + h * k3v);
    const double x1 = x + h / 6.0 * (k1x + 2 * k2x + 2 * k3x + k4x);
    const double xd1 = xd + h / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (i > 0 && x1 <= 0.0) {
      e_rk4 = -(xd + (xd1 - xd) * x / (x - x1));  // exit speed, linearly interpolated
      break;
    }
    x = x1;
    xd = xd1;
  }
  EXPECT_NEAR(e1, e_rk4, 1e-6);
  // the hysteresis model dissipates less than e = 0.7 implies (it is derived
  // for e near 1): the effective restitution is clearly above the nominal
  EXPECT_GT(e1, 0.75);
  EXPECT_FALSE(restitution_depends_on_state(law));
  // Hertz without damping is elastic; 1e-6: simulate_collision's RK4 step
  // error on the exit speed (1e-8 relative) and the clamp interpolation
  EXPECT_NEAR(law_restitution(Hertz{1e9, 1.5, std::nullopt}, 1.0, 1.0), 1.0, 1e-6);
}

// The elastic contact duration: pi sqrt(m/k) for a linear spring (half a
// period of the oscillator), and for Hertz (n = 3/2) the classical
// 2.943 delta_max / v (Johnson, Contact Mechanics, §11.4), checked against
// an independent integration of m x'' = -K x^1.5 here (semi-implicit Euler,
// 1e6 steps: relative error ~1e-6; tolerance 1e-5).
TEST(Box2dRestitution, ElasticContactDuration) {
  EXPECT_NEAR(elastic_contact_duration_s(KelvinVoigt{1e4, 10.0, 0.0}, 1.0, 3.0),
              std::numbers::pi / 100.0, 1e-15);  // pi sqrt(1/1e4), rounding only
  const double k = 1.0242e10, m = 0.63, v = 1.78;
  const double estimate = elastic_contact_duration_s(Hertz{k, 1.5, std::nullopt}, m, v);
  const double h = estimate / 1e6;
  double x = 0.0, xd = v, t = 0.0;
  while (!(x < 0.0 && t > 0.0)) {
    xd -= h * k * std::pow(std::max(x, 0.0), 1.5) / m;
    x += h * xd;
    t += h;
  }
  EXPECT_NEAR(estimate / t, 1.0, 1e-5);
  // an infinite stiffness gives zero duration rather than a hang
  EXPECT_EQ(
      elastic_contact_duration_s(KelvinVoigt{std::numeric_limits<double>::infinity(), 0, 0}, 1, 1),
      0.0);
}

// approach speeds at or below zero are raised to the documented floor
TEST(Box2dRestitution, ZeroApproachSpeedIsFloored) {
  const ContactLaw kv = KelvinVoigt{1e4, 10.0, 0.05};
  // 1e-15: the same computation on the same inputs; only equality is meant
  EXPECT_NEAR(law_restitution(kv, 1.0, 0.0), law_restitution(kv, 1.0, kMinApproachSpeed_mps),
              1e-15);
}

}  // namespace
}  // namespace pb::internal::box2d
