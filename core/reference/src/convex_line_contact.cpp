#include "planarbench/reference/convex_line_contact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>
#include <variant>

#include "outline_kernels.hpp"
#include "planarbench/outline.hpp"
#include "planarbench/reference/outline_contact.hpp"

namespace pb {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// steps a warm walk along a chain may take before a binary search is cheaper
constexpr int kWarmSteps = 8;
// a point of C below the surface by d is nearer the surface than the closing
// edges of the half-plane's outline (45 deg) when its distance along the line
// from the segment's ends exceeds (1 + sqrt 2) d (header)
constexpr double kClosingEdgeFactor = 1.0 + std::numbers::sqrt2;
// rad: a face of C tied with the deepest vertex is answered when it is level
// with the surface to within this angle (header)
constexpr double kLevelTilt = 1e-10;
// Two depths closer than this may be ordered either way by the brute force's
// rounding (a depth is a few roundings of world coordinates of size scale:
// ~1e-14 relative; ten times that, plus a floor)
constexpr double kTieRelative = 1e-13;   // -
constexpr double kTieAbsolute_m = 1e-15;  // m

// Strictly convex, counter-clockwise and simple: every turn strictly left and
// the turns adding up to one revolution (not two or more: a star polygon).
bool strictly_convex(const std::vector<Vec2>& q) {
  const std::size_t n = q.size();
  if (n < 3) return false;
  double turning = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 e0 = q[(i + 1) % n] - q[i];
    const Vec2 e1 = q[(i + 2) % n] - q[(i + 1) % n];
    const double c = cross2(e0, e1);
    if (!(c > 0.0)) return false;
    turning += std::atan2(c, e0.dot(e1));
  }
  // one revolution is 2 pi; the next possible total is 4 pi
  return std::abs(turning - kTwoPi) < 1.0;
}

}  // namespace

std::optional<ConvexLineContact> ConvexLineContact::make(const Shape& a, int n_a, const Shape& b,
                                                         int n_b) {
  const bool a_line = std::holds_alternative<HalfPlane>(a);
  const bool b_line = std::holds_alternative<HalfPlane>(b);
  if (a_line == b_line) return std::nullopt;
  const Shape& convex = a_line ? b : a;
  const int n_convex = a_line ? n_b : n_a;
  const auto& plane = std::get<HalfPlane>(a_line ? a : b);
  const int n_line = a_line ? n_a : n_b;
  std::vector<Vec2> q = contact_outline(convex, n_convex);
  if (!strictly_convex(q)) return std::nullopt;
  std::vector<double> surface_x;
  for (const Vec2& p : make_outline(plane, n_line)) surface_x.push_back(p.x());
  for (std::size_t i = 1; i < surface_x.size(); ++i) {
    if (!(surface_x[i] < surface_x[i - 1])) return std::nullopt;
  }
  return ConvexLineContact(std::move(q), std::move(surface_x), plane.extent_m, a_line);
}

ConvexLineContact::ConvexLineContact(std::vector<Vec2> convex_m, std::vector<double> surface_x_m,
                                     double extent_m, bool line_is_a)
    : q_(std::move(convex_m)),
      surface_x_(std::move(surface_x_m)),
      half_extent_m_(0.5 * extent_m),
      n_(static_cast<int>(q_.size())),
      line_is_a_(line_is_a) {
  const auto n = static_cast<std::size_t>(n_);
  normal_angle_.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    const Vec2 e = q_[(j + 1) % n] - q_[j];
    const double raw = std::atan2(-e.x(), e.y());  // outward normal (e_y, -e_x)
    // unwrapped: each edge turns the normal left by (0, pi)
    normal_angle_[j] = j == 0 ? raw : normal_angle_[j - 1] + std::remainder(raw - normal_angle_[j - 1], kTwoPi);
  }
  s1x_.assign(n + 1, 0.0L);
  s1y_.assign(n + 1, 0.0L);
  s2xx_.assign(n + 1, 0.0L);
  s2xy_.assign(n + 1, 0.0L);
  s2yy_.assign(n + 1, 0.0L);
  for (std::size_t i = 0; i < n; ++i) {
    const long double x = q_[i].x();
    const long double y = q_[i].y();
    s1x_[i + 1] = s1x_[i] + x;
    s1y_[i + 1] = s1y_[i] + y;
    s2xx_[i + 1] = s2xx_[i] + x * x;
    s2xy_[i + 1] = s2xy_[i] + x * y;
    s2yy_[i + 1] = s2yy_[i] + y * y;
    radius_m_ = std::max(radius_m_, q_[i].norm());
  }
}

// The vertex between the edges whose outward normals bracket `direction`:
// the first edge whose normal angle is at least the direction's (angles taken
// in [angle_0, angle_0 + 2 pi)) starts at it.
int ConvexLineContact::support(const Vec2& direction) const {
  const double first = normal_angle_.front();
  double theta = std::atan2(direction.y(), direction.x());
  theta = first + std::fmod(std::fmod(theta - first, kTwoPi) + kTwoPi, kTwoPi);
  const auto it = std::lower_bound(normal_angle_.begin(), normal_angle_.end(), theta);
  const auto j = static_cast<int>(it - normal_angle_.begin());
  return j == n_ ? 0 : j;
}

// downhill (least m . q) from k; the heights along a strictly convex outline
// have one minimum, so the walk ends there
int ConvexLineContact::walk_down(int k, const Vec2& m) {
  double hk = height(k, m);
  const double h_prev = height(prev(k), m);
  const int step_back = h_prev < hk;
  if (step_back) {
    k = prev(k);
    hk = h_prev;
  }
  for (int steps = 0; steps < n_; ++steps) {
    const int j = step_back ? prev(k) : next(k);
    const double hj = height(j, m);
    if (!(hj < hk)) break;
    k = j;
    hk = hj;
  }
  return k;
}

int ConvexLineContact::walk_up(int k, const Vec2& m) { return walk_down(k, Vec2(-m)); }

// The last vertex below the surface (height + s < 0) on the chain from the
// lowest vertex k to the highest `top`, stepping by `step` (+1 or -1), along
// which the heights do not decrease. k is below, top is not. From `guess`
// (the last evaluation's end) by a walk of at most kWarmSteps, else by a
// binary search of the chain.
int ConvexLineContact::run_end(int k, int top, int step, int guess, const Vec2& m, double s) {
  auto offset = [&](int j) { return step > 0 ? (j - k + n_) % n_ : (k - j + n_) % n_; };
  auto at = [&](int o) { return step > 0 ? (k + o) % n_ : (k - o % n_ + n_) % n_; };
  auto below = [&](int o) { return height(at(o), m) + s < 0.0; };
  const int length = offset(top);
  if (has_history_) {
    int o = offset(guess);
    if (o < length) {
      if (below(o)) {
        for (int steps = 0; steps < kWarmSteps; ++steps) {
          if (!below(o + 1)) return at(o);
          ++o;
        }
      } else {
        for (int steps = 0; steps < kWarmSteps && o > 0; ++steps) {
          --o;
          if (below(o)) return at(o);
        }
      }
    }
  }
  int lo = 0, hi = length;  // below at lo, not at hi
  while (hi - lo > 1) {
    const int mid = lo + (hi - lo) / 2;
    (below(mid) ? lo : hi) = mid;
  }
  return at(lo);
}

// Surface vertices strictly between u0 < u1 (m along the line), counting as
// `ambiguous` those within `margin` of either end; the certain ones are
// first, first + 1, ...
int ConvexLineContact::surface_count_between(double u0, double u1, double margin, int& ambiguous,
                                             int& first) {
  // surface_x_ descends: the vertices beyond a value form a prefix
  auto beyond = [&](double v, bool or_equal) {
    const auto it = std::partition_point(surface_x_.begin(), surface_x_.end(), [&](double x) {
      ++work_.surface_probes;
      return or_equal ? x >= v : x > v;
    });
    return static_cast<int>(it - surface_x_.begin());
  };
  first = beyond(u1 - margin, true);
  const int certain = std::max(0, beyond(u0 + margin, false) - first);
  const int possible = beyond(u0 - margin, true) - beyond(u1 + margin, false);
  ambiguous = possible - certain;
  return certain;
}

// The depth-weighted centroid of C's run lo .. hi (count points), world;
// `fallback` when the depths sum to zero.
Vec2 ConvexLineContact::body_centroid(int lo, int hi, int count, const Vec2& m, double s,
                                      const Eigen::Matrix2d& r_body, const Vec2& x_body,
                                      const Vec2& fallback) {
  long double w_sum = 0.0L;
  long double qx_sum = 0.0L, qy_sum = 0.0L;
  if (count <= kDirectSumPoints) {
    for (int o = 0, i = lo; o < count; ++o, i = next(i)) {
      ++work_.summed_points;
      const Vec2& q = q_[static_cast<std::size_t>(i)];
      const double w = -(m.dot(q) + s);
      w_sum += w;
      qx_sum += w * q.x();
      qy_sum += w * q.y();
    }
  } else {
    // sums over the cyclic range lo .. hi from the prefix sums
    auto range = [&](const std::vector<long double>& p) {
      const auto l = static_cast<std::size_t>(lo);
      const auto h1 = static_cast<std::size_t>(hi) + 1;
      return lo <= hi ? p[h1] - p[l] : p.back() - p[l] + p[h1];
    };
    const long double sx = range(s1x_), sy = range(s1y_);
    const long double sxx = range(s2xx_), sxy = range(s2xy_), syy = range(s2yy_);
    const long double mx = m.x(), my = m.y(), sl = s;
    w_sum = -(mx * sx + my * sy + static_cast<long double>(count) * sl);
    qx_sum = -(sxx * mx + sxy * my + sl * sx);
    qy_sum = -(sxy * mx + syy * my + sl * sy);
  }
  if (!(w_sum > 0.0L)) return fallback;
  const Vec2 centroid(static_cast<double>(qx_sum / w_sum), static_cast<double>(qy_sum / w_sum));
  return internal::place_point(r_body, x_body, centroid);
}

// The depth-weighted centroid of the surface vertices first .. first + count
// - 1, all inside C, world. A point inside a convex polygon is nearest the
// line of one of its edges, so its depth is the least distance to those
// lines (the brute force's distance to the boundary).
std::optional<Vec2> ConvexLineContact::surface_centroid(int first, int count,
                                                        const Eigen::Matrix2d& r_line,
                                                        const Vec2& x_line,
                                                        const Eigen::Matrix2d& r_body,
                                                        const Vec2& x_body) {
  std::array<Vec2, kSurfaceSidePolygonVertices> vertex, normal;
  const auto n = static_cast<std::size_t>(n_);
  for (std::size_t e = 0; e < n; ++e) vertex[e] = internal::place_point(r_body, x_body, q_[e]);
  for (std::size_t e = 0; e < n; ++e) {
    const Vec2 edge = vertex[(e + 1) % n] - vertex[e];
    normal[e] = internal::edge_outward_normal(edge.x(), edge.y());
  }
  double w_sum = 0.0, wu_sum = 0.0;
  for (int j = first; j < first + count; ++j) {
    ++work_.summed_points;
    const double u = surface_x_[static_cast<std::size_t>(j)];
    const Vec2 p = internal::place_point(r_line, x_line, Vec2(u, 0.0));
    double depth = std::numeric_limits<double>::infinity();
    for (std::size_t e = 0; e < n; ++e) depth = std::min(depth, normal[e].dot(vertex[e] - p));
    w_sum += depth;
    wu_sum += depth * u;
  }
  if (!(w_sum > 0.0)) return std::nullopt;
  return internal::place_point(r_line, x_line, Vec2(wu_sum / w_sum, 0.0));
}

std::optional<ContactGeometry> ConvexLineContact::evaluate(const Pose& pose_a, const Pose& pose_b) {
  work_ = LineSearchWork{};
  const Pose& line = line_is_a_ ? pose_a : pose_b;
  const Pose& body = line_is_a_ ? pose_b : pose_a;
  const Eigen::Matrix2d r_line = line.rotation();
  const Eigen::Matrix2d r_body = body.rotation();
  const Vec2 n = r_line.col(1);  // the surface's outward normal, world
  const Vec2 t = r_line.col(0);  // along the surface, world (body x of the half-plane)
  const Vec2 m = r_body.transpose() * n;  // n in C's body frame
  const Vec2 d = body.position_m - line.position_m;
  const double s = n.dot(d);  // m, height of C's origin
  const double uc = t.dot(d);  // m, C's origin along the line
  const double scale_m = std::max(body.position_m.cwiseAbs().maxCoeff() + radius_m_,
                                  line.position_m.cwiseAbs().maxCoeff() + half_extent_m_);
  const double margin = internal::rounding_margin_m(scale_m);

  // the deepest vertex; a neighbour tied with it must make a level face
  const int k = walk_down(has_history_ ? deepest_ : support(-m), m);
  const double h_body_k = height(k, m);
  const double hk = h_body_k + s;
  {
    const double h_prev = height(prev(k), m), h_next = height(next(k), m);
    const int j = h_prev < h_next ? prev(k) : next(k);
    const double rise_m = std::min(h_prev, h_next) - h_body_k;
    if (!(rise_m > kTieRelative * scale_m + kTieAbsolute_m)) {
      const double face_m = (q_[static_cast<std::size_t>(j)] - q_[static_cast<std::size_t>(k)]).norm();
      if (!(rise_m <= kLevelTilt * face_m)) return std::nullopt;
    }
  }
  // wholly over the surface segment, and nearer the surface than the closing edges
  const double allow = kClosingEdgeFactor * std::max(0.0, -hk) + margin;
  if (!(uc - radius_m_ > -half_extent_m_ + allow && uc + radius_m_ < half_extent_m_ - allow)) {
    return std::nullopt;
  }

  const Vec2 p_k = internal::place_point(r_body, body.position_m, q_[static_cast<std::size_t>(k)]);
  Vec2 point = p_k;  // on C: the closest point apart, the line of action's point overlapping
  if (hk < 0.0) {
    const int top = walk_up(has_history_ ? highest_ : support(m), m);
    int lo = 0, hi = n_ - 1, count = n_;
    int ambiguous_c = 0, ambiguous_l = 0, count_l = 0, first_l = 0;
    if (height(top, m) + s < 0.0) {
      // C wholly below the surface: every vertex inside, no surface vertex inside C
      highest_ = top;
    } else {
      hi = run_end(k, top, +1, hi_, m, s);
      lo = run_end(k, top, -1, lo_, m, s);
      count = (hi - lo + n_) % n_ + 1;
      const Vec2 mt = r_body.transpose() * t;  // t in C's body frame
      const double u_origin = uc;
      auto along = [&](int i) { return mt.dot(q_[static_cast<std::size_t>(i)]) + u_origin; };
      auto h = [&](int i) { return height(i, m) + s; };
      // where C's boundary crosses the line: on the edges leaving the run
      auto crossing = [&](int in, int out) {
        const double h_in = h(in), h_out = h(out);
        const double lambda = h_in / (h_in - h_out);
        return along(in) + lambda * (along(out) - along(in));
      };
      const double u_hi = crossing(hi, next(hi));
      const double u_lo = crossing(lo, prev(lo));
      count_l = surface_count_between(std::min(u_lo, u_hi), std::max(u_lo, u_hi), margin, ambiguous_l,
                                      first_l);
      for (const int i : {lo, hi, prev(lo), next(hi)}) {
        if (std::abs(h(i)) <= margin) ++ambiguous_c;
      }
      if (lo == hi && std::abs(h(lo)) <= margin) --ambiguous_c;  // counted twice
      highest_ = top;
      hi_ = hi;
      lo_ = lo;
    }
    if (count - ambiguous_c > count_l + ambiguous_l) {
      point = body_centroid(lo, hi, count, m, s, r_body, body.position_m, p_k);
    } else if (count_l - ambiguous_l > count + ambiguous_c && count_l <= kDirectSumPoints &&
               n_ <= kSurfaceSidePolygonVertices) {
      const std::optional<Vec2> on_line =
          surface_centroid(first_l, count_l, r_line, line.position_m, r_body, body.position_m);
      if (!on_line) return std::nullopt;
      point = *on_line + hk * n;
    } else {
      return std::nullopt;
    }
  }
  deepest_ = k;
  has_history_ = true;

  ContactGeometry g;
  g.gap_m = hk;
  g.normal = line_is_a_ ? n : Vec2(-n);
  const Vec2 on_line = point - hk * n;
  g.point_a_m = line_is_a_ ? on_line : point;
  g.point_b_m = line_is_a_ ? point : on_line;
  return g;
}

}  // namespace pb
