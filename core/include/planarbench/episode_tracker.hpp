// Builds the contact-episode table (SPEC §4) from samples taken at an engine's
// own steps. An episode starts when the penetration becomes positive and ends
// when it returns to zero; the impulse is the trapezoid integral of the force
// over the steps. Onset and offset times are interpolated linearly between the
// two steps that bracket the sign change of the penetration.
#pragma once

#include <map>
#include <utility>
#include <vector>

#include "planarbench/engine.hpp"

namespace pb {

class EpisodeTracker {
 public:
  // One observation of a pair at time t_s. penetration_m > 0 means in contact;
  // normal_speed_mps is the relative normal velocity, > 0 approaching.
  void observe(double t_s, int body_a, int body_b, double penetration_m,
               double normal_speed_mps, double force_n);
  // Marks a step at which the pair was not seen at all (no contact reported):
  // closes an open episode of that pair at t_s.
  void observe_separated(double t_s, int body_a, int body_b, double normal_speed_mps);
  // Records an impact the observations cannot show: the pair was apart at
  // both ends of the step [t0_s, t1_s] and a contact impulse acted within it
  // (a rigid engine's continuous collision resolves a fast impact inside one
  // step: Box2D's time of impact). A closed episode of zero duration at the
  // time the approach speed closes gap0_m (the step's start when unknown),
  // with the step's impulse, peak force impulse / step, the normal speeds
  // before (approach, > 0) and after (separation, > 0), no penetration.
  void record_within_step(double t0_s, double t1_s, int body_a, int body_b, double gap0_m,
                          double approach_mps, double separation_mps, double impulse_ns);
  // pairs currently in contact
  [[nodiscard]] bool in_contact(int body_a, int body_b) const;
  [[nodiscard]] std::vector<ContactEpisode> episodes() const;  // closed + open ones

 private:
  struct Open {
    ContactEpisode ep;
    double last_t_s = 0.0;
    double last_force_n = 0.0;
    double last_penetration_m = 0.0;
    double last_speed_mps = 0.0;
  };
  struct Last {
    double t_s = 0.0;
    double penetration_m = 0.0;
    double speed_mps = 0.0;
    bool valid = false;
  };
  std::vector<ContactEpisode> closed_;
  std::map<std::pair<int, int>, Open> open_;
  std::map<std::pair<int, int>, Last> last_;
};

}  // namespace pb
