#include "planarbench/reference/exact_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <variant>

#include "planarbench/ellipse_distance.hpp"

namespace pb {

namespace {

// canonical order of shape kinds: the lower rank is the first body of a routine
int rank(const Shape& s) {
  if (std::holds_alternative<HalfPlane>(s)) return 0;
  if (std::holds_alternative<Polygon>(s)) return 1;
  if (std::holds_alternative<Ellipse>(s)) return 2;
  return 3;  // circle
}

bool canonical_pair_supported(const Shape& first, const Shape& second) {
  const int r1 = rank(first);
  const int r2 = rank(second);
  if (r2 == 3) return true;              // anything - circle
  if (r1 == 0) return r2 == 1 || r2 == 2;  // half-plane - polygon, ellipse
  return false;
}

// the half-plane's surface: a point on it and its outward normal
Vec2 surface_normal(const Pose& plane) { return plane.rotation() * Vec2(0.0, 1.0); }

ContactGeometry halfplane_circle(const Pose& plane, double radius, const Pose& disk) {
  const Vec2 n = surface_normal(plane);
  const Vec2 c = disk.position_m;
  const double h = n.dot(c - plane.position_m);  // centre height above the line
  ContactGeometry g;
  g.gap_m = h - radius;
  g.normal = n;
  g.point_b_m = c - radius * n;
  g.point_a_m = c - h * n;
  return g;
}

ContactGeometry halfplane_ellipse(const Pose& plane, const Ellipse& e, const Pose& body) {
  const Vec2 n = surface_normal(plane);
  // support point of the ellipse in -n, in the ellipse frame
  const Vec2 u = body.rotation().transpose() * (-n);
  const double a = e.semi_axis_a_m;
  const double b = e.semi_axis_b_m;
  const double k = std::sqrt(a * a * u.x() * u.x() + b * b * u.y() * u.y());
  const Vec2 q = body.to_world(Vec2(a * a * u.x() / k, b * b * u.y() / k));
  ContactGeometry g;
  g.gap_m = n.dot(q - plane.position_m);
  g.normal = n;
  g.point_b_m = q;
  g.point_a_m = q - g.gap_m * n;
  return g;
}

ContactGeometry halfplane_polygon(const Pose& plane, const WorldOutline& poly, const Pose& body) {
  const Vec2 n = surface_normal(plane);
  // heights of the vertices above the line, in the polygon frame
  const Vec2 nl = body.rotation().transpose() * n;
  const Vec2 origin = body.to_local(plane.position_m);
  int lowest = 0;
  double h_min = std::numeric_limits<double>::infinity();
  int below = 0;              // vertices under the line
  double depth_sum = 0.0;     // m
  Vec2 moment = Vec2::Zero(); // m^2, sum of depth x vertex (polygon frame)
  double second = 0.0;
  // m^3, sum of depth x (vertex along the surface)^2
  const Vec2 tl(nl.y(), -nl.x());  // the surface's tangent, polygon frame
  for (int i = 0; i < poly.size(); ++i) {
    const double h = nl.x() * (poly.x[i] - origin.x()) + nl.y() * (poly.y[i] - origin.y());
    if (h < h_min) {
      h_min = h;
      lowest = i;
    }
    if (h < 0.0) {
      ++below;
      depth_sum -= h;
      moment -= h * Vec2(poly.x[i], poly.y[i]);
      const double s = tl.dot(Vec2(poly.x[i], poly.y[i]));
      second -= h * s * s;
    }
  }
  ContactGeometry g;
  g.gap_m = h_min;
  g.normal = n;
  // SPEC §1, one force per pair: pressed in at several vertices (a face on
  // the line), the force acts at their depth-weighted centroid, which moves
  // continuously as vertices cross the line; with one vertex, at that vertex
  g.point_b_m = below > 1 ? body.to_world(moment / depth_sum)
                          : body.to_world(Vec2(poly.x[lowest], poly.y[lowest]));
  g.point_a_m = g.point_b_m - h_min * n;
  if (below > 1) {
    const double mean = tl.dot(moment) / depth_sum;
    g.spread_m2 = std::max(0.0, second / depth_sum - mean * mean);
  }
  return g;
}

ContactGeometry polygon_circle(const WorldOutline& poly, const Pose& body, double radius,
                               const Pose& disk) {
  const Vec2 c = disk.position_m;
  const Vec2 cl = body.to_local(c);
  const BoundaryHit hit = nearest_boundary_point(cl.x(), cl.y(), poly);
  const int e = hit.edge;
  const Vec2 ql(poly.x[e] + hit.t * poly.ex[e], poly.y[e] + hit.t * poly.ey[e]);
  // outward normal of the polygon at the nearest point (polygon frame)
  Vec2 m;
  const Vec2 d = cl - ql;
  if (hit.t > 0.0 && hit.t < 1.0) {
    m = Vec2(poly.nx[e], poly.ny[e]);
  } else if (d.norm() > 1e-12 * (1.0 + cl.norm())) {
    m = hit.inside ? Vec2(-d.normalized()) : Vec2(d.normalized());
  } else {
    const int n = poly.size();
    const int v = hit.t <= 0.0 ? e : (e + 1) % n;
    const int before = (v + n - 1) % n;
    m = Vec2(poly.nx[v] + poly.nx[before], poly.ny[v] + poly.ny[before]).normalized();
  }
  const double signed_distance = hit.inside ? -hit.distance_m : hit.distance_m;
  ContactGeometry g;
  g.normal = body.rotation() * m;
  g.gap_m = signed_distance - radius;
  g.point_a_m = body.to_world(ql);
  g.point_b_m = c - radius * g.normal;
  return g;
}

ContactGeometry ellipse_circle(const Ellipse& e, const Pose& body, double radius,
                               const Pose& disk) {
  const Vec2 c = disk.position_m;
  const EllipseClosestPoint cp =
      closest_point_on_ellipse(e.semi_axis_a_m, e.semi_axis_b_m, body.to_local(c));
  ContactGeometry g;
  g.normal = body.rotation() * cp.outward_normal;
  g.gap_m = cp.signed_distance_m - radius;
  g.point_a_m = body.to_world(cp.point_m);
  g.point_b_m = c - radius * g.normal;
  return g;
}

ContactGeometry circle_circle(double ra, const Pose& a, double rb, const Pose& b) {
  const Vec2 d = b.position_m - a.position_m;
  const double len = d.norm();
  // concentric disks: any direction is a normal; +y keeps it deterministic
  const Vec2 n = len > 0.0 ? Vec2(d / len) : Vec2(0.0, 1.0);
  ContactGeometry g;
  g.gap_m = len - ra - rb;
  g.normal = n;
  g.point_a_m = a.position_m + ra * n;
  g.point_b_m = b.position_m - rb * n;
  return g;
}

}  // namespace

bool ExactContact::supported(const Shape& a, const Shape& b) {
  return rank(a) <= rank(b) ? canonical_pair_supported(a, b) : canonical_pair_supported(b, a);
}

ExactContact::ExactContact(const Shape& a, const Shape& b) {
  swapped_ = rank(a) > rank(b);
  first_ = swapped_ ? b : a;
  second_ = swapped_ ? a : b;
  if (!canonical_pair_supported(first_, second_)) {
    throw std::invalid_argument(std::string("geometry=exact has no routine for ") +
                                shape_type_name(a) + " - " + shape_type_name(b));
  }
  for (const Shape* s : {&first_, &second_}) {
    if (const auto* p = std::get_if<Polygon>(s)) place_outline(p->points_m, Pose{}, polygon_);
  }
}

ContactGeometry ExactContact::evaluate(const Pose& pose_a, const Pose& pose_b) const {
  const Pose& p1 = swapped_ ? pose_b : pose_a;
  const Pose& p2 = swapped_ ? pose_a : pose_b;
  ContactGeometry g;
  if (const auto* c2 = std::get_if<Circle>(&second_)) {
    if (std::holds_alternative<HalfPlane>(first_)) {
      g = halfplane_circle(p1, c2->radius_m, p2);
    } else if (std::holds_alternative<Polygon>(first_)) {
      g = polygon_circle(polygon_, p1, c2->radius_m, p2);
    } else if (const auto* e1 = std::get_if<Ellipse>(&first_)) {
      g = ellipse_circle(*e1, p1, c2->radius_m, p2);
    } else {
      g = circle_circle(std::get<Circle>(first_).radius_m, p1, c2->radius_m, p2);
    }
  } else if (const auto* e2 = std::get_if<Ellipse>(&second_)) {
    g = halfplane_ellipse(p1, *e2, p2);
  } else {
    g = halfplane_polygon(p1, polygon_, p2);
  }
  return swapped_ ? g.swapped() : g;
}

}  // namespace pb
