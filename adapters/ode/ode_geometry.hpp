// Case shapes as ODE geoms. Circle -> sphere (exact, one contact point; a
// cylinder would give two and double the spring, ENGINES.md). Ellipse and
// convex polygon -> a convex prism extruded along z from the body's outline
// (ODE has no ellipse); in a scene, a rectangle centred on the body origin
// -> dCreateBox (below: why). Non-convex polygon -> one convex prism per
// piece of its convex decomposition (planarbench/convex_pieces.hpp, CGAL),
// all on the same body. Fixed half-plane -> dCreatePlane with the case's
// orientation.
#pragma once

#include <ode/ode.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "planarbench/case.hpp"

namespace pb::internal::ode {

// The arrays dCreateConvex reads. ODE keeps pointers to them (it does not
// copy): the owner keeps this struct alive and unmoved while the geom lives.
struct ConvexPrism {
  std::vector<dReal> planes;           // 4 per face: unit outward normal (x, y, z), offset d
  std::vector<dReal> points;           // 3 per vertex
  std::vector<unsigned int> polygons;  // per face: vertex count, then indices (CCW from outside)
  unsigned int plane_count = 0;
  unsigned int point_count = 0;
  double half_depth_m = 0.0;  // m, the prism spans z in [-half_depth, +half_depth]
};

// Prism of a counter-clockwise convex outline: vertex k at z = -w is index k,
// at z = +w index n + k; side face k joins outline points k and k + 1; then
// the top (+z) and bottom (-z) caps.
[[nodiscard]] ConvexPrism make_convex_prism(const std::vector<Vec2>& outline_ccw_m,
                                            double half_depth_m);

// true when the points turn left at every vertex (strictly convex, CCW)
[[nodiscard]] bool is_convex_ccw(const std::vector<Vec2>& points);

// a x + b y + c z = d of dCreatePlane: the surface of a half-plane body at
// (position, angle): unit normal = body +y in world, d = normal . position
struct PlaneCoefficients {
  double a = 0.0;
  double b = 0.0;
  double c = 0.0;
  double d = 0.0;  // m
};
[[nodiscard]] PlaneCoefficients halfplane_plane(const Vec2& position_m, double angle_rad);

// Creates the geom of a body's shape in `space` (not placed, no body).
// Half-planes are not handled here (they need the pose: halfplane_plane).
// `prism` receives the convex arrays for ellipses and polygons; a polygon must
// be convex here (shape_geoms takes any).
[[nodiscard]] dGeomID create_shape_geom(dSpaceID space, const Body& body, ConvexPrism& prism);

// The geoms of a body's shape, one per convex piece (a circle, an ellipse or a
// convex polygon is one). `prisms` receives one ConvexPrism per prism geom
// (stable addresses: ODE keeps pointers into them); `method` how a non-convex
// polygon was cut ("" otherwise).
struct ShapeGeoms {
  std::vector<dGeomID> geoms;
  // the vertices of the geoms (the bound on a pair's contacts,
  // ode_pair_contact.hpp): a prism of n outline points 2 n, a box 8, a sphere 1
  int vertices = 0;
  // per geom: where its own origin lies in the body frame, m (a piece's
  // prism is built about the piece's centroid: ODE's convex collider wants
  // the geom's origin inside it); zero for a whole shape
  std::vector<Vec2> offsets_m;
  std::string description;  // one line for the mapping: what the shape became
};
// rectangles_as_boxes: a rectangle centred on the body origin, its sides
// along the body axes, becomes dCreateBox (same z extent as its prism).
// ODE's own convex-convex collider (this build has no libccd) classifies two
// equal prisms pressed face to face as an edge-edge contact and reports ONE
// contact, midway along the face (measured: two 0.4 x 0.1 prisms stacked
// 9.8 um deep give 1 contact at x = 0; two dBoxes give 4, the corners of
// the face), so a stack of prisms stands on single points and rocks from
// corner to corner every step. ODE's users build boxes as dBox (its
// demo_boxstack); scenes do (stacks, pyramids), while the declared cases
// keep the prisms their pinned results were computed with.
[[nodiscard]] ShapeGeoms create_shape_geoms(dSpaceID space, const Body& body,
                                            std::vector<std::unique_ptr<ConvexPrism>>& prisms,
                                            bool rectangles_as_boxes = false);

// the half sides (a, b) of a rectangle centred on the origin with its sides
// along x and y (four corners (+-a, +-b), 1e-12 relative), else nullopt
[[nodiscard]] std::optional<Vec2> centred_rectangle_half_sides(const std::vector<Vec2>& points);

// one line for the mapping: what the shape became
[[nodiscard]] std::string describe_shape_geom(const Body& body, const ConvexPrism& prism);

}  // namespace pb::internal::ode
