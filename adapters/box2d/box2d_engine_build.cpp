// The Box2D adapter's building half (box2d_engine_impl.hpp): what a case
// needs that Box2D can express, and the b2World made from it - bodies and
// their fixtures, revolute joints to a static ground, each contact pair's
// restitution and friction as its users set them, and the mapping that states
// it.
#include <box2d/b2_body.h>
#include <box2d/b2_common.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_revolute_joint.h>
#include <box2d/b2_world.h>
#include <fmt/format.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <memory>
#include <utility>

#include "box2d_contact_probe.hpp"
#include "box2d_engine_impl.hpp"
#include "box2d_faults.hpp"
#include "box2d_frame.hpp"
#include "box2d_geometry.hpp"
#include "box2d_inject_geometry.hpp"
#include "box2d_mapping_notes.hpp"
#include "box2d_restitution.hpp"
#include "planarbench/broad_phase.hpp"
#include "planarbench/contact_force.hpp"
#include "planarbench/contact_pairs.hpp"
#include "planarbench/errors.hpp"

#ifndef PB_BOX2D_PACKAGE_VERSION
#define PB_BOX2D_PACKAGE_VERSION "unknown"
#endif

namespace pb::internal::box2d {

std::string Box2dEngine::version() const {
  const std::string reported =
      fmt::format("{}.{}.{}", b2_version.major, b2_version.minor, b2_version.revision);
  std::string package = PB_BOX2D_PACKAGE_VERSION;
  if (package == reported) return package;
  // Box2D 2.4.1's b2_settings.cpp still says 2.4.0 (ENGINES.md)
  return fmt::format("{} (library reports b2_version {})", package, reported);
}

Capability Box2dEngine::supports(const Case& c) const {
  const auto unsupported = [](std::string why) {
    return Capability{Support::unsupported, std::move(why)};
  };
  if (inject() && c.has_contact_groups()) {
    // the adapter would need a broad phase of its own for the group pairs,
    // where the default mode uses Box2D's
    return unsupported(
        "contact groups in box2d.mode = inject: the closed-form forces are applied to declared "
        "pairs only; run groups with the default mode (Box2D's broad phase finds their pairs)");
  }
  std::vector<int> joints_per_body(c.bodies.size(), 0);
  for (const auto& j : c.joints) {
    if (j.body < 0 || j.body >= static_cast<int>(c.bodies.size()))
      return unsupported("joint without a body");
    if (++joints_per_body[static_cast<std::size_t>(j.body)] > 1) {
      return unsupported(fmt::format(
          "body '{}' has more than one revolute joint: the effective mass of its contacts "
          "(restitution mapping) is only derived for free bodies and single pivots",
          c.bodies[static_cast<std::size_t>(j.body)].name));
    }
  }
  for (const auto& b : c.bodies) {
    if (std::holds_alternative<HalfPlane>(b.shape) && !b.fixed) {
      return unsupported(
          fmt::format("body '{}': a moving half-plane has no Box2D counterpart", b.name));
    }
    if (!inject()) {
      if (auto why = unsupported_shape_reason(b); !why.empty()) return unsupported(why);
    }
  }
  for (const auto& p : c.contacts) {
    const Shape& a = c.bodies.at(static_cast<std::size_t>(p.body_a)).shape;
    const Shape& b = c.bodies.at(static_cast<std::size_t>(p.body_b)).shape;
    if (inject()) {
      if (auto why = primitive_contact_unsupported_reason(a, b); !why.empty()) {
        return unsupported(fmt::format("contact '{}': {}", p.name, why));
      }
    } else if (std::holds_alternative<HalfPlane>(a) && std::holds_alternative<HalfPlane>(b)) {
      return unsupported(fmt::format("contact '{}': Box2D never collides two edge chains", p.name));
    }
  }
  if (inject()) {
    if (auto why = inject_friction_reason(c); !why.empty()) return unsupported(why);
    return Capability{Support::mapped,
                      "force injection: the case's contact law is applied with b2Body::ApplyForce "
                      "from closed-form geometry, explicit in time (the force of the state at the "
                      "start of each step); Box2D integrates in float"};
  }
  std::string how =
      "rigid contact: each contact law is expressed by the restitution it produces (no "
      "stiffness, no penetration by design, momentum exchanged within one step); float precision; "
      "b2_linearSlop = 0.005 m of overlap is tolerated";
  if (case_has_friction(c)) {
    how += "; Coulomb friction as Box2D's rigid friction, the pair's coefficient set on each "
           "contact (b2Contact::SetFriction)";
  }
  return Capability{Support::mapped, how};
}

void Box2dEngine::build(const Case& c, const SettingsOverrides& overrides) {
  const long steps_at_start = t_world_steps;
  settings_ = Box2dSettings{};
  binder_.apply(overrides);
  const Capability cap = supports(c);
  if (cap.support == Support::unsupported)
    throw EngineError("box2d cannot run this case: " + cap.reason);

  validate_bodies(c, settings_.dt_s);
  case_ = c;
  steps_ = 0;
  time_s_ = 0.0;
  fault_.clear();
  collide_ = !inject();
  trackers_.clear();
  bodies_.clear();
  world_.reset();
  mapping_ = nlohmann::json::object();

  world_ = std::make_unique<b2World>(to_b2(c.gravity_mps2));
  world_->SetAllowSleeping(false);
  world_->SetWarmStarting(settings_.warm_starting);
  world_->SetContinuousPhysics(settings_.continuous_physics);
  world_->SetSubStepping(false);
  world_->SetContactFilter(&filter_);
  world_->SetContactListener(&listener_);

  // the restitution threshold (box2d_settings.hpp)
  const double threshold =
      settings_.restitution_threshold_mps > 0.0
          ? settings_.restitution_threshold_mps
          : std::max(kFloatNoiseThreshold_mps, 2.0 * c.gravity_mps2.norm() * settings_.dt_s);
  interval_force_ = settings_.reported_force == "interval" ||
                    (settings_.reported_force == "auto" && c.has_contact_groups());
  // the pairs first: Box2D asks the filter about them from its first step
  std::vector<PairState> declared;
  std::vector<PairState> groups;
  map_pairs(threshold, declared, groups);
  pairs_.reset(c, std::move(declared), std::move(groups));
  create_bodies(threshold);
  create_joints();
  mapping_["restitution_threshold_mps"] = threshold;
  mapping_["restitution_threshold_rule"] =
      settings_.restitution_threshold_mps > 0.0
          ? "box2d.restitution_threshold"
          : "auto: max(0.02 m/s, 2 |g| dt): a resting contact gains "
            "|g| dt per step, and re-touches after float-noise gaps "
            "at < 0.02 m/s; slower impacts do not bounce";

  listener_.reserve_log(kOnsetLogCapacity);
  samples_.clear();
  seen_.clear();
  head_.clear();
  grow_pairs();
  listed_.clear();
  interval_ = 0;
  interval_steps_ = 0;
  latched_approach_mps_.assign(c.contacts.size(), 0.0);
  injected_force_n_.assign(c.bodies.size(), Vec2::Zero());
  injected_torque_nm_.assign(c.bodies.size(), 0.0);
  orphan_impulse_ns_ = 0.0;
  // t = 0: every declared pair (as measured before Box2D's first step, the
  // state the run starts from) and the group pairs near enough to touch
  active_.clear();
  for (int k = 0; k < pairs_.size(); ++k) active_.push_back(k);
  if (!inject()) add_initial_group_pairs();
  previous_active_.clear();
  sample_pairs();
  steps_before_start_ = t_world_steps - steps_at_start;
}

// Debian's libbox2d keeps its asserts (b2Body's constructor asserts finite
// poses, SetMassData a positive inertia), a dynamic body whose mass rounds to
// 0 in float gets 1 kg, and a first step beyond Box2D's clamps is not the
// case's: all refused here, with the body named (box2d_faults.hpp)
void Box2dEngine::validate_bodies(const Case& c, double dt_s) {
  if (const std::string why = refused_input_reason(c, dt_s); !why.empty()) {
    throw EngineError("box2d: refused: " + why);
  }
}

void Box2dEngine::create_bodies(double threshold_mps) {
  const Case& c = case_;
  // a half-plane's chain must reach every point a body can get to in the
  // run: |x0| + |v0| T + |g| T^2 / 2 + its size (the case's half-plane is infinite)
  double reach = 0.0;
  for (const auto& b : c.bodies) {
    if (b.fixed) continue;
    reach = std::max(reach, b.position_m.norm() + b.velocity_mps.norm() * c.duration_s +
                                0.5 * c.gravity_mps2.norm() * c.duration_s * c.duration_s +
                                bounding_radius_m(b.shape));
  }
  nlohmann::json bodies_json = nlohmann::json::array();
  inertia_.assign(c.bodies.size(), BodyInertia{});
  far_.clear();
  motion_.assign(c.bodies.size(), Motion{});
  for (const Body& b : c.bodies) {
    FarBound fb;
    fb.plane = b.fixed && std::holds_alternative<HalfPlane>(b.shape);
    fb.point_m = b.position_m;
    fb.normal = Vec2(-std::sin(b.angle_rad), std::cos(b.angle_rad));
    fb.radius_m = bounding_radius_m(b.shape);
    far_.push_back(fb);
  }
  for (std::size_t i = 0; i < c.bodies.size(); ++i) {
    const Body& b = c.bodies[i];
    const b2BodyDef def = body_def(b);
    b2Body* body = world_->CreateBody(&def);
    body->GetUserData().pointer = static_cast<uintptr_t>(i + 1);
    bodies_.push_back(body);

    FixtureOptions opt;
    opt.restitution_threshold_mps = threshold_mps;
    opt.body_index = static_cast<int>(i);
    if (const auto* hp = std::get_if<HalfPlane>(&b.shape)) {
      opt.half_plane_half_length_m =
          std::max(0.5 * hp->extent_m, reach + b.position_m.norm()) + 1.0;
    }
    nlohmann::json bj;
    bj["name"] = b.name;
    bj["b2_type"] = b.fixed ? "b2_staticBody" : "b2_dynamicBody";
    // in injection mode a shape Box2D cannot build is simply left out: no
    // fixture of a contact pair collides there anyway
    if (!inject() || unsupported_shape_reason(b).empty()) {
      bj["geometry"] = add_fixtures(*body, b, opt);
    } else {
      bj["geometry"] = "no fixtures (injection mode; " + unsupported_shape_reason(b) + ")";
    }
    if (!b.fixed) {
      // the case's mass and planar inertia, centre of mass at the body origin
      b2MassData md;
      md.mass = static_cast<float>(b.mass_kg);
      md.center.SetZero();
      md.I = static_cast<float>(b.inertia_kgm2);
      body->SetMassData(&md);
      bj["b2MassData"] = {{"mass_kg", md.mass}, {"center_m", {0.0, 0.0}}, {"I_kgm2", md.I}};
    }
    bodies_json.push_back(bj);
    inertia_[i] =
        BodyInertia{b.fixed, b.mass_kg, b.inertia_kgm2, b.position_m, false, Vec2::Zero()};
  }
  mapping_["bodies"] = bodies_json;
}

void Box2dEngine::create_joints() {
  if (case_.joints.empty()) return;
  // the world: a static body at the origin without fixtures
  b2BodyDef ground_def;
  ground_def.type = b2_staticBody;
  b2Body* ground = world_->CreateBody(&ground_def);
  nlohmann::json joints = nlohmann::json::array();
  for (const auto& j : case_.joints) {
    b2RevoluteJointDef def;
    def.bodyA = ground;
    def.bodyB = bodies_[static_cast<std::size_t>(j.body)];
    def.localAnchorA = to_b2(j.anchor_world_m);
    def.localAnchorB = to_b2(j.anchor_local_m);
    def.referenceAngle =
        static_cast<float>(case_.bodies[static_cast<std::size_t>(j.body)].angle_rad);
    def.collideConnected = false;
    world_->CreateJoint(&def);
    BodyInertia& in = inertia_[static_cast<std::size_t>(j.body)];
    in.pinned = true;
    in.pivot_m = j.anchor_world_m;
    joints.push_back({{"name", j.name},
                      {"box2d",
                       "b2RevoluteJoint between a static ground body and the body, "
                       "local anchors from the case, no limit, no motor"}});
  }
  mapping_["joints"] = joints;
}

void Box2dEngine::grow_pairs() {
  const auto n = static_cast<std::size_t>(pairs_.size());
  if (samples_.size() >= n) return;
  samples_.resize(n);
  trackers_.resize(n);
  seen_.resize(n, -1);
  head_.resize(n, -1);
}

void Box2dEngine::add_initial_group_pairs() {
  if (!case_.has_contact_groups()) return;
  // the case's boxes fattened as Box2D fattens its fixtures' AABBs: the
  // pairs its first step will hold (its boxes are of the inset cores and
  // their skin, the same extent)
  const double margin = static_cast<double>(b2_aabbExtension);  // m
  std::vector<Aabb> boxes;
  std::vector<int> ids;
  std::vector<int> planes;
  std::vector<bool> member(case_.bodies.size(), false);  // a body in two groups is boxed once
  for (const ContactGroup& g : case_.contact_groups) {
    for (const int i : g.bodies) {
      if (member[static_cast<std::size_t>(i)]) continue;
      member[static_cast<std::size_t>(i)] = true;
      const Body& b = case_.bodies[static_cast<std::size_t>(i)];
      if (std::holds_alternative<HalfPlane>(b.shape)) {
        planes.push_back(i);
        continue;
      }
      boxes.push_back(shape_aabb(b.shape, b.position_m, b.angle_rad).expanded(margin));
      ids.push_back(i);
    }
  }
  std::vector<std::pair<int, int>> near;
  std::vector<int> order;
  overlapping_pairs(boxes, ids, near, order);
  for (const int plane : planes) {
    const Body& hp = case_.bodies[static_cast<std::size_t>(plane)];
    for (std::size_t v = 0; v < boxes.size(); ++v) {
      if (height_above_half_plane(boxes[v], hp.position_m, hp.angle_rad) <= 0.0) {
        near.emplace_back(plane, ids[v]);
      }
    }
  }
  for (const auto& [i, j] : near) {
    // a declared pair is sampled already; a pair no rule covers never
    const int k = pairs_.find_or_add(i, j);
    if (k >= pairs_.pairs().declared()) active_.push_back(k);
  }
  grow_pairs();
  std::sort(active_.begin(), active_.end());
  active_.erase(std::unique(active_.begin(), active_.end()), active_.end());
}

// the restitution of each pair: from the law alone where it does not depend
// on the state (Hertz, Lankarani-Nikravesh), else set as each contact begins
// from the state Box2D has then (b2ContactListener::PreSolve). Nothing is
// estimated ahead of the run.
void Box2dEngine::map_pairs(double threshold_mps, std::vector<PairState>& declared,
                            std::vector<PairState>& groups) {
  declared.assign(case_.contacts.size(), PairState{});
  nlohmann::json pairs = nlohmann::json::array();
  for (std::size_t k = 0; k < case_.contacts.size(); ++k) {
    const ContactPair& p = case_.contacts[k];
    PairState& st = declared[k];
    st.law = p.law;
    st.threshold_mps = threshold_mps;
    st.friction = static_cast<float>(p.friction);
    nlohmann::json pj;
    pj["name"] = p.name;
    pj["body_a"] = case_.bodies[static_cast<std::size_t>(p.body_a)].name;
    pj["body_b"] = case_.bodies[static_cast<std::size_t>(p.body_b)].name;
    pj["law"] = contact_law_name(p.law);
    if (case_.bodies[static_cast<std::size_t>(p.body_a)].fixed &&
        case_.bodies[static_cast<std::size_t>(p.body_b)].fixed) {
      pj["note"] = "both bodies are fixed: the pair never moves into contact";
      pairs.push_back(pj);
      continue;
    }
    if (inject()) {
      pj["expressed_as"] =
          "the case's law itself (contact_force_n), applied with b2Body::ApplyForce at the contact "
          "point, equal and opposite on the two bodies, from the state at the start of each step; "
          "penetration, normal and point from closed-form geometry of the exact shapes; "
          "Lankarani-Nikravesh's approach speed latched at the first step with penetration > 0";
      pj["warning"] =
          "explicit forces need many steps per contact: a Kelvin-Voigt contact lasts about "
          "pi sqrt(m_eff / k), and dt should be a twentieth of that or less";
      pairs.push_back(pj);
      continue;
    }
    map_law(p.law, p.friction, st, pj);
    pairs.push_back(pj);
  }
  mapping_["contacts"] = pairs;

  // a group's pairs: each starts from its group's state when Box2D first
  // pairs the two bodies' fixtures (PairBook::find_or_add)
  groups.assign(case_.contact_groups.size(), PairState{});
  nlohmann::json groups_json = nlohmann::json::array();
  for (std::size_t g = 0; g < case_.contact_groups.size(); ++g) {
    const ContactGroup& grp = case_.contact_groups[g];
    PairState& st = groups[g];
    st.law = grp.law;
    st.threshold_mps = threshold_mps;
    st.friction = static_cast<float>(grp.friction);
    nlohmann::json gj;
    gj["name"] = grp.name;
    gj["bodies"] = grp.bodies.size();
    gj["law"] = contact_law_name(grp.law);
    gj["pairs_found_by"] =
        "Box2D's own broad phase (b2BroadPhase, a dynamic AABB tree of fixtures fattened by "
        "b2_aabbExtension = 0.1 m): b2ContactFilter::ShouldCollide lets two fixtures collide when "
        "the group (or a declared pair, whose own law then holds) lets their bodies touch "
        "(ContactPairs::may_touch); a pair gets its index in the run's pair list when Box2D "
        "first holds a contact of it, and is sampled only while it has one";
    gj["contacts_table"] =
        "a row per pair at each sample while its episode is open or the solver pushed it in the "
        "output interval; pairs apart have none";
    map_law(grp.law, grp.friction, st, gj);
    groups_json.push_back(gj);
  }
  if (!groups_json.empty()) mapping_["contact_groups"] = groups_json;
  mapping_["mode"] = settings_.mode;
  mapping_.update(mapping_notes(inject(), interval_force_));
}

void Box2dEngine::map_law(const ContactLaw& law, double friction, PairState& st,
                          nlohmann::json& pj) const {
  st.per_onset = restitution_depends_on_state(law);
  pj["restitution_method"] = law_restitution_method(law);
  if (st.per_onset) {
    pj["restitution_used"] =
        "set in b2ContactListener::PreSolve when a contact of the pair begins (its first "
        "PreSolve), from the state Box2D has then: the pair's touching manifold points as one "
        "contact at the depth-weighted centroid of their region, the depth-weighted mean of "
        "its two end points along the surface (SPEC §1; a face landing flat: its middle, "
        "however the body's convex pieces split it; a vertex two pieces share: that vertex), "
        "its effective mass 1 / (J M^-1 J^T) along the deepest point's normal, and the largest "
        "normal approach speed among the points; set on every touching contact of the pair; "
        "listed in onsets";
  } else {
    // scale invariance: any m_eff and approach speed give the same value
    st.restitution = law_restitution(law, 1.0, 1.0);
    pj["restitution"] = st.restitution;
    pj["restitution_used"] =
        "the law's own restitution, the same for every contact: it does not depend on m_eff "
        "or the approach speed (scale invariance of F = K delta^n (1 + a delta_dot / v0)); "
        "computed from the law alone";
  }
  if (const auto* ln = std::get_if<LankaraniNikravesh>(&law)) {
    pj["nominal_restitution"] = ln->restitution;
  }
  pj["restitution_mixing"] =
      "b2Contact::SetRestitution on each contact when it begins; every fixture has restitution 0 "
      "and friction 0 (frictionless: Box2D mixes friction by sqrt(f1 f2))";
  if (friction > 0.0) {
    pj["friction"] = {
        {"coefficient", friction},
        {"expressed_as",
         fmt::format("exactly, as a per-contact setting: b2Contact::SetFriction({}) on each "
                     "contact of the pair when it begins (PreSolve; it persists for the "
                     "contact's life and overrides the sqrt(f1 f2) mix of the fixtures' "
                     "friction, which stays 0), in float: {:.9g}",
                     friction, static_cast<double>(static_cast<float>(friction)))},
        {"model",
         "Box2D's sequential impulses: per contact point a tangential impulse clamped to "
         "friction x that point's accumulated normal impulse, solved before the normal one; "
         "rigid stick, no creep (tangent impulses warm-started)"},
        {"not_expressed",
         nlohmann::json::array(
             {"the contact point is the middle of the overlap, so a circle resting d deep (up "
              "to b2_linearSlop = 0.005 m) rolls on R - d / 2: a uniform disk's rolling "
              "acceleration is low by (1/3) d / R (0.67 % at d = 0.005 m, R = 0.25 m)"})}};
  }
}

}  // namespace pb::internal::box2d
