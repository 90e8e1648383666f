// How each case shape becomes a MuJoCo geom, and which MuJoCo collider then
// handles a pair of them (MuJoCo 2.2.2 collision table, engine_collision_driver).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "planarbench/case.hpp"

namespace pb::internal::mujoco {

// MuJoCo geom of a case shape. Circle -> sphere (one contact point against a
// plane; a cylinder would give two and double the spring, ENGINES.md).
// Ellipse -> ellipsoid (a, c, b) with out-of-plane semi-axis c = min(a, b):
// its section by the plane y = 0 is the exact ellipse; c changed MPR's depth
// error little (measured 0.8-2.6e-6 m over c in [0.25, 100] at 30-150 um
// penetration), min(a, b) was among the best. Polygon -> convex mesh, a
// bipyramid: the polygon in y = 0 plus two apexes (0, +-w, 0) over its centroid,
// so that every extreme point in the case plane is a polygon vertex at y = 0
// (a prism would put two vertices, at y = +-w, on each contact and double the
// spring like a cylinder). HalfPlane -> plane (MuJoCo planes are infinite for
// collision; its local +z is the case body's +y, the outward normal).
enum class GeomType { sphere, ellipsoid, mesh, plane };

[[nodiscard]] GeomType geom_type(const Shape& shape);
[[nodiscard]] const char* geom_type_name(GeomType t);

// ellipsoid semi-axes (MuJoCo local x, y, z) of a case ellipse, m
[[nodiscard]] std::array<double, 3> ellipsoid_size_m(const Ellipse& e);

// mesh vertices (MuJoCo local frame, m) of a convex polygon: the polygon's
// points (x, 0, y) then the apexes (a_x, +w, a_y) and (a_x, -w, a_y) over
// `apex` (a point inside the polygon: the body origin for a whole convex
// body, a piece's centroid for a piece), w = half the largest distance of a
// point from the apex (any w > 0 would do)
[[nodiscard]] std::vector<std::array<double, 3>> bipyramid_vertices(const Polygon& p,
                                                                    const Vec2& apex = Vec2::Zero());

// The convex polygons MuJoCo gets for a case polygon: itself when convex,
// else the pieces of its convex decomposition (planarbench/convex_pieces.hpp,
// CGAL), each a mesh geom of its own on the same body. `method` says how.
struct PolygonPieces {
  std::vector<Polygon> pieces;
  bool decomposed = false;
  std::string method;
};
[[nodiscard]] PolygonPieces polygon_pieces(const Polygon& p);

// true when every turn of the counter-clockwise polygon is a left turn (or
// straight): MuJoCo collides a mesh as its convex hull, so a non-convex
// polygon is cut into convex pieces (polygon_pieces)
[[nodiscard]] bool is_convex(const Polygon& p);

// The collider MuJoCo 2.2.2 uses for a pair of geom types.
enum class Collider {
  exact,  // plane-sphere, plane-ellipsoid (support point), plane-mesh (vertices), sphere-sphere
  mpr,    // everything else: libccd's Minkowski Portal Refinement (approximate depth)
  none,   // plane-plane: MuJoCo has no collider (planes are static)
};

[[nodiscard]] Collider collider(GeomType a, GeomType b);
// e.g. "plane-sphere (exact)", "sphere-ellipsoid (libccd MPR)"
[[nodiscard]] std::string collider_description(GeomType a, GeomType b);

}  // namespace pb::internal::mujoco
