// The arithmetic that the brute-force outline search (outline_contact.cpp)
// and the fast one (fast_outline_contact.cpp) share, so that both compute the
// very same numbers: placing a vertex in the world, one point against one
// edge, one crossing-number step, the contact geometry of a chosen point and
// the depth-weighted centroid of a run of inside points. Every function here
// is the single definition of its formula; neither search repeats it.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "planarbench/reference/contact_geometry.hpp"
#include "planarbench/reference/outline_contact.hpp"

namespace pb::internal {

// a body-frame point placed in the world (the same expression, hence the same
// rounding, wherever a vertex is placed)
[[nodiscard]] inline Vec2 place_point(const Eigen::Matrix2d& rotation, const Vec2& position_m,
                                      const Vec2& local_m) {
  return position_m + rotation * local_m;
}

// Rounding allowance of a decision taken on world coordinates of size
// `scale_m` (m): each bound or height is a few dozen roundings of numbers of
// that size, ~1e-14 relative; 1e-10 leaves four orders of margin, plus an
// absolute floor of 1e-12 m.
[[nodiscard]] inline double rounding_margin_m(double scale_m) { return 1e-10 * scale_m + 1e-12; }

// what the point and crossing tests need of edge (x0, y0) -> (x1, y1)
struct EdgeData {
  double ex = 0.0, ey = 0.0;  // m, edge vector
  double inv_len2 = 0.0;      // 1/m^2, 1 / |e|^2 (0 for a degenerate edge)
  double x_per_y = 0.0;       // -, ex / ey (0 for a horizontal edge)
};

[[nodiscard]] inline EdgeData edge_data(double x0, double y0, double x1, double y1) {
  EdgeData e;
  e.ex = x1 - x0;
  e.ey = y1 - y0;
  const double len2 = e.ex * e.ex + e.ey * e.ey;
  e.inv_len2 = len2 > 0.0 ? 1.0 / len2 : 0.0;
  e.x_per_y = e.ey != 0.0 ? e.ex / e.ey : 0.0;
  return e;
}

// unit outward normal of a counter-clockwise outline's edge: the interior is
// on the left, the outward normal on the right (zero for a degenerate edge)
[[nodiscard]] inline Vec2 edge_outward_normal(double ex, double ey) {
  const double len = std::sqrt(ex * ex + ey * ey);
  return len > 0.0 ? Vec2(ey / len, -ex / len) : Vec2(0.0, 0.0);
}

// squared distance from (px, py) to the edge starting at (x0, y0), and the
// position t in [0, 1] of the nearest point on it (projection, clamped)
[[nodiscard]] inline double point_edge_distance2(double px, double py, double x0, double y0,
                                                 double ex, double ey, double inv_len2, double& t) {
  const double dx = px - x0;
  const double dy = py - y0;
  t = std::clamp((dx * ex + dy * ey) * inv_len2, 0.0, 1.0);
  const double rx = dx - t * ex;
  const double ry = dy - t * ey;
  return rx * rx + ry * ry;
}

// crossing number step: a ray from (px, py) towards +x crosses the edge
// (x0, y0) -> (x0 + ex, y1); half-open in y so that a vertex counts once
[[nodiscard]] inline bool ray_crosses_edge(double px, double py, double x0, double y0, double y1,
                                           double x_per_y) {
  return (y0 > py) != (y1 > py) && px < x0 + (py - y0) * x_per_y;
}

// one edge of the other body in the world, for the contact geometry
struct EdgeView {
  double x0 = 0.0, y0 = 0.0;  // m, start vertex
  double ex = 0.0, ey = 0.0;  // m, edge vector
  Vec2 normal = Vec2::Zero(); // unit outward normal
};

// The geometry of a chosen outline point p of one body and its nearest point
// on the other body (`hit`): the boundary point q, the outward normal m of
// the boundary feature there, and the a -> b orientation. `edge_of(e)` gives
// edge e of the other body (EdgeView), `other_n` its edge count.
// m: a point inside a wedge of the other outline (two faces meeting at a
// convex vertex) whose depths below the two faces agree within this is on the
// wedge's bisector: it is pushed out along the bisector, not along whichever
// face the rounding made nearer. Two sampled curves pressed vertex against
// vertex (head_on's disks) put each deepest vertex on the other's bisector;
// taking the nearer face flipped the normal by a whole edge angle (2 deg at
// 180 points) with the rounding of the positions, and with friction the slip
// direction with it, each flip located as an event (issue 35: 4e6 steps for
// 0.5 s). A picometre is far above the rounding of placed coordinates (1e-16
// m at 1 m) and below any depth difference a force would notice.
inline constexpr double kWedgeTie_m = 1e-12;

// the outward normal for an overlapping point p whose nearest feature is the
// interior of edge hit.edge: that edge's normal, or the bisector of it and
// the neighbouring face at its nearer end where p lies as deep below both
// (kWedgeTie_m) and the faces turn (collinear samples of a line keep theirs)
template <class EdgeOf>
[[nodiscard]] Vec2 wedge_normal(const Vec2& p, const BoundaryHit& hit, int other_n,
                                EdgeOf&& edge_of) {
  const int e = hit.edge;
  const EdgeView edge = edge_of(e);
  const int nb = hit.t < 0.5 ? (e + other_n - 1) % other_n : (e + 1) % other_n;
  const EdgeView next = edge_of(nb);
  // the faces must turn by more than their normals' rounding
  if ((next.normal - edge.normal).norm() <= 1e-9) return edge.normal;
  // depth of p below the neighbouring face's line, and its projection's place
  const Vec2 d(p.x() - next.x0, p.y() - next.y0);
  const double depth = -d.dot(next.normal);
  const double len2 = next.ex * next.ex + next.ey * next.ey;
  const double t = len2 > 0.0 ? (d.x() * next.ex + d.y() * next.ey) / len2 : -1.0;
  if (!(t >= 0.0 && t <= 1.0) || std::abs(depth - hit.distance_m) > kWedgeTie_m) {
    return edge.normal;
  }
  const Vec2 sum = edge.normal + next.normal;
  return sum.norm() > 0.0 ? Vec2(sum.normalized()) : edge.normal;
}

template <class EdgeOf>
[[nodiscard]] ContactGeometry hit_geometry(const Vec2& p, const BoundaryHit& hit, bool of_a,
                                           bool overlapping, int other_n, EdgeOf&& edge_of) {
  const int e = hit.edge;
  const EdgeView edge = edge_of(e);
  const Vec2 q(edge.x0 + hit.t * edge.ex, edge.y0 + hit.t * edge.ey);

  // outward normal of the other body at q: the edge's inside the edge; at a
  // vertex the direction between the points, unless that is rounding noise
  Vec2 m;
  if (hit.t > 0.0 && hit.t < 1.0) {
    m = edge.normal;
    if (overlapping) m = wedge_normal(p, hit, other_n, edge_of);
  } else {
    const Vec2 d = p - q;
    const double len = d.norm();
    // below this the direction between the points is rounding noise
    const double tiny = 1e-12 * (1.0 + p.norm());
    if (len > tiny) {
      m = overlapping ? Vec2(-d / len) : Vec2(d / len);
    } else {
      // the mean of the two edges' normals at the vertex
      const int v = hit.t <= 0.0 ? e : (e + 1) % other_n;
      const int before = (v + other_n - 1) % other_n;
      const Vec2 nv = edge_of(v).normal;
      const Vec2 nb = edge_of(before).normal;
      m = Vec2(nv.x() + nb.x(), nv.y() + nb.y());
      m = m.norm() > 0.0 ? Vec2(m.normalized()) : nv;
    }
  }

  ContactGeometry g;
  g.gap_m = overlapping ? -hit.distance_m : hit.distance_m;
  if (of_a) {
    // p on a, q on b: m is b's outward normal, so a -> b is -m
    g.normal = -m;
    g.point_a_m = p;
    g.point_b_m = q;
  } else {
    g.normal = m;
    g.point_a_m = q;
    g.point_b_m = p;
  }
  return g;
}

// the run of consecutive inside points around one of them: how many, and
// their depth-weighted centroid; add_other_inside() then adds the body's
// inside points of its other overlap regions (a concave body)
struct Run {
  int points = 0;                  // inside points summed (the run, then the others)
  Vec2 centroid_m = Vec2::Zero();  // m, world, depth-weighted centroid of those points
  int first = -1;                  // index of the run's first point in forward order
  int run_points = 0;              // points of the run around its start
  double w_sum = 0.0;              // m, sum of the depths
  Vec2 p_sum = Vec2::Zero();       // m^2, sum of depth x point
  Eigen::Matrix2d pp_sum = Eigen::Matrix2d::Zero();  // m^3, sum of depth x point point^T
};

// m^2, the depth-weighted variance of a run's points along `tangent` about
// their centroid (ContactGeometry::spread_m2); 0 for one point
[[nodiscard]] inline double spread_along(const Run& r, const Vec2& tangent) {
  if (r.points < 2 || !(r.w_sum > 0.0)) return 0.0;
  const Eigen::Matrix2d cov = r.pp_sum / r.w_sum - r.centroid_m * r.centroid_m.transpose();
  return std::max(0.0, tangent.dot(cov * tangent));
}

// The run around `start` (an inside point, or -1 for none) of an outline of n
// points: `inside(i)`, `depth_m(i)` and `point_m(i)` (world) of point i. Walks
// back from start, then forward, so that the sum is always taken in the same
// order.
template <class Inside, class Depth, class Point>
[[nodiscard]] Run inside_run(int n, int start, Inside&& inside, Depth&& depth_m, Point&& point_m) {
  Run r;
  if (start < 0) return r;
  double w_sum = 0.0;
  Vec2 p_sum = Vec2::Zero();
  auto add = [&](int i) {
    const double w = depth_m(i);
    const Vec2 p = point_m(i);
    w_sum += w;
    p_sum += w * p;
    r.pp_sum += w * p * p.transpose();
    ++r.points;
  };
  add(start);
  int back = 1;
  for (; back < n; ++back) {
    const int i = (start - back + n) % n;
    if (!inside(i)) break;
    add(i);
  }
  for (int fwd = 1; fwd < n - back + 1; ++fwd) {
    const int i = (start + fwd) % n;
    if (!inside(i)) break;
    add(i);
  }
  r.first = (start - (back - 1) + n) % n;
  r.run_points = r.points;
  r.w_sum = w_sum;
  r.p_sum = p_sum;
  r.centroid_m = w_sum > 0.0 ? Vec2(p_sum / w_sum) : point_m(start);
  return r;
}

// whose inside points place the line of action: a's (true) or b's (false);
// not asked for ActionPoints::both (place_line_of_action)
[[nodiscard]] inline bool action_points_of_a(const Run& a, const Run& b, bool a_deepest,
                                             ActionPoints rule) {
  switch (rule) {
    case ActionPoints::both: break;
    case ActionPoints::a: return a.first >= 0 || b.first < 0;
    case ActionPoints::b: return !(b.first >= 0 || a.first < 0);
    case ActionPoints::vertex_a:
      if (a.points == 1) return true;
      break;
    case ActionPoints::vertex_b:
      if (b.points == 1) return false;
      break;
    case ActionPoints::more: break;
  }
  return a.points > b.points || (a.points == b.points && a_deepest);
}

// SPEC §1, one force per pair: the line of action passes through the
// depth-weighted centroid of every inside point of the body, not only of the
// run around the deepest one. A concave body pressed in at several places
// (an arch on both feet) would otherwise take the whole force at one of them,
// turn, press the other deeper, switch, and chatter without end. The other
// points are added after the run's, in increasing index order (`inside_ascending`:
// the body's inside point indices, ascending), so that a single overlap region
// keeps the run's sum bit for bit and both searches add in the same order.
template <class Indices, class Depth, class Point>
void add_other_inside(Run& r, int n, const Indices& inside_ascending, Depth&& depth_m,
                      Point&& point_m) {
  if (r.first < 0) return;
  bool added = false;
  for (const int i : inside_ascending) {
    if ((i - r.first + n) % n < r.run_points) continue;  // in the run already
    const double w = depth_m(i);
    const Vec2 p = point_m(i);
    r.w_sum += w;
    r.p_sum += w * p;
    r.pp_sum += w * p * p.transpose();
    ++r.points;
    added = true;
  }
  if (added && r.w_sum > 0.0) r.centroid_m = r.p_sum / r.w_sum;
}

// The line of action of an overlap whose deepest point gave g (gap, normal,
// the deepest point and its boundary point): through the depth-weighted
// centroid of the inside points that `rule` names (action_points_of_a), or,
// for ActionPoints::both, of every inside point of both bodies. b's inside
// points lie on a's side of the overlap, a's on b's side, delta apart along
// the normal; b's are moved by delta n onto a's side so that the centroid
// is of points of one side. Each point weighs its depth, which is 0 where it
// enters or leaves the other body, so that centroid moves continuously as
// points come and go, where the side with more points jumps when the counts
// change (two sampled curves pressed lightly: the force's lever flips by an
// edge length, and the rotation it drives flips it back: a sliding mode the
// integrator can only follow with vanishing steps; reference README, Scenes).
// The spread is along the tangent, which the move along the normal keeps.
inline void place_line_of_action(ContactGeometry& g, const Run& run_a, const Run& run_b,
                                 bool a_deepest, ActionPoints rule) {
  const double delta = -g.gap_m;
  const Vec2 tangent(g.normal.y(), -g.normal.x());
  if (rule == ActionPoints::both && run_a.points > 0 && run_b.points > 0 &&
      run_a.w_sum + run_b.w_sum > 0.0) {
    const double w = run_a.w_sum + run_b.w_sum;
    g.point_a_m = (run_a.p_sum + run_b.p_sum + run_b.w_sum * delta * g.normal) / w;
    g.point_b_m = g.point_a_m - delta * g.normal;
    Run both;
    both.points = run_a.points + run_b.points;
    both.w_sum = w;
    both.centroid_m = (run_a.p_sum + run_b.p_sum) / w;
    both.pp_sum = run_a.pp_sum + run_b.pp_sum;
    g.spread_m2 = spread_along(both, tangent);
    return;
  }
  const bool use_a = rule == ActionPoints::both ? run_a.points > 0
                                                 : action_points_of_a(run_a, run_b, a_deepest, rule);
  if (use_a) {
    g.point_a_m = run_a.centroid_m;
    g.point_b_m = g.point_a_m - delta * g.normal;
  } else {
    g.point_b_m = run_b.centroid_m;
    g.point_a_m = g.point_b_m + delta * g.normal;
  }
  g.spread_m2 = spread_along(use_a ? run_a : run_b, tangent);
}

}  // namespace pb::internal
