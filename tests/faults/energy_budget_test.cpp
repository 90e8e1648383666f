// Tests for core/include/planarbench/energy_budget.hpp
//
// The budget is checked against closed forms of simple passive motions
// written out here: free fall (v = g t, drop g t^2 / 2), a throw (v0 + g t),
// a spring released from a penetration (all of K delta0^2 / 2 turned into
// kinetic energy), and motions that are not passive (a kick that doubles the
// speed: four times the kinetic energy).
#include "planarbench/energy_budget.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pb {
namespace {

constexpr double kG = 9.8066;  // m/s^2

// one moving disk (m = 2 kg, I = 0.25 kg m^2) above a fixed ground
Case disk_case(const Vec2& gravity_mps2 = Vec2(0.0, -kG)) {
  Case c;
  c.gravity_mps2 = gravity_mps2;
  Body ground;
  ground.name = "ground";
  ground.fixed = true;
  ground.shape = HalfPlane{};
  Body disk;
  disk.name = "disk";
  disk.shape = Circle{0.5};
  disk.mass_kg = 2.0;
  disk.inertia_kgm2 = 0.25;
  disk.position_m = Vec2(0.0, 3.0);
  c.bodies = {ground, disk};
  ContactPair p;
  p.name = "ground_disk";
  p.body_a = 0;
  p.body_b = 1;
  p.law = KelvinVoigt{1e4, 10.0, 0.0};
  c.contacts = {p};
  return c;
}

// state vector of disk_case with the disk at (x, y) moving at v, spinning at w
std::vector<BodyState> disk_state(const Vec2& x, const Vec2& v, double w = 0.0) {
  std::vector<BodyState> s(2);
  s[1].position_m = x;
  s[1].velocity_mps = v;
  s[1].angular_velocity_radps = w;
  return s;
}

TEST(ElasticEnergy, ClosedFormsOfTheThreeLaws) {
  // Kelvin-Voigt: K delta^2 / 2 = 1e4 * (0.01)^2 / 2 = 0.5 J (the damper stores nothing)
  EXPECT_NEAR(elastic_energy_j(KelvinVoigt{1e4, 10.0, 0.1}, 0.01), 0.5, 1e-15);
  // Hertz: K delta^(n+1) / (n+1) = 1e10 * (1e-4)^2.5 / 2.5 = 0.4 J; 1e-14 relative: a
  // pow and a division
  EXPECT_NEAR(elastic_energy_j(Hertz{1e10, 1.5, {}}, 1e-4), 0.4, 0.4 * 1e-14);
  // Lankarani-Nikravesh stores the same as its Hertz part: 2e6 * 0.1^3 / 3 J (n = 2)
  EXPECT_NEAR(elastic_energy_j(LankaraniNikravesh{2e6, 2.0, 0.7, {}}, 0.1), 2e6 * 1e-3 / 3.0, 1e-9);
  // no penetration, no energy
  EXPECT_EQ(elastic_energy_j(KelvinVoigt{1e4, 10.0, 0.0}, -0.01), 0.0);
}

// Free fall from rest is the bound itself: KE = m (g t)^2 / 2 = m g (g t^2 / 2),
// the work of gravity over the drop.
TEST(EnergyBudget, ExactFreeFallSitsOnTheBound) {
  const Case c = disk_case();
  EnergyBudget e(c);
  e.start(disk_state(Vec2(0.0, 3.0), Vec2::Zero()), {});
  for (const double t : {0.01, 0.1, 0.5}) {
    const double drop = 0.5 * kG * t * t;
    const double ratio = e.update(disk_state(Vec2(0.0, 3.0 - drop), Vec2(0.0, -kG * t)));
    // 1e-12: the two sides are the same number computed two ways
    EXPECT_NEAR(ratio, 1.0, 1e-12) << t;
    EXPECT_FALSE(e.runaway());
  }
  // J: m (g t)^2 / 2 at t = 0.5
  EXPECT_NEAR(e.kinetic_now_j(), 0.5 * 2.0 * std::pow(kG * 0.5, 2), 1e-9);
}

// A float engine (Box2D) cannot resolve the first 1e-4 s of a fall from 3 m:
// the drop g t^2 / 2 = 4.9e-8 m is below a float's step at 3 m (2.4e-7 m), so
// its position has not moved while its speed g t is exact. From positions
// alone gravity has made no energy available (a false runaway, seen in the
// sweep at Box2D dt <= 5e-5 s); the time-aware update floors the budget with
// EnergyBound, m (g t)^2 / 2 from rest, which this state meets exactly.
TEST(EnergyBudget, ElapsedTimeFloorsTheBudgetWhenPositionsLagTheSpeed) {
  const Case c = disk_case();
  const double t = 1e-4;
  const auto lagging = disk_state(Vec2(0.0, 3.0), Vec2(0.0, -kG * t));
  EnergyBudget by_position(c);
  by_position.start(disk_state(Vec2(0.0, 3.0), Vec2::Zero()), {});
  by_position.update(lagging);
  EXPECT_TRUE(by_position.runaway());
  EnergyBudget by_time(c);
  by_time.start(disk_state(Vec2(0.0, 3.0), Vec2::Zero()), {});
  // 1e-12: KE and the bound are the same number computed two ways
  EXPECT_NEAR(by_time.update(lagging, t), 1.0, 1e-12);
  EXPECT_FALSE(by_time.runaway());
  // a real runaway is still one: 4x the speed is 16x the energy
  by_time.update(disk_state(Vec2(0.0, 3.0), Vec2(0.0, -4.0 * kG * t)), t);
  EXPECT_TRUE(by_time.runaway());
}

// The budget keeps the most energy made available: a ball that bounced back
// up (elastically, to half its drop) may carry the kinetic energy of the
// lowest point it reached.
TEST(EnergyBudget, RememberTheMostEnergyMadeAvailable) {
  const Case c = disk_case();
  EnergyBudget e(c);
  e.start(disk_state(Vec2(0.0, 3.0), Vec2::Zero()), {});
  // down 2 m: v = sqrt(2 g 2)
  const double v_low = std::sqrt(2.0 * kG * 2.0);
  e.update(disk_state(Vec2(0.0, 1.0), Vec2(0.0, -v_low)));
  // back up at 2 m: the pointwise bound is m g 1 m, the budget m g 2 m; a
  // speed of v_low there (energy not lost on the way up) is a ratio of 1
  // 1e-12: closed-form values of order 1-100 J computed two ways; only rounding differs
  EXPECT_NEAR(e.update(disk_state(Vec2(0.0, 2.0), Vec2(0.0, v_low))), 1.0, 1e-12);
  EXPECT_NEAR(e.most_available_j(), 2.0 * kG * 2.0, 1e-12);
}

// A kick that multiplies the speed by k multiplies the kinetic energy by k^2:
// 3x (9) stays below the factor 10, 3.5x (12.25) is a runaway. Spin counts:
// I w^2 / 2 with w chosen to carry the same energy.
TEST(EnergyBudget, EnergyBeyondTheFactorIsARunaway) {
  const Case c = disk_case(Vec2::Zero());
  EnergyBudget e(c);
  const Vec2 v0(1.0, 0.0);  // m/s: KE(0) = 1 J, no gravity
  e.start(disk_state(Vec2(0.0, 3.0), v0), {});
  // 1e-12: closed-form values of order 1-100 J computed two ways; only rounding differs
  EXPECT_NEAR(e.update(disk_state(Vec2(1.0, 3.0), 3.0 * v0)), 9.0, 1e-12);
  EXPECT_FALSE(e.runaway());
  EXPECT_NEAR(e.update(disk_state(Vec2(1.0, 3.0), 3.5 * v0)), 12.25, 1e-12);
  EXPECT_TRUE(e.runaway());
  EXPECT_NE(e.describe().find("12.25 times"), std::string::npos) << e.describe();
  // 11 J of spin alone: w = sqrt(2 * 11 / 0.25)
  e.update(disk_state(Vec2(1.0, 3.0), Vec2::Zero(), std::sqrt(2.0 * 11.0 / 0.25)));
  EXPECT_TRUE(e.runaway());
  // NaN is left to the non-finite check, never called a runaway
  e.update(disk_state(Vec2(1.0, 3.0), Vec2(std::nan(""), 0.0)));
  EXPECT_FALSE(e.runaway());
}

// A disk that starts 0.1 m deep in a K = 1e4 N/m contact holds 50 J of
// elastic energy: released without gravity, it may leave with all of it
// (v = sqrt(2 * 50 / 2) = 7.07 m/s), far above the 0 J of kinetic energy it
// started with.
TEST(EnergyBudget, InitialPenetrationCountsItsElasticEnergy) {
  const Case c = disk_case(Vec2::Zero());
  ContactSample deep;
  deep.body_a = 1;  // either order names the pair
  deep.body_b = 0;
  deep.penetration_m = 0.1;
  EnergyBudget e(c);
  e.start(disk_state(Vec2(0.0, 0.4), Vec2::Zero()), {deep});
  // 1e-12: closed-form values of order 1-100 J computed two ways; only rounding differs
  EXPECT_NEAR(e.most_available_j(), 50.0, 1e-12);
  EXPECT_NEAR(e.update(disk_state(Vec2(0.0, 0.6), Vec2(0.0, std::sqrt(50.0)))), 1.0, 1e-12);
  // an engine that gives no penetration (NaN) stores nothing
  ContactSample unknown = deep;
  unknown.penetration_m = std::nan("");
  EnergyBudget f(c);
  f.start(disk_state(Vec2(0.0, 0.4), Vec2::Zero()), {unknown});
  f.update(disk_state(Vec2(0.0, 0.6), Vec2(0.0, std::sqrt(50.0))));
  EXPECT_TRUE(f.runaway());
}

// Nothing moving and no gravity: the floor (every body at 1e-6 m/s) keeps the
// ratio finite, and a body really at rest stays at 0.
TEST(EnergyBudget, RestWithoutGravityIsNotARunaway) {
  const Case c = disk_case(Vec2::Zero());
  EnergyBudget e(c);
  e.start(disk_state(Vec2(0.0, 3.0), Vec2::Zero()), {});
  EXPECT_EQ(e.update(disk_state(Vec2(0.0, 3.0), Vec2::Zero())), 0.0);
  EXPECT_FALSE(e.runaway());
  // J: m (1e-6)^2 / 2
  EXPECT_NEAR(e.most_available_j(), 0.5 * 2.0 * 1e-12, 1e-27);
}

// The a-priori bound (sqrt(E0) + |g| t sqrt(M/2))^2 is exact for one body
// thrown straight down: KE = m (v0 + g t)^2 / 2, distance v0 t + g t^2 / 2.
TEST(EnergyBound, OneBodyThrownDownIsTheBound) {
  const double m = 2.0;   // kg
  const double v0 = 3.0;  // m/s
  const EnergyBound b{0.5 * m * v0 * v0, m, kG};
  for (const double t : {0.0, 0.3, 2.0}) {
    // 1e-12 relative: the same closed form computed two ways
    const double ke = 0.5 * m * std::pow(v0 + kG * t, 2);
    EXPECT_NEAR(b.kinetic_j(t), ke, 1e-12 * ke + 1e-15) << t;
    const double d = v0 * t + 0.5 * kG * t * t;
    EXPECT_NEAR(b.displacement_m(m, t), d, 1e-12 * d + 1e-15) << t;
  }
}

// With two bodies the bound allows all the energy in the lighter one: a
// 1 kg ball and a 3 kg ball falling from rest for 1 s hold at most
// (g t)^2 M / 2 = 2 g^2 J, which the 1 kg ball alone would carry at g t sqrt(M/m) = 2 g t.
TEST(EnergyBound, EnergyMayGatherInTheLightestBody) {
  const EnergyBound b{0.0, 4.0, kG};
  // 1e-12: closed-form values of order 1-100 J computed two ways; only rounding differs
  EXPECT_NEAR(b.kinetic_j(1.0), 2.0 * kG * kG, 1e-12);
  // m: int_0^1 2 g t dt = g for the 1 kg ball
  EXPECT_NEAR(b.displacement_m(1.0, 1.0), kG, 1e-12);
}

}  // namespace
}  // namespace pb
