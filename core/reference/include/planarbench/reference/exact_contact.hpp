// Exact contact geometry of the true shapes (setting geometry=exact): the
// closest points or the penetration of circles, ellipses, polygons and the
// infinite line of a half-plane, without outline points. It separates the
// outline discretisation error from everything else.
//
// Pairs and how each is computed (normal from body a to body b, gap as in
// contact_geometry.hpp):
//   half-plane - circle   gap = n.(c - p0) - R, n the line's outward normal
//   half-plane - ellipse  the ellipse's support point in -n (its deepest or
//                         closest point): (a^2 u_x, b^2 u_y) / sqrt(a^2 u_x^2 + b^2 u_y^2)
//   half-plane - polygon  the polygon's lowest vertex gives the gap; pressed
//                         in at several vertices, the force acts at their
//                         depth-weighted centroid (SPEC §1: a face flat on
//                         the line is one contact, at its middle)
//   circle - circle       gap = |c_b - c_a| - R_a - R_b
//   ellipse - circle      signed distance from the circle's centre to the
//                         ellipse (Eberly, ellipse_distance.hpp) minus R
//   polygon - circle      signed distance from the circle's centre to the
//                         polygon boundary minus R
//   polygon - polygon     two convex polygons: their distance apart; pressed
//                         in, the separating axis test's least overlap and
//                         the incident face clipped to the reference face,
//                         the force at its pressed points' depth-weighted
//                         centroid (exact_contact.cpp)
// Not available: ellipse - ellipse, ellipse - polygon, concave polygon -
// polygon (their outlines, pair_geometry.hpp), half-plane - half-plane.
// With a circle, the penetration is measured through the circle's centre
// along the other body's normal: the standard definition, and the limit of the
// outline definition (deepest point) as the outlines get dense.
#pragma once

#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/reference/contact_geometry.hpp"
#include "planarbench/reference/outline_contact.hpp"

namespace pb {

class ExactContact {
 public:
  // throws std::invalid_argument for a pair without an exact routine
  ExactContact(const Shape& a, const Shape& b);

  [[nodiscard]] static bool supported(const Shape& a, const Shape& b);
  [[nodiscard]] ContactGeometry evaluate(const Pose& pose_a, const Pose& pose_b) const;

 private:
  Shape first_;    // the pair in canonical order (half-plane, polygon, ellipse, circle)
  Shape second_;
  bool swapped_ = false;      // the canonical order is (b, a)
  WorldOutline polygon_;      // a polygon among the two, in its body frame
  // two convex polygons: their vertices in the body frames, and scratch for
  // them in the world (evaluate is const: the scratch is the object's own)
  std::vector<Vec2> local_first_, local_second_;
  mutable std::vector<Vec2> world_first_, world_second_;
};

}  // namespace pb
