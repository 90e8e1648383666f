#include "planarbench/impacts/impact_simulation.hpp"

#include <fmt/format.h>

#include <cmath>
#include <vector>

#include "planarbench/errors.hpp"
#include "planarbench/impacts/impact_case.hpp"

namespace pb {

namespace {

// true once no episode is open and at least one has closed
bool contact_over(const std::vector<ContactEpisode>& episodes) {
  if (episodes.empty()) return false;
  for (const ContactEpisode& e : episodes) {
    if (std::isnan(e.offset_time_s)) return false;
  }
  return true;
}

}  // namespace

ImpactOutcome simulate_impact(Engine& engine, const Case& impact, const SettingsOverrides& overrides,
                              const ImpactObject& o) {
  ImpactOutcome out;
  try {
    engine.build(impact, overrides);
    std::vector<BodyState> states;
    const int samples = impact.output_samples();
    for (int k = 1; k < samples; ++k) {
      engine.advance_to(impact.output_time(k));
      const std::vector<ContactEpisode> episodes = engine.episodes();
      if (!contact_over(episodes)) continue;
      engine.body_states(states);
      const BodyState& s = states[1];
      const Vec2 r = lowest_point_offset(o, s.angle_rad);
      // vertical velocity of the lowest point: v_y + omega r_x
      if (s.velocity_mps.y() + s.angular_velocity_radps * r.x() < 0.0) continue;
      out.read_time_s = engine.time();
      out.episodes = static_cast<int>(episodes.size());
      out.contact_s = episodes.back().offset_time_s - episodes.front().onset_time_s;
      out.after.angle_rad = s.angle_rad;
      out.after.velocity_mps = s.velocity_mps;
      out.after.velocity_mps.y() -= impact.gravity_mps2.y() * (out.read_time_s - kLeadTime_s);
      out.after.angular_velocity_radps = s.angular_velocity_radps;
      out.steps = engine.steps();
      return out;
    }
    out.steps = engine.steps();
    out.failure = fmt::format("the contact had not ended after {} s", impact.duration_s);
  } catch (const EngineError& e) {
    out.failure = e.what();
  }
  return out;
}

}  // namespace pb
