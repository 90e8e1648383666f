// Force injection (`mujoco.mode=inject`): MuJoCo's contacts stay inactive
// (gap beyond any penetration, so the constraint solver never sees them) but
// MuJoCo's colliders still report them; at every evaluation of the dynamics
// (each Euler step, each RK4 stage) the case's own force law is evaluated at
// the deepest contact of each pair and applied as equal and opposite forces at
// the contact point into qfrc_passive (mj_applyFT, i.e. J^T f: force and torque
// about each body). Comparing inject with native separates the contact-law
// mapping from MuJoCo's integration.
#pragma once

#include <mujoco/mujoco.h>

#include <vector>

#include "mujoco_model.hpp"
#include "mujoco_pair_state.hpp"
#include "planarbench/case.hpp"

namespace pb::internal::mujoco {

class ForceInjector {
 public:
  // installs MuJoCo's process-global mjcb_passive once; throws EngineError if
  // something else already owns it
  ForceInjector(const Case& c, const mjModel* m, const ModelLayout& layout);

  // at a step boundary: latches each pair's approach speed at the first state
  // with penetration > 0 (Lankarani-Nikravesh's delta_dot_minus), clears it
  // once the pair separates
  void latch(const std::vector<PairObservation>& obs);
  // the case law's force of pair k at an observation, N (what is applied)
  [[nodiscard]] double force_n(std::size_t k, const PairObservation& o) const;

  // While alive, mjcb_passive on this thread applies this injector's forces
  // (for its own model only). The callback is global, its target thread-local.
  class Scope {
   public:
    explicit Scope(ForceInjector& injector);
    ~Scope();
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    ForceInjector* previous_;
  };

 private:
  static void passive_callback(const mjModel* m, mjData* d);
  void apply(const mjModel* m, mjData* d);

  const Case& case_;
  const mjModel* model_;
  const ModelLayout& layout_;
  Scratch scratch_;
  std::vector<PairObservation> obs_;
  std::vector<double> approach_mps_;  // latched, NaN = none
};

}  // namespace pb::internal::mujoco
