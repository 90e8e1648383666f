// Tests for core/analytic/normal_contact_episodes.cpp
#include "normal_contact_episodes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "normal_contact_motion.hpp"
#include "planarbench/contact_law_response.hpp"

namespace pb::internal {
namespace {

// Without gravity a body of 1 kg hits a Kelvin-Voigt contact (K = 1e4 N/m,
// c = 10 N s/m) at 3 m/s. pb::kelvin_voigt_response (core, written apart from
// this closed form) gives the clamped oscillator's figures: restitution,
// duration until the penetration returns to 0, peak force, peak penetration
// and impulse m v (1 + e).
TEST(NormalContactEpisodes, WithoutGravityMatchesTheCoreResponse) {
  const double k = 1e4;
  const double c = 10.0;
  const double v = 3.0;
  NormalContactMotion m({1.0, k, c, 0.0, 0.0, -v});
  m.extend_to(1.0);
  const auto eps = normal_contact_episodes(m, 1.0);
  ASSERT_EQ(eps.size(), 1u);
  const ContactEpisode& e = eps[0];
  const CollisionResponse r = kelvin_voigt_response(k, c, 1.0, v);
  EXPECT_EQ(e.onset_time_s, 0.0);
  EXPECT_EQ(e.approach_speed_mps, v);
  // rounding of closed forms with exp and asin: 1e-14 relative
  EXPECT_NEAR(e.restitution, r.restitution, 1e-14);
  EXPECT_NEAR(e.separation_speed_mps, r.restitution * v, 1e-14 * v);
  EXPECT_NEAR(e.offset_time_s, r.duration_s, 1e-15);
  EXPECT_NEAR(e.impulse_ns, r.impulse_ns, 1e-13 * r.impulse_ns);
  EXPECT_NEAR(e.max_penetration_m, r.max_penetration_m, 1e-14 * r.max_penetration_m);
  // the core's peak force is a golden-section search: ~1e-12 relative
  EXPECT_NEAR(e.peak_force_n, r.peak_force_n, 1e-12 * r.peak_force_n);
}

// With gravity the impulse of the momentum balance equals the integral of the
// force itself (Simpson's rule over each phase, 2e5 intervals: error ~1e-15).
TEST(NormalContactEpisodes, ImpulseIsTheIntegralOfTheForce) {
  NormalContactMotion m({1.0, 1e4, 10.0, -8.492764724752476, 0.0, -6.157317981455282});
  m.extend_to(0.1);
  const auto eps = normal_contact_episodes(m, 0.1);
  ASSERT_EQ(eps.size(), 1u);
  double integral = 0.0;
  for (std::size_t j = 0; j < m.phases().size(); ++j) {
    const NormalPhase& ph = m.phases()[j];
    if (ph.kind != NormalPhaseKind::pressed || ph.start_s > 0.1) continue;  // zero force elsewhere
    const int n = 200000;
    const double h = (ph.end_s - ph.start_s) / n;
    double sum = 0.0;
    for (int i = 0; i <= n; ++i) {
      // at the onset itself (u = 0, no force reported) take the right limit c v
      const double t = ph.start_s + h * i;
      const double f = i == 0 ? m.max_force_n(j, t, t) : m.state_at(t).force_n;
      sum += f * (i == 0 || i == n ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0));
    }
    integral += sum * h / 3.0;
  }
  EXPECT_NEAR(eps[0].impulse_ns, integral, 1e-11 * integral);
}

// Starting at rest touching, loaded by gravity: a step load on a damped
// oscillator. Textbook (e.g. Meirovitch §3.3): delta = delta_st (1 - e^(-s t)
// (cos w_d t + s / w_d sin w_d t)), largest at w_d t = pi:
// delta_max = delta_st (1 + exp(-zeta pi / sqrt(1 - zeta^2))). The episode
// stays open: offset, separation and restitution NaN; approach speed 0.
TEST(NormalContactEpisodes, RestingStartIsAnOpenEpisode) {
  const double a = -6.934313360383997;
  NormalContactMotion m({1.0, 1e4, 10.0, a, 0.0, 0.0});
  m.extend_to(1.0);
  const auto eps = normal_contact_episodes(m, 1.0);
  ASSERT_EQ(eps.size(), 1u);
  const ContactEpisode& e = eps[0];
  EXPECT_EQ(e.onset_time_s, 0.0);
  EXPECT_EQ(e.approach_speed_mps, 0.0);
  EXPECT_FALSE(std::signbit(e.approach_speed_mps));
  EXPECT_TRUE(std::isnan(e.offset_time_s));
  EXPECT_TRUE(std::isnan(e.separation_speed_mps));
  EXPECT_TRUE(std::isnan(e.restitution));
  const double zeta = 0.05;
  const double delta_st = -a / 1e4;
  const double delta_max =
      delta_st * (1.0 + std::exp(-zeta * std::numbers::pi / std::sqrt(1.0 - zeta * zeta)));
  EXPECT_NEAR(e.max_penetration_m, delta_max, 1e-15 * delta_max);
  // impulse so far: m (u'(1) - 0) - m a * 1 s
  EXPECT_NEAR(e.impulse_ns, m.state_at(1.0).gap_rate_mps - a, 1e-14);
  // the peak force is no less than any sample and no less than K delta_max
  EXPECT_GE(e.peak_force_n, 1e4 * delta_max);
  double sampled = 0.0;
  for (int i = 0; i <= 20000; ++i) sampled = std::max(sampled, m.state_at(0.1 * i / 20000).force_n);
  EXPECT_GE(e.peak_force_n, sampled);
  EXPECT_NEAR(e.peak_force_n, sampled, 1e-7 * sampled);  // a 5e-6 s grid
}

// Asked in the middle of a contact, the episode is open with the maxima so
// far; asked after it, closed.
TEST(NormalContactEpisodes, OnlyWhatHappenedByNow) {
  NormalContactMotion m({1.0, 1e4, 10.0, -9.8066, 0.1, 0.0});
  m.extend_to(1.0);
  const double onset = m.phases()[1].start_s;
  const auto during = normal_contact_episodes(m, onset + 0.005);
  ASSERT_EQ(during.size(), 1u);
  EXPECT_TRUE(std::isnan(during[0].offset_time_s));
  // 5 ms in, still compressing: the maximum so far is the penetration now
  EXPECT_DOUBLE_EQ(during[0].max_penetration_m, -m.state_at(onset + 0.005).gap_m);
  const auto after = normal_contact_episodes(m, 1.0);
  ASSERT_GE(after.size(), 1u);
  EXPECT_FALSE(std::isnan(after[0].offset_time_s));
  EXPECT_GT(after[0].max_penetration_m, during[0].max_penetration_m);
  EXPECT_TRUE(normal_contact_episodes(m, 0.5 * onset).empty());
}

// No damping: elastic, the episode lasts pi / w0 and e = 1.
TEST(NormalContactEpisodes, UndampedIsElastic) {
  NormalContactMotion m({1.0, 1e4, 0.0, 0.0, 0.0, -2.0});
  m.extend_to(1.0);
  const auto eps = normal_contact_episodes(m, 1.0);
  ASSERT_EQ(eps.size(), 1u);
  EXPECT_NEAR(eps[0].offset_time_s, std::numbers::pi / 100.0, 1e-16);
  EXPECT_NEAR(eps[0].restitution, 1.0, 1e-14);
  EXPECT_NEAR(eps[0].peak_force_n, 1e4 * 2.0 / 100.0, 1e-12);  // K v / w0
  EXPECT_NEAR(eps[0].impulse_ns, 4.0, 1e-13);                  // 2 m v
}

// A clamp followed by the force turning positive again is one episode: the
// penetration never returned to zero in between.
TEST(NormalContactEpisodes, RecontactStaysInOneEpisode) {
  NormalContactMotion m({1.0, 100.0, 2.0, -9.8066, 0.0, -1.42});
  m.extend_to(1.0);
  ASSERT_GE(m.phases().size(), 3u);
  ASSERT_EQ(m.phases()[1].kind, NormalPhaseKind::clamped);
  ASSERT_EQ(m.phases()[2].kind, NormalPhaseKind::pressed);
  const auto eps = normal_contact_episodes(m, 1.0);
  ASSERT_EQ(eps.size(), 1u);
  EXPECT_TRUE(std::isnan(eps[0].offset_time_s));
}

}  // namespace
}  // namespace pb::internal
