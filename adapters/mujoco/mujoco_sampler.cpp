#include "mujoco_sampler.hpp"

#include <algorithm>
#include <cmath>

#include "mujoco_exact_depth.hpp"
#include "mujoco_frame.hpp"
#include "mujoco_injector.hpp"

namespace pb::internal::mujoco {

BodyState mujoco_body_state(const mjModel* m, const mjData* d, const Case& c,
                            const ModelLayout& layout, std::size_t i) {
  const Body& b = c.bodies[i];
  BodyState s;
  if (b.fixed || m == nullptr) {
    s.position_m = b.position_m;
    s.angle_rad = b.angle_rad;
    return s;
  }
  const BodyLayout& l = layout.bodies[i];
  // centre of mass (inertial frame origin) and its velocity, world frame;
  // the angle from the hinge coordinate, continuous (no wrapping)
  s.position_m = from_mj(&d->xipos[3 * static_cast<std::size_t>(l.mj_body)]);
  s.angle_rad = ccw_from_hinge(d->qpos[l.qpos_hinge]);
  mjtNum v[6];  // (angular, linear) at the centre of mass
  mj_objectVelocity(m, d, mjOBJ_BODY, l.mj_body, v, 0);
  s.velocity_mps = from_mj(v + 3);
  s.angular_velocity_radps = ccw_rate_from_mj(v);
  return s;
}

PairSampler::PairSampler(const Case& c, const MujocoPlan& plan, const ModelLayout& layout)
    : case_(c),
      plan_(plan),
      layout_(layout),
      last_point_m_(c.contacts.size(), Vec2::Zero()),
      last_normal_(c.contacts.size(), Vec2::Zero()),
      seen_(c.contacts.size(), false),
      depth_(c.contacts.size()) {}

void PairSampler::sample(const mjModel* m, const mjData* d, double t, bool with_force,
                         std::span<const double> forces, ForceInjector* injector) {
  if (!scratch_) scratch_.emplace(m);
  observe_pairs(m, d, layout_, with_force, *scratch_, obs_, forces);
  if (injector != nullptr) {
    injector->latch(obs_);
    for (std::size_t k = 0; k < obs_.size(); ++k) obs_[k].force_n = injector->force_n(k, obs_[k]);
  }
  for (std::size_t k = 0; k < obs_.size(); ++k) {
    const PairLayout& p = layout_.pairs[k];
    if (!p.present) continue;
    const int a = case_.contacts[k].body_a;
    const int b = case_.contacts[k].body_b;
    const PairObservation& o = obs_[k];
    if (o.reported && o.penetration_m > 0.0 && plan_.pairs[k].check_depth) {
      const auto ia = static_cast<std::size_t>(a);
      const auto ib = static_cast<std::size_t>(b);
      const auto exact = exact_penetration_m(
          case_.bodies[ia].shape, mujoco_body_state(m, d, case_, layout_, ia),
          case_.bodies[ib].shape, mujoco_body_state(m, d, case_, layout_, ib));
      DepthCheck& dc = depth_[k];
      ++dc.samples;
      dc.max_abs_error_m = std::max(dc.max_abs_error_m, std::abs(o.penetration_m - *exact));
      dc.max_penetration_m = std::max(dc.max_penetration_m, *exact);
    }
    if (o.reported) {
      tracker_.observe(t, a, b, o.penetration_m, o.approach_speed_mps, o.force_n);
      last_point_m_[k] = o.point_m;
      last_normal_[k] = o.normal_ab;
      seen_[k] = true;
    } else {
      // not reported (beyond the margin): the speed along the last normal seen
      // closes an open episode
      double speed = 0.0;
      if (seen_[k]) {
        const auto p3 = to_mj(last_point_m_[k]);
        const auto n3 = to_mj(last_normal_[k]);
        speed = approach_speed_mps(m, d, p.mj_body_a, p.mj_body_b, p3.data(), n3.data(),
                                   *scratch_);
      }
      tracker_.observe_separated(t, a, b, speed);
    }
  }
}

void PairSampler::contacts(std::vector<ContactSample>& out) const {
  out.clear();
  for (std::size_t k = 0; k < obs_.size(); ++k) {
    const PairObservation& o = obs_[k];
    if (!o.reported || !(o.penetration_m > 0.0)) continue;
    ContactSample s;
    s.body_a = case_.contacts[k].body_a;
    s.body_b = case_.contacts[k].body_b;
    s.force_n = o.force_n;
    s.penetration_m = o.penetration_m;
    s.normal = o.normal_ab;
    s.point_m = o.point_m;
    s.tangential_force_n = o.tangential_force_n;
    out.push_back(s);
  }
}

void PairSampler::add_depth_checks(nlohmann::json& m) const {
  for (std::size_t k = 0; k < depth_.size() && m.contains("pairs"); ++k) {
    if (!plan_.pairs[k].check_depth) continue;
    m["pairs"][k]["mpr_depth_check"] = {
        {"what",
         "MuJoCo's (MPR) penetration against the exact circle-ellipse penetration, "
         "over every step in contact of this run"},
        {"samples", depth_[k].samples},
        {"max_abs_error_m", depth_[k].max_abs_error_m},
        {"max_exact_penetration_m", depth_[k].max_penetration_m}};
  }
}

}  // namespace pb::internal::mujoco
