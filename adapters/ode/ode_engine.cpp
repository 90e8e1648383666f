// The ODE adapter, engine "ode": builds any case from the pb::Case model
// through ODE 0.16.2 (double precision) the way its users do: one dWorld and
// one dSpace per engine, dSpaceCollide with a near callback, contact joints
// in a dJointGroup emptied every step, at the step the user gives. Modes:
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

namespace pb {

namespace {

using internal::ode::FirstTouch;
using internal::ode::LinearLaw;
using internal::ode::OdeSettings;
using internal::ode::OdeWorld;
using internal::ode::PairCollider;
using internal::ode::PairContact;
using internal::ode::SoftContact;

nlohmann::json vec_json(const Vec2& v) {
  return nlohmann::json::array({v.x(), v.y()});
}

nlohmann::json response_json(const CollisionResponse& r) {
  return {{"restitution", r.restitution},
          {"force_duration_s", r.force_duration_s},
          {"duration_s", r.duration_s},
          {"peak_force_n", r.peak_force_n},
          {"max_penetration_m", r.max_penetration_m},
          {"impulse_ns", r.impulse_ns}};
}

nlohmann::json law_json(const ContactLaw& law) {
  nlohmann::json j = {{"law", contact_law_name(law)}};
  if (const auto* kv = std::get_if<KelvinVoigt>(&law)) {
    j["stiffness_n_per_m"] = kv->stiffness_n_per_m;
    j["damping_ns_per_m"] = kv->damping_ns_per_m;
    j["damping_depth_m"] = kv->damping_depth_m;
  } else if (const auto* hz = std::get_if<Hertz>(&law)) {
    j["stiffness"] = hz->stiffness;
    j["exponent"] = hz->exponent;
  } else {
    const auto& ln = std::get<LankaraniNikravesh>(law);
    j["stiffness"] = ln.stiffness;
    j["exponent"] = ln.exponent;
    j["restitution"] = ln.restitution;
  }
  return j;
}

bool is_plain_kelvin_voigt(const ContactLaw& law) {
  const auto* kv = std::get_if<KelvinVoigt>(&law);
  return kv != nullptr && kv->damping_depth_m <= 0.0;
}

// what a soft contact (a linear spring-damper) cannot carry of the law
nlohmann::json not_expressed_native(const ContactLaw& law) {
  nlohmann::json out = nlohmann::json::array();
  if (const auto* kv = std::get_if<KelvinVoigt>(&law)) {
    if (kv->damping_depth_m > 0.0) {
      out.push_back(fmt::format(
          "the cubic damping ramp over {} m: a constant damper matched to the first impact",
          kv->damping_depth_m));
    }
    return out;
  }
  const double n = std::holds_alternative<Hertz>(law) ? std::get<Hertz>(law).exponent
                                                      : std::get<LankaraniNikravesh>(law).exponent;
  out.push_back(fmt::format("the nonlinear stiffness K delta^{}: a linear spring k", n));
  if (std::holds_alternative<LankaraniNikravesh>(law)) {
    out.push_back(
        "the hysteresis damping scaled by the approach speed latched at onset: a constant "
        "damper c");
  }
  out.push_back(
      "the equivalent matches the first impact's effective mass and approach speed only; "
      "other impacts get other durations and restitutions from it");
  return out;
}

// one contact pair's state between samples
struct PairTrack {
  double force_n = 0.0;               // N, normal force of the current sample
  double latched_approach_mps = 0.0;  // m/s, delta_dot at onset (eq. 7's delta_dot^-)
  bool in_contact = false;            // penetration > 0 at the current sample
  double depth_m = 0.0;               // m, at the current sample
  double speed_mps = 0.0;             // m/s, approach speed at the current sample
  Vec2 normal_ab = Vec2::Zero();
  Vec2 point_m = Vec2::Zero();
};

class OdeEngine final : public Engine {
 public:
  OdeEngine() : binder_(internal::ode::bind_ode_settings(settings_)) {}

  [[nodiscard]] std::string name() const override { return "ode"; }

  [[nodiscard]] std::string version() const override {
    return fmt::format(
        "ODE {} (pkg-config at build time; headers dODE_VERSION {}; "
        "dGetConfiguration: {})",
        internal::ode::ode_pkgconfig_version(), internal::ode::ode_header_version(),
        internal::ode::ode_configuration());
  }

  [[nodiscard]] Capability supports(const Case& c) const override;
  [[nodiscard]] const SettingsBinder& settings() const override { return binder_; }
  void build(const Case& c, const SettingsOverrides& overrides) override;
  void advance_to(double t_s) override;
  [[nodiscard]] double time() const override { return static_cast<double>(steps_) * step_s_; }
  void body_states(std::vector<BodyState>& out) const override;
  void contacts(std::vector<ContactSample>& out) const override;
  [[nodiscard]] std::vector<ContactEpisode> episodes() const override {
    return tracker_.episodes();
  }
  [[nodiscard]] long steps() const override { return steps_; }
  [[nodiscard]] nlohmann::json mapping() const override;
  [[nodiscard]] nlohmann::json extra_attributes() const override;
  [[nodiscard]] Physics physics() const override;
  [[nodiscard]] long steps_before_start() const override { return probe_steps_; }
  [[nodiscard]] long library_steps_on_this_thread() const override {
    return internal::ode::world_steps_on_this_thread();
  }

 private:
  void map_contacts_oracle(const std::vector<FirstTouch>& touches);
  void map_contacts_native();
  void add_common_mapping();
  void add_native_joints(std::size_t p);
  void add_oracle_joint(std::size_t p);
  void step_once();
  [[nodiscard]] bool injected_forces_run_away();
  void sample_contacts();

  OdeSettings settings_;
  SettingsBinder binder_;

  Case case_;
  std::unique_ptr<OdeWorld> world_;
  std::unique_ptr<PairCollider> collider_;
  std::vector<PairContact> now_;  // ODE's contacts at the current state
  std::vector<PairTrack> track_;
  std::vector<SoftContact> soft_;  // oracle mode, per pair
  std::vector<dJointFeedback> feedback_;  // per contact joint: pair p owns [p * cap, (p+1) * cap)
  std::vector<int> joints_made_;   // per pair: contact joints made this step
  std::size_t feedback_per_pair_ = 0;
  std::vector<double> angle_rad_;  // continuous angles, per body
  std::vector<Vec2> force_n_;      // inject mode: total force per body this step, N
  std::vector<double> torque_nm_;  // inject mode: about the centre of mass, N m
  EpisodeTracker tracker_;
  bool inject_ = false;
  bool oracle_ = false;
  bool quick_ = false;
  bool corrected_ = true;
  long probe_steps_ = 0;  // ODE steps taken during build (the oracle's probe run)
  // native mode: contact rows whose corrected damping did not hold (c < h k),
  // and the largest h k / c seen
  long rows_correction_invalid_ = 0;
  long rows_made_ = 0;
  double worst_hk_over_c_ = 0.0;
  double step_s_ = 1e-4;
  int substeps_ = 1;
  long steps_ = 0;
  std::string diverged_;  // non-empty once a body blew up
  nlohmann::json mapping_ = nlohmann::json::object();
  nlohmann::json extra_ = nlohmann::json::object();
  // ODE's non-fatal messages during this run's steps (ode_library.hpp)
  long messages_seen_ = 0;
  long messages_mark_ = 0;  // the thread's count when last looked at
  std::string first_message_;
};

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
      "ODE's own colliders (dSpaceCollide, near callback, dCollide) on spheres, convex prisms and "
      "planes";
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
  quick_ = settings_.stepper == "quick";
  corrected_ = settings_.damping_mapping == "corrected";
  steps_ = 0;
  probe_steps_ = 0;
  rows_correction_invalid_ = 0;
  rows_made_ = 0;
  worst_hk_over_c_ = 0.0;
  diverged_.clear();
  tracker_ = EpisodeTracker{};
  world_.reset();
  collider_.reset();
  messages_seen_ = 0;
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
  collider_ = std::make_unique<PairCollider>(case_, *world_);
  const std::size_t pairs = case_.contacts.size();
  track_.assign(pairs, PairTrack{});
  feedback_per_pair_ = oracle_ ? 1 : static_cast<std::size_t>(collider_->capacity());
  feedback_.assign(pairs * feedback_per_pair_, dJointFeedback{});
  joints_made_.assign(pairs, 0);
  now_.assign(pairs, PairContact{});
  angle_rad_.clear();
  force_n_.assign(case_.bodies.size(), Vec2::Zero());
  torque_nm_.assign(case_.bodies.size(), 0.0);
  for (int i = 0; i < world_->body_count(); ++i)
    angle_rad_.push_back(case_.bodies[static_cast<std::size_t>(i)].angle_rad);

  // what the bodies became
  nlohmann::json bodies = nlohmann::json::array();
  for (std::size_t i = 0; i < case_.bodies.size(); ++i) {
    const Body& b = case_.bodies[i];
    std::string held = "fixed: a static geom without body";
    if (!b.fixed) {
      held =
          "Plane2D joint keeps z = 0; the orientation's drift is reset to a pure z rotation "
          "after every step";
      for (const RevoluteJoint& j : case_.joints) {
        if (j.body == static_cast<int>(i)) {
          held = fmt::format("hinge to the world about z through ({}, {}) m (no Plane2D needed)",
                             j.anchor_world_m.x(), j.anchor_world_m.y());
        }
      }
    }
    nlohmann::json jb = {{"body", b.name},
                         {"geom", world_->geom_description(static_cast<int>(i))},
                         {"constraint", held}};
    if (!b.fixed) {
      jb["mass"] = fmt::format(
          "dMassSetParameters: m = {} kg, centre of mass at the body origin, "
          "I_xx = I_yy = I_zz = {} kg m^2 (the case's planar inertia; the "
          "out-of-plane entries never act)",
          b.mass_kg, b.inertia_kgm2);
    }
    bodies.push_back(jb);
  }
  mapping_["bodies"] = bodies;
  mapping_["frame"] =
      "case x-y plane = ODE x-y plane at z = 0; case angle = rotation about +z, counter-clockwise; "
      "quaternion (cos a/2, 0, 0, sin a/2)";
  mapping_["world"] = {{"gravity_mps2", {case_.gravity_mps2.x(), case_.gravity_mps2.y(), 0.0}},
                       {"joint_erp", dWorldGetERP(world_->world())},
                       {"joint_cfm", dWorldGetCFM(world_->world())},
                       {"contact_surface_layer_m", 0.0},
                       {"contact_max_correcting_vel", "infinity"},
                       {"auto_disable", false}};
  mapping_["stepper"] =
      quick_ ? fmt::format(
                   "dWorldQuickStep, {} iterations; dRandSetSeed(step index) before each "
                   "step under a process-wide lock (ODE's row-order seed is global)",
                   settings_.quick_iterations)
             : std::string("dWorldStep (direct LCP solver, deterministic)");

  probe_steps_ = internal::ode::world_steps_on_this_thread() - steps_at_start;

  // the state at t = 0; contacts that start penetrated store elastic
  // energy, which the runaway bounds allow for
  sample_contacts();
  double elastic_j = 0.0;
  for (std::size_t p = 0; p < now_.size(); ++p) {
    if (now_[p].touching) elastic_j += elastic_energy_j(case_.contacts[p].law, now_[p].depth_m);
  }
  world_->set_initial_contact_energy(elastic_j);
}

// oracle: the mapping of every pair from the probe run, the step, and
// mapping_["contacts"]
void OdeEngine::map_contacts_oracle(const std::vector<FirstTouch>& touches) {
  const bool corrected = settings_.damping_mapping == "corrected";
  std::vector<LinearLaw> linear(case_.contacts.size());
  std::vector<double> m_eff(case_.contacts.size(), 0.0);
  std::vector<std::string> m_eff_how(case_.contacts.size());
  std::vector<internal::ode::StepNeed> needs;

  for (std::size_t p = 0; p < case_.contacts.size(); ++p) {
    const ContactPair& pair = case_.contacts[p];
    const FirstTouch& t = touches[p];
    if (t.found) {
      m_eff[p] = internal::ode::effective_mass_kg(case_, pair, t.centres_m, t.point_m, t.normal_ab);
      m_eff_how[p] = fmt::format(
          "1 / (J M^-1 J^T) along the normal at the first touch of a contact-free probe run "
          "(same ODE model, dWorldStep at dt), t = {} s",
          t.time_s);
    } else {
      // no touch without contact forces: translation only, at the start
      double w = 0.0;
      for (const int bi : {pair.body_a, pair.body_b}) {
        const Body& b = case_.bodies[static_cast<std::size_t>(bi)];
        if (!b.fixed) w += 1.0 / b.mass_kg;
      }
      m_eff[p] = w > 0.0 ? 1.0 / w : std::numeric_limits<double>::infinity();
      m_eff_how[p] =
          "no touch in the contact-free probe run: 1 / sum(1/m) of the moving bodies "
          "(translation only)";
    }
    if (!std::isfinite(m_eff[p])) continue;  // neither body can move along the normal
    linear[p] = internal::ode::linear_law(pair.law, m_eff[p], t.found ? t.approach_speed_mps : 0.0);
    const CollisionResponse& r = linear[p].linear_response;
    needs.push_back({linear[p].stiffness_n_per_m, linear[p].damping_ns_per_m, r.force_duration_s});
  }

  // the step: dt / substeps
  if (settings_.substeps > 0) {
    substeps_ = settings_.substeps;
  } else {
    substeps_ = internal::ode::auto_substeps(settings_.dt_s, needs, settings_.contact_steps,
                                             corrected);
  }
  step_s_ = settings_.dt_s / substeps_;

  soft_.assign(case_.contacts.size(), SoftContact{});
  nlohmann::json pairs = nlohmann::json::array();
  for (std::size_t p = 0; p < case_.contacts.size(); ++p) {
    const ContactPair& pair = case_.contacts[p];
    const FirstTouch& t = touches[p];
    nlohmann::json jp = {
        {"pair", pair.name},
        {"body_a", case_.bodies[static_cast<std::size_t>(pair.body_a)].name},
        {"body_b", case_.bodies[static_cast<std::size_t>(pair.body_b)].name},
        {"case_law", law_json(pair.law)},
        {"threshold",
         fmt::format("not expressed: ODE reports a contact from depth >= 0 (case threshold {} m)",
                     pair.threshold_m)}};
    jp["expected_contact"] = {{"found", t.found}};
    if (t.found) {
      jp["expected_contact"]["time_s"] = t.time_s;
      jp["expected_contact"]["point_m"] = vec_json(t.point_m);
      jp["expected_contact"]["normal"] = vec_json(t.normal_ab);
      jp["expected_contact"]["approach_speed_mps"] = t.approach_speed_mps;
    }
    jp["expected_contact"]["how"] =
        "first step at which dCollide reports the pair in a contact-free probe run of the same "
        "ODE model (dWorldStep at dt); the approach speed is the normal relative speed there";
    jp["effective_mass_kg"] = m_eff[p];
    jp["effective_mass_how"] = m_eff_how[p];
    if (!std::isfinite(m_eff[p])) {
      jp["expressed_as"] = "nothing: neither body can move along the contact normal";
      pairs.push_back(jp);
      continue;
    }
    const LinearLaw& lin = linear[p];
    {
      soft_[p] = internal::ode::soft_contact(lin.stiffness_n_per_m, lin.damping_ns_per_m, step_s_,
                                             corrected);
      jp["expressed_as"] = fmt::format(
          "ODE contact joint, one per pair (the deepest of dCollide's contacts), mode = "
          "dContactSoftERP | dContactSoftCFM, {}, no dContactBounce; the "
          "contact row's lambda >= 0 is the clamp F >= 0",
          pair.has_friction() ? "mu: Coulomb (friction)" : "mu = 0 (frictionless)");
      jp["linear_law"] = {{"stiffness_n_per_m", lin.stiffness_n_per_m},
                          {"damping_ns_per_m", lin.damping_ns_per_m},
                          {"exact", lin.exact},
                          {"how", lin.how},
                          {"mass_kg", lin.mass_kg},
                          {"approach_speed_mps", lin.approach_speed_mps},
                          {"law_response", response_json(lin.law_response)},
                          {"linear_response", response_json(lin.linear_response)}};
      jp["soft_contact"] = {{"damping_mapping", settings_.damping_mapping},
                            {"step_s", step_s_},
                            {"erp", soft_[p].erp},
                            {"cfm_m_per_ns", soft_[p].cfm},
                            {"damping_used_ns_per_m", soft_[p].damping_used_ns_per_m},
                            {"numerical_damping_hk_ns_per_m", soft_[p].numerical_damping_ns_per_m},
                            {"correction_valid", soft_[p].correction_valid},
                            {"note", soft_[p].note}};
      jp["not_expressed"] = not_expressed_native(pair.law);
    }
    if (pair.has_friction()) jp["friction"] = internal::ode::friction_mapping(pair.friction);
    pairs.push_back(jp);
  }

  mapping_ = nlohmann::json::object();
  mapping_["engine"] = "ode";
  mapping_["mode"] = settings_.mode;
  mapping_["dt_s"] = settings_.dt_s;
  mapping_["substeps"] = substeps_;
  mapping_["step_s"] = step_s_;
  mapping_["substeps_how"] =
      settings_.substeps > 0
          ? std::string("set by ode.substeps")
          : fmt::format(
                "auto: smallest n with at least {} steps over each pair's first-impact "
                "force phase{}",
                settings_.contact_steps,
                corrected ? " and h k <= c (corrected mapping valid)" : "");
  mapping_["contacts"] = pairs;
  mapping_["integrator"] =
      "ODE's semi-implicit Euler (velocity first, then position with the new velocity): "
      "positions under constant acceleration lead the exact parabola by g h t / 2; orientation "
      "by ODE's default infinitesimal update, 2 atan(omega h / 2) per step instead of omega h";
  mapping_["collision"] =
      "dSimpleSpace + dSpaceCollide; the near callback keeps the case's contact pairs only and "
      "calls dCollide; of its contacts the deepest one is kept (a prism reports each vertex on "
      "both faces, and several soft contacts would add their springs)";
  add_common_mapping();
  extra_ = {{"step_s", step_s_},
            {"substeps", substeps_},
            {"ode_configuration", internal::ode::ode_configuration()},
            {"ode_pkgconfig_version", internal::ode::ode_pkgconfig_version()}};
}

// native and inject: the rule of every pair (no probe: nothing is known of
// the run's future), and mapping_["contacts"]
void OdeEngine::map_contacts_native() {
  nlohmann::json pairs = nlohmann::json::array();
  for (const ContactPair& pair : case_.contacts) {
    nlohmann::json jp = {
        {"pair", pair.name},
        {"body_a", case_.bodies[static_cast<std::size_t>(pair.body_a)].name},
        {"body_b", case_.bodies[static_cast<std::size_t>(pair.body_b)].name},
        {"case_law", law_json(pair.law)},
        {"threshold",
         fmt::format("not expressed: ODE reports a contact from depth >= 0 (case threshold {} m)",
                     pair.threshold_m)}};
    if (inject_) {
      jp["expressed_as"] =
          "no ODE contact joint: the case's law (contact_force_n) evaluated every step at the "
          "pair's penetration (its deepest contact) and applied with dBodyAddForceAtPos at the "
          "depth-weighted centroid of its contacts along the deepest contact's normal, equal and "
          "opposite; Lankarani-Nikravesh latches delta_dot at onset";
      jp["not_expressed"] = nlohmann::json::array(
          {"the force is explicit over each step (semi-implicit Euler of ODE's integrator)"});
    } else {
      jp["expressed_as"] = fmt::format(
          "every contact dCollide reports for the pair (every convex piece of either body) is an "
          "ODE contact joint, mode = dContactSoftERP | dContactSoftCFM, {}, no "
          "dContactBounce; the row's lambda >= 0 is the clamp F >= 0",
          pair.has_friction() ? "mu: Coulomb (friction)" : "mu = 0 (frictionless)");
      jp["law_per_step"] = fmt::format(
          "each step, in the near callback's pass: delta = the deepest contact's depth, "
          "(k, c) = the law at delta as a linear spring-damper ({}); contact i (depth d_i) gets "
          "k_i = k delta / sum d_j and c_i = c d_i / sum d_j, so the rows' springs sum to "
          "k delta and their dampers to c, both at the depth-weighted centroid of the contacts "
          "(SPEC §1, one force per pair)",
          std::holds_alternative<KelvinVoigt>(pair.law)
              ? "Kelvin-Voigt: its own K and c (c times the ramp's cubic step at delta)"
          : std::holds_alternative<Hertz>(pair.law)
              ? "Hertz: k = K delta^(n-1), c = 0"
              : "Lankarani-Nikravesh: k = K delta^(n-1), c = K delta^n 3 (1 - e^2) / 4 / "
                "delta_dot^-, delta_dot^- the approach speed at the first step with delta > 0");
      nlohmann::json soft = {
          {"rule",
           fmt::format(
               "ERP = h k_i / (h k_i + c'), CFM = 1 / (h k_i + c'), h = {} s, damping_mapping = "
               "{}{}",
               step_s_, settings_.damping_mapping,
               corrected_
                   ? ": c' = c_i - h k_i removes backward Euler's extra damping h k_i while "
                     "c_i >= h k_i; where c_i < h k_i it is clamped at c' = 0 and the contact "
                     "damps like h k_i (counted in damping_correction; for "
                     "Lankarani-Nikravesh c / k = 3 (1 - e^2) delta / (4 delta_dot^-), so this "
                     "holds only once delta >= 4 h delta_dot^- / (3 (1 - e^2)))"
                   : ": backward Euler adds about h k_i of damping")}};
      if (is_plain_kelvin_voigt(pair.law)) {
        // a linear law's numbers for one contact (a sphere on a plane): fixed
        const auto& kv = std::get<KelvinVoigt>(pair.law);
        const SoftContact one =
            internal::ode::soft_contact(kv.stiffness_n_per_m, kv.damping_ns_per_m, step_s_,
                                        corrected_);
        soft["one_contact"] = {{"erp", one.erp},
                               {"cfm_m_per_ns", one.cfm},
                               {"damping_used_ns_per_m", one.damping_used_ns_per_m},
                               {"numerical_damping_hk_ns_per_m", one.numerical_damping_ns_per_m},
                               {"correction_valid", one.correction_valid},
                               {"note", one.note}};
      }
      jp["soft_contact"] = soft;
      nlohmann::json lost = nlohmann::json::array();
      if (!std::holds_alternative<KelvinVoigt>(pair.law)) {
        lost.push_back(
            "within a step the law is linear in delta: the nonlinear stiffness is its secant at "
            "the step's start");
      }
      if (case_.bodies[static_cast<std::size_t>(pair.body_a)].fixed ||
          case_.bodies[static_cast<std::size_t>(pair.body_b)].fixed) {
        // nothing more to say
      }
      jp["not_expressed"] = lost;
      if (pair.has_friction()) jp["friction"] = internal::ode::friction_mapping(pair.friction);
    }
    pairs.push_back(jp);
  }
  mapping_ = nlohmann::json::object();
  mapping_["engine"] = "ode";
  mapping_["mode"] = settings_.mode;
  mapping_["dt_s"] = settings_.dt_s;
  mapping_["substeps"] = substeps_;
  mapping_["step_s"] = step_s_;
  mapping_["substeps_how"] =
      substeps_ == 1 ? std::string("none: ODE steps at dt, the step given")
                     : fmt::format("set by ode.substeps: {} steps per dt", substeps_);
  mapping_["contacts"] = pairs;
  mapping_["collision"] =
      "dSimpleSpace + dSpaceCollide; the near callback keeps the case's contact pairs only and "
      "calls dCollide on each pair of their geoms (convex pieces); one contact is kept per "
      "point of the plane (a prism reports each vertex on both faces, and a vertex two convex "
      "pieces share once per piece: ode_pair_contact.cpp), the law spread over their depths";
  add_common_mapping();
  extra_ = {{"step_s", step_s_},
            {"substeps", substeps_},
            {"ode_configuration", internal::ode::ode_configuration()},
            {"ode_pkgconfig_version", internal::ode::ode_pkgconfig_version()}};
}

void OdeEngine::add_common_mapping() {
  mapping_["integrator"] =
      "ODE's semi-implicit Euler (velocity first, then position with the new velocity): "
      "positions under constant acceleration lead the exact parabola by g h t / 2; orientation "
      "by ODE's default infinitesimal update, 2 atan(omega h / 2) per step instead of omega h";
  mapping_["contact_point"] =
      "midpoint of the two geoms' deepest points: ODE's pos shifted by depth/2 along the normal "
      "(sphere-plane, sphere-convex, convex-plane); sphere-sphere pos is the midpoint already; "
      "with several contacts, their depth-weighted centroid";
}

nlohmann::json OdeEngine::extra_attributes() const {
  nlohmann::json x = extra_;
  if (messages_seen_ > 0) {
    x["ode_messages_noted"] = {
        {"count", messages_seen_},
        {"example", first_message_},
        {"note", "ODE's non-fatal dMessage calls during the run's steps, counted instead of "
                 "printed"}};
  }
  return x;
}

nlohmann::json OdeEngine::mapping() const {
  nlohmann::json m = mapping_;
  if (!oracle_ && !inject_ && m.is_object()) {
    m["damping_correction"] = {
        {"what",
         "contact rows of this run whose corrected damping mapping did not hold (c_i < h k_i): "
         "there ODE's implicit soft contact damps like h k_i instead of c_i"},
        {"rows", rows_made_},
        {"rows_invalid", rows_correction_invalid_},
        {"worst_hk_over_c", worst_hk_over_c_}};
  }
  return m;
}

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
  for (std::size_t p = 0; p < now_.size(); ++p) {
    const PairContact& pc = now_[p];
    const double f = track_[p].force_n;  // N
    if (!pc.touching) continue;
    if (!std::isfinite(f)) {
      diverged_ = fmt::format("ode: the contact force of '{}' is not finite at t = {:.9g} s",
                              case_.contacts[p].name, time());
      return true;
    }
    if (!(f > 0.0)) continue;
    // body b is pushed along n_ab, body a against it; torque r x F about each centre
    const ContactPair& pair = case_.contacts[p];
    for (const auto& [i, sign] : {std::pair{pair.body_b, 1.0}, std::pair{pair.body_a, -1.0}}) {
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

// native: every contact of pair p a soft joint, the law spread over them
// (ode_contact_mapping.hpp, spread_law)
void OdeEngine::add_native_joints(std::size_t p) {
  const PairContact& pc = now_[p];
  const LinearizedLaw lin =
      linearize_law(case_.contacts[p].law, pc.depth_m, track_[p].latched_approach_mps);
  if (!(lin.stiffness_n_per_m > 0.0)) return;  // nothing pressed in: no force
  for (int i = 0; i < pc.count; ++i) {
    const dContactGeom& g = pc.geoms[static_cast<std::size_t>(i)];
    if (!(g.depth > 0.0)) continue;  // a touching contact carries no spring
    const internal::ode::SpreadLaw row_law = internal::ode::spread_law(
        lin.stiffness_n_per_m, lin.damping_ns_per_m, pc.depth_m, g.depth, pc.depth_sum_m);
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
    internal::ode::add_coulomb_friction(contact, case_.contacts[p].friction);
    const dJointID j = dJointCreateContact(world_->world(), world_->contact_group(), &contact);
    dJointAttach(j, dGeomGetBody(g.g1), dGeomGetBody(g.g2));
    auto& n = joints_made_[p];
    dJointSetFeedback(j, &feedback_[p * feedback_per_pair_ + static_cast<std::size_t>(n)]);
    ++n;
    ++rows_made_;
  }
}

// oracle: the deepest contact of pair p, with the calibrated soft contact
void OdeEngine::add_oracle_joint(std::size_t p) {
  const dContactGeom& g = now_[p].geoms[static_cast<std::size_t>(now_[p].deepest)];
  dContact contact{};
  contact.surface.mode = dContactSoftERP | dContactSoftCFM;
  contact.surface.mu = 0.0;
  contact.surface.soft_erp = soft_[p].erp;
  contact.surface.soft_cfm = soft_[p].cfm;
  contact.geom = g;
  internal::ode::add_coulomb_friction(contact, case_.contacts[p].friction);
  const dJointID j = dJointCreateContact(world_->world(), world_->contact_group(), &contact);
  dJointAttach(j, dGeomGetBody(g.g1), dGeomGetBody(g.g2));
  dJointSetFeedback(j, &feedback_[p * feedback_per_pair_]);
  joints_made_[p] = 1;
}

void OdeEngine::step_once() {
  const std::size_t pairs = now_.size();
  if (inject_ && injected_forces_run_away()) return;
  // contact forces of this step, from the contacts at the current state
  for (std::size_t p = 0; p < pairs; ++p) {
    joints_made_[p] = 0;
    const PairContact& pc = now_[p];
    if (!pc.touching) continue;
    if (inject_) {
      const double f = track_[p].force_n;  // N, the law at the current state
      if (!(f > 0.0)) continue;
      // body b is pushed along n_ab, body a the other way, at the pair's point
      const ContactPair& pair = case_.contacts[p];
      const Vec2 at = pc.point_m;
      if (const dBodyID b = world_->body(pair.body_b); b != nullptr) {
        dBodyAddForceAtPos(b, f * pc.normal_ab.x(), f * pc.normal_ab.y(), 0.0, at.x(), at.y(), 0.0);
      }
      if (const dBodyID a = world_->body(pair.body_a); a != nullptr) {
        dBodyAddForceAtPos(a, -f * pc.normal_ab.x(), -f * pc.normal_ab.y(), 0.0, at.x(), at.y(),
                           0.0);
      }
    } else if (oracle_) {
      add_oracle_joint(p);
    } else {
      add_native_joints(p);
    }
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
  // the world-frame force on g1's body, the normal points into g1
  if (!inject_) {
    for (std::size_t p = 0; p < pairs; ++p) {
      double f = 0.0;  // N
      for (int i = 0; i < joints_made_[p]; ++i) {
        const dJointFeedback& fb = feedback_[p * feedback_per_pair_ + static_cast<std::size_t>(i)];
        const int k = oracle_ ? now_[p].deepest : i;
        const dReal* n = now_[p].geoms[static_cast<std::size_t>(k)].normal;
        f += std::max(0.0, fb.f1[0] * n[0] + fb.f1[1] * n[1] + fb.f1[2] * n[2]);
      }
      track_[p].force_n = f;
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
  const double t = time();
  for (std::size_t p = 0; p < now_.size(); ++p) {
    const PairContact& pc = now_[p];
    PairTrack& tr = track_[p];
    const ContactPair& pair = case_.contacts[p];
    const bool in = pc.touching && pc.depth_m > 0.0;
    // eq. 7's delta_dot^-: the approach speed at the first sample with delta > 0
    if (in && !tr.in_contact) tr.latched_approach_mps = std::max(pc.approach_speed_mps, 0.0);
    if (inject_) {
      tr.force_n = pc.touching ? contact_force_n(pair.law, pc.depth_m, pc.approach_speed_mps,
                                                 tr.latched_approach_mps)
                               : 0.0;
    }
    if (in) {
      if (!tr.in_contact && steps_ > 0) {
        // the step before: not in contact; its penetration is estimated from
        // this one and the approach speed so that the onset is interpolated
        tracker_.observe(t - step_s_, pair.body_a, pair.body_b,
                         std::min(0.0, pc.depth_m - step_s_ * pc.approach_speed_mps),
                         pc.approach_speed_mps, 0.0);
      }
      tracker_.observe(t, pair.body_a, pair.body_b, pc.depth_m, pc.approach_speed_mps, tr.force_n);
      tr.depth_m = pc.depth_m;
      tr.speed_mps = pc.approach_speed_mps;
      tr.normal_ab = pc.normal_ab;
      tr.point_m = pc.point_m;
    } else if (tr.in_contact) {
      // separated during the last step: ODE gives no distance, so estimate
      // the (non-positive) penetration from the last one and the speeds
      const double s = internal::ode::approach_speed_mps(*world_, pair, tr.point_m, tr.normal_ab);
      const double d = std::min(0.0, tr.depth_m + 0.5 * step_s_ * (tr.speed_mps + s));
      tracker_.observe(t, pair.body_a, pair.body_b, d, s, tr.force_n);
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
  for (std::size_t p = 0; p < now_.size(); ++p) {
    const PairContact& pc = now_[p];
    if (!(pc.touching && pc.depth_m > 0.0)) continue;
    ContactSample s;
    s.body_a = case_.contacts[p].body_a;
    s.body_b = case_.contacts[p].body_b;
    s.force_n = track_[p].force_n;
    s.penetration_m = pc.depth_m;
    s.normal = pc.normal_ab;
    s.point_m = pc.point_m;
    out.push_back(s);
  }
}

}  // namespace

std::unique_ptr<Engine> make_ode_engine() {
  return std::make_unique<OdeEngine>();
}

}  // namespace pb
