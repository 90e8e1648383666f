#include "exact_gap.hpp"

#include <cmath>
#include <utility>
#include <variant>

#include "planarbench/ellipse_distance.hpp"

namespace pb::internal {

namespace {

Vec2 rotated(const Vec2& v, double angle_rad) {
  const double c = std::cos(angle_rad);
  const double s = std::sin(angle_rad);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

// the three supported kinds, in the order the pair functions take them
int shape_rank(const Shape& s) {
  if (std::holds_alternative<HalfPlane>(s)) return 0;
  if (std::holds_alternative<Ellipse>(s)) return 1;
  if (std::holds_alternative<Circle>(s)) return 2;
  return -1;
}

// outward normal of a half-plane body: body +y
Vec2 half_plane_normal(const Pose& p) {
  return rotated(Vec2(0.0, 1.0), p.angle_rad);
}

ExactGap half_plane_circle(const Pose& ph, const Circle& c, const Pose& pc) {
  ExactGap g;
  g.normal = half_plane_normal(ph);
  const double height = (pc.position_m - ph.position_m).dot(g.normal);
  g.gap_m = height - c.radius_m;
  g.point_a_m = pc.position_m - height * g.normal;
  g.point_b_m = pc.position_m - c.radius_m * g.normal;
  return g;
}

ExactGap half_plane_ellipse(const Pose& ph, const Ellipse& e, const Pose& pe) {
  ExactGap g;
  g.normal = half_plane_normal(ph);
  // the ellipse's support point toward the line, direction -n in its frame
  const Vec2 d = rotated(-g.normal, -pe.angle_rad);
  const double a2 = e.semi_axis_a_m * e.semi_axis_a_m;
  const double b2 = e.semi_axis_b_m * e.semi_axis_b_m;
  const double h = std::sqrt(a2 * d.x() * d.x() + b2 * d.y() * d.y());
  const Vec2 support = pe.position_m + rotated(Vec2(a2 * d.x() / h, b2 * d.y() / h), pe.angle_rad);
  g.gap_m = (support - ph.position_m).dot(g.normal);
  g.point_b_m = support;
  g.point_a_m = support - g.gap_m * g.normal;
  return g;
}

ExactGap ellipse_circle(const Ellipse& e, const Pose& pe, const Circle& c, const Pose& pc) {
  const double a = e.semi_axis_a_m;
  const double b = e.semi_axis_b_m;
  const Vec2 local = rotated(pc.position_m - pe.position_m, -pe.angle_rad);
  // the shared Eberly solution; its outward normal is (x / a^2, y / b^2) normalised
  const EllipseClosestPoint q = pb::closest_point_on_ellipse(a, b, local);
  ExactGap g;
  g.normal = rotated(q.outward_normal, pe.angle_rad);
  g.gap_m = q.signed_distance_m - c.radius_m;
  g.point_a_m = pe.position_m + rotated(q.point_m, pe.angle_rad);
  g.point_b_m = pc.position_m - c.radius_m * g.normal;
  return g;
}

ExactGap circle_circle(const Circle& ca, const Pose& pa, const Circle& cb, const Pose& pb) {
  const Vec2 d = pb.position_m - pa.position_m;
  const double dist = d.norm();
  ExactGap g;
  g.normal = dist > 0.0 ? Vec2(d / dist) : Vec2(1.0, 0.0);
  g.gap_m = dist - ca.radius_m - cb.radius_m;
  g.point_a_m = pa.position_m + ca.radius_m * g.normal;
  g.point_b_m = pb.position_m - cb.radius_m * g.normal;
  return g;
}

}  // namespace

EllipseClosest closest_point_on_ellipse(double a_m, double b_m, const Vec2& p_m) {
  // a view of the shared implementation (planarbench/ellipse_distance.hpp)
  const EllipseClosestPoint q = pb::closest_point_on_ellipse(a_m, b_m, p_m);
  EllipseClosest r;
  r.point = q.point_m;
  r.signed_distance_m = q.signed_distance_m;
  return r;
}

bool exact_gap_supported(const Shape& a, const Shape& b) {
  const int ra = shape_rank(a);
  const int rb = shape_rank(b);
  if (ra < 0 || rb < 0) return false;  // polygons
  if (ra == rb) return ra == 2;        // circle-circle only
  return true;
}

ExactGap exact_gap(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb) {
  // evaluate with the lower rank first, then turn the result around
  if (shape_rank(a) > shape_rank(b)) {
    ExactGap g = exact_gap(b, pb, a, pa);
    g.normal = -g.normal;
    std::swap(g.point_a_m, g.point_b_m);
    return g;
  }
  if (std::holds_alternative<HalfPlane>(a)) {
    if (const auto* c = std::get_if<Circle>(&b)) return half_plane_circle(pa, *c, pb);
    return half_plane_ellipse(pa, std::get<Ellipse>(b), pb);
  }
  if (const auto* e = std::get_if<Ellipse>(&a)) {
    return ellipse_circle(*e, pa, std::get<Circle>(b), pb);
  }
  return circle_circle(std::get<Circle>(a), pa, std::get<Circle>(b), pb);
}

}  // namespace pb::internal
