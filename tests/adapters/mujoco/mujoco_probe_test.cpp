// Tests for adapters/mujoco/mujoco_probe.cpp
//
// A disk falls from rest a height H onto the ground through a contact-free
// model: it first touches at t* = sqrt(2 H / g) with speed g t*, and along a
// normal through its centre its effective mass is its mass.
#include "mujoco_probe.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "mujoco_mjcf.hpp"
#include "mujoco_test_cases.hpp"

namespace pb::internal::mujoco {
namespace {

struct Probe {
  explicit Probe(const Case& c) {
    MjcfOptions o;
    for (std::size_t k = 0; k < c.contacts.size(); ++k) {
      PairParams p;
      p.gap_m = 0.01 + 1e3;  // every pair inactive
      o.pairs.push_back(p);
    }
    model = test::load_case(c, o, layout, 0.01);
  }
  ModelPtr model;
  ModelLayout layout;
};

TEST(Probe, FallingDiskTouchesAtTheFreeFallTime) {
  const double H = 0.2;
  Case c = test::disk_drop(H);
  c.bodies[0].mass_kg = 2.5;
  const Probe p(c);
  long steps = -1;
  const auto touch = probe_first_touch(p.model.get(), c, p.layout, 1.0, steps);
  ASSERT_TRUE(touch[0].found);
  const double h = 1e-4;  // the model's step
  // the probe is a look-ahead run: it stepped up to the touch (oracle mode only)
  EXPECT_EQ(steps, std::lround(touch[0].time_s / h));
  const double t_star = std::sqrt(2.0 * H / test::kG);
  // the first state at or past the touch: within one step; semi-implicit
  // Euler's positions lead the exact ones by g h t / 2 (< one step of travel)
  EXPECT_GE(touch[0].time_s, t_star - h);
  EXPECT_LE(touch[0].time_s, t_star + h);
  // Euler's velocities are exact for constant gravity: v = g t_n; 1e-12:
  // rounding accumulated over the ~2000 steps of the fall
  EXPECT_NEAR(touch[0].approach_speed_mps, test::kG * touch[0].time_s, 1e-12);
  // 1e-12 kg: MuJoCo's M^-1 of a diagonal mass matrix, rounding only
  EXPECT_NEAR(touch[0].effective_mass_kg, 2.5, 1e-12);
  EXPECT_NEAR(touch[0].normal_ab.y(), 1.0, 1e-15);  // ground (a) -> disk (b)
}

TEST(Probe, PairTouchingAtStartIsFoundAtZero) {
  const Case c = test::sliding();
  const Probe p(c);
  long steps = -1;
  const auto touch = probe_first_touch(p.model.get(), c, p.layout, 1.0, steps);
  ASSERT_TRUE(touch[0].found);
  EXPECT_EQ(touch[0].time_s, 0.0);
  EXPECT_NEAR(touch[0].approach_speed_mps, 0.0, 1e-12);
}

TEST(Probe, PairThatNeverTouchesIsNotFound) {
  const Case c = test::disk_drop(5.0);  // needs 1.01 s to fall 5 m
  const Probe p(c);
  long steps = -1;
  const auto touch = probe_first_touch(p.model.get(), c, p.layout, 0.5, steps);
  EXPECT_FALSE(touch[0].found);
}

}  // namespace
}  // namespace pb::internal::mujoco
