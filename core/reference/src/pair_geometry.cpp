#include "planarbench/reference/pair_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <variant>

namespace pb {

namespace {
bool both_polygons(const Body& a, const Body& b) {
  return std::holds_alternative<Polygon>(a.shape) && std::holds_alternative<Polygon>(b.shape);
}

// points along a polygon's faces for a pair of two polygons: kFaceSamples
// points around the perimeter (the paper's 180), every vertex kept and each
// edge cut into equal parts. A polygon's vertices alone carry a contact on a
// half-plane or a curve, whose own points sample the face it presses; two
// polygons' vertices alone do not: two equal boxes stacked put each corner
// on the other's side edge, at depth 0 below its nearest boundary, so the
// pair's penetration read 0 while the faces overlapped by delta, and the
// contact chattered between no force and a sideways normal (reference
// README, Scenes). Sampled faces put points inside the other body at the
// faces' true depth.
constexpr int kFaceSamples = 180;

std::vector<Vec2> face_sampled_outline(const Polygon& p) {
  const auto& v = p.points_m;
  double perimeter = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) perimeter += (v[(i + 1) % v.size()] - v[i]).norm();
  const double spacing = perimeter / kFaceSamples;
  std::vector<Vec2> out;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec2& a = v[i];
    const Vec2& b = v[(i + 1) % v.size()];
    const int parts = std::max(1, static_cast<int>(std::lround((b - a).norm() / spacing)));
    for (int k = 0; k < parts; ++k) out.push_back(a + (b - a) * (static_cast<double>(k) / parts));
  }
  return out;
}

// outline points for the pair: in outline mode, and for two polygons that
// are not both convex (no exact routine: their outlines are exact shapes)
bool uses_outline(const Body& a, const Body& b, GeometryMode mode) {
  return mode == GeometryMode::outline ||
         (both_polygons(a, b) && !ExactContact::supported(a.shape, b.shape));
}

std::vector<Vec2> pair_outline(const Body& body, const Body& other) {
  if (both_polygons(body, other)) return face_sampled_outline(std::get<Polygon>(body.shape));
  return contact_outline(body.shape, body.outline_points);
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
//
// Two bodies that both sample their boundary (two polygons' sampled faces,
// pair_outline; two curves) press points of both into each other, about as
// many on each side: by the paper's rule the line of action jumps from one
// side's centroid to the other's whenever a point comes or goes, by an edge
// length. Two lightly pressed disks of a pile (issue 44): the jump's moment
// turns the disks, the turn brings the other side's point in and flips the
// lever back, a sliding mode on the rule's switch that the integrator
// followed with steps of 1e-12 s (a 10-disk pile at 180 points had not
// passed t = 0.1212 s after 300 s). Their pairs take every inside point of
// both (ActionPoints::both), whose depth weights make the line of action
// continuous as points come and go. Measured on the shipped cases with two
// curves: head_on within 1e-14 m of the paper's rule, dual_pendulum within
// 4.5e-5 m (its outline's error against the exact truth is 4.5e-3 m).
ActionPoints action_points(const Body& a, const Body& b, bool with_friction) {
  const bool polygon_a = std::holds_alternative<Polygon>(a.shape);
  const bool polygon_b = std::holds_alternative<Polygon>(b.shape);
  const bool plane = std::holds_alternative<HalfPlane>(a.shape) ||
                     std::holds_alternative<HalfPlane>(b.shape);
  if (polygon_a && polygon_b) return ActionPoints::both;
  if (!polygon_a && !polygon_b && !plane) return ActionPoints::both;
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
  if (uses_outline(a, b, mode)) {
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
  if (uses_outline(a, b, mode)) {
    if (detection == DetectionMode::fast) {
      if (!with_friction) {
        convex_line_ = ConvexLineContact::make(a.shape, a.outline_points, b.shape, b.outline_points);
      }
      fast_.emplace(pair_outline(a, b), pair_outline(b, a));
      fast_->set_action_points(action_points(a, b, with_friction));
    } else {
      outline_.emplace(pair_outline(a, b), pair_outline(b, a));
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
