#include "mujoco_plan.hpp"

#include <fmt/format.h>

#include "planarbench/errors.hpp"

#include <variant>

#include "mujoco_exact_depth.hpp"
#include "mujoco_mjcf.hpp"
#include "planarbench/outline.hpp"

namespace pb::internal::mujoco {

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
    pp.check_depth = pp.collider == Collider::mpr &&
                     exact_penetration_m(a.shape, BodyState{}, b.shape, BodyState{}).has_value();
    plan.pairs.push_back(pp);
  }
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
