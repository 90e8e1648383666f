#include "planarbench/reference/exact_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <variant>

#include "planarbench/convex_pieces.hpp"
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

bool convex_polygon(const Shape& s) {
  const auto* p = std::get_if<Polygon>(&s);
  return p != nullptr && is_convex_ccw(p->points_m);
}

bool canonical_pair_supported(const Shape& first, const Shape& second) {
  const int r1 = rank(first);
  const int r2 = rank(second);
  if (r2 == 3) return true;              // anything - circle
  if (r1 == 0) return r2 == 1 || r2 == 2;  // half-plane - polygon, ellipse
  return r1 == 1 && r2 == 1 && convex_polygon(first) && convex_polygon(second);
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

// world vertices of a convex polygon at a pose
void place_vertices(const std::vector<Vec2>& local, const Pose& pose, std::vector<Vec2>& out) {
  out.resize(local.size());
  const Eigen::Matrix2d r = pose.rotation();
  for (std::size_t i = 0; i < local.size(); ++i) out[i] = pose.position_m + r * local[i];
}

// the outward unit normal of edge i (counter-clockwise vertices)
Vec2 edge_normal(const std::vector<Vec2>& v, std::size_t i) {
  const Vec2 e = v[(i + 1) % v.size()] - v[i];
  return Vec2(e.y(), -e.x()).normalized();
}

// the face of `ref` along which `other` is least deep: max over faces of the
// least height of other's vertices above it (the separating axis test)
double max_separation(const std::vector<Vec2>& ref, const std::vector<Vec2>& other, std::size_t& face) {
  double best = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < ref.size(); ++i) {
    const Vec2 n = edge_normal(ref, i);
    double least = std::numeric_limits<double>::infinity();
    for (const Vec2& w : other) least = std::min(least, n.dot(w - ref[i]));
    if (least > best) {
      best = least;
      face = i;
    }
  }
  return best;
}

// m, the distance between two disjoint convex polygons and its closest points
double polygon_distance(const std::vector<Vec2>& a, const std::vector<Vec2>& b, Vec2& pa, Vec2& pb) {
  double best = std::numeric_limits<double>::infinity();
  auto try_side = [&](const std::vector<Vec2>& pts, const std::vector<Vec2>& poly, bool pts_are_a) {
    for (const Vec2& p : pts) {
      for (std::size_t i = 0; i < poly.size(); ++i) {
        const Vec2& q0 = poly[i];
        const Vec2 e = poly[(i + 1) % poly.size()] - q0;
        const double t = std::clamp((p - q0).dot(e) / e.squaredNorm(), 0.0, 1.0);
        const Vec2 q = q0 + t * e;
        const double d = (p - q).norm();
        if (d < best) {
          best = d;
          pa = pts_are_a ? p : q;
          pb = pts_are_a ? q : p;
        }
      }
    }
  };
  try_side(a, b, true);
  try_side(b, a, false);
  return best;
}

// Two convex polygons (SPEC §1: one force per pair). Apart: their distance.
// Overlapping: the separating axis test gives the penetration delta, the
// least overlap along a face normal (the minimum translation), and that face
// (the reference face) the normal; the other polygon's face most against it
// (the incident face), clipped to the reference face's extent, gives the
// points pressed below it, and the force acts at their depth-weighted
// centroid: a face flat on a face, however much of it overlaps, is one
// contact at the middle of the overlap (Catto, "Contact manifolds", GDC
// 2007, and Box2D's b2CollidePolygons for the clipping; the centroid as the
// half-plane's rule above). A body's vertex exactly on the other's side line
// (two equal boxes stacked) counts at its depth below the reference face,
// which the outline's nearest-boundary depth puts at 0.
ContactGeometry polygon_polygon(const std::vector<Vec2>& la, const Pose& pose_a,
                                const std::vector<Vec2>& lb, const Pose& pose_b,
                                std::vector<Vec2>& a, std::vector<Vec2>& b) {
  place_vertices(la, pose_a, a);
  place_vertices(lb, pose_b, b);
  std::size_t face_a = 0, face_b = 0;
  const double sep_a = max_separation(a, b, face_a);
  const double sep_b = max_separation(b, a, face_b);
  ContactGeometry g;
  if (sep_a > 0.0 || sep_b > 0.0) {
    g.gap_m = polygon_distance(a, b, g.point_a_m, g.point_b_m);
    const Vec2 d = g.point_b_m - g.point_a_m;
    // touching within rounding: the separating face's normal
    g.normal = d.norm() > 1e-12 * (1.0 + g.point_a_m.norm())
                   ? Vec2(d.normalized())
                   : (sep_a >= sep_b ? edge_normal(a, face_a) : Vec2(-edge_normal(b, face_b)));
    return g;
  }
  // the reference face: a's unless b's separation is clearly the larger (a
  // tie, two faces flat on each other, keeps a's: no flip with rounding)
  const double scale = 1.0 + std::max(pose_a.position_m.norm(), pose_b.position_m.norm());
  const bool ref_is_a = !(sep_b > sep_a + 1e-12 * scale);
  const std::vector<Vec2>& ref = ref_is_a ? a : b;
  const std::vector<Vec2>& inc = ref_is_a ? b : a;
  const std::size_t rf = ref_is_a ? face_a : face_b;
  const Vec2 nr = edge_normal(ref, rf);  // outward of the reference body
  const Vec2 r0 = ref[rf];
  const Vec2 r1 = ref[(rf + 1) % ref.size()];
  const Vec2 tangent = (r1 - r0).normalized();
  // the incident face: its outward normal most against nr
  std::size_t inc_face = 0;
  double most = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < inc.size(); ++i) {
    const double c = edge_normal(inc, i).dot(nr);
    if (c < most) {
      most = c;
      inc_face = i;
    }
  }
  Vec2 p0 = inc[inc_face];
  Vec2 p1 = inc[(inc_face + 1) % inc.size()];
  // clipped to the reference face's extent along its tangent
  const double lo = tangent.dot(r0);
  const double hi = tangent.dot(r1);
  auto clip = [&](double bound, double sign) {
    const double d0 = sign * (tangent.dot(p0) - bound);
    const double d1 = sign * (tangent.dot(p1) - bound);
    if (d0 < 0.0 && d1 < 0.0) return false;
    if (d0 < 0.0) p0 = p0 + (p1 - p0) * (d0 / (d0 - d1));
    if (d1 < 0.0) p1 = p1 + (p0 - p1) * (d1 / (d1 - d0));
    return true;
  };
  const double delta = -std::max(sep_a, sep_b);
  // the points pressed below the reference face, by depth
  double w_sum = 0.0;
  Vec2 p_sum = Vec2::Zero();
  double s_sum = 0.0, ss_sum = 0.0;
  if (clip(lo, 1.0) && clip(hi, -1.0)) {
    for (const Vec2& p : {p0, p1}) {
      const double depth = -nr.dot(p - r0);
      if (!(depth > 0.0)) continue;
      w_sum += depth;
      p_sum += depth * p;
      const double s = tangent.dot(p);
      s_sum += depth * s;
      ss_sum += depth * s * s;
    }
  }
  Vec2 point = inc[inc_face];  // on the incident body
  if (w_sum > 0.0) {
    point = p_sum / w_sum;
    const double mean = s_sum / w_sum;
    g.spread_m2 = std::max(0.0, ss_sum / w_sum - mean * mean);
  } else {
    // no point of the incident face below the reference face within its
    // extent (corner against corner): the incident body's deepest vertex
    double deepest = -std::numeric_limits<double>::infinity();
    for (const Vec2& v : inc) {
      const double depth = -nr.dot(v - r0);
      if (depth > deepest) {
        deepest = depth;
        point = v;
      }
    }
  }
  g.gap_m = -delta;
  if (ref_is_a) {
    // b's points are inside a, delta below a's face along -n
    g.normal = nr;
    g.point_b_m = point;
    g.point_a_m = point + delta * g.normal;
  } else {
    g.normal = -nr;
    g.point_a_m = point;
    g.point_b_m = point - delta * g.normal;
  }
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
  if (std::holds_alternative<Polygon>(first_) && std::holds_alternative<Polygon>(second_)) {
    local_first_ = std::get<Polygon>(first_).points_m;
    local_second_ = std::get<Polygon>(second_).points_m;
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
  } else if (!local_first_.empty()) {
    g = polygon_polygon(local_first_, p1, local_second_, p2, world_first_, world_second_);
  } else {
    g = halfplane_polygon(p1, polygon_, p2);
  }
  return swapped_ ? g.swapped() : g;
}

}  // namespace pb
