#include "mujoco_injector.hpp"

#include <cmath>
#include <limits>
#include <mutex>

#include "mujoco_frame.hpp"
#include "planarbench/contact_force.hpp"
#include "planarbench/errors.hpp"

namespace pb::internal::mujoco {

namespace {

thread_local ForceInjector* t_active = nullptr;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

ForceInjector::ForceInjector(const Case& c, const mjModel* m, const ModelLayout& layout)
    : case_(c), model_(m), layout_(layout), scratch_(m), approach_mps_(c.contacts.size(), kNaN) {
  static std::once_flag once;
  std::call_once(once, [] {
    if (mjcb_passive != nullptr) {
      throw EngineError("mujoco: mjcb_passive is already set by other code; inject mode needs it");
    }
    mjcb_passive = &ForceInjector::passive_callback;
  });
  if (mjcb_passive != &ForceInjector::passive_callback) {
    throw EngineError("mujoco: mjcb_passive was replaced by other code; inject mode needs it");
  }
}

void ForceInjector::latch(const std::vector<PairObservation>& obs) {
  for (std::size_t k = 0; k < obs.size(); ++k) {
    const bool touching = obs[k].reported && obs[k].penetration_m > 0.0;
    if (!touching) {
      approach_mps_[k] = kNaN;
    } else if (std::isnan(approach_mps_[k])) {
      approach_mps_[k] = obs[k].approach_speed_mps;
    }
  }
}

double ForceInjector::force_n(std::size_t k, const PairObservation& o) const {
  if (!o.reported || !(o.penetration_m > 0.0)) return 0.0;
  // before the first latch (inside the step that meets), the current rate is
  // the approach speed
  const double v0 = std::isnan(approach_mps_[k]) ? o.approach_speed_mps : approach_mps_[k];
  return contact_force_n(case_.contacts[k].law, o.penetration_m, o.approach_speed_mps, v0);
}

void ForceInjector::apply(const mjModel* m, mjData* d) {
  // d->contact holds this evaluation's collisions (mj_collision ran in the
  // position stage, before mj_passive)
  observe_pairs(m, d, layout_, false, scratch_, obs_);
  const mjtNum zero[3] = {0.0, 0.0, 0.0};
  for (std::size_t k = 0; k < obs_.size(); ++k) {
    const double f = force_n(k, obs_[k]);
    if (!(f > 0.0)) continue;
    const PairLayout& p = layout_.pairs[k];
    const mjContact& con = d->contact[obs_[k].deepest];
    const auto n = to_mj(obs_[k].normal_ab);
    // the law pushes body b along n_ab and body a against it, both at the point
    const mjtNum on_b[3] = {f * n[0], f * n[1], f * n[2]};
    const mjtNum on_a[3] = {-on_b[0], -on_b[1], -on_b[2]};
    if (p.mj_body_b > 0) mj_applyFT(m, d, on_b, zero, con.pos, p.mj_body_b, d->qfrc_passive);
    if (p.mj_body_a > 0) mj_applyFT(m, d, on_a, zero, con.pos, p.mj_body_a, d->qfrc_passive);
  }
}

void ForceInjector::passive_callback(const mjModel* m, mjData* d) {
  if (t_active != nullptr && t_active->model_ == m) t_active->apply(m, d);
}

ForceInjector::Scope::Scope(ForceInjector& injector) : previous_(t_active) {
  t_active = &injector;
}
ForceInjector::Scope::~Scope() {
  t_active = previous_;
}

}  // namespace pb::internal::mujoco
