// The ODE adapter, engine "ode": builds any case from the pb::Case model
// through ODE 0.16.2 (double precision) the way its users do: one dWorld and
// one dSpace per engine, contact joints in a dJointGroup emptied every step,
// at the step the user gives. A scene's pairs come from ODE's broad phase
// (a dSweepAndPruneSpace, dSpaceCollide and a near callback:
// ode_space_collider.hpp);
// a case of declared pairs calls dCollide on each pair's geoms directly
// (ode_pair_contact.hpp). Modes:
//   native  (default) every contact ODE reports is a soft contact joint whose
//           ERP/CFM is set each step from the case's law at the pair's
//           current penetration, spread over the pair's contacts (SPEC §5b:
//           the state at the time, no look-ahead);
//   oracle  the law replaced by one spring-damper calibrated on a
//           contact-free probe run (foreknowledge, opt-in), deepest contact
//           only, optionally auto sub-stepped;
//   inject  no contact joints: the case's law applied as a force.
// ode_contact_mapping says how, and mapping() records it.
#include "planarbench/adapters/ode_engine.hpp"


#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <variant>

#include "ode_contact_mapping.hpp"
#include "ode_frame.hpp"
#include "ode_geometry.hpp"
#include "ode_library.hpp"
#include "ode_friction.hpp"
#include "ode_pair_contact.hpp"
#include "ode_probe.hpp"
#include "ode_settings.hpp"
#include "ode_world.hpp"
#include "planarbench/contact_force.hpp"
#include "planarbench/energy_budget.hpp"
#include "planarbench/episode_tracker.hpp"
#include "planarbench/errors.hpp"

#include "ode_engine_impl.hpp"

namespace pb::internal::ode {

Capability OdeEngine::supports(const Case& c) const {
  for (const Body& b : c.bodies) {
    if (std::holds_alternative<HalfPlane>(b.shape) && !b.fixed) {
      return {Support::unsupported,
              fmt::format("body '{}' is a moving half-plane: ODE planes (dCreatePlane) are "
                          "non-placeable and cannot move",
                          b.name)};
    }
    if (!b.fixed && !(b.mass_kg > 0.0 && b.inertia_kgm2 > 0.0)) {
      return {Support::unsupported,
              fmt::format("body '{}' moves but has no positive mass and inertia", b.name)};
    }
  }
  if (settings_.mode == "oracle" && c.has_contact_groups()) {
    return {Support::unsupported,
            "mode oracle calibrates each declared pair on a contact-free probe run before the "
            "run; a scene's group pairs are only known once ODE's broad phase finds them"};
  }
  if (settings_.mode == "inject") {
    if (auto why = inject_friction_reason(c); !why.empty()) return {Support::unsupported, why};
    return {Support::native, ""};
  }
  std::string mapped;
  auto add = [&](const std::string& why) {
    mapped += (mapped.empty() ? "" : "; ") + why;
  };
  for (const Body& b : c.bodies) {
    const auto* p = std::get_if<Polygon>(&b.shape);
    if (p != nullptr && !internal::ode::is_convex_ccw(p->points_m)) {
      add(fmt::format("body '{}': a non-convex polygon as convex prisms of its pieces", b.name));
    }
  }
  for (const ContactGroup& g : c.contact_groups) {
    if (is_plain_kelvin_voigt(g.law)) continue;
    add(fmt::format(
        "group '{}': {} as ODE's linear soft contact, its stiffness and damping set each step "
        "from the law at the current penetration",
        g.name, contact_law_name(g.law)));
  }
  for (const ContactPair& p : c.contacts) {
    if (is_plain_kelvin_voigt(p.law)) continue;
    if (settings_.mode == "oracle") {
      add(fmt::format(
          "pair '{}': {} -> linear spring-damper with the first impact's force duration and "
          "restitution (ODE soft contacts are linear; calibrated on a probe run)",
          p.name, contact_law_name(p.law)));
    } else {
      add(fmt::format(
          "pair '{}': {} as ODE's linear soft contact, its stiffness and damping set each step "
          "from the law at the current penetration",
          p.name, contact_law_name(p.law)));
    }
  }
  if (!mapped.empty()) return {Support::mapped, mapped};
  return {Support::native, ""};
}

Physics OdeEngine::physics() const {
  Physics p;
  p.mode = settings_.mode;
  p.collision_by = "engine";
  p.collision =
      "ODE's own colliders on spheres, convex prisms and planes: a scene's pairs from ODE's broad "
      "phase (dSweepAndPruneSpace, dSpaceCollide, a near callback that keeps the pairs the case's "
      "rules "
      "let touch and calls dCollide); a case of declared pairs by dCollide on each pair's geoms "
      "directly";
  if (settings_.mode == "inject") {
    p.contact_force_by = "adapter (case law)";
    p.contact_force =
        "the case's law evaluated by the adapter at ODE's contact geometry and applied with "
        "dBodyAddForceAtPos; ODE integrates it";
    p.parameters = "the case's law as stated";
  } else if (settings_.mode == "oracle") {
    p.contact_force_by = "engine";
    p.contact_force = "ODE's soft contact joints (ERP/CFM), the deepest contact of each pair";
    p.parameters =
        "one linear spring-damper per pair calibrated on a contact-free probe run of the case "
        "(the first impact's effective mass and approach speed); auto sub-stepping when "
        "ode.substeps = 0";
    p.foreknowledge = true;
  } else {
    p.contact_force_by = "engine";
    p.contact_force =
        "ODE's soft contact joints (ERP/CFM), one per contact ODE reports, solved by ODE's LCP";
    p.parameters =
        "each step, from the case's law at the pair's current penetration and the approach speed "
        "latched at its onset (linearised: k = F_elastic / delta, c = the law's damping "
        "coefficient), spread over the pair's contacts (k_i = k delta / sum d_j, c_i = c d_i / "
        "sum d_j)";
  }
  return p;
}

void OdeEngine::build(const Case& c, const SettingsOverrides& overrides) {
  settings_ = OdeSettings{};
  binder_.apply(overrides);
  internal::ode::validate_ode_settings(settings_, overrides);
  internal::ode::ensure_ode_ready_in_this_thread();
  const Capability cap = supports(c);
  if (cap.support == Support::unsupported) throw EngineError("ode: " + cap.reason);

  case_ = c;
  inject_ = settings_.mode == "inject";
  oracle_ = settings_.mode == "oracle";
  quick_ = settings_.stepper == "quick" ||
           (settings_.stepper == "auto" && case_.has_contact_groups());
  corrected_ = settings_.damping_mapping == "corrected";
  steps_ = 0;
  probe_steps_ = 0;
  rows_correction_invalid_ = 0;
  rows_made_ = 0;
  worst_hk_over_c_ = 0.0;
  diverged_.clear();
  tracker_ = EpisodeTracker{};
  collider_.reset();
  world_.reset();
  messages_seen_ = 0;
  pairs_ = std::make_unique<ContactPairs>(case_);
  first_message_.clear();

  // every ODE step this build takes (a trace, not the probe's own count)
  const long steps_at_start = internal::ode::world_steps_on_this_thread();
  if (oracle_) {
    // first touches from a contact-free run, then the mapping and the step
    long probe_steps = 0;
    const std::vector<FirstTouch> touches =
        internal::ode::probe_first_touches(case_, settings_.dt_s, probe_steps);
    try {
      map_contacts_oracle(touches);
    } catch (const EngineError&) {
      throw;
    } catch (const std::exception& e) {
      // a law the mapping cannot handle (e.g. a collision that never ends)
      throw EngineError(fmt::format("ode: cannot map the case's contact laws: {}", e.what()));
    }
  } else {
    substeps_ = settings_.substeps;
    step_s_ = settings_.dt_s / substeps_;
    map_contacts_native();
  }

  world_ = std::make_unique<OdeWorld>(case_);
  if (quick_) dWorldSetQuickStepNumIterations(world_->world(), settings_.quick_iterations);
  if (case_.has_contact_groups()) {
    collider_ = std::make_unique<SpaceCollider>(case_, *world_, *pairs_);
  } else {
    collider_ = std::make_unique<PairCollider>(case_, *world_);
  }
  // per pair, grown as pairs are added (sample_contacts); per joint, a pool
  // sized by each step's contacts (step_once)
  track_.assign(static_cast<std::size_t>(pairs_->size()), PairTrack{});
  in_contact_.clear();
  forced_.clear();
  now_.clear();
  joints_.clear();
  feedback_.clear();
  explicit_n_.clear();
  angle_rad_.clear();
  force_n_.assign(case_.bodies.size(), Vec2::Zero());
  torque_nm_.assign(case_.bodies.size(), 0.0);
  for (int i = 0; i < world_->body_count(); ++i)
    angle_rad_.push_back(case_.bodies[static_cast<std::size_t>(i)].angle_rad);

  // what the bodies became
  mapping_["bodies"] = bodies_json();
  if (!oracle_) mapping_["collision"] = collision_text();
  mapping_["frame"] =
      "case x-y plane = ODE x-y plane at z = 0; case angle = rotation about +z, counter-clockwise; "
      "quaternion (cos a/2, 0, 0, sin a/2)";
  mapping_["world"] = {{"gravity_mps2", {case_.gravity_mps2.x(), case_.gravity_mps2.y(), 0.0}},
                       {"joint_erp", dWorldGetERP(world_->world())},
                       {"joint_cfm", dWorldGetCFM(world_->world())},
                       {"contact_surface_layer_m", 0.0},
                       {"contact_max_correcting_vel", "infinity"},
                       {"auto_disable", false}};
  mapping_["stepper"] = fmt::format(
      "{}{}",
      quick_ ? fmt::format("dWorldQuickStep, {} iterations; dRandSetSeed(step index) before "
                           "each step under a process-wide lock (ODE's row-order seed is "
                           "global)",
                           settings_.quick_iterations)
             : std::string("dWorldStep (direct LCP solver, deterministic)"),
      settings_.stepper != "auto" ? std::string()
      : quick_ ? std::string("; ode.stepper = auto: a scene (contact groups), one island of many "
                             "rows, where dWorldStep's dense O(m^3) LCP is out of reach")
               : std::string("; ode.stepper = auto: a case of declared pairs"));

  probe_steps_ = internal::ode::world_steps_on_this_thread() - steps_at_start;

  // the state at t = 0; contacts that start penetrated store elastic
  // energy, which the runaway bounds allow for
  sample_contacts();
  double elastic_j = 0.0;
  for (const PairContact& pc : now_.pairs) {
    elastic_j += elastic_energy_j(pair(pc.pair).law, pc.depth_m);
  }
  world_->set_initial_contact_energy(elastic_j);
}

// oracle: the mapping of every pair from the probe run, the step, and
// mapping_["contacts"]
void OdeEngine::advance_to(double t_s) {
  if (!world_) throw EngineError("ode: advance_to before build");
  internal::ode::ensure_ode_ready_in_this_thread();
  const auto target = static_cast<long>(std::floor(t_s / step_s_ + 1e-9));
  messages_mark_ = internal::ode::ode_messages_on_this_thread().count;
  while (steps_ < target && diverged_.empty()) step_once();
  const internal::ode::OdeMessages& said = internal::ode::ode_messages_on_this_thread();
  if (said.count > messages_mark_) {
    if (messages_seen_ == 0) first_message_ = said.last;
    messages_seen_ += said.count - messages_mark_;
  }
  if (!diverged_.empty()) throw EngineError(diverged_);
}

// inject mode: the forces about to be applied, per body, against the
// runaway bounds; a non-finite or runaway force ends the run before ODE
// integrates it (ODE asserts on a non-finite state inside dWorldStep)
bool OdeEngine::injected_forces_run_away() {
  std::fill(force_n_.begin(), force_n_.end(), Vec2::Zero());
  std::fill(torque_nm_.begin(), torque_nm_.end(), 0.0);
  for (const PairContact& pc : now_.pairs) {
    const double f = track_[static_cast<std::size_t>(pc.pair)].force_n;  // N
    const ContactPair& cp = pair(pc.pair);
    if (!std::isfinite(f)) {
      diverged_ = fmt::format("ode: the contact force of '{}' is not finite at t = {:.9g} s",
                              cp.name, time());
      return true;
    }
    if (!(f > 0.0)) continue;
    // body b is pushed along n_ab, body a against it; torque r x F about each centre
    for (const auto& [i, sign] : {std::pair{cp.body_b, 1.0}, std::pair{cp.body_a, -1.0}}) {
      if (world_->body(i) == nullptr) continue;
      const auto k = static_cast<std::size_t>(i);
      const Vec2 force = sign * f * pc.normal_ab;
      const Vec2 r = pc.point_m - world_->state(i).position_m;
      force_n_[k] += force;
      torque_nm_[k] += r.x() * force.y() - r.y() * force.x();
    }
  }
  for (int i = 0; i < world_->body_count(); ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (world_->body(i) == nullptr || force_n_[k].isZero(0.0)) continue;
    const std::string why = world_->applied_force_reason(i, force_n_[k], torque_nm_[k], step_s_);
    if (why.empty()) continue;
    diverged_ = fmt::format("ode: body '{}' diverged at t = {:.9g} s: {}", case_.bodies[k].name,
                            time(), why);
    return true;
  }
  return false;
}

// native: every contact of entry e of now_.pairs a soft joint, the law
// spread over them (ode_contact_mapping.hpp, spread_law)
void OdeEngine::add_native_joints(std::size_t e) {
  const PairContact& pc = now_.pairs[e];
  const ContactPair& cp = pair(pc.pair);
  const LinearizedLaw lin = linearize_law(
      cp.law, pc.depth_m, track_[static_cast<std::size_t>(pc.pair)].latched_approach_mps);
  if (!(lin.stiffness_n_per_m > 0.0)) return;  // nothing pressed in: no force
  const bool friction = cp.has_friction();
  int pressed = 0;
  for (int i = 0; i < pc.count; ++i) pressed += now_.geom(pc, i).depth > 0.0;
  for (int i = 0; i < pc.count; ++i) {
    const dContactGeom& g = now_.geom(pc, i);
    if (!(g.depth > 0.0)) continue;  // a touching contact carries no spring
    // with friction, one CFM for the pair's rows (ode_contact_mapping.hpp, face_row)
    internal::ode::SpreadLaw row_law = internal::ode::spread_law(
        lin.stiffness_n_per_m, lin.damping_ns_per_m, pc.depth_m, g.depth, pc.depth_sum_m);
    double explicit_n = 0.0;  // N, along the normal on g1's body
    if (friction) {
      const internal::ode::FaceRow face =
          internal::ode::face_row(lin.stiffness_n_per_m, lin.damping_ns_per_m, pc.depth_m,
                                  g.depth, pc.depth_sum_m, pressed);
      row_law.damping_ns_per_m = face.implicit_damping_ns_per_m;
      explicit_n = -face.explicit_damping_ns_per_m * separation_speed_mps(g);
      add_normal_force(g, explicit_n);
    }
    const internal::ode::SoftRow row = internal::ode::soft_row(
        row_law.stiffness_n_per_m, row_law.damping_ns_per_m, step_s_, corrected_);
    if (!row.correction_valid) {
      ++rows_correction_invalid_;
      if (row_law.damping_ns_per_m > 0.0) {
        worst_hk_over_c_ = std::max(
            worst_hk_over_c_, step_s_ * row_law.stiffness_n_per_m / row_law.damping_ns_per_m);
      }
    }
    dContact contact{};
    contact.surface.mode = dContactSoftERP | dContactSoftCFM;
    contact.surface.mu = 0.0;
    contact.surface.soft_erp = row.erp;
    contact.surface.soft_cfm = row.cfm;
    contact.geom = g;
    internal::ode::add_coulomb_friction(contact, cp.friction);
    const dJointID j = dJointCreateContact(world_->world(), world_->contact_group(), &contact);
    dJointAttach(j, dGeomGetBody(g.g1), dGeomGetBody(g.g2));
    JointRange& made = joints_[e];
    const auto slot = static_cast<std::size_t>(made.first + made.count);
    dJointSetFeedback(j, &feedback_[slot]);
    explicit_n_[slot] = explicit_n;
    ++made.count;
    ++rows_made_;
  }
}

// m/s, g1's material point at the contact relative to g2's, along the normal
// (which points into g1): > 0 separating
double OdeEngine::separation_speed_mps(const dContactGeom& g) const {
  dVector3 v1 = {0.0, 0.0, 0.0, 0.0};
  dVector3 v2 = {0.0, 0.0, 0.0, 0.0};
  if (const dBodyID b = dGeomGetBody(g.g1); b != nullptr) {
    dBodyGetPointVel(b, g.pos[0], g.pos[1], g.pos[2], v1);
  }
  if (const dBodyID b = dGeomGetBody(g.g2); b != nullptr) {
    dBodyGetPointVel(b, g.pos[0], g.pos[1], g.pos[2], v2);
  }
  return g.normal[0] * (v1[0] - v2[0]) + g.normal[1] * (v1[1] - v2[1]) +
         g.normal[2] * (v1[2] - v2[2]);
}

// f_n (N) along the contact's normal on g1's body at the contact, -f_n on g2's
void OdeEngine::add_normal_force(const dContactGeom& g, double f_n) const {
  if (f_n == 0.0) return;
  for (const auto& [geom, sign] : {std::pair{g.g1, 1.0}, std::pair{g.g2, -1.0}}) {
    if (const dBodyID b = dGeomGetBody(geom); b != nullptr) {
      dBodyAddForceAtPos(b, sign * f_n * g.normal[0], sign * f_n * g.normal[1],
                         sign * f_n * g.normal[2], g.pos[0], g.pos[1], g.pos[2]);
    }
  }
}

// oracle: the deepest contact of entry e of now_.pairs (a declared pair),
// with the calibrated soft contact
void OdeEngine::add_oracle_joint(std::size_t e) {
  const PairContact& pc = now_.pairs[e];
  const auto p = static_cast<std::size_t>(pc.pair);
  const dContactGeom& g = now_.geom(pc, pc.deepest);
  dContact contact{};
  contact.surface.mode = dContactSoftERP | dContactSoftCFM;
  contact.surface.mu = 0.0;
  contact.surface.soft_erp = soft_[p].erp;
  contact.surface.soft_cfm = soft_[p].cfm;
  contact.geom = g;
  internal::ode::add_coulomb_friction(contact, pair(pc.pair).friction);
  const dJointID j = dJointCreateContact(world_->world(), world_->contact_group(), &contact);
  dJointAttach(j, dGeomGetBody(g.g1), dGeomGetBody(g.g2));
  dJointSetFeedback(j, &feedback_[static_cast<std::size_t>(joints_[e].first)]);
  joints_[e].count = 1;
}

void OdeEngine::step_once() {
  if (inject_ && injected_forces_run_away()) return;
  // at most one joint per contact of the state: the step's pool, grown
  // before any joint points into it
  if (feedback_.size() < now_.geoms.size()) {
    feedback_.resize(now_.geoms.size());
    explicit_n_.resize(now_.geoms.size());
  }
  joints_.resize(now_.pairs.size());
  // contact forces of this step, from the contacts at the current state
  int rows = 0;
  for (std::size_t e = 0; e < now_.pairs.size(); ++e) {
    const PairContact& pc = now_.pairs[e];
    joints_[e] = JointRange{rows, 0};
    if (inject_) {
      const double f = track_[static_cast<std::size_t>(pc.pair)].force_n;  // N, the law now
      if (!(f > 0.0)) continue;
      // body b is pushed along n_ab, body a the other way, at the pair's point
      const ContactPair& cp = pair(pc.pair);
      const Vec2 at = pc.point_m;
      if (const dBodyID b = world_->body(cp.body_b); b != nullptr) {
        dBodyAddForceAtPos(b, f * pc.normal_ab.x(), f * pc.normal_ab.y(), 0.0, at.x(), at.y(), 0.0);
      }
      if (const dBodyID a = world_->body(cp.body_a); a != nullptr) {
        dBodyAddForceAtPos(a, -f * pc.normal_ab.x(), -f * pc.normal_ab.y(), 0.0, at.x(), at.y(),
                           0.0);
      }
    } else if (oracle_) {
      add_oracle_joint(e);
    } else {
      add_native_joints(e);
    }
    rows += joints_[e].count;
  }

  if (quick_) {
    // the row-order seed is process-global: reseed and step under one lock
    const std::lock_guard<std::mutex> lock(internal::ode::quickstep_random_lock());
    dRandSetSeed(static_cast<unsigned long>(steps_));
    internal::ode::quick_step_world(world_->world(), step_s_);
  } else {
    internal::ode::step_world(world_->world(), step_s_);
  }
  ++steps_;

  // native, oracle: the force the contact joints applied over the step; f1 is
  // the world-frame force on g1's body, the normal points into g1. A pair
  // without joints this step had no force.
  if (!inject_) {
    for (const int p : forced_) {
      track_[static_cast<std::size_t>(p)].force_n = 0.0;
      track_[static_cast<std::size_t>(p)].tangential_force_n = 0.0;
    }
    forced_.clear();
    for (std::size_t e = 0; e < now_.pairs.size(); ++e) {
      const PairContact& pc = now_.pairs[e];
      double f = 0.0;   // N
      double ft = 0.0;  // N, on body_b along t
      // f1 acts on g1's body; the joint's force on b is then -f1 (g1 is
      // body_a's geom) or f1
      const double on_b = pc.g1_is_a ? -1.0 : 1.0;
      const Vec2 t = contact_tangent(pc.normal_ab);
      for (int i = 0; i < joints_[e].count; ++i) {
        const auto row = static_cast<std::size_t>(joints_[e].first + i);
        const dJointFeedback& fb = feedback_[row];
        const int k = oracle_ ? pc.deepest : i;
        const dReal* n = now_.geom(pc, k).normal;
        // the row's force and, with friction, its explicit damping (add_native_joints)
        f += std::max(0.0, fb.f1[0] * n[0] + fb.f1[1] * n[1] + fb.f1[2] * n[2] + explicit_n_[row]);
        ft += on_b * (fb.f1[0] * t.x() + fb.f1[1] * t.y());
      }
      PairTrack& tr = track_[static_cast<std::size_t>(pc.pair)];
      tr.force_n = f;
      tr.tangential_force_n = ft;
      forced_.push_back(pc.pair);
    }
    dJointGroupEmpty(world_->contact_group());
  }

  world_->remove_planar_drift();
  // checked after every step, before the next collision: ODE's colliders
  // assert on non-finite geometry (libode keeps its dIASSERTs)
  if (const int bad = world_->first_blown_up_body(); bad >= 0) {
    diverged_ = fmt::format("ode: body '{}' diverged at t = {:.9g} s: {}",
                            case_.bodies[static_cast<std::size_t>(bad)].name, time(),
                            world_->blow_up_reason(bad));
    return;
  }
  for (int i = 0; i < world_->body_count(); ++i) {
    if (world_->body(i) == nullptr) continue;
    auto& a = angle_rad_[static_cast<std::size_t>(i)];
    a = internal::ode::unwrapped_angle(a, world_->state(i).angle_rad);
  }
  sample_contacts();
}

// ODE's contacts at the current state, the force that goes with them, and
// the episode tracker. Native mode: the force is the one the joint applied
// over the step that ended now (with the implicit soft contact it is the
// spring-damper force at the end of that step). Inject mode: the law at the
// current state, which the next step applies.
void OdeEngine::sample_contacts() {
  collider_->collide(now_);
  if (track_.size() < static_cast<std::size_t>(pairs_->size())) {
    track_.resize(static_cast<std::size_t>(pairs_->size()));
  }
  // the pairs touching now and those in contact at the last sample, in
  // ascending pair index (both lists are): the tracker sees them in one order
  visit_.clear();
  constexpr int kNone = std::numeric_limits<int>::max();
  for (std::size_t a = 0, b = 0; a < now_.pairs.size() || b < in_contact_.size();) {
    const int pa = a < now_.pairs.size() ? now_.pairs[a].pair : kNone;
    const int pb = b < in_contact_.size() ? in_contact_[b] : kNone;
    if (pa <= pb) {
      visit_.emplace_back(pa, static_cast<int>(a++));
      if (pa == pb) ++b;
    } else {
      visit_.emplace_back(pb, -1);
      ++b;
    }
  }
  in_contact_.clear();
  const double t = time();
  for (const auto& [p, e] : visit_) {
    const PairContact* pc = e >= 0 ? &now_.pairs[static_cast<std::size_t>(e)] : nullptr;
    PairTrack& tr = track_[static_cast<std::size_t>(p)];
    const ContactPair& cp = pair(p);
    const bool in = pc != nullptr && pc->depth_m > 0.0;
    // eq. 7's delta_dot^-: the approach speed at the first sample with delta > 0
    if (in && !tr.in_contact) tr.latched_approach_mps = std::max(pc->approach_speed_mps, 0.0);
    if (inject_) {
      tr.force_n = pc != nullptr ? contact_force_n(cp.law, pc->depth_m, pc->approach_speed_mps,
                                                   tr.latched_approach_mps)
                                 : 0.0;
    }
    if (in) {
      if (!tr.in_contact && steps_ > 0) {
        // the step before: not in contact; its penetration is estimated from
        // this one and the approach speed so that the onset is interpolated
        tracker_.observe(t - step_s_, cp.body_a, cp.body_b,
                         std::min(0.0, pc->depth_m - step_s_ * pc->approach_speed_mps),
                         pc->approach_speed_mps, 0.0);
      }
      tracker_.observe(t, cp.body_a, cp.body_b, pc->depth_m, pc->approach_speed_mps, tr.force_n);
      tr.depth_m = pc->depth_m;
      tr.speed_mps = pc->approach_speed_mps;
      tr.normal_ab = pc->normal_ab;
      tr.point_m = pc->point_m;
      in_contact_.push_back(p);
    } else if (tr.in_contact) {
      // separated during the last step: ODE gives no distance, so estimate
      // the (non-positive) penetration from the last one and the speeds
      const double s = internal::ode::approach_speed_mps(*world_, cp, tr.point_m, tr.normal_ab);
      const double d = std::min(0.0, tr.depth_m + 0.5 * step_s_ * (tr.speed_mps + s));
      tracker_.observe(t, cp.body_a, cp.body_b, d, s, tr.force_n);
    }
    tr.in_contact = in;
  }
}

void OdeEngine::body_states(std::vector<BodyState>& out) const {
  out.resize(case_.bodies.size());
  if (!world_) return;
  for (int i = 0; i < world_->body_count(); ++i) {
    BodyState s = world_->state(i);
    if (world_->body(i) != nullptr) s.angle_rad = angle_rad_[static_cast<std::size_t>(i)];
    out[static_cast<std::size_t>(i)] = s;
  }
}

void OdeEngine::contacts(std::vector<ContactSample>& out) const {
  out.clear();
  for (const PairContact& pc : now_.pairs) {
    if (!(pc.depth_m > 0.0)) continue;
    const PairTrack& tr = track_[static_cast<std::size_t>(pc.pair)];
    ContactSample s;
    s.body_a = pair(pc.pair).body_a;
    s.body_b = pair(pc.pair).body_b;
    s.force_n = tr.force_n;
    s.tangential_force_n = tr.tangential_force_n;
    s.penetration_m = pc.depth_m;
    s.normal = pc.normal_ab;
    s.point_m = pc.point_m;
    out.push_back(s);
  }
}

}  // namespace pb::internal::ode

namespace pb {

std::unique_ptr<Engine> make_ode_engine() {
  return std::make_unique<internal::ode::OdeEngine>();
}

}  // namespace pb
