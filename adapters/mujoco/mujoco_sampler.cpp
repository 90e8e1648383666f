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

PairSampler::PairSampler(const Case& c, const MujocoPlan& plan, ModelLayout& layout)
    : case_(c), plan_(plan), layout_(layout) {
  grow();
}

void PairSampler::grow() {
  const std::size_t n = layout_.pairs.size();
  for (std::size_t k = seen_.size(); k < n; ++k) {
    const ContactPair& cp = layout_.pair(static_cast<int>(k));
    check_.push_back(k < plan_.pairs.size() ? plan_.pairs[k].check_depth
                                            : depth_checked(case_, plan_, cp.body_a, cp.body_b));
  }
  last_point_m_.resize(n, Vec2::Zero());
  last_normal_.resize(n, Vec2::Zero());
  seen_.resize(n, false);
  depth_.resize(n);
}

void PairSampler::sample(const mjModel* m, const mjData* d, double t, bool with_force,
                         std::span<const double> forces, ForceInjector* injector) {
  if (!scratch_) scratch_.emplace(m);
  buckets_.build(d, layout_);
  grow();
  observe_pairs(m, d, layout_, buckets_, with_force, *scratch_, obs_, forces);
  if (injector != nullptr) {
    dense_.assign(layout_.pairs.size(), PairObservation{});
    for (const PairObservation& o : obs_) dense_[static_cast<std::size_t>(o.pair)] = o;
    injector->latch(dense_);
    for (PairObservation& o : obs_) o.force_n = injector->force_n(static_cast<std::size_t>(o.pair), o);
  }
  // the pairs observed now and those reported before, merged in ascending
  // pair order (the tracker closes episodes in the order it is told)
  reported_now_.clear();
  std::size_t before = 0;
  auto separated = [&](int k) {
    // not reported (beyond the margin): the speed along the last normal seen
    // closes the open episode
    const auto uk = static_cast<std::size_t>(k);
    const PairLayout& p = layout_.pairs[uk];
    double speed = 0.0;
    if (seen_[uk]) {
      const auto p3 = to_mj(last_point_m_[uk]);
      const auto n3 = to_mj(last_normal_[uk]);
      speed = approach_speed_mps(m, d, p.mj_body_a, p.mj_body_b, p3.data(), n3.data(), *scratch_);
    }
    tracker_.observe_separated(t, p.body_a, p.body_b, speed);
  };
  for (const PairObservation& o : obs_) {
    const int k = o.pair;
    for (; before < reported_.size() && reported_[before] < k; ++before) separated(reported_[before]);
    if (before < reported_.size() && reported_[before] == k) ++before;
    const auto uk = static_cast<std::size_t>(k);
    const PairLayout& p = layout_.pairs[uk];
    if (!p.present) continue;
    if (!o.reported) {
      separated(k);
      continue;
    }
    const int a = p.body_a;
    const int b = p.body_b;
    if (o.penetration_m > 0.0 && check_[uk]) {
      const auto ia = static_cast<std::size_t>(a);
      const auto ib = static_cast<std::size_t>(b);
      const auto exact = exact_penetration_m(
          case_.bodies[ia].shape, mujoco_body_state(m, d, case_, layout_, ia),
          case_.bodies[ib].shape, mujoco_body_state(m, d, case_, layout_, ib));
      DepthCheck& dc = depth_[uk];
      ++dc.samples;
      dc.max_abs_error_m = std::max(dc.max_abs_error_m, std::abs(o.penetration_m - *exact));
      dc.max_penetration_m = std::max(dc.max_penetration_m, *exact);
    }
    tracker_.observe(t, a, b, o.penetration_m, o.approach_speed_mps, o.force_n);
    last_point_m_[uk] = o.point_m;
    last_normal_[uk] = o.normal_ab;
    seen_[uk] = true;
    reported_now_.push_back(k);
  }
  for (; before < reported_.size(); ++before) separated(reported_[before]);
  reported_.swap(reported_now_);
}

void PairSampler::contacts(std::vector<ContactSample>& out) const {
  out.clear();
  for (const PairObservation& o : obs_) {
    if (!o.reported || !(o.penetration_m > 0.0)) continue;
    const ContactPair& cp = layout_.pair(o.pair);
    ContactSample s;
    s.body_a = cp.body_a;
    s.body_b = cp.body_b;
    s.force_n = o.force_n;
    s.penetration_m = o.penetration_m;
    s.normal = o.normal_ab;
    s.point_m = o.point_m;
    s.tangential_force_n = o.tangential_force_n;
    out.push_back(s);
  }
}

void PairSampler::add_depth_checks(nlohmann::json& m) const {
  // declared pairs only: the mapping lists those one by one
  for (std::size_t k = 0; k < plan_.pairs.size() && k < depth_.size() && m.contains("pairs"); ++k) {
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
