#include "mujoco_geometry.hpp"

#include <algorithm>
#include <utility>
#include <variant>

#include "planarbench/convex_pieces.hpp"

namespace pb::internal::mujoco {

GeomType geom_type(const Shape& shape) {
  if (std::holds_alternative<Circle>(shape)) return GeomType::sphere;
  if (std::holds_alternative<Ellipse>(shape)) return GeomType::ellipsoid;
  if (std::holds_alternative<Polygon>(shape)) return GeomType::mesh;
  return GeomType::plane;
}

const char* geom_type_name(GeomType t) {
  switch (t) {
    case GeomType::sphere:
      return "sphere";
    case GeomType::ellipsoid:
      return "ellipsoid";
    case GeomType::mesh:
      return "mesh";
    case GeomType::plane:
      return "plane";
  }
  return "plane";
}

std::array<double, 3> ellipsoid_size_m(const Ellipse& e) {
  return {e.semi_axis_a_m, std::min(e.semi_axis_a_m, e.semi_axis_b_m), e.semi_axis_b_m};
}

std::vector<std::array<double, 3>> bipyramid_vertices(const Polygon& p, const Vec2& apex) {
  std::vector<std::array<double, 3>> v;
  double r_max = 0.0;
  for (const Vec2& q : p.points_m) {
    v.push_back({q.x(), 0.0, q.y()});
    r_max = std::max(r_max, (q - apex).norm());
  }
  const double w = 0.5 * r_max;
  v.push_back({apex.x(), w, apex.y()});
  v.push_back({apex.x(), -w, apex.y()});
  return v;
}

PolygonPieces polygon_pieces(const Polygon& p) {
  PolygonPieces out;
  if (is_convex(p)) {
    out.pieces.push_back(p);
    return out;
  }
  const ConvexDecomposition d = convex_pieces(p.points_m, 0);
  for (const ConvexPiece& piece : d.pieces) out.pieces.push_back(Polygon{piece});
  out.decomposed = true;
  out.method = d.method;
  return out;
}

bool is_convex(const Polygon& p) {
  const auto& q = p.points_m;
  const std::size_t n = q.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 e1 = q[(i + 1) % n] - q[i];
    const Vec2 e2 = q[(i + 2) % n] - q[(i + 1) % n];
    // z of the cross product: negative is a right (reflex) turn
    const double cross = e1.x() * e2.y() - e1.y() * e2.x();
    if (cross < -1e-12 * e1.norm() * e2.norm()) return false;
  }
  return true;
}

Collider collider(GeomType a, GeomType b) {
  if (a > b) std::swap(a, b);
  // plane-sphere: mjc_PlaneSphere; plane-ellipsoid, plane-mesh: mjc_PlaneConvex
  // (support point / vertices below the plane)
  if (b == GeomType::plane) return a == GeomType::plane ? Collider::none : Collider::exact;
  if (a == GeomType::sphere && b == GeomType::sphere) return Collider::exact;
  return Collider::mpr;
}

std::string collider_description(GeomType a, GeomType b) {
  std::string s = std::string(geom_type_name(a)) + "-" + geom_type_name(b);
  switch (collider(a, b)) {
    case Collider::exact:
      return s + " (exact)";
    case Collider::mpr:
      return s + " (libccd MPR, approximate depth)";
    case Collider::none:
      return s + " (no collider)";
  }
  return s;
}

}  // namespace pb::internal::mujoco
