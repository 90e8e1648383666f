#include "mujoco_probe.hpp"

#include <algorithm>

#include "mujoco_fault.hpp"
#include "mujoco_frame.hpp"
#include "mujoco_pair_state.hpp"
#include "mujoco_stepping.hpp"
#include "planarbench/errors.hpp"

namespace pb::internal::mujoco {

std::vector<FirstTouch> probe_first_touch(const mjModel* m, const Case& c,
                                          const ModelLayout& layout, double until_s,
                                          long& steps_taken) {
  steps_taken = 0;
  DataPtr data(mj_makeData(m));
  mjData* d = data.get();
  set_initial_state(m, d, c, layout);
  WarningWatch watch;
  watch.reset(d);
  Scratch scratch(m);
  std::vector<PairObservation> obs;
  std::vector<FirstTouch> touch(c.contacts.size());
  std::size_t pending = 0;
  for (const auto& p : layout.pairs) pending += p.present ? 1 : 0;

  const double dt = m->opt.timestep;
  for (long step = 0; pending > 0 && static_cast<double>(step) * dt <= until_s; ++step) {
    forward_checked(m, d);
    // a fault here fails the build: the model itself cannot be run
    for (const RaisedWarning& w : watch.raised(d)) {
      if (!warning_info(w.warning).fault) continue;
      throw EngineError("contact-free probe run (calibration): " +
                        fault_reason(c, layout, w, static_cast<double>(step) * dt,
                                     last_warning_text()));
    }
    observe_pairs(m, d, layout, false, scratch, obs);
    for (std::size_t k = 0; k < touch.size(); ++k) {
      const PairObservation& o = obs[k];
      // touching: distance within the pair's contact threshold (paper: 1e-10 m)
      if (touch[k].found || !o.reported || -o.penetration_m > c.contacts[k].threshold_m) continue;
      FirstTouch& t = touch[k];
      t.found = true;
      t.time_s = static_cast<double>(step) * dt;
      t.point_m = o.point_m;
      t.normal_ab = o.normal_ab;
      t.approach_speed_mps = std::max(o.approach_speed_mps, 0.0);
      const auto p3 = to_mj(o.point_m);
      const auto n3 = to_mj(o.normal_ab);
      const PairLayout& pl = layout.pairs[k];
      t.effective_mass_kg =
          effective_mass_kg(m, d, pl.mj_body_a, pl.mj_body_b, p3.data(), n3.data(), scratch);
      --pending;
    }
    if (pending == 0) break;  // every pair found: no step beyond the last touch
    integrate(m, d);
    ++steps_taken;
  }
  return touch;
}

}  // namespace pb::internal::mujoco
