// Runs one impact case on an engine and reads its post-impact state
// (SPEC §8): the engine is stepped on the case's 1e-4 s grid until the
// contact has ended, i.e. every contact episode is closed and the lowest
// point of the ellipse moves away from the ground; the velocities then are
// carried back ballistically to the touch (x' and theta' unchanged in flight,
// y' + g (t - t_touch)): the measured post-impact state is the one at the
// impact's instant.
#pragma once

#include <string>

#include "planarbench/engine.hpp"
#include "planarbench/impacts/impact_object.hpp"
#include "planarbench/settings.hpp"

namespace pb {

struct ImpactOutcome {
  ImpactState after;          // at the touch, the project's convention
  double read_time_s = 0.0;   // s, when the contact was over
  double contact_s = 0.0;     // s, first onset to the last offset
  int episodes = 0;           // contact episodes (chatter shows as > 1)
  long steps = 0;             // the engine's steps
  std::string failure;        // why no prediction ("" when there is one)
  [[nodiscard]] bool ok() const { return failure.empty(); }
};

// Builds `impact` on `engine` with `overrides` and runs it. An EngineError
// (divergence, a refused build) becomes the outcome's failure; so does a
// contact that has not ended by the case's duration.
[[nodiscard]] ImpactOutcome simulate_impact(Engine& engine, const Case& impact,
                                            const SettingsOverrides& overrides,
                                            const ImpactObject& o);

}  // namespace pb
