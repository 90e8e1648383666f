#include "box2d_inject_geometry.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "planarbench/ellipse_distance.hpp"

namespace pb::internal::box2d {

namespace {

using Rot = Eigen::Rotation2Dd;

// support point of a shape in world direction d (the point furthest along d)
Vec2 support_point(const Shape& shape, const Pose& pose, const Vec2& d) {
  const Rot rot(pose.angle_rad);
  if (const auto* c = std::get_if<Circle>(&shape)) return pose.position_m + c->radius_m * d;
  if (const auto* e = std::get_if<Ellipse>(&shape)) {
    // maximise u.x over (a cos t, b sin t): x = (a^2 u_x, b^2 u_y) / sqrt(a^2 u_x^2 + b^2 u_y^2)
    const Vec2 u = rot.inverse() * d;
    const double a2 = e->semi_axis_a_m * e->semi_axis_a_m;
    const double b2 = e->semi_axis_b_m * e->semi_axis_b_m;
    const Vec2 local =
        Vec2(a2 * u.x(), b2 * u.y()) / std::sqrt(a2 * u.x() * u.x() + b2 * u.y() * u.y());
    return pose.position_m + rot * local;
  }
  const auto& poly = std::get<Polygon>(shape);
  Vec2 best = pose.position_m;
  double best_h = -std::numeric_limits<double>::infinity();
  for (const auto& v : poly.points_m) {
    const Vec2 w = pose.position_m + rot * v;
    if (w.dot(d) > best_h) {
      best_h = w.dot(d);
      best = w;
    }
  }
  return best;
}

// half-plane a (surface = body x axis, outward normal = body +y) against any
// convex shape b: the support point of b against the normal
PrimitiveContact halfplane_contact(const Pose& pa, const Shape& b, const Pose& pb) {
  const Vec2 n = Rot(pa.angle_rad) * Vec2(0.0, 1.0);
  const Vec2 s = support_point(b, pb, -n);
  const double gap = n.dot(s - pa.position_m);
  return PrimitiveContact{-gap, n, s - 0.5 * gap * n};
}

PrimitiveContact circle_circle(const Circle& a, const Pose& pa, const Circle& b, const Pose& pb) {
  const Vec2 d = pb.position_m - pa.position_m;
  const double dist = d.norm();
  const Vec2 n = dist > 0.0 ? Vec2(d / dist) : Vec2(0.0, 1.0);
  const double gap = dist - a.radius_m - b.radius_m;
  const Vec2 on_a = pa.position_m + a.radius_m * n;
  const Vec2 on_b = pb.position_m - b.radius_m * n;
  return PrimitiveContact{-gap, n, 0.5 * (on_a + on_b)};
}

// ellipse a against circle b: closest boundary point q of a to b's centre;
// the normal is the ellipse's outward normal at q (= (c - q)/|c - q| outside)
PrimitiveContact ellipse_circle(const Ellipse& e, const Pose& pa, const Circle& c, const Pose& pb) {
  const Rot rot(pa.angle_rad);
  const Vec2 p = rot.inverse() * (pb.position_m - pa.position_m);
  const double a = e.semi_axis_a_m;
  const double b = e.semi_axis_b_m;
  // the shared Eberly solution: signed distance < 0 when the centre is inside
  const EllipseClosestPoint q = pb::closest_point_on_ellipse(a, b, p);
  const Vec2 n = rot * q.outward_normal;
  const double gap = q.signed_distance_m - c.radius_m;
  const Vec2 on_a = pa.position_m + rot * q.point_m;
  const Vec2 on_b = pb.position_m - c.radius_m * n;
  return PrimitiveContact{-gap, n, 0.5 * (on_a + on_b)};
}

// polygon a against circle b: closest point on the polygon's boundary
PrimitiveContact polygon_circle(const Polygon& poly, const Pose& pa, const Circle& c,
                                const Pose& pb) {
  const Rot rot(pa.angle_rad);
  const Vec2 p = rot.inverse() * (pb.position_m - pa.position_m);
  const auto& v = poly.points_m;
  const std::size_t n = v.size();
  double best = std::numeric_limits<double>::infinity();
  Vec2 q = v[0];
  Vec2 edge_normal = Vec2(0.0, 1.0);
  bool inside = false;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& v1 = v[i];
    const Vec2& v2 = v[(i + 1) % n];
    const Vec2 e = v2 - v1;
    const double s = std::clamp((p - v1).dot(e) / e.squaredNorm(), 0.0, 1.0);
    const Vec2 foot = v1 + s * e;
    const double d = (p - foot).norm();
    if (d < best) {
      best = d;
      q = foot;
      edge_normal = Vec2(e.y(), -e.x()).normalized();
    }
    // crossing-number point-in-polygon test
    if ((v1.y() > p.y()) != (v2.y() > p.y()) && p.x() < v1.x() + (p.y() - v1.y()) * e.x() / e.y()) {
      inside = !inside;
    }
  }
  Vec2 n_local = edge_normal;
  if (best > 1e-12) n_local = inside ? Vec2((q - p) / best) : Vec2((p - q) / best);
  const Vec2 nw = rot * n_local;
  const double gap = inside ? -(best + c.radius_m) : best - c.radius_m;
  const Vec2 on_a = pa.position_m + rot * q;
  const Vec2 on_b = pb.position_m - c.radius_m * nw;
  return PrimitiveContact{-gap, nw, 0.5 * (on_a + on_b)};
}

// the contact with a and b swapped back: the normal flips, the rest stays
PrimitiveContact flipped(PrimitiveContact c) {
  c.normal = -c.normal;
  return c;
}

bool is_circle(const Shape& s) {
  return std::holds_alternative<Circle>(s);
}
bool is_halfplane(const Shape& s) {
  return std::holds_alternative<HalfPlane>(s);
}

}  // namespace

Vec2 closest_point_on_ellipse(double a_m, double b_m, const Vec2& p_m) {
  // the shared implementation (planarbench/ellipse_distance.hpp), point only
  return pb::closest_point_on_ellipse(a_m, b_m, p_m).point_m;
}

std::string primitive_contact_unsupported_reason(const Shape& a, const Shape& b) {
  const bool ok = (is_halfplane(a) != is_halfplane(b)) || (is_circle(a) && !is_halfplane(b)) ||
                  (is_circle(b) && !is_halfplane(a));
  if (ok) return "";
  return std::string("no closed-form contact geometry for ") + shape_type_name(a) + "-" +
         shape_type_name(b) +
         " (injection mode supports half-plane with any convex shape, "
         "circle with circle, ellipse or polygon)";
}

PrimitiveContact primitive_contact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb) {
  if (is_halfplane(a)) return halfplane_contact(pa, b, pb);
  if (is_halfplane(b)) return flipped(halfplane_contact(pb, a, pa));
  if (const auto* ca = std::get_if<Circle>(&a)) {
    if (const auto* cb = std::get_if<Circle>(&b)) return circle_circle(*ca, pa, *cb, pb);
    if (const auto* eb = std::get_if<Ellipse>(&b)) return flipped(ellipse_circle(*eb, pb, *ca, pa));
    return flipped(polygon_circle(std::get<Polygon>(b), pb, *ca, pa));
  }
  const auto& cb = std::get<Circle>(b);
  if (const auto* ea = std::get_if<Ellipse>(&a)) return ellipse_circle(*ea, pa, cb, pb);
  return polygon_circle(std::get<Polygon>(a), pa, cb, pb);
}

}  // namespace pb::internal::box2d
