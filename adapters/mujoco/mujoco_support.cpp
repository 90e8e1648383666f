#include "mujoco_support.hpp"

#include <fmt/format.h>

#include <array>
#include <variant>

#include "mujoco_geometry.hpp"
#include "mujoco_mjcf.hpp"
#include "mujoco_plan.hpp"

namespace pb::internal::mujoco {

namespace {

// the first reason MuJoCo cannot build the case, or empty
std::string unsupported_reason(const Case& c) {
  for (std::size_t i = 0; i < c.bodies.size(); ++i) {
    const Body& b = c.bodies[i];
    if (!b.fixed && std::holds_alternative<HalfPlane>(b.shape)) {
      return fmt::format("body '{}': a moving half-plane (MuJoCo planes must be static)", b.name);
    }
    if (!b.fixed && !(b.mass_kg > 0.0 && b.inertia_kgm2 > 0.0)) {
      return fmt::format("body '{}': a moving body needs mass > 0 and inertia > 0", b.name);
    }
  }
  for (std::size_t k = 0; k < c.joints.size(); ++k) {
    const RevoluteJoint& j = c.joints[k];
    if (j.body < 0 || j.body >= static_cast<int>(c.bodies.size())) {
      return fmt::format("joint '{}': no such body", j.name);
    }
    if (c.bodies[static_cast<std::size_t>(j.body)].fixed) {
      return fmt::format("joint '{}': joined to a fixed body", j.name);
    }
    if (joint_of_body(c, j.body) != static_cast<int>(k)) {
      return fmt::format("joint '{}': a second revolute joint on body '{}' (it would be fixed)",
                         j.name, c.bodies[static_cast<std::size_t>(j.body)].name);
    }
  }
  const int n = static_cast<int>(c.bodies.size());
  for (const ContactPair& cp : c.contacts) {
    if (cp.body_a < 0 || cp.body_a >= n || cp.body_b < 0 || cp.body_b >= n ||
        cp.body_a == cp.body_b) {
      return fmt::format("contact pair '{}': bodies must be two distinct bodies", cp.name);
    }
  }
  return {};
}

}  // namespace

Capability mujoco_capability(const Case& c, const std::string& mode, MujocoLine line) {
  const bool inject = mode == "inject";
  if (auto r = unsupported_reason(c); !r.empty()) return {Support::unsupported, r};
  if (c.has_contact_groups() && mode != "native") {
    return {Support::unsupported,
            fmt::format("contact groups run in native mode only (mode '{}': oracle calibrates each "
                        "declared pair on a probe run, inject applies each declared pair's law)",
                        mode)};
  }
  if (c.contact_groups.size() > static_cast<std::size_t>(kMaxContactGroups)) {
    return {Support::unsupported,
            fmt::format("{} contact groups: MuJoCo has {} collision bits (contype), one per group",
                        c.contact_groups.size(), kMaxContactGroups)};
  }
  if (inject) {
    if (auto r = inject_friction_reason(c); !r.empty()) return {Support::unsupported, r};
  }
  std::string reasons;
  auto add = [&](const std::string& r) {
    if (reasons.find(r) != std::string::npos) return;
    if (!reasons.empty()) reasons.append("; ");
    reasons.append(r);
  };
  for (const Body& b : c.bodies) {
    if (const auto* p = std::get_if<Polygon>(&b.shape); p && !is_convex(*p)) {
      add(fmt::format("body '{}': a non-convex polygon as one mesh geom per convex piece (CGAL)",
                      b.name));
    }
  }
  // what one rule (a pair's or a group's) becomes between two geom types
  auto rule = [&](GeomType ga, GeomType gb, const ContactLaw& law, bool friction) {
    if (collider(ga, gb) == Collider::mpr) {
      const char* by = line == MujocoLine::v3
                           ? "MuJoCo 3's native convex collider (nativeccd, its default since "
                             "3.3.0)"
                           : "libccd MPR (approximate depth)";
      add(fmt::format("{} penetration from {}", collider_description(ga, gb), by));
    }
    if (inject) return;
    add("the law as a soft constraint near d = 1: gravity's share of the contact load is "
        "scaled by 1 - d (resting penetration ~0 instead of m g / k)");
    if (friction) {
      add("Coulomb friction as MuJoCo's soft frictional contact (condim 3): a load inside the "
          "cone is held by a slow creep");
    }
    const auto* kv = std::get_if<KelvinVoigt>(&law);
    if (mode == "oracle") {
      if (kv && kv->damping_depth_m > 0.0) add("damping ramp replaced by a linear equivalent");
      if (!kv) {
        add(fmt::format("{} replaced by a linear spring-damper matching one impact's duration "
                        "and restitution (calibrated on a probe run)",
                        contact_law_name(law)));
      }
    } else if (!kv) {
      add(fmt::format("{} as a linear spring-damper set each step from the law at the current "
                      "penetration",
                      contact_law_name(law)));
    }
  };
  for (const ContactPair& cp : c.contacts) {
    const auto& a = c.bodies[static_cast<std::size_t>(cp.body_a)];
    const auto& b = c.bodies[static_cast<std::size_t>(cp.body_b)];
    if (a.fixed && b.fixed) continue;
    rule(geom_type(a.shape), geom_type(b.shape), cp.law, cp.has_friction());
  }
  // a group: the geom types its members bring (moving ones meet every
  // member, fixed ones the moving), not its N^2 pairs
  for (const ContactGroup& g : c.contact_groups) {
    std::array<int, 4> moving{};
    std::array<int, 4> fixed{};
    for (const int i : g.bodies) {
      const Body& b = c.bodies[static_cast<std::size_t>(i)];
      (b.fixed ? fixed : moving)[static_cast<std::size_t>(geom_type(b.shape))] += 1;
    }
    for (std::size_t ta = 0; ta < 4; ++ta) {
      if (moving[ta] == 0) continue;
      for (std::size_t tb = 0; tb < 4; ++tb) {
        const int others = fixed[tb] + moving[tb] - (ta == tb ? 1 : 0);
        if (others > 0) {
          rule(static_cast<GeomType>(ta), static_cast<GeomType>(tb), g.law, g.has_friction());
        }
      }
    }
  }
  if (c.has_contact_groups()) {
    add("contact groups: MuJoCo's own broad phase pairs the groups' geoms (contype, "
        "conaffinity: one bit per group)");
  }
  if (reasons.empty()) return {Support::native, ""};
  return {Support::mapped, reasons};
}

}  // namespace pb::internal::mujoco
