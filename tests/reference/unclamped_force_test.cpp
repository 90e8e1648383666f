// Tests for core/reference/src/unclamped_force.cpp
//
// Where the law pushes, the unclamped force is contact_force_n itself; where
// it would pull, it is the law's formula (paper eqs. 1 and 7) without the
// clamp, computed here by hand.
#include "planarbench/reference/unclamped_force.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "planarbench/contact_force.hpp"

namespace pb {
namespace {

TEST(UnclampedForce, KelvinVoigtBothSigns) {
  const ContactLaw kv = KelvinVoigt{1e4, 10.0, 0.0};
  // pushing: equal to the shared law (relative 1e-15: one probe subtraction)
  EXPECT_NEAR(unclamped_force_n(kv, 0.05, 3.0, 0.0), contact_force_n(kv, 0.05, 3.0, 0.0), 1e-12);
  // separating fast: K delta + c delta_dot = 500 - 600 = -100 N (the clamp's region)
  EXPECT_NEAR(unclamped_force_n(kv, 0.05, -60.0, 0.0), -100.0, 1e-11);
  EXPECT_EQ(contact_force_n(kv, 0.05, -60.0, 0.0), 0.0);
  // below contact: the same straight line continued
  // 1e-11 / 1e-12 N on O(100) N: K delta with delta a rounded decimal
  // (1e4 * 1.1e-16 * 0.05) and one addition, ~1e-13 N
  EXPECT_NEAR(unclamped_force_n(kv, -0.01, 2.0, 0.0), -100.0 + 20.0, 1e-12);
}

TEST(UnclampedForce, KelvinVoigtWithRamp) {
  // damping ramped by the cubic step over 0.1 m: at delta = 0.05 the step is 0.5
  const ContactLaw kv = KelvinVoigt{1e4, 10.0, 0.1};
  // 1e-10 N on terms of 1000 N: the cubic step's few roundings (~1e-16 each)
  EXPECT_NEAR(unclamped_force_n(kv, 0.05, -200.0, 0.0), 500.0 - 0.5 * 10.0 * 200.0, 1e-10);
  EXPECT_NEAR(unclamped_force_n(kv, -0.01, 2.0, 0.0), -100.0, 1e-12);  // no damping below 0
}

TEST(UnclampedForce, LankaraniNikravesh) {
  // F = K delta^1.5 (1 + 3 (1 - e^2)/4 delta_dot / v0), here with v0 = 1.78 m/s
  const double k = 1.0242e10, e = 0.7, v0 = 1.78, d = 1e-4;
  const ContactLaw ln = LankaraniNikravesh{k, 1.5, e, std::nullopt, {}};
  for (const double rate : {1.5, 0.0, -1.2, -5.0}) {
    const double expect = k * std::pow(d, 1.5) * (1.0 + 0.75 * (1.0 - e * e) * rate / v0);
    // relative 1e-12: pow and a handful of products, each 1.1e-16
    EXPECT_NEAR(unclamped_force_n(ln, d, rate, v0) / expect, 1.0, 1e-12) << rate;
  }
  EXPECT_EQ(unclamped_force_n(ln, -1e-6, 1.0, v0), 0.0);
}

TEST(UnclampedForce, HertzHasNoDamping) {
  const ContactLaw hz = Hertz{1e9, 1.5, std::nullopt};
  // 1000 N from pow(1e-4, 1.5): relative 1e-9, a few roundings of 1.1e-16
  // with plenty to spare (any damping at -3 m/s would change it by O(1))
  EXPECT_NEAR(unclamped_force_n(hz, 1e-4, -3.0, 0.0), 1e9 * 1e-6, 1e-6);
}

}  // namespace
}  // namespace pb
