#include "ode_probe.hpp"

#include <cmath>

#include "ode_pair_contact.hpp"
#include "ode_world.hpp"

namespace pb::internal::ode {

std::vector<FirstTouch> probe_first_touches(const Case& c, double h, long& steps_taken) {
  steps_taken = 0;
  std::vector<FirstTouch> out(c.contacts.size());
  OdeWorld world(c);
  PairCollider collider(c, world);
  StepContacts now;

  // pairs of two fixed bodies never touch: count only the others
  std::size_t waiting = 0;
  for (const ContactPair& p : c.contacts) {
    const bool moving = !c.bodies[static_cast<std::size_t>(p.body_a)].fixed ||
                        !c.bodies[static_cast<std::size_t>(p.body_b)].fixed;
    if (moving) ++waiting;
  }
  const auto last_step = static_cast<long>(std::floor(c.duration_s / h + 1e-9));
  for (long k = 0; waiting > 0; ++k) {
    collider.collide(now);
    for (const PairContact& pc : now.pairs) {
      FirstTouch& first = out[static_cast<std::size_t>(pc.pair)];
      if (first.found) continue;
      first.found = true;
      first.time_s = static_cast<double>(k) * h;
      first.point_m = pc.point_m;
      first.normal_ab = pc.normal_ab;
      first.approach_speed_mps = pc.approach_speed_mps;
      first.centres_m = world.centres();
      --waiting;
    }
    if (waiting == 0 || k >= last_step || world.first_blown_up_body() >= 0) break;
    step_world(world.world(), h);
    ++steps_taken;
    world.remove_planar_drift();
  }
  return out;
}

}  // namespace pb::internal::ode
