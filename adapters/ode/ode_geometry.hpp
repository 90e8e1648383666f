// Case shapes as ODE geoms. Circle -> sphere (exact, one contact point; a
// cylinder would give two and double the spring, ENGINES.md). Ellipse and
// convex polygon -> a convex prism extruded along z from the body's outline
// (ODE has no ellipse). Non-convex polygon -> one convex prism per piece of
// its convex decomposition (planarbench/convex_pieces.hpp, CGAL), all on the
// same body. Fixed half-plane -> dCreatePlane with the case's orientation.
#pragma once

#include <ode/ode.h>

#include <memory>
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
  // per geom: where its own origin lies in the body frame, m (a piece's
  // prism is built about the piece's centroid: ODE's convex collider wants
  // the geom's origin inside it); zero for a whole shape
  std::vector<Vec2> offsets_m;
  std::string description;  // one line for the mapping: what the shape became
};
[[nodiscard]] ShapeGeoms create_shape_geoms(dSpaceID space, const Body& body,
                                            std::vector<std::unique_ptr<ConvexPrism>>& prisms);

// one line for the mapping: what the shape became
[[nodiscard]] std::string describe_shape_geom(const Body& body, const ConvexPrism& prism);

}  // namespace pb::internal::ode
