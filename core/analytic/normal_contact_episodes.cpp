#include "normal_contact_episodes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pb::internal {

std::vector<ContactEpisode> normal_contact_episodes(const NormalContactMotion& motion,
                                                    double now_s) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  const double m = motion.params().mass_kg;
  const double a = motion.params().normal_gravity_mps2;
  const auto& phases = motion.phases();

  std::vector<ContactEpisode> out;
  bool open = false;
  ContactEpisode ep;
  double onset_rate_mps = 0.0;  // u' at the onset
  for (std::size_t i = 0; i < phases.size() && phases[i].start_s <= now_s; ++i) {
    const NormalPhase& ph = phases[i];
    const bool touching = ph.kind != NormalPhaseKind::separated;
    if (touching && !open) {
      // onset: u' < 0 moving in; the approach speed is -u'
      open = true;
      ep = ContactEpisode{};
      ep.onset_time_s = ph.start_s;
      onset_rate_mps = ph.gap_rate0_mps;
      ep.approach_speed_mps = 0.0 - ph.gap_rate0_mps;  // +0, not -0, at rest
      ep.peak_force_n = 0.0;
      ep.max_penetration_m = std::max(0.0, -ph.gap0_m);
    }
    if (touching) {
      const double to_s = std::min(ph.end_s, now_s);
      ep.peak_force_n = std::max(ep.peak_force_n, motion.max_force_n(i, ph.start_s, to_s));
      ep.max_penetration_m =
          std::max(ep.max_penetration_m, motion.max_penetration_m(i, ph.start_s, to_s));
    } else if (open) {
      // offset: this separated phase starts at u = 0 moving out
      open = false;
      ep.offset_time_s = ph.start_s;
      ep.separation_speed_mps = ph.gap_rate0_mps;
      ep.restitution =
          ep.approach_speed_mps > 0.0 ? ep.separation_speed_mps / ep.approach_speed_mps : nan;
      ep.impulse_ns =
          m * (ph.gap_rate0_mps - onset_rate_mps) - m * a * (ep.offset_time_s - ep.onset_time_s);
      out.push_back(ep);
    }
  }
  if (open) {
    // still in contact at now_s: the impulse so far
    const NormalState s = motion.state_at(now_s);
    ep.offset_time_s = nan;
    ep.separation_speed_mps = nan;
    ep.restitution = nan;
    ep.impulse_ns = m * (s.gap_rate_mps - onset_rate_mps) - m * a * (now_s - ep.onset_time_s);
    out.push_back(ep);
  }
  return out;
}

}  // namespace pb::internal
