// Tests for core/src/episode_tracker.cpp
#include "planarbench/episode_tracker.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pb {
namespace {

// A penetration delta(t) = 1 - (t - 2)^2 sampled every 0.1 s is positive on
// (1, 3); with force F = 10 delta and the normal speed delta' = -2 (t - 2).
// Linear interpolation of the sign change gives the onset and offset exactly
// when a sample falls on the root (t = 1.0 and 3.0 are grid points here, up
// to rounding of 0.1 k).
TEST(EpisodeTracker, OneEpisodeFromSampledParabola) {
  EpisodeTracker tr;
  for (int k = 0; k <= 40; ++k) {
    const double t = 0.1 * k;
    const double d = 1.0 - (t - 2.0) * (t - 2.0);
    tr.observe(t, 0, 1, d, -2.0 * (t - 2.0), d > 0 ? 10.0 * d : 0.0);
  }
  const auto eps = tr.episodes();
  ASSERT_EQ(eps.size(), 1u);
  EXPECT_NEAR(eps[0].onset_time_s, 1.0, 1e-9);   // grid rounding of 0.1 k only
  EXPECT_NEAR(eps[0].offset_time_s, 3.0, 1e-9);
  // speeds are the sampled delta' at t = 1.0 and 3.0: same grid rounding (~1e-15)
  EXPECT_NEAR(eps[0].approach_speed_mps, 2.0, 1e-9);
  EXPECT_NEAR(eps[0].separation_speed_mps, 2.0, 1e-9);
  EXPECT_NEAR(eps[0].restitution, 1.0, 1e-9);
  // peak at the sample t = 0.1 * 20 = 2.0 (exact in binary up to one rounding)
  EXPECT_NEAR(eps[0].peak_force_n, 10.0, 1e-12);
  EXPECT_NEAR(eps[0].max_penetration_m, 1.0, 1e-12);
  // exact integral of 10 (1 - (t-2)^2) over (1, 3) is 40/3; the trapezoid
  // rule with h = 0.1 underestimates by (b-a) h^2 f''/12 = 2 * 0.01 * 20 / 12
  EXPECT_NEAR(eps[0].impulse_ns, 40.0 / 3.0 - 2.0 * 0.01 * 20.0 / 12.0, 1e-9);
}

// An episode not closed by the end of the run keeps offset NaN.
TEST(EpisodeTracker, OpenEpisodeHasNoOffset) {
  EpisodeTracker tr;
  tr.observe(0.0, 0, 1, -1.0, 1.0, 0.0);
  tr.observe(1.0, 0, 1, 1.0, 1.0, 5.0);
  EXPECT_TRUE(tr.in_contact(0, 1));
  const auto eps = tr.episodes();
  ASSERT_EQ(eps.size(), 1u);
  // linear interpolation of -1 -> +1 over (0, 1): exactly 0.5, a few ulps allowed
  EXPECT_NEAR(eps[0].onset_time_s, 0.5, 1e-15);
  EXPECT_TRUE(std::isnan(eps[0].offset_time_s));
}

// Engines that stop reporting a contact close it at that step.
TEST(EpisodeTracker, SeparatedClosesAtThatStep) {
  EpisodeTracker tr;
  tr.observe(1.0, 2, 3, 0.1, 1.0, 5.0);
  tr.observe(1.5, 2, 3, 0.1, -0.5, 5.0);
  tr.observe_separated(2.0, 2, 3, -0.5);
  const auto eps = tr.episodes();
  ASSERT_EQ(eps.size(), 1u);
  EXPECT_EQ(eps[0].offset_time_s, 2.0);
  EXPECT_EQ(eps[0].separation_speed_mps, 0.5);
  EXPECT_EQ(eps[0].restitution, 0.5);
  EXPECT_FALSE(tr.in_contact(2, 3));
}

// An impact inside one step (apart at both ends, an impulse within): one
// closed episode at the time the approach closes the gap, duration 0, force
// impulse / step. Values chosen exact in binary: gap 0.25 m at 1 m/s from
// t = 2 s is t = 2.25 s.
TEST(EpisodeTracker, ImpactWithinAStepIsAnEpisode) {
  EpisodeTracker tr;
  tr.observe(2.0, 0, 1, -0.25, 1.0, 0.0);
  tr.record_within_step(2.0, 3.0, 0, 1, 0.25, 1.0, 0.5, 1.5);
  EXPECT_FALSE(tr.in_contact(0, 1));
  const auto eps = tr.episodes();
  ASSERT_EQ(eps.size(), 1u);
  EXPECT_EQ(eps[0].onset_time_s, 2.25);
  EXPECT_EQ(eps[0].offset_time_s, 2.25);
  EXPECT_EQ(eps[0].restitution, 0.5);
  EXPECT_EQ(eps[0].impulse_ns, 1.5);
  EXPECT_EQ(eps[0].peak_force_n, 1.5);
  EXPECT_EQ(eps[0].max_penetration_m, 0.0);
  // a gap the approach does not close within the step, or an unknown one:
  // the step's end, or its start
  tr.record_within_step(4.0, 5.0, 0, 1, 7.0, 1.0, 0.5, 1.0);
  tr.record_within_step(6.0, 7.0, 0, 1, std::nan(""), 1.0, 0.5, 1.0);
  const auto all = tr.episodes();
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[1].onset_time_s, 5.0);
  EXPECT_EQ(all[2].onset_time_s, 6.0);
}

}  // namespace
}  // namespace pb
