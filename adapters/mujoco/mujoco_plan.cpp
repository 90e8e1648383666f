#include "mujoco_plan.hpp"

#include <fmt/format.h>

#include <array>
#include <variant>

#include "planarbench/errors.hpp"

#include "mujoco_exact_depth.hpp"
#include "mujoco_mjcf.hpp"
#include "planarbench/outline.hpp"

namespace pb::internal::mujoco {

namespace {

constexpr int kGeomTypes = 4;  // GeomType's values

// each group's bit and attributes, and each member's copy and its margin
// (GroupPlan): O(members) per group, from counts of the geom types a
// member can meet (moving members meet every member, fixed ones the moving)
void plan_groups(const Case& c, double detection_margin_m, MujocoPlan& plan) {
  if (c.contact_groups.size() > static_cast<std::size_t>(kMaxContactGroups)) {
    throw EngineError(fmt::format(
        "mujoco: the case has {} contact groups; MuJoCo has {} collision bits (contype, "
        "conaffinity), one per group",
        c.contact_groups.size(), kMaxContactGroups));
  }
  for (std::size_t g = 0; g < c.contact_groups.size(); ++g) {
    const ContactGroup& group = c.contact_groups[g];
    GroupPlan gp;
    gp.bit = static_cast<int>(g);
    if (group.has_friction()) {
      gp.condim = 3;
      gp.friction[0] = group.friction;
    }
    plan.groups.push_back(gp);
    std::array<int, kGeomTypes> moving{};
    std::array<int, kGeomTypes> fixed{};
    for (const int i : group.bodies) {
      const auto t = static_cast<std::size_t>(plan.bodies[static_cast<std::size_t>(i)].geom);
      (c.bodies[static_cast<std::size_t>(i)].fixed ? fixed : moving)[t] += 1;
    }
    for (const int i : group.bodies) {
      BodyPlan& bp = plan.bodies[static_cast<std::size_t>(i)];
      const bool is_fixed = c.bodies[static_cast<std::size_t>(i)].fixed;
      bool all_exact = true;
      for (int t = 0; t < kGeomTypes; ++t) {
        const auto ut = static_cast<std::size_t>(t);
        int partners = moving[ut] + (is_fixed ? 0 : fixed[ut]);
        if (!is_fixed && ut == static_cast<std::size_t>(bp.geom)) --partners;  // not itself
        if (partners > 0 && collider(bp.geom, static_cast<GeomType>(t)) == Collider::mpr) {
          all_exact = false;
        }
      }
      bp.groups.push_back(static_cast<int>(g));
      bp.copy_margin_m.push_back(all_exact ? detection_margin_m : 0.0);
    }
  }
}

}  // namespace

int BodyPlan::copy_of_group(int g) const {
  for (std::size_t k = 0; k < groups.size(); ++k) {
    if (groups[k] == g) return static_cast<int>(k);
  }
  return 0;
}

bool group_meshes_meet(const Case& c, const MujocoPlan& plan) {
  for (const ContactGroup& g : c.contact_groups) {
    int meshes = 0;
    int moving = 0;
    for (const int i : g.bodies) {
      if (plan.bodies[static_cast<std::size_t>(i)].geom != GeomType::mesh) continue;
      ++meshes;
      if (!c.bodies[static_cast<std::size_t>(i)].fixed) ++moving;
    }
    if (meshes >= 2 && moving >= 1) return true;
  }
  return false;
}

bool depth_checked(const Case& c, const MujocoPlan& plan, int a, int b) {
  const auto ua = static_cast<std::size_t>(a);
  const auto ub = static_cast<std::size_t>(b);
  return collider(plan.bodies[ua].geom, plan.bodies[ub].geom) == Collider::mpr &&
         exact_penetration_m(c.bodies[ua].shape, BodyState{}, c.bodies[ub].shape, BodyState{})
             .has_value();
}

MujocoPlan plan_mujoco(const Case& c, double detection_margin_m) {
  MujocoPlan plan;
  for (std::size_t i = 0; i < c.bodies.size(); ++i) {
    const Body& b = c.bodies[i];
    BodyPlan bp;
    bp.geom = geom_type(b.shape);
    bp.joint = b.fixed ? -1 : joint_of_body(c, static_cast<int>(i));
    if (const auto* p = std::get_if<Polygon>(&b.shape)) {
      PolygonPieces pp = polygon_pieces(*p);
      bp.decomposed = pp.decomposed;
      bp.decomposition = pp.method;
      bp.pieces = std::move(pp.pieces);
      // the apexes must stand over their piece for its section y = 0 to be
      // the piece: the body origin for a whole convex body, a piece's centroid
      for (const Polygon& piece : bp.pieces) {
        bp.apexes.push_back(bp.decomposed ? polygon_area_properties(piece.points_m).centroid_m
                                          : Vec2(Vec2::Zero()));
      }
    }
    plan.bodies.push_back(std::move(bp));
  }
  for (const ContactPair& cp : c.contacts) {
    const Body& a = c.bodies[static_cast<std::size_t>(cp.body_a)];
    const Body& b = c.bodies[static_cast<std::size_t>(cp.body_b)];
    PairPlan pp;
    pp.present = !(a.fixed && b.fixed);
    pp.geom_a = plan.bodies[static_cast<std::size_t>(cp.body_a)].geom;
    pp.geom_b = plan.bodies[static_cast<std::size_t>(cp.body_b)].geom;
    pp.collider = collider(pp.geom_a, pp.geom_b);
    pp.margin_m = pp.collider == Collider::exact ? detection_margin_m : 0.0;
    if (cp.has_friction()) {
      pp.condim = 3;
      pp.friction[0] = cp.friction;
      pp.friction[1] = cp.friction;
    }
    pp.check_depth = depth_checked(c, plan, cp.body_a, cp.body_b);
    plan.pairs.push_back(pp);
  }
  plan_groups(c, detection_margin_m, plan);
  long geom_pairs = 0;
  for (std::size_t k = 0; k < c.contacts.size(); ++k) {
    if (!plan.pairs[k].present) continue;
    geom_pairs += static_cast<long>(plan.bodies[static_cast<std::size_t>(c.contacts[k].body_a)].geom_count()) *
                  plan.bodies[static_cast<std::size_t>(c.contacts[k].body_b)].geom_count();
  }
  if (geom_pairs > kMaxGeomPairs) {
    throw EngineError(fmt::format(
        "mujoco: the case's contacts need {} explicit geom <pair>s (one per two convex pieces), "
        "~{:.1f} GB at {} bytes each in MuJoCo's compiler and model; this adapter writes at most "
        "{} ({:.2f} GB): fewer outline points or fewer concave bodies in contact",
        geom_pairs, 1e-9 * static_cast<double>(geom_pairs) * kBytesPerGeomPair, kBytesPerGeomPair,
        kMaxGeomPairs, 1e-9 * static_cast<double>(kMaxGeomPairs) * kBytesPerGeomPair));
  }
  return plan;
}

}  // namespace pb::internal::mujoco
