#include "planarbench/reference/pair_geometry.hpp"

#include <stdexcept>
#include <variant>

namespace pb {

namespace {
bool both_polygons(const Body& a, const Body& b) {
  return std::holds_alternative<Polygon>(a.shape) && std::holds_alternative<Polygon>(b.shape);
}

// A pair with friction on a half-plane takes its line of action from the
// body's own inside points: the half-plane's outline points sample a straight
// line at a spacing its extent sets (22 mm for 4 m), so by the paper's rule
// (the body with more inside points) a polygon's face would be pressed at
// wherever those samples fall, a stiffness against rocking of K times their
// spread (w^2 / 12 for a face of width w) instead of the face's own corners'
// (w^2 / 4), and the one-force law's dependence on tilt (dF / dphi = K w / 2,
// not the moment's on depth: a circulatory force) then drives a stuck face
// into self-excited rocking (reference README, "Friction on a face").
//
// A polygon's outline points are its vertices; a half-plane's or a curve's
// sample its boundary. Where a polygon presses one vertex into such a body
// (a corner landing), the sampled body's points inside the corner's wedge
// outnumber the vertex, and by the paper's rule the line of action runs
// through their centroid: beside the corner by up to ~0.8 of the depth where
// the wedge is lopsided (concave_corner: restitution 3.8 % low), a lever the
// body does not have. A vertex contact acts at the vertex (the exact
// geometry's line of action), so one inside vertex places it; two or more (a
// face, two feet) keep the paper's rule, whose samples under a face spread
// its force as the face does.
ActionPoints action_points(const Body& a, const Body& b, bool with_friction) {
  const bool polygon_a = std::holds_alternative<Polygon>(a.shape);
  const bool polygon_b = std::holds_alternative<Polygon>(b.shape);
  if (with_friction && std::holds_alternative<HalfPlane>(a.shape)) return ActionPoints::b;
  if (with_friction && std::holds_alternative<HalfPlane>(b.shape)) return ActionPoints::a;
  if (polygon_a && !polygon_b) return ActionPoints::vertex_a;
  if (polygon_b && !polygon_a) return ActionPoints::vertex_b;
  return ActionPoints::more;
}
}  // namespace

bool PairGeometry::supported(const Body& a, const Body& b, GeometryMode mode,
                             std::string* reason) {
  auto refuse = [&](const std::string& why) {
    if (reason) *reason = why;
    return false;
  };
  if (std::holds_alternative<HalfPlane>(a.shape) && std::holds_alternative<HalfPlane>(b.shape)) {
    return refuse("contact between two half-planes is not defined");
  }
  if (mode == GeometryMode::outline || both_polygons(a, b)) {
    for (const Body* body : {&a, &b}) {
      if (!std::holds_alternative<Polygon>(body->shape) && body->outline_points < 3) {
        return refuse("body '" + body->name + "' has fewer than 3 outline points");
      }
    }
    return true;
  }
  if (!ExactContact::supported(a.shape, b.shape)) {
    return refuse(std::string("geometry=exact has no routine for ") + shape_type_name(a.shape) +
                  " - " + shape_type_name(b.shape) + " (use geometry=outline)");
  }
  return true;
}

PairGeometry::PairGeometry(const Body& a, const Body& b, GeometryMode mode,
                           DetectionMode detection, bool with_friction) {
  std::string reason;
  if (!supported(a, b, mode, &reason)) throw std::invalid_argument(reason);
  if (mode == GeometryMode::outline || both_polygons(a, b)) {
    if (detection == DetectionMode::fast) {
      if (!with_friction) {
        convex_line_ = ConvexLineContact::make(a.shape, a.outline_points, b.shape, b.outline_points);
      }
      fast_.emplace(contact_outline(a.shape, a.outline_points),
                    contact_outline(b.shape, b.outline_points));
      fast_->set_action_points(action_points(a, b, with_friction));
    } else {
      outline_.emplace(contact_outline(a.shape, a.outline_points),
                       contact_outline(b.shape, b.outline_points));
      outline_->set_action_points(action_points(a, b, with_friction));
    }
  } else {
    exact_.emplace(a.shape, b.shape);
  }
}

ContactGeometry PairGeometry::evaluate(const Pose& pose_a, const Pose& pose_b) {
  if (convex_line_) {
    if (const std::optional<ContactGeometry> g = convex_line_->evaluate(pose_a, pose_b)) {
      ++closed_form_count_;
      return *g;
    }
  }
  if (fast_) {
    ++tree_count_;
    return fast_->evaluate(pose_a, pose_b);
  }
  return outline_ ? outline_->evaluate(pose_a, pose_b) : exact_->evaluate(pose_a, pose_b);
}

void PairGeometry::forget_history() {
  if (convex_line_) convex_line_->forget_history();
  if (fast_) fast_->forget_history();
}

}  // namespace pb
