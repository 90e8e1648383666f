// Tests for core/impacts/src/impact_case.cpp and impact_simulation.cpp with
// the real engines: the start on the ballistic arc, the post-impact state
// read after the contact and carried back to the touch, against an
// independent truth (a disk's vertical drop: the clamped Kelvin-Voigt
// contact with gravity, integrated here by RK4 at 1e-8 s), determinism, and
// each engine's prediction of measured-like impacts.
#include <gtest/gtest.h>

#include <cmath>

#include "planarbench/engines.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/impacts/impact_case.hpp"
#include "planarbench/impacts/impact_fit.hpp"
#include "planarbench/impacts/impact_model.hpp"
#include "planarbench/impacts/impact_simulation.hpp"
#include "synthetic_impacts.hpp"

namespace {

const pb::ImpactObject kObject;

// The truth of a vertical drop of a disk (mass m) on the clamped Kelvin-Voigt
// law with gravity: the impulse of the contact per unit mass (= the
// post-impact speed carried back to the touch, minus the pre-impact one) and
// the contact's duration. RK4 at 1e-8 s: its error ~ (omega h)^4 ~ 1e-19.
struct DropTruth {
  double delta_v_mps;
  double contact_s;
};
DropTruth drop_truth(double m, double k, double c, double v_in) {
  const double g = pb::kImpactGravity_mps2;
  const double h = 1e-8;
  // state: penetration d (m, > 0 in contact), its rate (m/s), impulse / m (m/s)
  auto force = [&](double d, double dd) { return std::max(0.0, k * d + c * dd); };
  double d = 0.0, dd = v_in, j = 0.0, t = 0.0;
  auto rhs = [&](double d0, double dd0, double out[3]) {
    const double f = force(d0, dd0) / m;
    out[0] = dd0;
    out[1] = g - f;  // the penetration grows with gravity, shrinks with the force
    out[2] = f;
  };
  while (t < 0.05) {
    double k1[3], k2[3], k3[3], k4[3];
    rhs(d, dd, k1);
    rhs(d + 0.5 * h * k1[0], dd + 0.5 * h * k1[1], k2);
    rhs(d + 0.5 * h * k2[0], dd + 0.5 * h * k2[1], k3);
    rhs(d + h * k3[0], dd + h * k3[1], k4);
    d += h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]);
    dd += h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1]);
    j += h / 6 * (k1[2] + 2 * k2[2] + 2 * k3[2] + k4[2]);
    t += h;
    if (d <= 0.0 && dd < 0.0) break;  // back at the surface, leaving
  }
  return {j, t};
}

}  // namespace

TEST(ImpactCase, TheArcReachesTheMeasuredStateAtTheTouch) {
  const pb::ImpactState at_touch = pb::test::impact_state(0.8, 0.6, -2.4, 12.0);
  const pb::Case c = pb::impact_case(kObject, at_touch, pb::ImpactLaw{}, 180);
  ASSERT_EQ(c.bodies.size(), 2u);
  const pb::Body& e = c.bodies[1];
  const double t = pb::kLeadTime_s;
  const double g = pb::kImpactGravity_mps2;
  // the free flight over the lead time, by hand
  EXPECT_NEAR(e.angle_rad + e.angular_velocity_radps * t, 0.8, 1e-15);
  EXPECT_NEAR(e.velocity_mps.y() - g * t, -2.4, 1e-15);
  EXPECT_NEAR(e.position_m.x() + e.velocity_mps.x() * t, 0.0, 1e-15);
  EXPECT_NEAR(e.position_m.y() + e.velocity_mps.y() * t - 0.5 * g * t * t,
              pb::touching_height(kObject, 0.8), 1e-15);
  EXPECT_NEAR(pb::ballistic_gap(kObject, at_touch, t), 0.0, 1e-15);
  EXPECT_GT(pb::ballistic_gap(kObject, at_touch, 0.0), 2e-3);  // 2.4 mm above the ground
  EXPECT_EQ(e.mass_kg, kObject.mass_kg);
  EXPECT_EQ(e.inertia_kgm2, kObject.inertia_kgm2());
}

// issue 34: the paper's Lankarani-Nikravesh law in place of Kelvin-Voigt,
// exactly the values given (reference_ln's parameters)
TEST(ImpactCase, TheLawIsLankaraniNikraveshWhenAsked) {
  const pb::ImpactState at_touch = pb::test::impact_state(0.8, 0.6, -2.4, 12.0);
  pb::ImpactLaw law;
  law.stiffness_n_per_m = 2e6;
  law.kind = pb::ImpactLawKind::lankarani_nikravesh;
  law.exponent = 1.3;
  law.restitution = 0.55;
  law.friction = 0.19;
  const pb::Case c = pb::impact_case(kObject, at_touch, law, 180);
  const auto* ln = std::get_if<pb::LankaraniNikravesh>(&c.contacts.at(0).law);
  ASSERT_NE(ln, nullptr);
  EXPECT_EQ(ln->stiffness, 2e6);
  EXPECT_EQ(ln->exponent, 1.3);
  EXPECT_EQ(ln->restitution, 0.55);
  EXPECT_EQ(c.contacts.at(0).friction, 0.19);
  // and Kelvin-Voigt by default
  EXPECT_TRUE(std::holds_alternative<pb::KelvinVoigt>(
      pb::impact_case(kObject, at_touch, pb::ImpactLaw{}, 180).contacts.at(0).law));
}

TEST(ImpactCase, AnArcThatTouchesEarlierIsRefused) {
  // rising lowest point: the spin lifts it faster than the centre falls
  const pb::ImpactState s = pb::test::impact_state(0.6, 0.0, -0.01, -40.0);
  EXPECT_THROW((void)pb::impact_case(kObject, s, pb::ImpactLaw{}, 180), pb::InputError);
}

// A disk's vertical drop: no friction, no spin. Each engine against the truth
// of the law it is given. Tolerances on the impulse J / m = v_post - v_pre
// (the engines' methods, as in cases/thresholds.toml): for a contact of
// duration T_c stepped at h = 1e-4 s, omega = pi / T_c, semi-implicit Euler
// (MuJoCo, ODE) returns the restitution e within (omega h)^2 + zeta omega h
// + g h / v_n, i.e. J within that times e / (1 + e); Box2D's rigid bounce
// carries the law's gravity-free restitution and no gravity impulse during
// the contact: J low by up to g T_c / (J / m) (cases/thresholds.toml's rigid
// bounce), + 0.1 % for float32 rounding and the gravity-free residual.
TEST(ImpactSimulation, ADiskDropMatchesTheClampedLawWithGravity) {
  pb::ImpactObject disk;
  disk.semi_axis_a_m = disk.semi_axis_b_m = 0.03;
  const pb::ImpactLaw law{5e4, 0.17, 0.0};
  const double c = 2 * law.damping_ratio * std::sqrt(law.stiffness_n_per_m * disk.mass_kg);
  const double v_in = 2.5;
  const DropTruth truth = drop_truth(disk.mass_kg, law.stiffness_n_per_m, c, v_in);
  const double e = truth.delta_v_mps / v_in - 1.0;
  const double omega_h = M_PI / truth.contact_s * 1e-4;
  const double euler = (omega_h * omega_h + law.damping_ratio * omega_h + 9.81e-4 / v_in) * e / (1 + e);
  const pb::ImpactState at_touch = pb::test::impact_state(0.0, 0.0, -v_in, 0.0);
  struct Expect {
    const char* engine;
    std::vector<std::pair<std::string, std::string>> settings;
    double rtol;
    const char* why;
  };
  const std::vector<Expect> engines = {
      {"reference", {{"reference.geometry", "\"exact\""}}, 1e-7, "rk45 at rtol 1e-10 with located events"},
      // a 180-gon's vertex, not the circle, meets the ground: the stiffness
      // acts on a depth offset by at most R (1 - cos(1 deg)) = 4.6e-6 m,
      // 2e-3 of the 2.2 mm peak depth
      {"reference", {}, 2e-3, "the outline's vertex"},
      {"mujoco", {}, euler, "semi-implicit Euler at 1e-4 s"},
      {"ode", {}, euler, "semi-implicit Euler at 1e-4 s"},
      {"box2d", {}, 9.81 * truth.contact_s / truth.delta_v_mps + 1e-3, "rigid bounce: no gravity impulse"},
  };
  for (const Expect& x : engines) {
    auto engine = pb::make_engine(x.engine);
    pb::SettingsOverrides o;
    for (const auto& [k, v] : x.settings) o.set(k, v, {"test", 0});
    const pb::Case cs = pb::impact_case(disk, at_touch, law, std::string(x.engine) == "box2d" ? 24 : 180);
    const pb::ImpactOutcome out = pb::simulate_impact(*engine, cs, o, disk);
    ASSERT_TRUE(out.ok()) << x.engine << ": " << out.failure;
    const double dv = out.after.velocity_mps.y() + v_in;
    EXPECT_NEAR(dv / truth.delta_v_mps, 1.0, x.rtol)
        << x.engine << " (" << x.why << "): " << dv << " vs " << truth.delta_v_mps;
    // symmetry: nothing turns or slides (Box2D's floats: 1e-6)
    EXPECT_NEAR(out.after.velocity_mps.x(), 0.0, 1e-6) << x.engine;
    EXPECT_NEAR(out.after.angular_velocity_radps, 0.0, 1e-4) << x.engine;
    // read after the contact: the truth's contact ends 1 ms + T_c after the
    // start (Box2D's rigid bounce within a step of the touch)
    const bool rigid = std::string(x.engine) == "box2d";
    EXPECT_GE(out.read_time_s, pb::kLeadTime_s + (rigid ? 0.0 : 0.9 * truth.contact_s)) << x.engine;
    EXPECT_EQ(out.episodes, 1) << x.engine;
  }
}

TEST(ImpactSimulation, EveryEnginePredictsAnObliqueImpactTheSameBitsTwice) {
  const pb::ImpactState at_touch = pb::test::impact_state(0.9, 0.7, -2.5, 8.0);
  const pb::ImpactLaw law{5e4, 0.17, 0.18};
  for (const char* name : {"reference", "mujoco", "ode", "box2d"}) {
    auto engine = pb::make_engine(name);
    const pb::Case cs = pb::impact_case(kObject, at_touch, law, std::string(name) == "box2d" ? 24 : 180);
    const pb::ImpactOutcome a = pb::simulate_impact(*engine, cs, {}, kObject);
    const pb::ImpactOutcome b = pb::simulate_impact(*pb::make_engine(name), cs, {}, kObject);
    ASSERT_TRUE(a.ok()) << name << ": " << a.failure;
    EXPECT_EQ(a.after.velocities(), b.after.velocities()) << name;
    // an impact: the normal speed reversed
    EXPECT_GT(a.after.velocity_mps.y(), 0.5) << name;
  }
}

TEST(ImpactSimulation, PredictionsDoNotDependOnTheThreads) {
  const pb::ImpactSet set = pb::test::synthetic_impacts(16, 11, [](const pb::ImpactState& s) { return s; });
  const pb::ImpactTable t = pb::make_impact_table(set, kObject, {-1.0, -1.0});
  pb::EngineModelSpec spec;
  spec.name = "ode";
  spec.engine = "ode";
  spec.factory = [] { return pb::make_engine("ode"); };
  const auto model = pb::engine_impact_model(spec);
  std::vector<std::size_t> all(t.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  const std::vector<double> p = {4e4, 0.2, 0.2};
  const auto one = pb::predict_impacts(*model, t, all, p, 1);
  const auto two = pb::predict_impacts(*model, t, all, p, 2);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t k = 0; k < one.size(); ++k) {
    EXPECT_EQ(one[k].after.velocities(), two[k].after.velocities()) << k;
    EXPECT_EQ(one[k].steps, two[k].steps) << k;
  }
}

// scaled_impact_case: the same impact in a world of decimetres. Its fields by
// dimension (lengths and velocities x s, inertia x s^2, gravity x s; a
// Kelvin-Voigt law unchanged, K delta^n's K x s^(1 - n)), and the motion: the
// reference at exact geometry (rk45 at rtol 1e-10, its events located)
// predicts the oblique impact in both worlds alike, read back in m/s.
TEST(ImpactCase, AScaledWorldIsTheSameImpactInAnotherUnit) {
  const pb::ImpactState at_touch = pb::test::impact_state(0.9, 0.7, -2.5, 8.0);
  const pb::ImpactLaw law{5e4, 0.17, 0.18};
  const double s = 10.0;
  const pb::Case c = pb::impact_case(kObject, at_touch, law);
  const pb::Case big = pb::scaled_impact_case(c, s);
  EXPECT_EQ(big.gravity_mps2, c.gravity_mps2 * s);
  const pb::Body& b = big.bodies[1];
  EXPECT_EQ(b.position_m, c.bodies[1].position_m * s);
  EXPECT_EQ(b.velocity_mps, c.bodies[1].velocity_mps * s);
  EXPECT_EQ(b.angular_velocity_radps, c.bodies[1].angular_velocity_radps);
  EXPECT_EQ(b.angle_rad, c.bodies[1].angle_rad);
  EXPECT_EQ(b.mass_kg, c.bodies[1].mass_kg);
  EXPECT_DOUBLE_EQ(b.inertia_kgm2, c.bodies[1].inertia_kgm2 * s * s);
  EXPECT_EQ(std::get<pb::Ellipse>(b.shape).semi_axis_a_m, kObject.semi_axis_a_m * s);
  EXPECT_EQ(std::get<pb::KelvinVoigt>(big.contacts[0].law).stiffness_n_per_m, law.stiffness_n_per_m);
  pb::ImpactLaw ln = law;
  ln.kind = pb::ImpactLawKind::lankarani_nikravesh;
  ln.exponent = 1.5;
  const pb::Case big_ln = pb::scaled_impact_case(pb::impact_case(kObject, at_touch, ln), s);
  EXPECT_DOUBLE_EQ(std::get<pb::LankaraniNikravesh>(big_ln.contacts[0].law).stiffness,
                   ln.stiffness_n_per_m / std::sqrt(s));

  pb::SettingsOverrides exact;
  exact.set("reference.geometry", "\"exact\"", {"test", 0});
  const pb::ImpactOutcome one = pb::simulate_impact(*pb::make_engine("reference"), c, exact, kObject);
  const pb::ImpactOutcome ten = pb::simulate_impact(*pb::make_engine("reference"), big, exact,
                                                    pb::scaled_impact_object(kObject, s));
  ASSERT_TRUE(one.ok()) << one.failure;
  ASSERT_TRUE(ten.ok()) << ten.failure;
  // 1e-6 m/s: the integrator's rtol 1e-10 on a motion of 2.5 m/s, with its
  // step control's absolute floors (1e-10 m, which do not scale) on top
  EXPECT_NEAR(ten.after.velocity_mps.x() / s, one.after.velocity_mps.x(), 1e-6);
  EXPECT_NEAR(ten.after.velocity_mps.y() / s, one.after.velocity_mps.y(), 1e-6);
  // 1e-4 rad/s: the same on a spin of ~10 rad/s
  EXPECT_NEAR(ten.after.angular_velocity_radps, one.after.angular_velocity_radps, 1e-4);
}

// Hunt and Crossley's own law (issue 34): the case states it as eq. 7's family
// with chi = alpha times the impact's approach speed, so that the reference
// (exact geometry, rk45 at rtol 1e-10, the approach speed latched at the
// located onset) drops a disk as F = K delta^1.5 (1 + alpha delta_dot) with
// gravity does, integrated here by RK4 at 1e-8 s (error ~ (omega h)^4).
TEST(ImpactSimulation, AHuntCrossleyDropMatchesItsOwnLaw) {
  pb::ImpactObject disk;
  disk.semi_axis_a_m = disk.semi_axis_b_m = 0.03;
  pb::ImpactLaw law;
  law.kind = pb::ImpactLawKind::hunt_crossley;
  law.stiffness_n_per_m = 2e7;  // N/m^1.5: ~2 mm deep at 2.5 m/s
  law.exponent = 1.5;
  law.damping_s_per_m = 0.25;
  law.friction = 0.0;
  const double v_in = 2.5;
  const pb::ImpactState at_touch = pb::test::impact_state(0.0, 0.0, -v_in, 0.0);
  const pb::Case c = pb::impact_case(disk, at_touch, law);
  const auto& ln = std::get<pb::LankaraniNikravesh>(c.contacts[0].law);
  ASSERT_TRUE(ln.damping_factor.has_value());
  EXPECT_DOUBLE_EQ(*ln.damping_factor, law.damping_s_per_m * v_in);

  const double g = pb::kImpactGravity_mps2, m = disk.mass_kg, h = 1e-8;
  auto accel = [&](double d, double dd) {
    const double f = d > 0.0 ? std::max(0.0, law.stiffness_n_per_m * std::pow(d, 1.5) *
                                                  (1.0 + law.damping_s_per_m * dd))
                             : 0.0;
    return std::pair<double, double>{g - f / m, f / m};  // penetration's, impulse's rates
  };
  double d = 0.0, dd = v_in, j = 0.0;
  for (double t = 0.0; t < 0.05; t += h) {
    const auto [a1, f1] = accel(d, dd);
    const auto [a2, f2] = accel(d + 0.5 * h * dd, dd + 0.5 * h * a1);
    const auto [a3, f3] = accel(d + 0.5 * h * (dd + 0.5 * h * a1), dd + 0.5 * h * a2);
    const auto [a4, f4] = accel(d + h * (dd + 0.5 * h * a2), dd + h * a3);
    d += h * dd + h * h / 6 * (a1 + a2 + a3);
    dd += h / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
    j += h / 6 * (f1 + 2 * f2 + 2 * f3 + f4);
    if (d <= 0.0 && dd < 0.0) break;
  }
  pb::SettingsOverrides exact;
  exact.set("reference.geometry", "\"exact\"", {"test", 0});
  const pb::ImpactOutcome out = pb::simulate_impact(*pb::make_engine("reference"), c, exact, disk);
  ASSERT_TRUE(out.ok()) << out.failure;
  // 1e-5 relative: rk45 at rtol 1e-10 with its onset located, and the RK4
  // here stepping over the release by up to 1e-8 s of a ~1 ms contact
  EXPECT_NEAR((out.after.velocity_mps.y() + v_in) / j, 1.0, 1e-5);
}
