// Case shapes as Box2D fixtures. A non-convex polygon becomes convex pieces
// (CGAL's partition, planarbench/convex_pieces.hpp), each a fixture of the
// same body. Box2D's polygons and edges carry a skin of
// b2_polygonRadius (0.01 m) around their core, and collide with the skinned
// surface: the adapter moves every core inward by the skin so that the
// surface Box2D collides is the case's own surface (circles carry no skin).
#pragma once

#include <box2d/b2_body.h>

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "planarbench/case.hpp"

namespace pb::internal::box2d {

// m, the skin of b2PolygonShape, b2EdgeShape and b2ChainShape (b2_common.h:
// b2_polygonRadius = 2 b2_linearSlop)
[[nodiscard]] double skin_m();
// m, Box2D's allowed overlap before position correction (b2_linearSlop)
[[nodiscard]] double linear_slop_m();
// m, the longest chain segment used for a half-plane: keeps the float error of
// a manifold's plane point (eps * segment) below 1e-6 m
constexpr double kMaxSegment_m = 10.0;
// outline vertices per fan piece: with the centre this is b2_maxPolygonVertices
constexpr int kFanOutlineVertices = 7;

// Closed counter-clockwise outline moved inward by r: every edge line is
// offset by r along its inward normal and each vertex moves to the
// intersection of its two offset lines, V = P - r (n1 + n2) / (1 + n1.n2)
// (n1, n2 the outward unit normals of the edges before and after P). The
// skinned polygon (Minkowski sum with a disk of radius r) then has the
// original edges exactly and rounds each vertex by r (1/cos(phi/2) - 1)
// (phi the turning angle), 1.5e-6 m at phi = 2 deg and r = 0.01 m.
[[nodiscard]] std::vector<Vec2> inset_outline(const std::vector<Vec2>& outline, double r_m);

// The Box2D core of one convex piece of a non-convex polygon: the piece
// clipped by the half-planes of the polygon's edges moved inward by r - the
// piece's own outline edges, and at each convex corner of the polygon that
// the piece shares with another piece (a seam's end) both of the polygon's
// edges there. Its seams stay where they are. Skinned (Minkowski sum with a
// disk of radius r), the pieces' union then has the outline's edges exactly,
// its reflex corners sharp, each convex corner rounded as a convex body's is,
// by r (1/cos(phi/2) - 1) (phi the turning angle), and each piece reaches
// across its seams by r into the neighbouring piece of the same body. With
// every piece inset on its own (inset_outline of each piece, seams included)
// a corner two pieces share was rounded as each piece's sharper corner: the
// L of concave_corner, whose seam halves its 90 deg outer corner, had each
// 45 deg piece corner rounded by r (1/sin(22.5 deg) - 1) = 1.61 r instead of
// r (sqrt(2) - 1) = 0.41 r, and landed 3.8 ms late. nullopt when a point of
// the piece is not a point of the polygon, or a core edge lies nearer than r
// to the outline (its skin would leave the body); the caller then insets the
// piece on its own.
[[nodiscard]] std::optional<std::vector<Vec2>> inset_piece(const std::vector<Vec2>& piece,
                                                           const std::vector<Vec2>& polygon,
                                                           double r_m);

// Convex pieces of a closed counter-clockwise outline that is star-shaped
// seen from `centre`: each piece is the centre plus up to
// max_outline_vertices consecutive outline vertices, consecutive pieces share
// their end vertex, and pieces grow greedily while they stay convex. A convex
// outline of at most max_outline_vertices + 1 vertices is one piece without
// the centre. `error` is set (and pieces empty) when the outline is not
// star-shaped from the centre.
struct Fan {
  std::vector<std::vector<Vec2>> pieces;
  std::string error;
};
[[nodiscard]] Fan convex_fan(const std::vector<Vec2>& outline, const Vec2& centre,
                             int max_outline_vertices);

// true when the closed polygon turns left at every vertex, clearly so: sin
// of every turn above 1e-6, so that Box2D's float hull keeps every vertex
// (strictly convex, CCW; planarbench/convex_pieces.hpp has the tolerant test)
[[nodiscard]] bool is_convex_ccw(const std::vector<Vec2>& polygon);

// Why Box2D cannot build this body ("" when it can).
[[nodiscard]] std::string unsupported_shape_reason(const Body& body);

// m, the largest distance of the shape's surface from its body origin
// (infinite for a half-plane)
[[nodiscard]] double bounding_radius_m(const Shape& shape);

// What every new fixture gets besides its shape.
struct FixtureOptions {
  double restitution_threshold_mps = 1.0;  // m/s
  int body_index = -1;                     // stored in b2FixtureUserData::pointer (+1)
  double half_plane_half_length_m = 10.0;  // m, half length of a half-plane's chain
};

// Creates the fixtures of `body` (frictionless, restitution 0, density 0:
// the mass data is set separately) and returns how the shape was expressed.
// Throws EngineError when Box2D would alter a polygon piece (welded or
// collinear vertices).
nlohmann::json add_fixtures(b2Body& body, const Body& case_body, const FixtureOptions& options);

}  // namespace pb::internal::box2d
