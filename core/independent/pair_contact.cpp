#include "pair_contact.hpp"

#include <fmt/format.h>

#include <cmath>
#include <variant>

#include "ellipse_closest_point.hpp"
#include "planarbench/errors.hpp"
#include "plane_rotation.hpp"

namespace pb::independent {

namespace {

bool is_line(const Shape& s) {
  return std::holds_alternative<HalfPlane>(s);
}
bool is_circle(const Shape& s) {
  return std::holds_alternative<Circle>(s);
}
bool is_ellipse(const Shape& s) {
  return std::holds_alternative<Ellipse>(s);
}

// body `other` against the half-plane `line`; the normal from the line into other
PairContact against_line(const BodyMotion& line, const Shape& other, const BodyMotion& mo) {
  const Vec2 n = rotate(line.pose.angle_rad, Vec2(0.0, 1.0));  // outward normal (body +y)
  const Vec2 p0 = line.pose.centre_m;
  const SupportPoint sp = support_point(other, mo.pose, -n);
  const double centre_height = n.dot(mo.pose.centre_m - p0);
  PairContact c;
  c.depth_m = sp.reach_m - centre_height;
  c.next_vertex_depth_m = sp.next_reach_m - centre_height;
  c.vertex = sp.vertex;
  c.normal = n;
  c.point_a_m = sp.point_m + c.depth_m * n;  // its projection onto the line
  c.point_b_m = sp.point_m;
  return c;
}

// the disk `disk` against the ellipse `ell`; the normal from the ellipse to the disk
PairContact disk_ellipse(const Ellipse& ell, const BodyMotion& me, double radius_m,
                         const BodyMotion& md) {
  const Vec2 query = rotate(-me.pose.angle_rad, md.pose.centre_m - me.pose.centre_m);
  const EllipseNearest q = nearest_on_ellipse(ell.semi_axis_a_m, ell.semi_axis_b_m, query);
  if (!q.outside || !(q.distance_m > 0.0)) {
    throw EngineError(
        "independent truth: the disk's centre reached the ellipse: the penetration of a disk "
        "against an ellipse is defined here only with the centre outside it");
  }
  const Vec2 qw = me.pose.centre_m + rotate(me.pose.angle_rad, q.point_m);
  PairContact c;
  c.normal = (md.pose.centre_m - qw) / q.distance_m;
  c.depth_m = radius_m - q.distance_m;
  c.point_a_m = qw;
  c.point_b_m = md.pose.centre_m - radius_m * c.normal;
  return c;
}

PairContact flipped(PairContact c) {
  std::swap(c.point_a_m, c.point_b_m);
  c.normal = -c.normal;
  return c;
}

}  // namespace

Vec2 point_velocity(const BodyMotion& m, const Vec2& x_m) {
  const Vec2 r = x_m - m.pose.centre_m;
  return m.velocity_mps + m.angular_velocity_radps * Vec2(-r.y(), r.x());
}

std::string pair_contact_unsupported(const Body& a, const Body& b) {
  const Shape& sa = a.shape;
  const Shape& sb = b.shape;
  if (is_line(sa) || is_line(sb)) {
    const Body& line = is_line(sa) ? a : b;
    const Body& other = is_line(sa) ? b : a;
    if (is_line(other.shape)) return "two half-planes";
    if (!line.fixed) return fmt::format("the half-plane '{}' moves (a fixed one only)", line.name);
    if (other.fixed) return "both bodies fixed";
    return {};
  }
  if ((is_circle(sa) && is_ellipse(sb)) || (is_ellipse(sa) && is_circle(sb))) return {};
  return fmt::format(
      "shapes {} and {}: the independent truth covers a fixed half-plane against a circle, "
      "ellipse or polygon, and a circle against an ellipse",
      shape_type_name(sa), shape_type_name(sb));
}

PairContact pair_contact(const Shape& a, const BodyMotion& ma, const Shape& b,
                         const BodyMotion& mb) {
  PairContact c;
  if (is_line(a)) {
    c = against_line(ma, b, mb);
  } else if (is_line(b)) {
    c = flipped(against_line(mb, a, ma));
  } else if (is_ellipse(a)) {
    c = disk_ellipse(std::get<Ellipse>(a), ma, std::get<Circle>(b).radius_m, mb);
  } else {
    c = flipped(disk_ellipse(std::get<Ellipse>(b), mb, std::get<Circle>(a).radius_m, ma));
  }
  c.depth_rate_mps =
      -c.normal.dot(point_velocity(mb, c.point_b_m) - point_velocity(ma, c.point_a_m));
  return c;
}

}  // namespace pb::independent
