// Tests for core/src/contact_law_response.cpp
#include "planarbench/contact_law_response.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pb {
namespace {

// A 1 kg point mass hits a Kelvin-Voigt wall (k = 1e4 N/m, c = 10 N s/m) at
// v = 6.1573 m/s with no gravity: zeta = 0.05, omega = 100 rad/s. Closed form
// (ENGINES.md): e = exp(-zeta (pi - 2 asin zeta) / sqrt(1 - zeta^2)) = 0.8588.
TEST(ContactLawResponse, KelvinVoigtClosedFormMatchesSpecFigures) {
  const auto r = kelvin_voigt_response(1e4, 10.0, 1.0, 6.1573);
  EXPECT_NEAR(r.restitution, 0.8588, 5e-5);  // SPEC's printed 4 digits
  const double zeta = 0.05;
  const double wd = 100.0 * std::sqrt(1.0 - zeta * zeta);
  // closed form of the clamp time: 1e-15 s is a few ulps of the 3e-2 s result
  EXPECT_NEAR(r.force_duration_s, (M_PI - 2.0 * std::asin(zeta)) / wd, 1e-15);
  // momentum balance m v (1 + e), m = 1 kg: 1e-12 N s is rounding of a ~12 N s sum
  EXPECT_NEAR(r.impulse_ns, 6.1573 * (1.0 + r.restitution), 1e-12);
  // independent closed form (SPEC §2, ENGINES.md): e = exp(-zeta (pi - 2 asin zeta) / sqrt(1 - zeta^2));
  // 1e-14: rounding of exp, asin and sqrt only
  EXPECT_NEAR(r.restitution, std::exp(-zeta * (M_PI - 2.0 * std::asin(zeta)) / std::sqrt(1.0 - zeta * zeta)),
              1e-14);
  EXPECT_GT(r.duration_s, r.force_duration_s);  // free flight out after the clamp
}

// The numerical collision must reproduce the closed form of the same law:
// RK4 with 20000 steps over the contact is accurate to ~1e-10 relative here,
// so 1e-7 leaves room for the step-interpolated force release time.
TEST(ContactLawResponse, SimulationAgreesWithClosedFormForKelvinVoigt) {
  const auto exact = kelvin_voigt_response(1e4, 10.0, 1.0, 5.0);
  const auto sim = simulate_collision(KelvinVoigt{1e4, 10.0, 0.0}, 1.0, 5.0);
  EXPECT_NEAR(sim.restitution, exact.restitution, 1e-7);
  EXPECT_NEAR(sim.duration_s, exact.duration_s, 1e-7 * exact.duration_s);
  EXPECT_NEAR(sim.force_duration_s, exact.force_duration_s, 1e-6 * exact.force_duration_s);
  EXPECT_NEAR(sim.peak_force_n, exact.peak_force_n, 1e-6 * exact.peak_force_n);
  EXPECT_NEAR(sim.max_penetration_m, exact.max_penetration_m, 1e-7 * exact.max_penetration_m);
}

// Undamped Hertz impact (Johnson, Contact Mechanics, §11.4): energy gives
// delta_max = (5 m v^2 / (4 K))^(2/5); the duration is
// 2 delta_max / v * int_0^1 dx / sqrt(1 - x^(5/2)) = 2 delta_max / v * 0.4 B(0.4, 0.5).
TEST(ContactLawResponse, HertzImpactMatchesJohnson) {
  const double k = 1.0242e10;
  const double m = 0.5;
  const double v = 1.78;
  const auto r = simulate_collision(Hertz{k, 1.5, std::nullopt}, m, v);
  const double dmax = std::pow(5.0 * m * v * v / (4.0 * k), 0.4);
  EXPECT_NEAR(r.max_penetration_m, dmax, 1e-8 * dmax);  // sampled max: (1/20000)^2
  const double beta = std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);
  // RK4 with 20000 steps and a bisected last step: 1e-8 relative
  EXPECT_NEAR(r.duration_s, 2.0 * dmax / v * 0.4 * beta, 1e-8 * r.duration_s);
  EXPECT_NEAR(r.restitution, 1.0, 1e-9);  // elastic law, RK4 energy error ~1e-12
}

// Lankarani-Nikravesh at e = 0.7 dissipates; the model is derived for e near 1,
// so the effective restitution differs from the nominal one (it is higher).
TEST(ContactLawResponse, LankaraniNikraveshIsDissipative) {
  const auto r = simulate_collision(LankaraniNikravesh{1.0242e10, 1.5, 0.7, std::nullopt, {}}, 0.5, 1.78);
  EXPECT_LT(r.restitution, 1.0);
  EXPECT_GT(r.restitution, 0.7);
}

// The linear equivalent reproduces the target's restitution and force duration.
TEST(ContactLawResponse, LinearEquivalentRoundTrips) {
  const auto target = kelvin_voigt_response(2e4, 30.0, 2.0, 3.0);
  const auto eq = linear_equivalent(target, 2.0);
  EXPECT_NEAR(eq.stiffness_n_per_m, 2e4, 1e-9 * 2e4);  // bisection to 1e-16 in zeta
  EXPECT_NEAR(eq.damping_ns_per_m, 30.0, 1e-9 * 30.0);
}

}  // namespace
}  // namespace pb
