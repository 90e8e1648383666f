// What the runner reads of a MuJoCo run at each step, whichever MuJoCo ran it
// (engine "mujoco", 2.2.2 in process; engine "mujoco3", 3.3.8 in WebAssembly,
// through a 2.2.2 model of the same MJCF that mirrors its state): each case
// body's state, each pair's observation (mujoco_pair_state.hpp) fed to the
// episode tracker, the active contacts, and MPR's depth against the exact
// geometry.
#pragma once

#include <mujoco/mujoco.h>

#include <optional>
#include <span>
#include <vector>

#include "mujoco_contact_buckets.hpp"
#include "mujoco_model.hpp"
#include "mujoco_pair_state.hpp"
#include "mujoco_plan.hpp"
#include "planarbench/case.hpp"
#include "planarbench/engine.hpp"
#include "planarbench/episode_tracker.hpp"

namespace pb::internal::mujoco {

class ForceInjector;

// state of case body i in MuJoCo's data (after the position stage and
// mj_comVel); a fixed body's from the case
[[nodiscard]] BodyState mujoco_body_state(const mjModel* m, const mjData* d, const Case& c,
                                          const ModelLayout& layout, std::size_t i);

class PairSampler {
 public:
  // `layout` gains the group pairs MuJoCo's collider reports
  PairSampler(const Case& c, const MujocoPlan& plan, ModelLayout& layout);

  // Observes the pairs with contacts at time t_s (d after the constraint
  // solve), and closes the contact of each pair reported at the sample
  // before and not now (every other pair is apart and stays so: nothing to
  // observe). Forces: from mj_contactForce on d, or, when `forces` is given
  // (6 per contact of d->contact), from those (another MuJoCo computed
  // them); none when !with_force. With an injector, its law's force
  // replaces MuJoCo's.
  void sample(const mjModel* m, const mjData* d, double t_s, bool with_force,
              std::span<const double> forces, ForceInjector* injector);

  // the pairs with contacts at the last sample, ascending pair
  [[nodiscard]] const std::vector<PairObservation>& observations() const { return obs_; }
  void contacts(std::vector<ContactSample>& out) const;
  [[nodiscard]] std::vector<ContactEpisode> episodes() const { return tracker_.episodes(); }
  // adds each pair's "mpr_depth_check" to mapping["pairs"]
  void add_depth_checks(nlohmann::json& mapping) const;

 private:
  struct DepthCheck {
    long samples = 0;
    double max_abs_error_m = 0.0;
    double max_penetration_m = 0.0;
  };

  // the per-pair vectors sized for the layout's pairs (group pairs join)
  void grow();

  const Case& case_;
  const MujocoPlan& plan_;
  ModelLayout& layout_;
  std::optional<Scratch> scratch_;
  ContactBuckets buckets_;
  std::vector<PairObservation> obs_;
  std::vector<PairObservation> dense_;  // the injector's view: one per pair
  std::vector<int> reported_;       // pairs reported at the last sample, ascending
  std::vector<int> reported_now_;   // scratch
  std::vector<Vec2> last_point_m_;  // per pair: last contact point seen
  std::vector<Vec2> last_normal_;   // per pair: last normal seen (a -> b)
  std::vector<bool> seen_;
  std::vector<bool> check_;         // per pair: MPR depth checked (depth_checked)
  std::vector<DepthCheck> depth_;
  EpisodeTracker tracker_;
};

}  // namespace pb::internal::mujoco
