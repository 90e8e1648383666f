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
  std::vector<PairContact> now;

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
    for (std::size_t p = 0; p < now.size(); ++p) {
      if (out[p].found || !now[p].touching) continue;
      out[p].found = true;
      out[p].time_s = static_cast<double>(k) * h;
      out[p].point_m = now[p].point_m;
      out[p].normal_ab = now[p].normal_ab;
      out[p].approach_speed_mps = now[p].approach_speed_mps;
      out[p].centres_m = world.centres();
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
