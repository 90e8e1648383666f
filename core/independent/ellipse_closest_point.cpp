#include "ellipse_closest_point.hpp"

#include <cmath>
#include <utility>

namespace pb::independent {

namespace {

// F(s) of Eberly §2 in the scaled form: with z_i = y_i / e_i and
// r = (e0 / e1)^2, t = e1^2 s and F(s) = (r z0 / (s + r))^2 + (z1 / (s + 1))^2 - 1;
// its root s lies in [z1 - 1, |(r z0, z1)| - 1] when F(0) >= 0 (outside).
double scaled_root(double r, double z0, double z1) {
  const double n0 = r * z0;
  double lo = z1 - 1.0;                  // F(lo) >= 0
  double hi = std::hypot(n0, z1) - 1.0;  // F(hi) <= 0
  double s = lo;
  for (int i = 0; i < 2200; ++i) {  // 2200 halvings exhaust any double interval
    s = 0.5 * (lo + hi);
    if (s == lo || s == hi) break;
    const double f0 = n0 / (s + r);
    const double f1 = z1 / (s + 1.0);
    const double f = f0 * f0 + f1 * f1 - 1.0;
    if (f > 0.0) {
      lo = s;
    } else if (f < 0.0) {
      hi = s;
    } else {
      break;
    }
  }
  return s;
}

// first quadrant, e0 >= e1 > 0, y0, y1 >= 0, query outside
Vec2 nearest_first_quadrant(double e0, double e1, double y0, double y1) {
  if (y1 > 0.0) {
    if (y0 > 0.0) {
      const double z0 = y0 / e0;
      const double z1 = y1 / e1;
      const double r = (e0 / e1) * (e0 / e1);
      const double s = scaled_root(r, z0, z1);
      return {r * y0 / (s + r), y1 / (s + 1.0)};
    }
    return {0.0, e1};  // on the minor axis: the co-vertex
  }
  // on the major axis outside the ellipse: the vertex (the evolute's branch
  // x0 = e0 y0 / (e0^2 - e1^2) needs y0 < (e0^2 - e1^2) / e0 < e0, i.e. inside)
  return {e0, 0.0};
}

}  // namespace

EllipseNearest nearest_on_ellipse(double semi_x_m, double semi_y_m, const Vec2& query_m) {
  EllipseNearest out;
  const double qx = query_m.x();
  const double qy = query_m.y();
  const double level = (qx / semi_x_m) * (qx / semi_x_m) + (qy / semi_y_m) * (qy / semi_y_m);
  if (!(level > 1.0)) {
    out.outside = false;
    return out;
  }
  // the larger semi-axis first (Eberly's e0 >= e1)
  const bool swapped = semi_y_m > semi_x_m;
  const double e0 = swapped ? semi_y_m : semi_x_m;
  const double e1 = swapped ? semi_x_m : semi_y_m;
  const double y0 = std::abs(swapped ? qy : qx);
  const double y1 = std::abs(swapped ? qx : qy);
  Vec2 p = nearest_first_quadrant(e0, e1, y0, y1);
  if (swapped) p = Vec2(p.y(), p.x());
  out.point_m = Vec2(std::copysign(p.x(), qx), std::copysign(p.y(), qy));
  out.distance_m = (query_m - out.point_m).norm();
  return out;
}

}  // namespace pb::independent
