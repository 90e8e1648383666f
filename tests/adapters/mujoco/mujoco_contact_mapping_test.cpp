// Tests for adapters/mujoco/mujoco_contact_mapping.cpp
//
// Truths: the direct solref is the law per unit effective mass (ENGINES.md);
// a clamped linear oscillator has restitution exp(-zeta (pi - 2 asin zeta) /
// sqrt(1 - zeta^2)) and force duration (pi - 2 asin zeta) / omega_d
// (ENGINES.md); a Lankarani-Nikravesh collision is integrated here with its
// own RK4, independently of the core's simulate_collision; a Hertz impact
// lasts 2 (delta_max / v) Int_0^1 (1 - x^(5/2))^(-1/2) dx with delta_max =
// (5 m v^2 / (4 K))^(2/5) (energy balance; the integral is a Beta function).
#include "mujoco_contact_mapping.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace pb::internal::mujoco {
namespace {

constexpr double kPi = std::numbers::pi;

struct Clamped {
  double restitution;
  double force_duration_s;
};

// the clamped linear oscillator of mass m, closed form
Clamped linear_closed_form(double k, double c, double m) {
  const double zeta = c / (2.0 * std::sqrt(k * m));
  const double wd = std::sqrt(k / m) * std::sqrt(1.0 - zeta * zeta);
  const double phase = kPi - 2.0 * std::asin(zeta);
  return {std::exp(-zeta * phase / std::sqrt(1.0 - zeta * zeta)), phase / wd};
}

// Lankarani-Nikravesh collision of a mass m at speed v, classic RK4 with a
// fixed step of duration / 50000, until the force clamps to zero
Clamped ln_collision(double K, double e, double m, double v) {
  auto force = [&](double d, double dd) {
    if (d <= 0.0) return 0.0;
    return std::max(0.0, K * std::pow(d, 1.5) * (1.0 + 0.75 * (1.0 - e * e) * dd / v));
  };
  const double d_max = std::pow(5.0 * m * v * v / (4.0 * K), 0.4);
  const double h = 3.0 * d_max / v / 50000.0;
  double d = 0.0;
  double dd = v;
  double t = 0.0;
  for (int i = 0; i < 10'000'000; ++i) {
    auto acc = [&](double x, double xd) { return -force(std::max(x, 1e-300), xd) / m; };
    const double k1x = dd, k1v = acc(d, dd);
    const double k2x = dd + 0.5 * h * k1v, k2v = acc(d + 0.5 * h * k1x, dd + 0.5 * h * k1v);
    const double k3x = dd + 0.5 * h * k2v, k3v = acc(d + 0.5 * h * k2x, dd + 0.5 * h * k2v);
    const double k4x = dd + h * k3v, k4v = acc(d + h * k3x, dd + h * k3v);
    const double d1 = d + h / 6.0 * (k1x + 2 * k2x + 2 * k3x + k4x);
    const double dd1 = dd + h / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (t > 0.0 && (d1 <= 0.0 || force(d1, dd1) <= 0.0) && dd1 < 0.0) {
      // linear interpolation of the end inside the last step
      const double f0 = force(d, dd);
      const double f1 = d1 <= 0.0 ? 0.0 : force(d1, dd1);
      const double frac = f0 > 0.0 ? f0 / (f0 - f1) : 0.0;
      return {-(dd + frac * (dd1 - dd)) / v, t + frac * h};
    }
    d = d1;
    dd = dd1;
    t += h;
  }
  return {NAN, NAN};
}

TEST(ContactMapping, KelvinVoigtIsTheLawPerUnitEffectiveMass) {
  const LawMapping m = map_contact_law(KelvinVoigt{1e4, 10.0, 0.0}, {0.8, 3.0, "test"});
  EXPECT_TRUE(m.exact);
  EXPECT_EQ(m.stiffness_n_per_m, 1e4);
  EXPECT_EQ(m.damping_ns_per_m, 10.0);
  EXPECT_DOUBLE_EQ(m.solref[0], -1e4 / 0.8);
  EXPECT_DOUBLE_EQ(m.solref[1], -10.0 / 0.8);
  EXPECT_EQ(m.json.at("law"), "kelvin_voigt");
  EXPECT_TRUE(m.json.at("not_expressed").empty());
}

TEST(ContactMapping, LankaraniNikraveshMatchesOneImpactsRestitutionAndDuration) {
  // the dual pendulum's law at its first impact (m_eff 0.633 kg, 1.78 m/s)
  const double K = 1.0242e10;
  const double m = 0.633;
  const double v = 1.78;
  const LawMapping map = map_contact_law(LankaraniNikravesh{K, 1.5, 0.7, {}, {}}, {m, v, "test"});
  EXPECT_FALSE(map.exact);
  const Clamped law = ln_collision(K, 0.7, m, v);
  const Clamped lin = linear_closed_form(map.stiffness_n_per_m, map.damping_ns_per_m, m);
  // 1e-5 relative: this test's RK4 (50000 steps, clamp interpolated) and the
  // core's (20000 steps) agree to ~1e-6; the margin covers both
  EXPECT_NEAR(lin.restitution, law.restitution, 1e-5 * law.restitution);
  EXPECT_NEAR(lin.force_duration_s, law.force_duration_s, 1e-5 * law.force_duration_s);
  EXPECT_DOUBLE_EQ(map.solref[0], -map.stiffness_n_per_m / m);
  EXPECT_DOUBLE_EQ(map.solref[1], -map.damping_ns_per_m / m);
  EXPECT_EQ(map.json.at("approach_speed_mps"), v);
  EXPECT_EQ(map.json.at("not_expressed").size(), 2u);
}

TEST(ContactMapping, HertzIsAnUndampedSpringOfTheSameDuration) {
  const double K = 1e9;
  const double m = 2.0;
  const double v = 0.5;
  const LawMapping map = map_contact_law(Hertz{K, 1.5, {}}, {m, v, "test"});
  EXPECT_EQ(map.damping_ns_per_m, 0.0);
  const double d_max = std::pow(5.0 * m * v * v / (4.0 * K), 0.4);
  // Int_0^1 (1 - x^p)^(-1/2) dx = Gamma(1/p) Gamma(1/2) / (p Gamma(1/p + 1/2)), p = 5/2
  const double p = 2.5;
  const double integral =
      std::tgamma(1.0 / p) * std::tgamma(0.5) / (p * std::tgamma(1.0 / p + 0.5));
  const double duration = 2.0 * d_max / v * integral;
  // half a period of sqrt(k/m) lasts the Hertz duration; 1e-6 relative:
  // the core integrates the Hertz impact to ~1e-8
  EXPECT_NEAR(kPi / std::sqrt(map.stiffness_n_per_m / m), duration, 1e-6 * duration);
}

TEST(ContactMapping, RestingPairFallsBackToAStatedApproachSpeed) {
  const LawMapping map =
      map_contact_law(LankaraniNikravesh{1e10, 1.5, 0.7, {}, {}}, {1.0, 0.0, "test"});
  EXPECT_EQ(map.json.at("approach_speed_mps"), kFallbackApproachSpeedMps);
  EXPECT_EQ(map.json.at("not_expressed").size(), 3u);
}

TEST(ContactMapping, DampingRampBecomesALinearEquivalent) {
  const LawMapping map = map_contact_law(KelvinVoigt{1e4, 10.0, 0.1}, {1.0, 6.0, "test"});
  EXPECT_FALSE(map.exact);
  // the ramp damps less than full c: the equivalent damper is weaker
  EXPECT_LT(map.damping_ns_per_m, 10.0);
  EXPECT_NE(map.json.at("not_expressed")[0].get<std::string>().find("ramp"), std::string::npos);
}

}  // namespace
}  // namespace pb::internal::mujoco
