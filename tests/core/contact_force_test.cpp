// Tests for core/src/contact_force.cpp
#include "planarbench/contact_force.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pb {
namespace {

// Kelvin-Voigt (paper eq. 1): F = K delta + c delta_dot, clamped at 0.
TEST(ContactForce, KelvinVoigtIsLinearAndNeverPulls) {
  const ContactLaw law = KelvinVoigt{1e4, 10.0, 0.0};
  // exact in binary floating point for these values: 1e4 * 0.01 + 10 * 2 = 120
  EXPECT_DOUBLE_EQ(contact_force_n(law, 0.01, 2.0, 0.0), 120.0);
  // restitution phase: 1e4 * 0.001 + 10 * (-5) = -40 -> clamped
  EXPECT_EQ(contact_force_n(law, 0.001, -5.0, 0.0), 0.0);
  // no penetration, no force, whatever the rate
  EXPECT_EQ(contact_force_n(law, 0.0, 3.0, 0.0), 0.0);
  EXPECT_EQ(contact_force_n(law, -1e-3, 3.0, 0.0), 0.0);
}

// ADAMS IMPACT ramp: damping 0 at delta = 0, full at delta >= depth,
// 3x^2 - 2x^3 in between (x = 0.5 gives 0.5).
TEST(ContactForce, DampingRampIsTheCubicStep) {
  const ContactLaw law = KelvinVoigt{1e4, 10.0, 0.1};
  EXPECT_DOUBLE_EQ(contact_force_n(law, 0.05, 2.0, 0.0), 1e4 * 0.05 + 0.5 * 10.0 * 2.0);
  EXPECT_DOUBLE_EQ(contact_force_n(law, 0.2, 2.0, 0.0), 1e4 * 0.2 + 10.0 * 2.0);
  EXPECT_EQ(cubic_step(-1.0), 0.0);
  EXPECT_EQ(cubic_step(2.0), 1.0);
  EXPECT_DOUBLE_EQ(cubic_step(0.25), 0.25 * 0.25 * (3.0 - 0.5));
}

// Lankarani-Nikravesh (paper eq. 7) at delta_dot = delta_dot_minus gives
// K delta^1.5 (1 + 3(1-e^2)/4); the bracket turns negative only for rebound
// speeds above delta_dot_minus / (0.75 (1 - e^2)), where it is clamped.
TEST(ContactForce, LankaraniNikraveshHysteresis) {
  const double k = 1.0242e10;
  const ContactLaw law = LankaraniNikravesh{k, 1.5, 0.7, std::nullopt, {}};
  const double d = 1e-4;
  const double elastic = k * std::pow(d, 1.5);
  // 1 + 0.75 * 0.51 = 1.3825; relative 1e-15: a few roundings of pow and products
  EXPECT_NEAR(contact_force_n(law, d, 1.78, 1.78), elastic * 1.3825, 1e-15 * elastic * 2);
  // same roundings, a smaller bracket (0.6175): 1e-15 relative to the elastic force
  EXPECT_NEAR(contact_force_n(law, d, -1.78, 1.78), elastic * (1.0 - 0.3825), 1e-15 * elastic);
  const ContactLaw soft = LankaraniNikravesh{k, 1.5, 0.1, std::nullopt, {}};
  // 1 + 0.75 (1 - 0.01) (-2) < 0: a rebound faster than the approach would pull
  EXPECT_EQ(contact_force_n(soft, d, -2.0 * 1.78, 1.78), 0.0);
  // no approach speed (contact starting at rest): elastic only
  EXPECT_DOUBLE_EQ(contact_force_n(law, d, 0.3, 0.0), elastic);
}

// Hertz stiffness, paper eqs. 3-4 with the square root (SPEC §1): for steel
// E = 210 GPa, nu = 0.33, R = 8.5 mm on both sides SPEC gives K ~ 1.024e10.
TEST(ContactForce, HertzStiffnessOfThePendulumSteel) {
  const HertzMaterial m{210e9, 210e9, 0.33, 0.33, 0.0085, 0.0085};
  // independent evaluation: h = (1 - nu^2) / (pi E); K = 4 / (3 pi 2h) sqrt(R / 2)
  const double h = (1.0 - 0.33 * 0.33) / (M_PI * 210e9);
  const double expected = 4.0 / (3.0 * M_PI * 2.0 * h) * std::sqrt(0.0085 / 2.0);
  EXPECT_NEAR(hertz_stiffness(m), expected, 1e-12 * expected);  // same formula, other order
  EXPECT_NEAR(hertz_stiffness(m), 1.024e10, 0.0005e10);  // SPEC's printed digits: half a unit
}

// linearize_law: the linear spring-damper k delta + c delta_dot that gives
// the law's own force (contact_force_n, a separate evaluation of eqs. 1-7) at
// that delta, for any rate; the tolerance is a few roundings of forces of
// up to ~2e4 N (relative 1e-14).
TEST(LinearizeLaw, ReproducesTheLawAtThisPenetration) {
  const ContactLaw laws[] = {KelvinVoigt{1e4, 10.0, 0.0}, KelvinVoigt{1e4, 10.0, 0.1},
                             Hertz{2e6, 1.5, std::nullopt},
                             LankaraniNikravesh{1.0242e10, 1.5, 0.7, std::nullopt, {}}};
  const double approach = 1.78;  // m/s
  for (const ContactLaw& law : laws) {
    for (const double delta : {1e-6, 1e-4, 0.03, 0.2}) {
      for (const double rate : {-1.5, 0.0, 0.7, 1.78}) {
        const LinearizedLaw lin = linearize_law(law, delta, approach);
        const double unclamped = lin.stiffness_n_per_m * delta + lin.damping_ns_per_m * rate;
        const double law_force = contact_force_n(law, delta, rate, approach);
        if (law_force > 0.0) {
          EXPECT_NEAR(unclamped, law_force, 1e-14 * std::abs(law_force) + 1e-300)
              << contact_law_name(law) << " delta " << delta << " rate " << rate;
        } else {
          EXPECT_LE(unclamped, 0.0);  // where the law clamps, the linear one pulls
        }
      }
    }
  }
  // nothing pressed in: nothing to spring
  const LinearizedLaw none = linearize_law(KelvinVoigt{1e4, 10.0, 0.0}, 0.0, approach);
  EXPECT_EQ(none.stiffness_n_per_m, 0.0);
  EXPECT_EQ(none.damping_ns_per_m, 0.0);
  // Lankarani-Nikravesh without a latched approach speed has no damping term
  const LinearizedLaw elastic =
      linearize_law(LankaraniNikravesh{2e6, 1.5, 0.8, std::nullopt, {}}, 1e-3, 0.0);
  EXPECT_EQ(elastic.damping_ns_per_m, 0.0);
  EXPECT_DOUBLE_EQ(elastic.stiffness_n_per_m * 1e-3, 2e6 * std::pow(1e-3, 1.5));
}

// A stated damping factor chi replaces eq. 7's 3 (1 - e^2) / 4 (issue 34's
// Hunt-Crossley): K delta^n (1 + chi delta_dot / delta_dot_minus) and the
// linearised damping K delta^n chi / delta_dot_minus, by hand; e is then
// unused. Stating eq. 7's own factor gives eq. 7's law.
TEST(ContactForce, AStatedDampingFactorReplacesEquationSevens) {
  const double k = 2e7;
  const double d = 2e-3;
  const double elastic = k * std::pow(d, 1.5);
  const LankaraniNikravesh hc{k, 1.5, 0.3, std::nullopt, 1.2};
  EXPECT_EQ(damping_factor(hc), 1.2);
  // 1 + 1.2 * 0.5 / 2.5 = 1.24; 1e-15 relative: a few roundings
  EXPECT_NEAR(contact_force_n(hc, d, 0.5, 2.5), elastic * 1.24, 1e-15 * elastic * 2);
  const LinearizedLaw lin = linearize_law(hc, d, 2.5);
  EXPECT_NEAR(lin.damping_ns_per_m, elastic * 1.2 / 2.5, 1e-15 * elastic);
  const LankaraniNikravesh eq7{k, 1.5, 0.7, std::nullopt, {}};
  EXPECT_DOUBLE_EQ(damping_factor(eq7), 0.75 * (1.0 - 0.49));
  LankaraniNikravesh stated = eq7;
  stated.damping_factor = damping_factor(eq7);
  EXPECT_EQ(contact_force_n(stated, d, 0.5, 2.5), contact_force_n(eq7, d, 0.5, 2.5));
}

}  // namespace
}  // namespace pb
