// The Box2D 2.4.1 adapter, engine "box2d". Builds any case from pb::Case the
// way Box2D's users do (b2World, b2BodyDef, fixtures, b2RevoluteJoint to a
// static ground body) and samples it after every step. Two modes:
//   engine  Box2D's rigid contact; each case law is expressed by the
//           restitution it produces (box2d_restitution.hpp);
//   inject  the contact pairs do not collide in Box2D; the adapter measures
//           the contact in closed form and applies the case's force law with
//           b2Body::ApplyForce before each step.
#include "planarbench/adapters/box2d_engine.hpp"

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
#include "box2d_faults.hpp"
#include "box2d_frame.hpp"
#include "box2d_geometry.hpp"
#include "box2d_inject_geometry.hpp"
#include "box2d_mapping_notes.hpp"
#include "box2d_restitution.hpp"
#include "box2d_settings.hpp"
#include "box2d_world_callbacks.hpp"
#include "planarbench/contact_force.hpp"
#include "planarbench/episode_tracker.hpp"
#include "planarbench/errors.hpp"

#ifndef PB_BOX2D_PACKAGE_VERSION
#define PB_BOX2D_PACKAGE_VERSION "unknown"
#endif

namespace pb {

namespace {

using namespace internal::box2d;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// onsets whose restitution is logged in the mapping (a bound: no allocation
// while stepping)
constexpr std::size_t kOnsetLogCapacity = 256;
// m, the penetration given to the episode tracker for a pair Box2D counts as
// touching (a manifold with points) whose float separation came out >= 0
constexpr double kTouching_m = 1e-12;

// every b2World::Step of this thread: a trace the engine reads before and
// after build (SPEC §5b: the default mode steps nothing ahead of t = 0)
thread_local long t_world_steps = 0;

// the contact state of one pair after the latest step
struct PairSample {
  bool valid = false;
  double penetration_m = kNaN;  // m, > 0 overlap (as measured)
  double tracked_m = kNaN;      // m, the penetration the episode tracker was given
  double speed_mps = kNaN;      // m/s, normal approach speed (> 0 approaching)
  double force_n = 0.0;         // N, reported at this time (engine: the last step's)
  double step_force_n = 0.0;    // N, mean force over the step that ended here
  double tangential_force_n = 0.0;  // N, on body_b along t, mean over that step (issue 32)
  Vec2 normal = Vec2::Zero();   // from body_a to body_b
  Vec2 point_m = Vec2::Zero();
};

bool finite(const BodyState& s) {
  return std::isfinite(s.position_m.x()) && std::isfinite(s.position_m.y()) &&
         std::isfinite(s.angle_rad) && std::isfinite(s.velocity_mps.x()) &&
         std::isfinite(s.velocity_mps.y()) && std::isfinite(s.angular_velocity_radps);
}

class Box2dEngine final : public Engine {
 public:
  Box2dEngine() { bind_settings(binder_, &settings_); }

  [[nodiscard]] std::string name() const override { return "box2d"; }
  [[nodiscard]] std::string version() const override;
  [[nodiscard]] Capability supports(const Case& c) const override;
  [[nodiscard]] const SettingsBinder& settings() const override { return binder_; }
  void build(const Case& c, const SettingsOverrides& overrides) override;
  void advance_to(double t_s) override;
  [[nodiscard]] double time() const override { return time_s_; }
  void body_states(std::vector<BodyState>& out) const override;
  void contacts(std::vector<ContactSample>& out) const override;
  [[nodiscard]] std::vector<ContactEpisode> episodes() const override;
  [[nodiscard]] long steps() const override { return steps_; }
  [[nodiscard]] nlohmann::json mapping() const override { return mapping_with_onsets(); }
  [[nodiscard]] nlohmann::json extra_attributes() const override;
  [[nodiscard]] Physics physics() const override;
  [[nodiscard]] long steps_before_start() const override { return steps_before_start_; }
  [[nodiscard]] long library_steps_on_this_thread() const override { return t_world_steps; }

 private:
  [[nodiscard]] bool inject() const { return settings_.mode == "inject"; }
  static void validate_bodies(const Case& c, double dt_s);
  void create_bodies(double threshold_mps);
  void create_joints();
  void map_pairs();
  void step();
  void apply_injected_forces();
  void check_state();
  [[noreturn]] void fail(std::string reason);
  void sample_pairs();
  void sample_engine_pair(std::size_t k);
  // m, a lower bound of pair k's gap from the bodies' centres and bounding
  // radii, and the most that gap can change in one step: the probe's exact
  // gap is needed only where the pair can touch within a step
  [[nodiscard]] bool far_apart(std::size_t k, double& lower_bound_m) const;
  void sample_injected_pair(std::size_t k);
  void track(std::size_t k, const PairSample& before, PairSample& now);
  [[nodiscard]] nlohmann::json mapping_with_onsets() const;

  Box2dSettings settings_;
  SettingsBinder binder_{"box2d"};

  Case case_;
  long steps_ = 0;
  double time_s_ = 0.0;
  bool collide_ = true;  // the contact filter lets the case pairs collide (engine mode)

  PairTable pairs_;
  std::vector<PairState> pair_states_;
  std::vector<BodyInertia> inertia_;
  std::vector<PairSample> samples_;
  // per pair, for far_apart: a fixed half-plane body_a's line (point, unit
  // normal towards body_b) or the bodies' bounding radii
  struct FarBound {
    bool plane = false;    // body_a is a fixed half-plane
    bool usable = false;   // a bound exists (a plane, or two finite radii)
    Vec2 point_m = Vec2::Zero();
    Vec2 normal = Vec2::Zero();
    double radius_a_m = 0.0;
    double radius_b_m = 0.0;
  };
  std::vector<FarBound> far_;
  std::vector<double> latched_approach_mps_;  // inject mode: delta_dot at onset, per pair
  std::vector<Vec2> injected_force_n_;        // inject mode: total force per body this step, N
  std::vector<double> injected_torque_nm_;    // inject mode: about the centre of mass, N m
  EpisodeTracker tracker_;
  double orphan_impulse_ns_ = 0.0;  // N s, solver impulse outside any episode (should stay 0)

  nlohmann::json mapping_ = nlohmann::json::object();
  // the callbacks must outlive the world (members are destroyed in reverse order)
  PairContactFilter filter_{pairs_, collide_};
  PairContactListener listener_{pairs_, pair_states_, inertia_, time_s_};
  std::unique_ptr<b2World> world_;
  std::vector<b2Body*> bodies_;  // index = Case::bodies index
  std::string fault_;  // why the run stopped ("" while it did not): it does not go on
  long steps_before_start_ = 0;  // b2World steps taken during build
};

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
  if (c.first_pair_with_friction() != nullptr) {
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
  tracker_ = EpisodeTracker{};
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
  create_bodies(threshold);
  create_joints();

  pairs_.reset(static_cast<int>(c.bodies.size()));
  pair_states_.assign(c.contacts.size(), PairState{});
  for (std::size_t k = 0; k < c.contacts.size(); ++k) {
    const ContactPair& p = c.contacts[k];
    pairs_.set(p.body_a, p.body_b, static_cast<int>(k));
    pair_states_[k].law = p.law;
    pair_states_[k].threshold_mps = threshold;
    pair_states_[k].friction = static_cast<float>(p.friction);
  }
  map_pairs();
  mapping_["restitution_threshold_mps"] = threshold;
  mapping_["restitution_threshold_rule"] =
      settings_.restitution_threshold_mps > 0.0
          ? "box2d.restitution_threshold"
          : "auto: max(0.02 m/s, 2 |g| dt): a resting contact gains "
            "|g| dt per step, and re-touches after float-noise gaps "
            "at < 0.02 m/s; slower impacts do not bounce";

  listener_.reserve_log(kOnsetLogCapacity);
  samples_.assign(c.contacts.size(), PairSample{});
  latched_approach_mps_.assign(c.contacts.size(), 0.0);
  injected_force_n_.assign(c.bodies.size(), Vec2::Zero());
  injected_torque_nm_.assign(c.bodies.size(), 0.0);
  orphan_impulse_ns_ = 0.0;
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
  for (const ContactPair& p : c.contacts) {
    const Body& ba = c.bodies[static_cast<std::size_t>(p.body_a)];
    const Body& bb = c.bodies[static_cast<std::size_t>(p.body_b)];
    FarBound fb;
    fb.radius_a_m = bounding_radius_m(ba.shape);
    fb.radius_b_m = bounding_radius_m(bb.shape);
    fb.plane = ba.fixed && std::holds_alternative<HalfPlane>(ba.shape);
    fb.point_m = ba.position_m;
    fb.normal = Vec2(-std::sin(ba.angle_rad), std::cos(ba.angle_rad));
    fb.usable = std::isfinite(fb.radius_b_m) && !bb.fixed &&
                (fb.plane || std::isfinite(fb.radius_a_m));
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

// the restitution of each pair: from the law alone where it does not depend
// on the state (Hertz, Lankarani-Nikravesh), else set as each contact begins
// from the state Box2D has then (b2ContactListener::PreSolve). Nothing is
// estimated ahead of the run.
void Box2dEngine::map_pairs() {
  nlohmann::json pairs = nlohmann::json::array();
  for (std::size_t k = 0; k < case_.contacts.size(); ++k) {
    const ContactPair& p = case_.contacts[k];
    PairState& st = pair_states_[k];
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
    st.per_onset = restitution_depends_on_state(p.law);
    pj["restitution_method"] = law_restitution_method(p.law);
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
      st.restitution = law_restitution(p.law, 1.0, 1.0);
      pj["restitution"] = st.restitution;
      pj["restitution_used"] =
          "the law's own restitution, the same for every contact: it does not depend on m_eff "
          "or the approach speed (scale invariance of F = K delta^n (1 + a delta_dot / v0)); "
          "computed from the law alone";
    }
    if (const auto* ln = std::get_if<LankaraniNikravesh>(&p.law)) {
      pj["nominal_restitution"] = ln->restitution;
    }
    pj["restitution_mixing"] =
        "b2Contact::SetRestitution on each contact when it begins; every fixture has restitution 0 "
        "and friction 0 (frictionless: Box2D mixes friction by sqrt(f1 f2))";
    if (p.has_friction()) {
      pj["friction"] = {
          {"coefficient", p.friction},
          {"expressed_as",
           fmt::format("exactly, as a per-contact setting: b2Contact::SetFriction({}) on each "
                       "contact of the pair when it begins (PreSolve; it persists for the "
                       "contact's life and overrides the sqrt(f1 f2) mix of the fixtures' "
                       "friction, which stays 0), in float: {:.9g}",
                       p.friction, static_cast<double>(static_cast<float>(p.friction)))},
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
    pairs.push_back(pj);
  }
  mapping_["contacts"] = pairs;
  mapping_["mode"] = settings_.mode;
  mapping_.update(mapping_notes(inject()));
}

void Box2dEngine::advance_to(double t_s) {
  if (!world_) throw EngineError("box2d: advance_to before build");
  if (!fault_.empty()) throw EngineError(fault_);
  // a fixed-step engine stops at its last step not after t_s (engine.hpp)
  const double dt = settings_.dt_s;
  while (static_cast<double>(steps_ + 1) * dt <= t_s + 1e-9 * dt) step();
}

void Box2dEngine::step() {
  const float dt = static_cast<float>(settings_.dt_s);
  if (!collide_) apply_injected_forces();  // inject mode (collide_ caches !inject())
  for (auto& st : pair_states_) {
    st.step_impulse_ns = 0.0;
    st.step_tangent_impulse_ns = 0.0;
  }
  world_->Step(dt, settings_.velocity_iterations, settings_.position_iterations);
  ++t_world_steps;
  ++steps_;
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
  for (std::size_t k = 0; k < samples_.size(); ++k) {
    if (!collide_) {  // inject mode
      sample_injected_pair(k);
    } else {
      sample_engine_pair(k);
    }
  }
}

bool Box2dEngine::far_apart(std::size_t k, double& lower_bound_m) const {
  const FarBound& fb = far_[k];
  if (!fb.usable) return false;
  const ContactPair& p = case_.contacts[k];
  const b2Body& a = *bodies_[static_cast<std::size_t>(p.body_a)];
  const b2Body& b = *bodies_[static_cast<std::size_t>(p.body_b)];
  // centres of mass and velocities as Box2D holds them (no angle needed)
  const Vec2 ca = from_b2(a.GetWorldCenter());
  const Vec2 cb = from_b2(b.GetWorldCenter());
  const Vec2 va = from_b2(a.GetLinearVelocity());
  const Vec2 vb = from_b2(b.GetLinearVelocity());
  const double wa = static_cast<double>(a.GetAngularVelocity());
  const double wb = static_cast<double>(b.GetAngularVelocity());
  // the gap of the skinned surfaces (the case's surfaces) is at least the
  // centre's height above a half-plane, or the centres' distance, less the
  // bounding radii, less 1e-5 m for the float placement of Box2D's shapes
  // (~8 ulp at 10 m)
  constexpr double kFloatMargin_m = 1e-5;
  double speed = (vb - va).norm() + std::abs(wb) * fb.radius_b_m;  // m/s
  if (fb.plane) {
    lower_bound_m = (cb - fb.point_m).dot(fb.normal) - fb.radius_b_m - kFloatMargin_m;
  } else {
    lower_bound_m = (cb - ca).norm() - fb.radius_a_m - fb.radius_b_m - kFloatMargin_m;
    speed += std::abs(wa) * fb.radius_a_m;
  }
  // semi-implicit Euler moves a step's positions with its end velocity:
  // within one step a gap changes by at most h (speed + |g| h); twice that
  // keeps the previous and the next step apart as well
  const double h = settings_.dt_s;
  const double reach = 2.0 * h * (speed + case_.gravity_mps2.norm() * h);
  return lower_bound_m > reach;
}

void Box2dEngine::sample_engine_pair(std::size_t k) {
  const ContactPair& p = case_.contacts[k];
  const b2Body& a = *bodies_[static_cast<std::size_t>(p.body_a)];
  const b2Body& b = *bodies_[static_cast<std::size_t>(p.body_b)];
  const PairSample before = samples_[k];
  PairSample& s = samples_[k];
  const double impulse = pair_states_[k].step_impulse_ns;
  // Far apart (no episode open, no impulse this step, and the gap's lower
  // bound beyond what one step can close): the tracker is given the bound as
  // the gap. Onsets, offsets and within-step impacts read only the samples
  // next to a touching step, which are never far, so every episode is the
  // one the probe's exact gap gives; the probe's b2Distance was 17 % of a
  // step of falling_ball (callgrind).
  double lower_bound = 0.0;
  if (steps_ > 0 && impulse == 0.0 && !tracker_.in_contact(p.body_a, p.body_b) &&
      far_apart(k, lower_bound)) {
    s.valid = broad_phase_pair(a, b);
    s.step_force_n = 0.0;
    s.force_n = 0.0;
    s.tangential_force_n = 0.0;
    s.penetration_m = s.valid ? -lower_bound : kNaN;
    s.tracked_m = s.penetration_m;
    s.speed_mps = kNaN;
    track(k, before, s);
    return;
  }
  // before the first step Box2D's broad phase has not paired anything yet
  const ContactGeometry g =
      probe_contact(a, b, steps_ == 0 ? ProbeScope::every_child : ProbeScope::broad_phase);
  s.valid = g.valid;
  s.step_force_n = impulse / settings_.dt_s;
  s.force_n = s.step_force_n;
  s.tangential_force_n = pair_states_[k].step_tangent_impulse_ns / settings_.dt_s;
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
    const bool open = tracker_.in_contact(p.body_a, p.body_b);
    s.tracked_m = g.penetration_m;
    if (g.touching) s.tracked_m = std::max(s.tracked_m, kTouching_m);
    if (open && s.tracked_m <= 0.0 && s.tracked_m > -resolution) s.tracked_m = kTouching_m;
  } else {
    s.penetration_m = kNaN;
    s.tracked_m = kNaN;
    s.speed_mps = kNaN;
  }
  // the step's impulse belongs to an episode open at the step's start or
  // opening at its end
  const bool was_open = tracker_.in_contact(p.body_a, p.body_b);
  track(k, before, s);
  if (!was_open && !tracker_.in_contact(p.body_a, p.body_b) && impulse > 0.0) {
    if (steps_ > 0 && before.valid && s.valid) {
      // apart at both ends of the step and pushed within it: Box2D's time of
      // impact solved a fast impact inside the step (b2World::SolveTOI, whose
      // impulses PostSolve reports): an episode of its own
      const double t_before = static_cast<double>(steps_ - 1) * settings_.dt_s;
      tracker_.record_within_step(t_before, time_s_, p.body_a, p.body_b, -before.penetration_m,
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
  const ContactPair& p = case_.contacts[k];
  if (!now.valid) {
    tracker_.observe_separated(time_s_, p.body_a, p.body_b, kNaN);
    return;
  }
  if (steps_ > 0 && before.valid) {
    const double t_before = static_cast<double>(steps_ - 1) * settings_.dt_s;
    tracker_.observe(t_before, p.body_a, p.body_b, before.tracked_m, now.speed_mps,
                     now.step_force_n);
  }
  tracker_.observe(time_s_, p.body_a, p.body_b, now.tracked_m, now.speed_mps, now.step_force_n);
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
  for (std::size_t k = 0; k < samples_.size(); ++k) {
    const PairSample& s = samples_[k];
    const ContactPair& p = case_.contacts[k];
    // in contact: inside an episode, or pushed during the last step
    if (!s.valid || !(tracker_.in_contact(p.body_a, p.body_b) || s.force_n > 0.0)) continue;
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
  return tracker_.episodes();
}

nlohmann::json Box2dEngine::mapping_with_onsets() const {
  nlohmann::json j = mapping_;
  if (inject() || !j.contains("contacts")) return j;
  nlohmann::json onsets = nlohmann::json::array();
  for (const auto& r : listener_.log()) {
    onsets.push_back({{"time_s", r.time_s},
                      {"contact", case_.contacts[static_cast<std::size_t>(r.pair)].name},
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
  return j;
}

}  // namespace

std::unique_ptr<Engine> make_box2d_engine() {
  return std::make_unique<Box2dEngine>();
}

}  // namespace pb
