// One contact pair's penetration, its rate, normal and points, from the two
// bodies' poses and velocities, in closed form (support points against a
// line) or by the root solve of ellipse_closest_point.hpp (a disk against an
// ellipse). Written for the independent truth: no code shared with
// core/reference or core/src's geometry.
//
// The penetration delta is the deepest overlap along the normal (SPEC §1):
//   a shape against a half-plane: delta = -n . (p - p0), p the shape's support
//     point in -n, p0 on the line, n its outward normal;
//   a disk (centre c, radius R) against an ellipse: delta = R - |c - q|, q the
//     ellipse's point nearest to c (the disk's centre must stay outside it).
// Its rate is exact: delta_dot = -n_ab . (v_b(p_b) - v_a(p_a)) with v_k(p) the
// velocity of body k's material point at p. The support / nearest points move
// along their boundary, tangent to it, so their own motion drops out of the
// derivative (the envelope theorem).
#pragma once

#include <limits>
#include <string>

#include "planarbench/case.hpp"
#include "support_point.hpp"

namespace pb::independent {

// a body's pose and velocity in the world
struct BodyMotion {
  Pose pose;
  Vec2 velocity_mps = Vec2::Zero();     // m/s, of the centre of mass
  double angular_velocity_radps = 0.0;  // rad/s
};

// velocity of the body's material point at the world point x, m/s
[[nodiscard]] Vec2 point_velocity(const BodyMotion& m, const Vec2& x_m);

struct PairContact {
  double depth_m = 0.0;           // m, delta: > 0 overlapping
  double depth_rate_mps = 0.0;    // m/s, d delta / dt: > 0 approaching
  Vec2 normal = Vec2::Zero();     // unit, from body a to body b
  Vec2 point_a_m = Vec2::Zero();  // m, world, body a's deepest / nearest point
  Vec2 point_b_m = Vec2::Zero();  // m, world, body b's
  // polygons: depth of the next-deepest vertex, m (-inf otherwise)
  double next_vertex_depth_m = -std::numeric_limits<double>::infinity();
  int vertex = -1;  // polygons: the deepest vertex
  [[nodiscard]] Vec2 point_m() const { return 0.5 * (point_a_m + point_b_m); }
};

// "" when this truth handles the pair of shapes (a fixed half-plane against a
// circle, ellipse or polygon; a circle against an ellipse), else why not
[[nodiscard]] std::string pair_contact_unsupported(const Body& a, const Body& b);

// the pair's contact at the given motions (throws EngineError when a disk's
// centre reaches the inside of the ellipse, where delta is not defined)
[[nodiscard]] PairContact pair_contact(const Shape& a, const BodyMotion& ma, const Shape& b,
                                       const BodyMotion& mb);

}  // namespace pb::independent
