#include "ode_geometry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <variant>

#include "planarbench/convex_pieces.hpp"
#include "planarbench/outline.hpp"

namespace pb::internal::ode {

ConvexPrism make_convex_prism(const std::vector<Vec2>& outline, double w) {
  const auto n = static_cast<unsigned int>(outline.size());
  if (n < 3) throw std::invalid_argument("convex prism needs at least 3 outline points");
  ConvexPrism p;
  p.half_depth_m = w;
  p.point_count = 2 * n;
  p.plane_count = n + 2;
  p.points.reserve(6 * static_cast<std::size_t>(n));
  // bottom ring (z = -w) then top ring (z = +w)
  for (const double z : {-w, w}) {
    for (const Vec2& q : outline) {
      p.points.insert(p.points.end(), {q.x(), q.y(), z});
    }
  }
  p.planes.reserve(4 * static_cast<std::size_t>(n + 2));
  p.polygons.reserve(5 * static_cast<std::size_t>(n) + 2 * (static_cast<std::size_t>(n) + 1));
  // side faces: outward normal of a CCW edge (dx, dy) is (dy, -dx); the
  // vertex order bottom k, bottom k+1, top k+1, top k is CCW seen from outside
  for (unsigned int k = 0; k < n; ++k) {
    const unsigned int k1 = (k + 1) % n;
    const Vec2 edge = outline[k1] - outline[k];
    const Vec2 normal = Vec2(edge.y(), -edge.x()).normalized();
    p.planes.insert(p.planes.end(), {normal.x(), normal.y(), 0.0, normal.dot(outline[k])});
    p.polygons.insert(p.polygons.end(), {4u, k, k1, n + k1, n + k});
  }
  // top cap, normal +z: the outline's own CCW order
  p.planes.insert(p.planes.end(), {0.0, 0.0, 1.0, w});
  p.polygons.push_back(n);
  for (unsigned int k = 0; k < n; ++k) p.polygons.push_back(n + k);
  // bottom cap, normal -z: reversed order
  p.planes.insert(p.planes.end(), {0.0, 0.0, -1.0, w});
  p.polygons.push_back(n);
  for (unsigned int k = n; k-- > 0;) p.polygons.push_back(k);
  return p;
}

bool is_convex_ccw(const std::vector<Vec2>& pts) {
  const std::size_t n = pts.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 e1 = pts[(i + 1) % n] - pts[i];
    const Vec2 e2 = pts[(i + 2) % n] - pts[(i + 1) % n];
    if (!(e1.x() * e2.y() - e1.y() * e2.x() > 0.0)) return false;
  }
  return true;
}

PlaneCoefficients halfplane_plane(const Vec2& position_m, double angle_rad) {
  // body +y rotated by the angle: (-sin, cos)
  const Vec2 normal(-std::sin(angle_rad), std::cos(angle_rad));
  return {normal.x(), normal.y(), 0.0, normal.dot(position_m)};
}

namespace {

// the prism is deep enough in z that no in-plane contact prefers a cap: the
// caps lie at least as far from the centre as any outline point
double prism_half_depth(const std::vector<Vec2>& outline) {
  double r = 0.0;
  for (const Vec2& q : outline) r = std::max(r, q.norm());
  return std::max(r, 1e-3);
}

}  // namespace

dGeomID create_shape_geom(dSpaceID space, const Body& body, ConvexPrism& prism) {
  if (const auto* c = std::get_if<Circle>(&body.shape)) {
    return dCreateSphere(space, c->radius_m);
  }
  if (std::holds_alternative<HalfPlane>(body.shape)) {
    throw std::invalid_argument("create_shape_geom: half-planes are planes, not shapes");
  }
  const std::vector<Vec2> outline = make_outline(body.shape, body.outline_points);
  prism = make_convex_prism(outline, prism_half_depth(outline));
  return dCreateConvex(space, prism.planes.data(), prism.plane_count, prism.points.data(),
                       prism.point_count, prism.polygons.data());
}

std::optional<Vec2> centred_rectangle_half_sides(const std::vector<Vec2>& points) {
  if (points.size() != 4) return std::nullopt;
  double a = 0.0;
  double b = 0.0;
  for (const Vec2& q : points) {
    a = std::max(a, std::abs(q.x()));
    b = std::max(b, std::abs(q.y()));
  }
  if (!(a > 0.0 && b > 0.0)) return std::nullopt;
  int quadrants = 0;  // one corner in each: bit (x > 0) + 2 (y > 0)
  for (const Vec2& q : points) {
    if (std::abs(std::abs(q.x()) - a) > 1e-12 * a || std::abs(std::abs(q.y()) - b) > 1e-12 * b) {
      return std::nullopt;
    }
    quadrants |= 1 << ((q.x() > 0.0 ? 1 : 0) + (q.y() > 0.0 ? 2 : 0));
  }
  if (quadrants != 0xf) return std::nullopt;
  return Vec2(a, b);
}

ShapeGeoms create_shape_geoms(dSpaceID space, const Body& body,
                              std::vector<std::unique_ptr<ConvexPrism>>& prisms,
                              bool rectangles_as_boxes) {
  ShapeGeoms out;
  const auto* polygon = std::get_if<Polygon>(&body.shape);
  if (rectangles_as_boxes && polygon != nullptr) {
    if (const auto half = centred_rectangle_half_sides(polygon->points_m)) {
      const double w = prism_half_depth(polygon->points_m);
      out.geoms.push_back(dCreateBox(space, 2.0 * half->x(), 2.0 * half->y(), 2.0 * w));
      out.offsets_m.push_back(Vec2::Zero());
      out.vertices = 8;
      out.description = fmt::format(
          "dCreateBox {} x {} x {} m (the rectangle, z in [-{}, {}] m): ODE's box colliders "
          "(box-plane, box-box: the corners of the face in contact); a prism pressed face to "
          "face on a prism gets one contact from ODE's convex-convex collider",
          2.0 * half->x(), 2.0 * half->y(), 2.0 * w, w, w);
      return out;
    }
  }
  if (polygon == nullptr || is_convex_ccw(polygon->points_m)) {
    auto prism = std::make_unique<ConvexPrism>();
    out.geoms.push_back(create_shape_geom(space, body, *prism));
    out.offsets_m.push_back(Vec2::Zero());
    out.description = describe_shape_geom(body, *prism);
    out.vertices = std::holds_alternative<Circle>(body.shape)
                       ? 1
                       : static_cast<int>(prism->point_count);
    prisms.push_back(std::move(prism));
    return out;
  }
  // a non-convex polygon: one prism per convex piece, every prism as deep as
  // the whole body's (no in-plane contact prefers a cap)
  const ConvexDecomposition parts = convex_pieces(polygon->points_m, 0);
  const double w = prism_half_depth(polygon->points_m);
  for (const ConvexPiece& piece : parts.pieces) {
    // the prism about the piece's centroid, placed there by the geom's offset
    const Vec2 centre = polygon_area_properties(piece).centroid_m;
    ConvexPiece local = piece;
    for (Vec2& q : local) q -= centre;
    auto prism = std::make_unique<ConvexPrism>(make_convex_prism(local, w));
    out.offsets_m.push_back(centre);
    out.geoms.push_back(dCreateConvex(space, prism->planes.data(), prism->plane_count,
                                      prism->points.data(), prism->point_count,
                                      prism->polygons.data()));
    out.vertices += static_cast<int>(prism->point_count);
    prisms.push_back(std::move(prism));
  }
  out.description = fmt::format(
      "{} dCreateConvex prisms, z in [-{}, {}] m, one per convex piece of the non-convex "
      "{}-point polygon ({}), each built about its piece's centroid and offset there on the "
      "body: ODE collides each piece; the pair's contacts from every piece are one contact of "
      "the case",
      parts.pieces.size(), w, w, polygon->points_m.size(), parts.method);
  return out;
}

std::string describe_shape_geom(const Body& body, const ConvexPrism& prism) {
  if (const auto* c = std::get_if<Circle>(&body.shape)) {
    return fmt::format("sphere r = {} m (exact circle in z = 0, one contact point)", c->radius_m);
  }
  if (std::holds_alternative<HalfPlane>(body.shape)) {
    return "dCreatePlane through the body origin, normal = body +y (infinite line)";
  }
  return fmt::format(
      "dCreateConvex prism of the {}-point outline, z in [-{}, {}] m ({} faces); ODE's "
      "convex colliders see the polygon, not the exact {}",
      prism.point_count / 2, prism.half_depth_m, prism.half_depth_m, prism.plane_count,
      shape_type_name(body.shape));
}

}  // namespace pb::internal::ode
