// What an ODE run records about its mapping (Engine::mapping(), extra
// attributes): how each contact pair's law became ODE soft contacts in the
// run's mode, its ERP/CFM rule, what it could not express. Members of the
// engine class (ode_engine_impl.hpp); ode_engine.cpp builds and steps it.
#include <fmt/format.h>

#include <variant>
#include <vector>

#include "ode_engine_impl.hpp"
#include "ode_friction.hpp"
#include "ode_library.hpp"
#include "planarbench/contact_law_response.hpp"

namespace pb::internal::ode {

namespace {

nlohmann::json vec_json(const Vec2& v) {
  return nlohmann::json::array({v.x(), v.y()});
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
    if (ln.damping_factor) j["damping_factor"] = *ln.damping_factor;  // issue 34's laws only
  }
  return j;
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

}  // namespace

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
                          {"law_response", to_json(lin.law_response)},
                          {"linear_response", to_json(lin.linear_response)}};
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

  start_mapping();
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
      "dCollide called directly on each declared pair's geoms (no space traversal); of its "
      "contacts the deepest one is kept (a prism reports each vertex on both faces, and several "
      "soft contacts would add their springs)";
  add_common_mapping();
}

// native and inject: how one rule's law (a declared pair's or a group's)
// becomes ODE contacts
nlohmann::json OdeEngine::native_rule_json(const ContactLaw& law, double friction) const {
  nlohmann::json jp = nlohmann::json::object();
  if (inject_) {
    jp["expressed_as"] =
        "no ODE contact joint: the case's law (contact_force_n) evaluated every step at the "
        "pair's penetration (its deepest contact) and applied with dBodyAddForceAtPos at the "
        "depth-weighted centroid of its contacts along the deepest contact's normal, equal and "
        "opposite; Lankarani-Nikravesh latches delta_dot at onset";
    jp["not_expressed"] = nlohmann::json::array(
        {"the force is explicit over each step (semi-implicit Euler of ODE's integrator)"});
    return jp;
  }
  jp["expressed_as"] = fmt::format(
      "every contact dCollide reports for the pair (every convex piece of either body) is an "
      "ODE contact joint, mode = dContactSoftERP | dContactSoftCFM, {}, no "
      "dContactBounce; the row's lambda >= 0 is the clamp F >= 0",
      friction > 0.0 ? "mu: Coulomb (friction)" : "mu = 0 (frictionless)");
  jp["law_per_step"] = fmt::format(
      "each step, from the contacts dCollide reported at the state: delta = the deepest "
      "contact's depth, (k, c) = the law at delta as a linear spring-damper ({}); contact i "
      "(depth d_i) gets k_i = k delta / sum d_j and c_i = c d_i / sum d_j, so the rows' springs "
      "sum to k delta and their dampers to c, both at the depth-weighted centroid of the "
      "contacts (SPEC §1, one force per pair)",
      std::holds_alternative<KelvinVoigt>(law)
          ? "Kelvin-Voigt: its own K and c (c times the ramp's cubic step at delta)"
      : std::holds_alternative<Hertz>(law)
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
  if (is_plain_kelvin_voigt(law)) {
    // a linear law's numbers for one contact (a sphere on a plane): fixed
    const auto& kv = std::get<KelvinVoigt>(law);
    const SoftContact one = internal::ode::soft_contact(kv.stiffness_n_per_m, kv.damping_ns_per_m,
                                                        step_s_, corrected_);
    soft["one_contact"] = {{"erp", one.erp},
                           {"cfm_m_per_ns", one.cfm},
                           {"damping_used_ns_per_m", one.damping_used_ns_per_m},
                           {"numerical_damping_hk_ns_per_m", one.numerical_damping_ns_per_m},
                           {"correction_valid", one.correction_valid},
                           {"note", one.note}};
  }
  jp["soft_contact"] = soft;
  nlohmann::json lost = nlohmann::json::array();
  if (!std::holds_alternative<KelvinVoigt>(law)) {
    lost.push_back(
        "within a step the law is linear in delta: the nonlinear stiffness is its secant at "
        "the step's start");
  }
  jp["not_expressed"] = lost;
  if (friction > 0.0) {
    jp["friction"] = internal::ode::friction_mapping(friction);
    jp["friction"]["face_rows"] =
        "with friction every pressed row of the pair takes the implicit damping c / n (n rows: "
        "one CFM for all, so dWorldStep's friction bounds follow the spread law's shares) and "
        "the rest of its share, c_i - c / n, as a force applied before the step along its "
        "normal from its separation speed (ode_contact_mapping.hpp, face_row)";
  }
  return jp;
}

// native and inject: the rule of every declared pair and every contact group
// (no probe: nothing is known of the run's future), and mapping_["contacts"]
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
    jp.update(native_rule_json(pair.law, pair.friction));
    pairs.push_back(jp);
  }
  start_mapping();
  mapping_["substeps_how"] =
      substeps_ == 1 ? std::string("none: ODE steps at dt, the step given")
                     : fmt::format("set by ode.substeps: {} steps per dt", substeps_);
  mapping_["contacts"] = pairs;
  if (case_.has_contact_groups()) {
    nlohmann::json groups = nlohmann::json::array();
    for (const ContactGroup& g : case_.contact_groups) {
      nlohmann::json jg = {
          {"group", g.name},
          {"bodies", g.bodies.size()},
          {"case_law", law_json(g.law)},
          {"threshold",
           fmt::format("not expressed: ODE reports a contact from depth >= 0 (case threshold {} m)",
                       g.threshold_m)}};
      jg.update(native_rule_json(g.law, g.friction));
      groups.push_back(jg);
    }
    mapping_["contact_groups"] = groups;
  }
  add_common_mapping();
}

// native and inject: how ODE finds the contacts (needs the world: a
// scene's hash levels)
std::string OdeEngine::collision_text() const {
  if (case_.has_contact_groups()) {
    return fmt::format(
        "ODE's broad phase: every geom in one dSweepAndPruneSpace sorted along {} (the axis "
        "the moving bodies spread over most at the start; planes, infinite boxes, are tested "
        "against every geom), each geom's category and collide bits = its body's groups "
        "(bit g % 63) and bit 63 for a body of a declared pair; dSpaceCollide calls the near "
        "callback for the geom pairs whose boxes overlap, which skips two fixed bodies and the "
        "pairs no rule lets touch (ContactPairs::may_touch), calls dCollide (g1 the moving "
        "geom, else the lower body's), and registers the pair (ContactPairs::find_or_add) when "
        "ODE reports a contact; one contact is kept per point of the plane "
        "(ode_pair_contact.cpp), the law spread over their depths; the joints are made in "
        "ascending pair index",
        world_->sweep_axes());
  }
  return "dCollide called directly on each declared pair's geoms, every convex piece of one "
         "body against every piece of the other, in the case's pair order (no space traversal: "
         "the geoms sit in a dSimpleSpace never collided); one contact is kept per point of the "
         "plane (a prism reports each vertex on both faces, and a vertex two convex pieces share "
         "once per piece: ode_pair_contact.cpp), the law spread over their depths";
}

// what the bodies became; a [[generate]] set is one entry (its bodies share
// shape, mass and constraint; a 1000-body scene's mapping stays short)
nlohmann::json OdeEngine::bodies_json() const {
  std::vector<int> set_of(case_.bodies.size(), -1);
  for (std::size_t g = 0; g < case_.generated.size(); ++g) {
    const GeneratedBodies& gen = case_.generated[g];
    for (int k = 0; k < gen.count; ++k) {
      set_of[static_cast<std::size_t>(gen.body(k))] = static_cast<int>(g);
    }
  }
  nlohmann::json bodies = nlohmann::json::array();
  for (std::size_t i = 0; i < case_.bodies.size(); ++i) {
    const Body& b = case_.bodies[i];
    std::string name = b.name;
    if (set_of[i] >= 0) {
      const GeneratedBodies& gen = case_.generated[static_cast<std::size_t>(set_of[i])];
      if (static_cast<int>(i) != gen.first_body) continue;
      name = fmt::format("{} .. {} ({} generated)", b.name,
                         case_.bodies[static_cast<std::size_t>(gen.body(gen.count - 1))].name,
                         gen.count);
    }
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
    nlohmann::json jb = {{"body", name},
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
  return bodies;
}

void OdeEngine::start_mapping() {
  mapping_ = nlohmann::json::object();
  mapping_["engine"] = "ode";
  mapping_["mode"] = settings_.mode;
  mapping_["dt_s"] = settings_.dt_s;
  mapping_["substeps"] = substeps_;
  mapping_["step_s"] = step_s_;
}

void OdeEngine::add_common_mapping() {
  extra_ = {{"step_s", step_s_},
            {"substeps", substeps_},
            {"ode_configuration", internal::ode::ode_configuration()},
            {"ode_pkgconfig_version", internal::ode::ode_pkgconfig_version()}};
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
  x["stepper"] = quick_ ? "dWorldQuickStep" : "dWorldStep";
  if (case_.has_contact_groups() && pairs_) {
    // the pairs ODE's broad phase reported a contact for (per-pair state
    // grows with these), of the n (n - 1) / 2 a group could form
    x["pairs_registered"] = pairs_->size();
  }
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

}  // namespace pb::internal::ode
