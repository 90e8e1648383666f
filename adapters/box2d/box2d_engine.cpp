// The Box2D 2.4.1 adapter, engine "box2d". Builds any case from pb::Case the
// way Box2D's users do (b2World, b2BodyDef, fixtures, b2RevoluteJoint to a
// static ground body) and samples it after every step. Two modes:
//   engine  Box2D's rigid contact; each case law is expressed by the
//           restitution it produces (box2d_restitution.hpp);
//   inject  the contact pairs do not collide in Box2D; the adapter measures
//           the contact in closed form and applies the case's force law with
//           b2Body::ApplyForce before each step.
// This file steps and samples the world and reports the run;
// box2d_engine_build.cpp builds it from the case (box2d_engine_impl.hpp).
#include "planarbench/adapters/box2d_engine.hpp"

#include <box2d/b2_body.h>
#include <box2d/b2_common.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_world.h>
#include <fmt/format.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <memory>
#include <utility>

#include "box2d_contact_probe.hpp"
#include "box2d_faults.hpp"
#include "box2d_frame.hpp"
#include "box2d_inject_geometry.hpp"
#include "box2d_settings.hpp"
#include "box2d_engine_impl.hpp"
#include "box2d_world_callbacks.hpp"
#include "planarbench/contact_force.hpp"
#include "planarbench/episode_tracker.hpp"
#include "planarbench/errors.hpp"

namespace pb::internal::box2d {

thread_local long t_world_steps = 0;

void Box2dEngine::advance_to(double t_s) {
  if (!world_) throw EngineError("box2d: advance_to before build");
  if (!fault_.empty()) throw EngineError(fault_);
  // a fixed-step engine stops at its last step not after t_s (engine.hpp)
  const double dt = settings_.dt_s;
  bool first = true;
  while (static_cast<double>(steps_ + 1) * dt <= t_s + 1e-9 * dt) {
    // a call that steps starts the next output interval (one that does not
    // leaves the last interval's forces reported)
    if (first) {
      ++interval_;
      interval_steps_ = 0;
      first = false;
    }
    step();
  }
}

void Box2dEngine::step() {
  const float dt = static_cast<float>(settings_.dt_s);
  if (!collide_) apply_injected_forces();  // inject mode (collide_ caches !inject())
  pairs_.step = steps_ + 1;                // stamps this step's impulses (PostSolve)
  world_->Step(dt, settings_.velocity_iterations, settings_.position_iterations);
  ++t_world_steps;
  ++steps_;
  ++interval_steps_;
  time_s_ = static_cast<double>(steps_) * settings_.dt_s;
  check_state();
  sample_pairs();
}

// the force of the state at the start of the step, equal and opposite; a
// force Box2D would clamp (or overflow float with) ends the run before the step
void Box2dEngine::apply_injected_forces() {
  std::fill(injected_force_n_.begin(), injected_force_n_.end(), Vec2::Zero());
  std::fill(injected_torque_nm_.begin(), injected_torque_nm_.end(), 0.0);
  for (std::size_t k = 0; k < samples_.size(); ++k) {
    const PairSample& s = samples_[k];
    const ContactPair& p = case_.contacts[k];
    if (s.valid && !std::isfinite(s.force_n)) {
      fail(fmt::format("box2d: non-finite contact force of '{}' at t = {:.9g} s", p.name, time_s_));
    }
    if (!s.valid || !(s.force_n > 0.0)) continue;
    // totals per body; torque about the centre of mass, r x F
    auto add = [&](int body, const Vec2& f_n) {
      const auto i = static_cast<std::size_t>(body);
      if (case_.bodies[i].fixed) return;
      const Vec2 r = s.point_m - from_b2(bodies_[i]->GetWorldCenter());
      injected_force_n_[i] += f_n;
      injected_torque_nm_[i] += r.x() * f_n.y() - r.y() * f_n.x();
    };
    const Vec2 f_on_b = s.force_n * s.normal;  // N
    add(p.body_b, f_on_b);
    add(p.body_a, -f_on_b);
  }
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    if (case_.bodies[i].fixed || injected_force_n_[i].isZero(0.0)) continue;
    const std::string why =
        injected_force_reason(*bodies_[i], case_.bodies[i], case_.gravity_mps2,
                              injected_force_n_[i], injected_torque_nm_[i], settings_.dt_s);
    if (!why.empty()) {
      fail(fmt::format("box2d: body '{}' diverged at t = {:.9g} s: {}", case_.bodies[i].name,
                       time_s_, why));
    }
  }
  for (std::size_t k = 0; k < samples_.size(); ++k) {
    const PairSample& s = samples_[k];
    const ContactPair& p = case_.contacts[k];
    if (!s.valid || !(s.force_n > 0.0)) continue;
    const b2Vec2 f_on_b = to_b2(s.force_n * s.normal);
    const b2Vec2 point = to_b2(s.point_m);
    bodies_[static_cast<std::size_t>(p.body_b)]->ApplyForce(f_on_b, point, true);
    bodies_[static_cast<std::size_t>(p.body_a)]->ApplyForce(-f_on_b, point, true);
  }
}

// after every step: a non-finite state, or a velocity at Box2D's clamp
void Box2dEngine::check_state() {
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    if (case_.bodies[i].fixed) continue;
    const BodyState s = body_state(*bodies_[i]);
    if (!finite(s)) {
      fail(fmt::format("box2d: non-finite state of body '{}' at t = {:.9g} s",
                       case_.bodies[i].name, time_s_));
    }
    if (const std::string why = clamped_velocity_reason(s, settings_.dt_s); !why.empty()) {
      fail(fmt::format("box2d: body '{}' diverged at t = {:.9g} s: {}", case_.bodies[i].name,
                       time_s_, why));
    }
  }
}

void Box2dEngine::fail(std::string reason) {
  fault_ = std::move(reason);
  throw EngineError(fault_);
}

void Box2dEngine::sample_pairs() {
  if (!collide_) {  // inject mode: every declared pair, in closed form
    for (std::size_t k = 0; k < samples_.size(); ++k) sample_injected_pair(k);
    return;
  }
  // every body's motion once, for the bounds of its pairs
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const b2Body& b = *bodies_[i];
    motion_[i] = Motion{from_b2(b.GetWorldCenter()), from_b2(b.GetLinearVelocity()),
                        static_cast<double>(b.GetAngularVelocity())};
  }
  if (steps_ > 0) list_contacts();
  for (const int k : active_) sample_engine_pair(static_cast<std::size_t>(k));
}

void Box2dEngine::list_contacts() {
  previous_active_.swap(active_);
  active_.clear();
  listed_.clear();
  // Box2D's contacts: the fixture pairs whose fat AABBs overlap (its broad
  // phase), every one the filter let through, so each has a pair. One whose
  // manifold is empty and whose bodies are farther apart than two steps can
  // close is apart and not sampled, its pair not even looked up: three of
  // four of a settled pile's (fat AABBs 0.1 m wider than its 5 cm disks)
  for (b2Contact* c = world_->GetContactList(); c != nullptr; c = c->GetNext()) {
    const int ia = body_index(*c->GetFixtureA());
    const int ib = body_index(*c->GetFixtureB());
    double gap_bound = 0.0;  // m
    if (!c->IsTouching() && far_apart(ia, ib, gap_bound)) continue;
    const int k = pairs_.find_or_add(ia, ib);
    if (k < 0) continue;
    const auto uk = static_cast<std::size_t>(k);
    if (uk >= samples_.size()) grow_pairs();
    if (seen_[uk] != steps_) {
      seen_[uk] = steps_;
      head_[uk] = -1;
      active_.push_back(k);
    }
    listed_.push_back(Listed{c, head_[uk]});
    head_[uk] = static_cast<int>(listed_.size()) - 1;
  }
  // a pair no longer listed (apart, or Box2D destroyed its contacts as its
  // AABBs parted): sampled once more, as apart, which ends an open episode,
  // and on to the interval's end if it was pushed in it (its mean force is
  // reported); then no longer
  for (const int k : previous_active_) {
    const auto uk = static_cast<std::size_t>(k);
    const PairSample& s = samples_[uk];
    const bool pushed = s.interval == interval_ && s.interval_impulse_ns > 0.0;
    if (seen_[uk] == steps_ || !(s.listed || pushed)) continue;
    seen_[uk] = steps_;
    head_[uk] = -1;
    active_.push_back(k);
  }
  std::sort(active_.begin(), active_.end());
}

bool Box2dEngine::far_apart(int body_a, int body_b, double& lower_bound_m) const {
  // a fixed half-plane as a (its line), the other's bounding radius; or two
  // bounding radii
  if (far_[static_cast<std::size_t>(body_b)].plane) std::swap(body_a, body_b);
  const FarBound& fa = far_[static_cast<std::size_t>(body_a)];
  const FarBound& fb = far_[static_cast<std::size_t>(body_b)];
  if (fb.plane || !std::isfinite(fb.radius_m) || (!fa.plane && !std::isfinite(fa.radius_m))) {
    return false;
  }
  // centres of mass and velocities as Box2D holds them (no angle needed)
  const Motion& a = motion_[static_cast<std::size_t>(body_a)];
  const Motion& b = motion_[static_cast<std::size_t>(body_b)];
  const Vec2& ca = a.centre_m;
  const Vec2& cb = b.centre_m;
  const Vec2& va = a.velocity_mps;
  const Vec2& vb = b.velocity_mps;
  const double wa = a.spin_radps;
  const double wb = b.spin_radps;
  // the gap of the skinned surfaces (the case's surfaces) is at least the
  // centre's height above a half-plane, or the centres' distance, less the
  // bounding radii, less 1e-5 m for the float placement of Box2D's shapes
  // (~8 ulp at 10 m)
  constexpr double kFloatMargin_m = 1e-5;
  double speed = (vb - va).norm() + std::abs(wb) * fb.radius_m;  // m/s
  if (fa.plane) {
    lower_bound_m = (cb - fa.point_m).dot(fa.normal) - fb.radius_m - kFloatMargin_m;
  } else {
    lower_bound_m = (cb - ca).norm() - fa.radius_m - fb.radius_m - kFloatMargin_m;
    speed += std::abs(wa) * fa.radius_m;
  }
  // semi-implicit Euler moves a step's positions with its end velocity:
  // within one step a gap changes by at most h (speed + |g| h); twice that
  // keeps the previous and the next step apart as well
  const double h = settings_.dt_s;
  const double reach = 2.0 * h * (speed + case_.gravity_mps2.norm() * h);
  return lower_bound_m > reach;
}

void Box2dEngine::sample_engine_pair(std::size_t k) {
  const ContactPair& p = pairs_.pair(static_cast<int>(k));
  const b2Body& a = *bodies_[static_cast<std::size_t>(p.body_a)];
  const b2Body& b = *bodies_[static_cast<std::size_t>(p.body_b)];
  const PairSample before = samples_[k];
  PairSample& s = samples_[k];
  const double impulse = pairs_.state(static_cast<int>(k)).impulse_ns(steps_);
  const double tangent_impulse = pairs_.state(static_cast<int>(k)).tangent_impulse_ns(steps_);
  // the pair's impulses over the output interval so far: its force is their
  // mean (box2d_mapping_notes.cpp, "forces"); at t = 0 nothing has acted
  if (s.interval != interval_) {
    s.interval = interval_;
    s.interval_impulse_ns = 0.0;
    s.interval_tangent_impulse_ns = 0.0;
  }
  s.interval_impulse_ns += impulse;
  s.interval_tangent_impulse_ns += tangent_impulse;
  // (reported_force = step: the last step's, impulse / dt)
  const long steps_in = interval_force_ ? interval_steps_ : (steps_ > 0 ? 1 : 0);
  const double interval_s = static_cast<double>(steps_in) * settings_.dt_s;
  const double mean_force =
      steps_in == 0 ? 0.0 : (interval_force_ ? s.interval_impulse_ns : impulse) / interval_s;
  const double mean_tangential =
      steps_in == 0
          ? 0.0
          : (interval_force_ ? s.interval_tangent_impulse_ns : tangent_impulse) / interval_s;
  bucket_.clear();
  for (int e = steps_ > 0 ? head_[k] : -1; e >= 0; e = listed_[static_cast<std::size_t>(e)].next) {
    bucket_.push_back(listed_[static_cast<std::size_t>(e)].contact);
  }
  // Box2D holds no contact of the pair any more: apart, and not measured
  // (the sample a pass over every pair gave such a pair each step)
  if (steps_ > 0 && bucket_.empty()) {
    s.valid = false;
    s.listed = false;
    s.step_force_n = 0.0;
    // what it had from the solver this interval still counts (0 by step)
    s.force_n = mean_force;
    s.tangential_force_n = mean_tangential;
    s.penetration_m = kNaN;
    s.tracked_m = kNaN;
    s.speed_mps = kNaN;
    trackers_[k].observe_separated(time_s_, p.body_a, p.body_b, kNaN);
    s.open = false;
    return;
  }
  s.listed = true;
  // Far apart (no episode open, no impulse this step, and the gap's lower
  // bound beyond what two steps can close): the bound stands for the gap,
  // without the probe (its b2Distance was 17 % of a step of falling_ball,
  // callgrind) or the tracker. Onsets, offsets and within-step impacts read
  // only the samples next to a touching step, which are never far, so every
  // episode is the one the probe's exact gap gives; the next sample that is
  // not far observes this one first (track), and nothing else reads what
  // the tracker was last given (episode_tracker.cpp). list_contacts leaves
  // out such a pair whose manifolds are all empty before it gets here.
  double lower_bound = 0.0;
  if (steps_ > 0 && impulse == 0.0 && !before.open && far_apart(p.body_a, p.body_b, lower_bound)) {
    s.valid = true;
    s.step_force_n = 0.0;
    s.force_n = mean_force;
    s.tangential_force_n = mean_tangential;
    s.penetration_m = -lower_bound;
    s.tracked_m = s.penetration_m;
    s.speed_mps = kNaN;
    return;
  }
  // before the first step Box2D's broad phase has not paired anything yet
  const ContactGeometry g =
      steps_ == 0 ? probe_contact(a, b, ProbeScope::every_child)
                  : probe_contact(a, b, bucket_.data(), static_cast<int>(bucket_.size()));
  // the step's impulse belongs to an episode open at the step's start or
  // opening at its end
  const bool was_open = before.open;
  s.valid = g.valid;
  s.step_force_n = impulse / settings_.dt_s;
  s.force_n = mean_force;
  s.tangential_force_n = mean_tangential;
  if (g.valid) {
    s.penetration_m = g.penetration_m;
    s.normal = g.normal;
    s.point_m = g.point_m;
    const BodyState sa = body_state(a);
    const BodyState sb = body_state(b);
    s.speed_mps = -g.normal.dot(point_velocity(sb, g.point_m) - point_velocity(sa, g.point_m));
    // a gap within the float resolution of the positions does not end an
    // episode: at rest Box2D's touching flag flickers with the last bit
    const double scale =
        std::max({1.0, g.point_m.norm(), sa.position_m.norm(), sb.position_m.norm()});
    const double resolution = 8.0 * static_cast<double>(FLT_EPSILON) * scale;  // m
    s.tracked_m = g.penetration_m;
    if (g.touching) s.tracked_m = std::max(s.tracked_m, kTouching_m);
    if (was_open && s.tracked_m <= 0.0 && s.tracked_m > -resolution) s.tracked_m = kTouching_m;
  } else {
    s.penetration_m = kNaN;
    s.tracked_m = kNaN;
    s.speed_mps = kNaN;
  }
  track(k, before, s);
  if (!was_open && !s.open && impulse > 0.0) {
    if (steps_ > 0 && before.valid && s.valid) {
      // apart at both ends of the step and pushed within it: Box2D's time of
      // impact solved a fast impact inside the step (b2World::SolveTOI, whose
      // impulses PostSolve reports): an episode of its own
      const double t_before = static_cast<double>(steps_ - 1) * settings_.dt_s;
      trackers_[k].record_within_step(t_before, time_s_, p.body_a, p.body_b, -before.penetration_m,
                                      before.speed_mps, -s.speed_mps, impulse);
    } else {
      orphan_impulse_ns_ += impulse;
    }
  }
}

// Box2D's symplectic Euler moves the positions of a step with the velocity
// at its end, after the impulses (b2Island::Solve): the state just after the
// velocity update (time t_n, penetration at t_n, speed and force of the step)
// is observed before the state at t_n+1, so the tracker's linear
// interpolation of onset and offset uses the velocity that really carried the
// bodies across the surface, and its trapezoid integrates the step's force
// over the whole step (impulse = force dt exactly)
void Box2dEngine::track(std::size_t k, const PairSample& before, PairSample& now) {
  const ContactPair& p = pairs_.pair(static_cast<int>(k));
  if (!now.valid) {
    trackers_[k].observe_separated(time_s_, p.body_a, p.body_b, kNaN);
    now.open = false;
    return;
  }
  if (steps_ > 0 && before.valid) {
    const double t_before = static_cast<double>(steps_ - 1) * settings_.dt_s;
    trackers_[k].observe(t_before, p.body_a, p.body_b, before.tracked_m, now.speed_mps,
                         now.step_force_n);
  }
  trackers_[k].observe(time_s_, p.body_a, p.body_b, now.tracked_m, now.speed_mps, now.step_force_n);
  now.open = trackers_[k].in_contact(p.body_a, p.body_b);
}

void Box2dEngine::sample_injected_pair(std::size_t k) {
  const ContactPair& p = case_.contacts[k];
  const std::size_t ia = static_cast<std::size_t>(p.body_a);
  const std::size_t ib = static_cast<std::size_t>(p.body_b);
  const BodyState sa = body_state(*bodies_[ia]);
  const BodyState sb = body_state(*bodies_[ib]);
  const PrimitiveContact c =
      primitive_contact(case_.bodies[ia].shape, Pose{sa.position_m, sa.angle_rad},
                        case_.bodies[ib].shape, Pose{sb.position_m, sb.angle_rad});
  const PairSample before = samples_[k];
  PairSample& s = samples_[k];
  const bool was_touching = before.valid && before.penetration_m > 0.0;
  s.valid = true;
  s.penetration_m = c.penetration_m;
  s.tracked_m = c.penetration_m;
  s.normal = c.normal;
  s.point_m = c.point_m;
  s.speed_mps = -c.normal.dot(point_velocity(sb, c.point_m) - point_velocity(sa, c.point_m));
  // delta_dot at onset, latched for Lankarani-Nikravesh (paper eq. 7)
  if (c.penetration_m > 0.0 && !was_touching) latched_approach_mps_[k] = s.speed_mps;
  // the force applied during the step that ended here, and the one for the next
  s.step_force_n = steps_ > 0 ? before.force_n : 0.0;
  s.force_n = contact_force_n(p.law, c.penetration_m, s.speed_mps, latched_approach_mps_[k]);
  track(k, before, s);
}

void Box2dEngine::body_states(std::vector<BodyState>& out) const {
  out.resize(bodies_.size());
  for (std::size_t i = 0; i < bodies_.size(); ++i) out[i] = body_state(*bodies_[i]);
}

void Box2dEngine::contacts(std::vector<ContactSample>& out) const {
  out.clear();
  // the pairs sampled at the latest step (every other pair is apart)
  for (const int kk : active_) {
    const auto k = static_cast<std::size_t>(kk);
    const PairSample& s = samples_[k];
    const ContactPair& p = pairs_.pair(kk);
    // in contact: inside an episode, or pushed during the output interval
    // (a pair no longer listed: only this, its last point and normal)
    const bool pushed = s.force_n > 0.0;
    if (s.valid ? !(pushed || s.open) : (s.listed || !pushed)) {
      continue;
    }
    ContactSample cs;
    cs.body_a = p.body_a;
    cs.body_b = p.body_b;
    cs.force_n = s.force_n;
    cs.tangential_force_n = s.tangential_force_n;
    cs.penetration_m = std::max(0.0, s.penetration_m);
    cs.normal = s.normal;
    cs.point_m = s.point_m;
    out.push_back(cs);
  }
}

std::vector<ContactEpisode> Box2dEngine::episodes() const {
  // each pair's, in onset order (ties: in pair order)
  std::vector<ContactEpisode> all;
  for (const EpisodeTracker& t : trackers_) {
    const std::vector<ContactEpisode> pair = t.episodes();
    all.insert(all.end(), pair.begin(), pair.end());
  }
  std::stable_sort(all.begin(), all.end(), [](const ContactEpisode& a, const ContactEpisode& b) {
    return a.onset_time_s < b.onset_time_s;
  });
  return all;
}

nlohmann::json Box2dEngine::mapping_with_onsets() const {
  nlohmann::json j = mapping_;
  if (inject() || !j.contains("contacts")) return j;
  nlohmann::json onsets = nlohmann::json::array();
  for (const auto& r : listener_.log()) {
    onsets.push_back({{"time_s", r.time_s},
                      {"contact", pairs_.pair(r.pair).name},
                      {"m_eff_kg", r.m_eff_kg},
                      {"points", r.points},
                      {"approach_speed_mps", r.approach_mps},
                      {"restitution", r.restitution}});
  }
  j["onsets"] = onsets;
  j["onsets_not_logged"] = listener_.unlogged();
  return j;
}

Physics Box2dEngine::physics() const {
  Physics p;
  p.mode = settings_.mode;
  if (inject()) {
    p.collision_by = "adapter";
    p.collision =
        "the adapter's closed-form geometry of the exact shapes (the pairs do not collide in "
        "Box2D)";
    p.contact_force_by = "adapter (case law)";
    p.contact_force = "the case's law applied with b2Body::ApplyForce; Box2D integrates it";
    p.parameters = "the case's law as stated";
    return p;
  }
  p.collision_by = "engine";
  p.collision = "Box2D's own narrow phase (b2Contact manifolds of circles, polygons, edge chains)";
  p.contact_force_by = "engine";
  p.contact_force = "Box2D's rigid contact solver (sequential impulses with restitution)";
  p.parameters =
      "each contact's restitution set as it begins (b2ContactListener::PreSolve) from the law at "
      "the approach speed and the effective mass at the depth-weighted centroid of the region of "
      "the pair's touching manifold points then (the law alone for Hertz and Lankarani-Nikravesh, whose "
      "restitution is scale-free)";
  return p;
}

nlohmann::json Box2dEngine::extra_attributes() const {
  nlohmann::json j = nlohmann::json::object();
  if (!inject()) j["impulse_outside_episodes_ns"] = orphan_impulse_ns_;
  if (case_.has_contact_groups()) {
    // how far the pair list grew: the pairs Box2D's broad phase ever held
    j["contact_pairs_indexed"] = pairs_.size();
  }
  return j;
}

}  // namespace pb::internal::box2d

namespace pb {

std::unique_ptr<Engine> make_box2d_engine() {
  return std::make_unique<internal::box2d::Box2dEngine>();
}

}  // namespace pb
