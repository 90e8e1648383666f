// The contact-episode table (SPEC §4) of a NormalContactMotion, exact: an
// episode runs from the onset (u reaches 0 moving in, or t = 0 when the run
// starts in contact) to the offset (u back to 0), through pressed and clamped
// phases. Peak force and peak penetration come from the closed form's
// stationary points; the impulse from the momentum balance along the normal,
// J = m (u'(t1) - u'(t0)) - m a (t1 - t0) (the force is the only other normal
// force), exact up to rounding.
#pragma once

#include <vector>

#include "normal_contact_motion.hpp"
#include "planarbench/engine.hpp"

namespace pb::internal {

// Every episode that started by now_s (<= motion.known_until_s()), body
// indices left at -1 for the caller. An episode open at now_s has offset,
// separation speed and restitution NaN and its maxima and impulse so far. An
// episode starting at rest (approach speed 0) has restitution NaN.
[[nodiscard]] std::vector<ContactEpisode> normal_contact_episodes(const NormalContactMotion& motion,
                                                                  double now_s);

}  // namespace pb::internal
