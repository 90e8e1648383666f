#include "planarbench/reference/outline_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <variant>

#include "outline_kernels.hpp"
#include "planarbench/outline.hpp"

namespace pb {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// one outline point of either body with its nearest point on the other body
struct Candidate {
  int vertex = -1;
  bool of_a = true;  // the point belongs to body a (its boundary hit is on b)
  BoundaryHit hit;
};

// distance from p to the segment s0-s1, squared
double point_segment_distance2(double px, double py, double s0x, double s0y, double s1x,
                               double s1y) {
  const double ex = s1x - s0x;
  const double ey = s1y - s0y;
  const double len2 = ex * ex + ey * ey;
  const double dx = px - s0x;
  const double dy = py - s0y;
  const double t = len2 > 0.0 ? std::clamp((dx * ex + dy * ey) / len2, 0.0, 1.0) : 0.0;
  const double rx = dx - t * ex;
  const double ry = dy - t * ey;
  return rx * rx + ry * ry;
}

// the geometry of the chosen candidate (outline_kernels.hpp)
ContactGeometry candidate_geometry(const Candidate& c, const WorldOutline& a,
                                   const WorldOutline& b, bool overlapping) {
  const WorldOutline& own = c.of_a ? a : b;
  const WorldOutline& other = c.of_a ? b : a;
  const Vec2 p(own.x[c.vertex], own.y[c.vertex]);
  return internal::hit_geometry(p, c.hit, c.of_a, overlapping, other.size(), [&](int e) {
    return internal::EdgeView{other.x[e], other.y[e], other.ex[e], other.ey[e],
                              Vec2(other.nx[e], other.ny[e])};
  });
}

// every outline point of `own` against the boundary of `other`; `deepest_own`
// is the deepest of own's points inside other. A point farther from other's
// bounding box than the closest distance found so far can be neither inside
// nor the closest: it is skipped (an exact pruning, same result).
void sweep(const WorldOutline& own, const WorldOutline& other, bool own_is_a,
           std::vector<BoundaryHit>& hits, Candidate& deepest_own, Candidate& closest) {
  const int n = own.size();
  hits.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const double gx = std::max({other.min_x - own.x[i], own.x[i] - other.max_x, 0.0});
    const double gy = std::max({other.min_y - own.y[i], own.y[i] - other.max_y, 0.0});
    if (gx * gx + gy * gy > closest.hit.distance_m * closest.hit.distance_m) {
      hits[static_cast<std::size_t>(i)] = BoundaryHit{kInf, -1, 0.0, false};
      continue;
    }
    const BoundaryHit hit = nearest_boundary_point(own.x[i], own.y[i], other);
    hits[static_cast<std::size_t>(i)] = hit;
    if (hit.inside && hit.distance_m > deepest_own.hit.distance_m) {
      deepest_own = Candidate{i, own_is_a, hit};
    }
    if (hit.distance_m < closest.hit.distance_m) closest = Candidate{i, own_is_a, hit};
  }
}

// the run of consecutive inside points around `start` (outline_kernels.hpp)
internal::Run inside_run(const WorldOutline& own, const std::vector<BoundaryHit>& hits, int start) {
  return internal::inside_run(
      own.size(), start, [&](int i) { return hits[static_cast<std::size_t>(i)].inside; },
      [&](int i) { return hits[static_cast<std::size_t>(i)].distance_m; },
      [&](int i) { return Vec2(own.x[i], own.y[i]); });
}

// every inside point of `own`: the run around `start`, then the other overlap
// regions (outline_kernels.hpp, add_other_inside)
internal::Run all_inside(const WorldOutline& own, const std::vector<BoundaryHit>& hits, int start,
                         std::vector<int>& ids) {
  internal::Run r = inside_run(own, hits, start);
  if (r.first < 0) return r;
  ids.clear();
  for (int i = 0; i < own.size(); ++i) {
    if (hits[static_cast<std::size_t>(i)].inside) ids.push_back(i);
  }
  internal::add_other_inside(
      r, own.size(), ids, [&](int i) { return hits[static_cast<std::size_t>(i)].distance_m; },
      [&](int i) { return Vec2(own.x[i], own.y[i]); });
  return r;
}

}  // namespace

std::vector<Vec2> contact_outline(const Shape& shape, int n) {
  std::vector<Vec2> pts = make_outline(shape, n);
  if (const auto* hp = std::get_if<HalfPlane>(&shape)) {
    // close the surface segment into a simple polygon below it
    pts.emplace_back(0.0, -0.5 * hp->extent_m);
  }
  return pts;
}

void place_outline(const std::vector<Vec2>& local_m, const Pose& pose, WorldOutline& out) {
  const std::size_t n = local_m.size();
  // x, y keep a copy of vertex 0 at the end so that edge i ends at vertex i+1
  out.x.resize(n + 1);
  out.y.resize(n + 1);
  out.ex.resize(n);
  out.ey.resize(n);
  out.inv_len2.resize(n);
  out.nx.resize(n);
  out.ny.resize(n);
  out.x_per_y.resize(n);
  const Eigen::Matrix2d r = pose.rotation();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 w = internal::place_point(r, pose.position_m, local_m[i]);
    out.x[i] = w.x();
    out.y[i] = w.y();
  }
  out.x[n] = out.x[0];
  out.y[n] = out.y[0];
  const auto [xmin, xmax] = std::minmax_element(out.x.begin(), out.x.end());
  const auto [ymin, ymax] = std::minmax_element(out.y.begin(), out.y.end());
  out.min_x = *xmin;
  out.max_x = *xmax;
  out.min_y = *ymin;
  out.max_y = *ymax;
  for (std::size_t i = 0; i < n; ++i) {
    const internal::EdgeData e = internal::edge_data(out.x[i], out.y[i], out.x[i + 1], out.y[i + 1]);
    out.ex[i] = e.ex;
    out.ey[i] = e.ey;
    out.inv_len2[i] = e.inv_len2;
    out.x_per_y[i] = e.x_per_y;
    const Vec2 normal = internal::edge_outward_normal(e.ex, e.ey);
    out.nx[i] = normal.x();
    out.ny[i] = normal.y();
  }
}

BoundaryHit nearest_boundary_point(double px, double py, const WorldOutline& poly) {
  const int n = poly.size();
  const double* x = poly.x.data();
  const double* y = poly.y.data();
  double best2 = kInf;
  int best_edge = 0;
  double best_t = 0.0;
  bool inside = false;
  for (int j = 0; j < n; ++j) {
    // projection onto edge j, clamped to the edge
    double t = 0.0;
    const double d2 = internal::point_edge_distance2(px, py, x[j], y[j], poly.ex[j], poly.ey[j],
                                                     poly.inv_len2[j], t);
    if (d2 < best2) {
      best2 = d2;
      best_edge = j;
      best_t = t;
    }
    // crossing number: a ray from p towards +x crosses edge j
    if (internal::ray_crosses_edge(px, py, x[j], y[j], y[j + 1], poly.x_per_y[j])) inside = !inside;
  }
  return BoundaryHit{std::sqrt(best2), best_edge, best_t, inside};
}

OutlineContactSearch::OutlineContactSearch(std::vector<Vec2> outline_a_m,
                                           std::vector<Vec2> outline_b_m)
    : local_a_(std::move(outline_a_m)), local_b_(std::move(outline_b_m)) {
  place_outline(local_a_, Pose{}, world_a_);
  place_outline(local_b_, Pose{}, world_b_);
}

ContactGeometry OutlineContactSearch::evaluate(const Pose& pose_a, const Pose& pose_b) {
  place_outline(local_a_, pose_a, world_a_);
  place_outline(local_b_, pose_b, world_b_);
  return evaluate_placed(world_a_, world_b_);
}

ContactGeometry OutlineContactSearch::evaluate_placed(const WorldOutline& a,
                                                      const WorldOutline& b) {
  // deepest point of each body inside the other (overlap), closest point (apart)
  Candidate deepest_a;
  deepest_a.hit.distance_m = -1.0;
  Candidate deepest_b = deepest_a;
  Candidate closest;
  closest.hit.distance_m = kInf;
  // the body with the smaller bounding box first: its points settle the
  // closest distance early, so that most of the other's are pruned
  const double area_a = (a.max_x - a.min_x) * (a.max_y - a.min_y);
  const double area_b = (b.max_x - b.min_x) * (b.max_y - b.min_y);
  if (area_b < area_a) {
    sweep(b, a, false, hits_b_, deepest_b, closest);
    sweep(a, b, true, hits_a_, deepest_a, closest);
  } else {
    sweep(a, b, true, hits_a_, deepest_a, closest);
    sweep(b, a, false, hits_b_, deepest_b, closest);
  }
  if (deepest_a.vertex < 0 && deepest_b.vertex < 0) {
    return candidate_geometry(closest, a, b, false);
  }

  // overlapping: delta and normal of the deepest point overall
  const bool a_deepest = deepest_a.hit.distance_m >= deepest_b.hit.distance_m;
  ContactGeometry g = candidate_geometry(a_deepest ? deepest_a : deepest_b, a, b, true);
  // line of action through the depth-weighted centroid of the inside points
  // of the body that has more of them
  const internal::Run run_a = all_inside(a, hits_a_, deepest_a.vertex, inside_ids_);
  const internal::Run run_b = all_inside(b, hits_b_, deepest_b.vertex, inside_ids_);
  internal::place_line_of_action(g, run_a, run_b, a_deepest, action_points_);
  return g;
}

double paper_two_stage_distance(const WorldOutline& a, const WorldOutline& b) {
  // stage 1: the closest pair of outline points
  double best2 = kInf;
  int bi = 0;
  int bj = 0;
  for (int i = 0; i < a.size(); ++i) {
    for (int j = 0; j < b.size(); ++j) {
      const double dx = a.x[i] - b.x[j];
      const double dy = a.y[i] - b.y[j];
      const double d2 = dx * dx + dy * dy;
      if (d2 < best2) {
        best2 = d2;
        bi = i;
        bj = j;
      }
    }
  }
  // stage 2: the edges next to that pair; the distance of two disjoint
  // segments is the least of their four end-point-to-segment distances
  const int na = a.size();
  const int nb = b.size();
  const int edges_a[2] = {(bi + na - 1) % na, bi};
  const int edges_b[2] = {(bj + nb - 1) % nb, bj};
  for (const int ea : edges_a) {
    for (const int eb : edges_b) {
      const double a0x = a.x[ea], a0y = a.y[ea], a1x = a.x[ea + 1], a1y = a.y[ea + 1];
      const double b0x = b.x[eb], b0y = b.y[eb], b1x = b.x[eb + 1], b1y = b.y[eb + 1];
      best2 = std::min({best2, point_segment_distance2(a0x, a0y, b0x, b0y, b1x, b1y),
                        point_segment_distance2(a1x, a1y, b0x, b0y, b1x, b1y),
                        point_segment_distance2(b0x, b0y, a0x, a0y, a1x, a1y),
                        point_segment_distance2(b1x, b1y, a0x, a0y, a1x, a1y)});
    }
  }
  return std::sqrt(best2);
}

}  // namespace pb
