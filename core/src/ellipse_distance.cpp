#include "planarbench/ellipse_distance.hpp"

#include <algorithm>
#include <cmath>

namespace pb {

namespace {

// The root of G(s) = (r0 z0 / (s + r0))^2 + (z1 / (s + 1))^2 - 1, decreasing
// on s > -1, bracketed by [z1 - 1, 0] inside (g < 0) and [z1 - 1, |(r0 z0, z1)| - 1]
// outside (Eberly 2013, eqs. for GetRoot), returned as u = s + 1. The search
// runs on u, not s: near the major axis inside the ellipse the root is close
// to s = -1, where s + 1 computed from s would keep only the bits of s above
// 1e-16 (a relative error of 1e-16 / (s + 1) in the point's minor coordinate;
// 8e-14 off the ellipse measured at u = 3e-4). The bracket [z1, ...] is exact
// in u. Bisection until the midpoint no longer moves: full double precision
// without any tolerance to choose.
double bisect_root_plus_one(double r0, double z0, double z1, double g) {
  const double n0 = r0 * z0;
  const double r0_minus_1 = r0 - 1.0;  // s + r0 = u + (r0 - 1)
  double u0 = z1;
  double u1 = g < 0.0 ? 1.0 : std::hypot(n0, z1);
  double u = u0;
  // about 2100 halvings exhaust any bracket of doubles; the cap only bounds the loop
  for (int i = 0; i < 2200; ++i) {
    u = 0.5 * (u0 + u1);
    if (u == u0 || u == u1) break;
    const double ratio0 = n0 / (u + r0_minus_1);
    const double ratio1 = z1 / u;
    const double gs = ratio0 * ratio0 + ratio1 * ratio1 - 1.0;
    if (gs > 0.0) {
      u0 = u;
    } else if (gs < 0.0) {
      u1 = u;
    } else {
      break;
    }
  }
  return u;
}

// first quadrant, e0 >= e1 > 0, y0, y1 >= 0: the closest point (x0, x1),
// x_i = e_i^2 y_i / (t + e_i^2) with t = s e1^2 (Eberly 2013, section 2)
Vec2 closest_first_quadrant(double e0, double e1, double y0, double y1) {
  if (y1 > 0.0) {
    if (y0 > 0.0) {
      const double z0 = y0 / e0;
      const double z1 = y1 / e1;
      const double g = z0 * z0 + z1 * z1 - 1.0;
      if (g == 0.0) return Vec2(y0, y1);
      const double r0 = (e0 / e1) * (e0 / e1);
      const double u = bisect_root_plus_one(r0, z0, z1, g);
      return Vec2(r0 * y0 / (u + (r0 - 1.0)), y1 / u);
    }
    return Vec2(0.0, e1);
  }
  // on the major axis: inside its evolute segment the closest point leaves the axis
  const double numer0 = e0 * y0;
  const double denom0 = e0 * e0 - e1 * e1;
  if (numer0 < denom0) {
    const double xde0 = numer0 / denom0;
    // xde0 in [0, 1): the max only guards the square root against rounding
    return Vec2(e0 * xde0, e1 * std::sqrt(std::max(0.0, 1.0 - xde0 * xde0)));
  }
  return Vec2(e0, 0.0);
}

}  // namespace

EllipseClosestPoint closest_point_on_ellipse(double a_m, double b_m, const Vec2& p_m) {
  // the algorithm wants the longer axis first and the point in the first quadrant
  const bool swap_axes = a_m < b_m;
  const double e0 = swap_axes ? b_m : a_m;
  const double e1 = swap_axes ? a_m : b_m;
  const double q0 = swap_axes ? p_m.y() : p_m.x();
  const double q1 = swap_axes ? p_m.x() : p_m.y();
  const Vec2 x = closest_first_quadrant(e0, e1, std::abs(q0), std::abs(q1));
  const double x0 = std::copysign(x.x(), q0);
  const double x1 = std::copysign(x.y(), q1);

  EllipseClosestPoint out;
  out.point_m = swap_axes ? Vec2(x1, x0) : Vec2(x0, x1);
  // outward normal: the gradient of (x/a)^2 + (y/b)^2
  const Vec2 grad(out.point_m.x() / (a_m * a_m), out.point_m.y() / (b_m * b_m));
  out.outward_normal = grad.normalized();
  const double level = (p_m.x() / a_m) * (p_m.x() / a_m) + (p_m.y() / b_m) * (p_m.y() / b_m);
  const double dist = (p_m - out.point_m).norm();
  out.signed_distance_m = level < 1.0 ? -dist : dist;
  return out;
}

}  // namespace pb
