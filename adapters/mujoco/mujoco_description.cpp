#include "mujoco_description.hpp"

#include <fmt/format.h>

#include "mujoco_geometry.hpp"
#include "planarbench/contact_force.hpp"

namespace pb::internal::mujoco {

nlohmann::json native_pair_json(const ContactLaw& law) {
  nlohmann::json j;
  j["law"] = contact_law_name(law);
  j["expressed_as"] =
      "MuJoCo's soft contact on every contact MuJoCo's collider reports for the pair, one "
      "direct solref for the pair set at every evaluation of the dynamics (after mj_collision, "
      "before mj_makeConstraint) from the state the step starts from";
  j["solref_rule"] =
      "solref = (-sigma k, -c) / m_set: (k, c) the law at the pair's penetration delta (its "
      "deepest contact) as a linear spring-damper; m_set = 1^T A^+ 1 with A = J M^-1 J^T of the "
      "pair's pressed contacts from MuJoCo's mj_jac and mj_solveM (one contact: "
      "1 / (J M^-1 J^T)); sigma = delta / delta_w, delta_w = w^T r / m_set, w = A^+ 1, so that "
      "the rows' springs sum to k delta (SPEC §1, one force per pair) and their dampers to c "
      "times the rows' w-weighted mean normal speed; before it, a contact that two convex "
      "pieces of one body report at one point (a vertex they share) is fused into the first "
      "(exclude = 2, MuJoCo's flag for a fused contact): one row per point";
  if (const auto* kv = std::get_if<KelvinVoigt>(&law)) {
    j["law_as_spring_damper"] =
        kv->damping_depth_m > 0.0
            ? "Kelvin-Voigt: k = K, c = c times the ramp's cubic step at delta"
            : "Kelvin-Voigt: k = K, c = c (exact: the law is a linear spring-damper)";
  } else if (std::holds_alternative<Hertz>(law)) {
    j["law_as_spring_damper"] = "Hertz: k = K delta^(n-1) (secant at delta), c = 0";
  } else {
    j["law_as_spring_damper"] =
        "Lankarani-Nikravesh: k = K delta^(n-1) (secant at delta), c = K delta^n 3 (1 - e^2) / 4 "
        "/ delta_dot^-, delta_dot^- the normal approach speed at the pair's first step pressed";
  }
  return j;
}

void add_soft_contact_notes(double d, nlohmann::json& lost) {
  lost.push_back(fmt::format(
      "MuJoCo's soft contact with impedance d = {}: the constraint acceleration is "
      "(1 - d) a0 - b v - k r (a0: acceleration without the contact), so inside a contact "
      "the share d of gravity is removed from the contact's own dynamics: a resting contact "
      "carries m g at a penetration (1 - d) m g / k (~0) instead of m g / k, and an impact "
      "runs as the spring-damper without gravity (the clamp releases at k delta + c "
      "delta_dot = -d m_eff a0.n instead of 0)",
      d));
  lost.push_back(
      "the reported force is MuJoCo's constraint force: m_eff (k delta + c delta_dot) plus "
      "the share d of the normal load of gravity");
}

nlohmann::json describe_bodies(const Case& case_, const MujocoPlan& plan_) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t i = 0; i < case_.bodies.size(); ++i) {
    const Body& b = case_.bodies[i];
    const GeomType g = plan_.bodies[i].geom;
    nlohmann::json j = {
        {"name", b.name}, {"shape", shape_type_name(b.shape)}, {"geom", geom_type_name(g)}};
    if (const auto* e = std::get_if<Ellipse>(&b.shape)) {
      const auto s = ellipsoid_size_m(*e);
      j["ellipsoid_semi_axes_m"] = {s[0], s[1], s[2]};
      j["note"] = "third (out-of-plane) semi-axis min(a, b); its section y = 0 is the ellipse";
    } else if (std::holds_alternative<Polygon>(b.shape)) {
      j["geoms"] = plan_.bodies[i].geom_count();
      if (plan_.bodies[i].decomposed) j["decomposition"] = plan_.bodies[i].decomposition;
      j["note"] =
          "convex mesh: a bipyramid whose section y = 0 is the polygon; MuJoCo stores mesh "
          "vertices in single precision (mjModel::mesh_vert is float): ~6e-8 relative";
    } else if (std::holds_alternative<Circle>(b.shape)) {
      j["note"] = "sphere: one contact point (a cylinder would give two)";
    }
    if (b.fixed) {
      j["joints"] = "none: a geom of the world body";
    } else {
      j["joints"] = plan_.bodies[i].joint >= 0
                        ? "hinge about +y at the pivot"
                        : "slide x, slide z, hinge about +y through the centre of mass";
      j["inertial"] = fmt::format(
          "explicit: mass {} kg, diaginertia ({}, {}, {}) kg m^2 (about y: the case's planar "
          "inertia; x, z only need to be valid)",
          b.mass_kg, b.inertia_kgm2, b.inertia_kgm2, b.inertia_kgm2);
    }
    out.push_back(j);
  }
  return out;
}

nlohmann::json describe_groups(const Case& c, const MujocoPlan& plan,
                               const std::vector<double>& solimp, nlohmann::json& lost,
                               MujocoLine line) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t g = 0; g < c.contact_groups.size(); ++g) {
    const ContactGroup& group = c.contact_groups[g];
    const GroupPlan& gp = plan.groups[g];
    nlohmann::json j = native_pair_json(group.law);
    j["name"] = group.name;
    j["bodies"] = group.bodies.size();
    j["found_by"] =
        "MuJoCo's own broad phase (mj_collision: sweep and prune over the bodies' boxes, then "
        "each geom pair whose contype and conaffinity share a bit, then its collider); each "
        "pair of the group joins the run's pairs when MuJoCo first reports a contact of it";
    j["geoms"] = fmt::format(
        "one copy of each member's geoms with contype = conaffinity = {} (bit {}), condim {}{}, "
        "solref 0 0 (set per contact by the rule), solimp as the pairs', margin = gap as below "
        "(MuJoCo mixes two geoms by max, min and mean: equal attributes give the group's own)",
        1u << gp.bit, gp.bit, gp.condim,
        gp.condim > 1 ? fmt::format(", friction {} {} {} (mu on both tangents)", gp.friction[0],
                                    gp.friction[1], gp.friction[2])
                      : "");
    j["solimp"] = solimp;
    // the margins of the group's geom types (each copy's, GroupPlan)
    nlohmann::json margins = nlohmann::json::object();
    bool mpr = false;
    for (const int i : group.bodies) {
      const BodyPlan& bp = plan.bodies[static_cast<std::size_t>(i)];
      const int copy = bp.copy_of_group(static_cast<int>(g));
      margins[geom_type_name(bp.geom)] = bp.copy_margin_m[static_cast<std::size_t>(copy)];
      mpr = mpr || bp.copy_margin_m[static_cast<std::size_t>(copy)] == 0.0;
    }
    j["margin_m"] = margins;
    if (group.has_friction()) j["friction_coefficient"] = group.friction;
    out.push_back(j);
    if (mpr) {
      lost.push_back(fmt::format(
          "group '{}': geom types that meet an MPR partner in the group get margin 0 (a margin "
          "spoils {}'s depth), so their exact pairs' onsets are resolved to one step",
          group.name, line == MujocoLine::v3 ? "the native convex collider" : "libccd MPR"));
    }
  }
  return out;
}

void describe_pair(const Case& c, const MujocoPlan& plan, std::size_t k, const PairParams& p,
                   bool inject, nlohmann::json& j, nlohmann::json& lost, MujocoLine line) {
  const ContactPair& cp = c.contacts[k];
  const PairPlan& pp = plan.pairs[k];
  j["name"] = cp.name;
  j["body_a"] = c.bodies[static_cast<std::size_t>(cp.body_a)].name;
  j["body_b"] = c.bodies[static_cast<std::size_t>(cp.body_b)].name;
  j["collider"] = collider_description(pp.geom_a, pp.geom_b);
  j["condim"] = pp.condim;
  j["margin_m"] = pp.margin_m;
  j["gap_m"] = p.gap_m;
  if (!inject) j["solimp"] = p.solimp;
  if (pp.collider == Collider::mpr && line == MujocoLine::v3) {
    lost.push_back(fmt::format(
        "pair '{}': penetration from MuJoCo 3's native convex collider (nativeccd, the default "
        "since 3.3.0; 2.2.2 used libccd's MPR), its error against the exact depth in the run's "
        "mpr_depth_check; margin 0, so the onset is resolved to one step",
        cp.name));
  } else if (pp.collider == Collider::mpr) {
    lost.push_back(fmt::format(
        "pair '{}': penetration from libccd MPR, depth error ~1e-6 m (measured 0.8-2.6e-6 m "
        "for a sphere against an ellipsoid at 30-150 um penetration, mpr_tolerance 1e-6); "
        "margin 0, so the onset is resolved to one step",
        cp.name));
  }
}

}  // namespace pb::internal::mujoco
