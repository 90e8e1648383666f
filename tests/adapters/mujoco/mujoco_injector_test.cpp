// Tests for adapters/mujoco/mujoco_injector.cpp
//
// An ellipse (a = 0.7, b = 0.3 m, m = 2 kg) turned 30 deg counter-clockwise
// rests 1 mm deep in the ground, at rest, with MuJoCo's contact inactive. The
// injected Kelvin-Voigt force is F = k delta = 10 N up, at the ellipse's
// lowest point, which lies left of the centre by (a^2 - b^2) sin t cos t / D,
// D = sqrt(a^2 sin^2 t + b^2 cos^2 t) (the support point of the turned
// ellipse). Newton: a_y = F / m - g; Euler: alpha = (x_p - x_c) F / I < 0
// (clockwise: the ellipse starts to lie down).
#include "mujoco_injector.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mujoco_frame.hpp"
#include "mujoco_mjcf.hpp"
#include "mujoco_test_cases.hpp"

namespace pb::internal::mujoco {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kA = 0.7;
constexpr double kB = 0.3;
constexpr double kTheta = kPi / 6.0;
constexpr double kDepth = 1e-3;  // m

double support_depth() {
  return std::sqrt(kA * kA * std::sin(kTheta) * std::sin(kTheta) +
                   kB * kB * std::cos(kTheta) * std::cos(kTheta));
}

Case resting_ellipse() {
  Case c;
  c.gravity_mps2 = Vec2(0.0, -test::kG);
  Body e;
  e.name = "ellipse";
  e.shape = Ellipse{kA, kB};
  e.mass_kg = 2.0;
  e.inertia_kgm2 = 2.0 * (kA * kA + kB * kB) / 4.0;
  e.position_m = Vec2(0.4, support_depth() - kDepth);
  e.angle_rad = kTheta;
  c.bodies.push_back(e);
  c.bodies.push_back(test::ground());
  c.contacts.push_back(test::kelvin_voigt_pair(1, 0, 1e4, 10.0));
  return c;
}

class Injection : public ::testing::Test {
 protected:
  void SetUp() override {
    c_ = resting_ellipse();
    MjcfOptions o;
    PairParams p;
    p.gap_m = 1e3;  // inactive: MuJoCo reports the contact, never solves it
    o.pairs.push_back(p);
    model_ = test::load_case(c_, o, layout_);
    data_.reset(mj_makeData(model_.get()));
    set_initial_state(model_.get(), data_.get(), c_, layout_);
    injector_ = std::make_unique<ForceInjector>(c_, model_.get(), layout_);
  }
  const BodyLayout& body() const { return layout_.bodies[0]; }
  Case c_;
  ModelPtr model_;
  ModelLayout layout_;
  DataPtr data_;
  std::unique_ptr<ForceInjector> injector_;
};

TEST_F(Injection, AppliesTheLawsForceAndTorqueAtTheContact) {
  {
    ForceInjector::Scope scope(*injector_);
    mj_forward(model_.get(), data_.get());
  }
  const double F = 1e4 * kDepth;  // N, at rest: no damping term
  const double m = 2.0;
  const double I = c_.bodies[0].inertia_kgm2;
  const double lever = -(kA * kA - kB * kB) * std::sin(kTheta) * std::cos(kTheta) / support_depth();
  // 1e-9: the penetration is exact to rounding (ellipsoid support point)
  EXPECT_NEAR(data_->qacc[body().dof_x], 0.0, 1e-9);
  EXPECT_NEAR(data_->qacc[body().dof_z], F / m - test::kG, 1e-9);
  const double alpha = ccw_rate_from_hinge(data_->qacc[body().dof_hinge]);
  EXPECT_NEAR(alpha, lever * F / I, 1e-9);
  EXPECT_LT(alpha, 0.0);  // clockwise
}

TEST_F(Injection, InactiveOutsideItsScope) {
  mj_forward(model_.get(), data_.get());
  // 1e-12 m/s^2: MuJoCo's solve of a diagonal mass matrix, rounding only
  EXPECT_NEAR(data_->qacc[body().dof_z], -test::kG, 1e-12);
  EXPECT_EQ(data_->qacc[body().dof_hinge], 0.0);
}

TEST_F(Injection, LatchesTheApproachSpeedAtFirstPenetration) {
  // Lankarani-Nikravesh uses the rate at onset: an observation approaching at
  // 2 m/s latches, a later one at 1 m/s uses the latched 2 m/s
  c_.contacts[0].law = LankaraniNikravesh{1e9, 1.5, 0.5, {}, {}};
  PairObservation o;
  o.reported = true;
  o.penetration_m = 1e-4;
  o.approach_speed_mps = 2.0;
  injector_->latch({o});
  o.approach_speed_mps = 1.0;
  const double expected = 1e9 * std::pow(1e-4, 1.5) * (1.0 + 0.75 * (1.0 - 0.25) * 1.0 / 2.0);
  // 1e-12 relative: the same closed form evaluated in another order
  EXPECT_NEAR(injector_->force_n(0, o), expected, 1e-12 * expected);
  // separated: the latch clears, the next contact latches its own speed
  o.penetration_m = -1e-5;
  injector_->latch({o});
  EXPECT_EQ(injector_->force_n(0, o), 0.0);
  o.penetration_m = 1e-4;
  injector_->latch({o});
  const double fresh = 1e9 * std::pow(1e-4, 1.5) * (1.0 + 0.75 * (1.0 - 0.25));
  EXPECT_NEAR(injector_->force_n(0, o), fresh, 1e-12 * fresh);
}

}  // namespace
}  // namespace pb::internal::mujoco
