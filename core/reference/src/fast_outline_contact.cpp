#include "planarbench/reference/fast_outline_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <utility>

#include "outline_kernels.hpp"

namespace pb {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// steps of the coherence descent over neighbouring points and edges
constexpr int kDescentSteps = 64;

// whether a node pair (or a node and a point) lies beyond `bound_m`: its axes
// are farther apart than the bound plus the radii and the margin (`reach_m`)
bool beyond_pair(double axis_d2_m2, double reach_m, double bound_m) {
  const double limit = bound_m + reach_m;
  return axis_d2_m2 > limit * limit;
}

// the segments a0 -> a1 and b0 -> b1 cross at a point inside both (strictly)
bool segments_cross(double a0x, double a0y, double a1x, double a1y, double b0x, double b0y,
                    double b1x, double b1y) {
  const double dax = a1x - a0x, day = a1y - a0y, dbx = b1x - b0x, dby = b1y - b0y;
  const double o1 = dax * (b0y - a0y) - day * (b0x - a0x);
  const double o2 = dax * (b1y - a0y) - day * (b1x - a0x);
  const double o3 = dbx * (a0y - b0y) - dby * (a0x - b0x);
  const double o4 = dbx * (a1y - b0y) - dby * (a1x - b0x);
  return ((o1 < 0.0 && o2 > 0.0) || (o1 > 0.0 && o2 < 0.0)) &&
         ((o3 < 0.0 && o4 > 0.0) || (o3 > 0.0 && o4 < 0.0));
}

}  // namespace

FastOutlineContactSearch::Body::Body(std::vector<Vec2> outline_m) : tree(std::move(outline_m)) {
  const auto n = static_cast<std::size_t>(tree.size());
  const std::size_t nodes = tree.nodes().size();
  for (const OutlineTree::Node& nd : tree.nodes()) {
    left.push_back(nd.left);
    right.push_back(nd.right);
    parent.push_back(nd.parent);
    first_edge.push_back(nd.first_edge);
    radius_m.push_back(nd.radius_m);
    reach_m.push_back(nd.radius_m + 0.5 * nd.axis_len_m);
    axis_inv_len2.push_back(nd.axis_inv_len2);
  }
  vertex_stamp.assign(n, 0);
  edge_stamp.assign(n, 0);
  node_stamp.assign(nodes, 0);
  x.assign(n, 0.0);
  y.assign(n, 0.0);
  ex.assign(n, 0.0);
  ey.assign(n, 0.0);
  inv_len2.assign(n, 0.0);
  x_per_y.assign(n, 0.0);
  ax.assign(nodes, 0.0);
  ay.assign(nodes, 0.0);
  adx.assign(nodes, 0.0);
  ady.assign(nodes, 0.0);
  best_stamp.assign(n, 0);
  best_d2.assign(n, kInf);
  best_edge.assign(n, -1);
  best_t.assign(n, 0.0);
  touched.assign(n, 0);
  status_stamp.assign(n, 0);
  hit_stamp.assign(n, 0);
  walk_stamp.assign(n, 0);
  inside_walked.assign(n, 0);
  inside.assign(n, 0);
  hit.assign(n, BoundaryHit{});
  near_stamp.assign(n, 0);
  near_edges.assign(n, 0);
}

FastOutlineContactSearch::FastOutlineContactSearch(std::vector<Vec2> outline_a_m,
                                                   std::vector<Vec2> outline_b_m)
    : a_(std::move(outline_a_m)), b_(std::move(outline_b_m)) {
  // depth-first with at most two children pushed per pop: the stacks never
  // hold more than one entry per level of the current path plus one
  pair_stack_.resize(static_cast<std::size_t>(a_.tree.depth() + b_.tree.depth() + 4));
  node_stack_.resize(static_cast<std::size_t>(std::max(a_.tree.depth(), b_.tree.depth()) + 4));
}

// ---- world placement, cached per evaluation --------------------------------

void FastOutlineContactSearch::begin(Body& body, const Pose& pose) {
  body.rotation = pose.rotation();
  body.position_m = pose.position_m;
  body.touched_count = 0;
  body.near_count = 0;
  body.inside_walked_count = 0;
}

void FastOutlineContactSearch::place_vertex(Body& body, int i) {
  const auto k = static_cast<std::size_t>(i);
  const Vec2 w = internal::place_point(body.rotation, body.position_m, body.tree.points()[k]);
  body.x[k] = w.x();
  body.y[k] = w.y();
  body.vertex_stamp[k] = stamp_;
}

void FastOutlineContactSearch::place_edge(Body& body, int j) {
  const auto k = static_cast<std::size_t>(j);
  const int j1 = j + 1 == body.size() ? 0 : j + 1;
  vertex(body, j);
  vertex(body, j1);
  const auto k1 = static_cast<std::size_t>(j1);
  const internal::EdgeData e = internal::edge_data(body.x[k], body.y[k], body.x[k1], body.y[k1]);
  body.ex[k] = e.ex;
  body.ey[k] = e.ey;
  body.inv_len2[k] = e.inv_len2;
  body.x_per_y[k] = e.x_per_y;
  body.edge_stamp[k] = stamp_;
}

// a node's capsule axis in the world; a leaf's axis is its edge
void FastOutlineContactSearch::place_node_axis(Body& body, int node) {
  const auto k = static_cast<std::size_t>(node);
  if (body.leaf(node)) {
    const int j = body.first_edge[k];
    edge(body, j);
    const auto kj = static_cast<std::size_t>(j);
    body.ax[k] = body.x[kj];
    body.ay[k] = body.y[kj];
    body.adx[k] = body.ex[kj];
    body.ady[k] = body.ey[kj];
    body.axis_inv_len2[k] = body.inv_len2[kj];
  } else {
    const OutlineTree::Node& nd = body.tree.nodes()[k];
    const Vec2 s = internal::place_point(body.rotation, body.position_m, nd.axis_start_m);
    const Vec2 d = body.rotation * nd.axis_m;
    body.ax[k] = s.x();
    body.ay[k] = s.y();
    body.adx[k] = d.x();
    body.ady[k] = d.y();
  }
  body.node_stamp[k] = stamp_;
}

// ---- candidates ------------------------------------------------------------

void FastOutlineContactSearch::record(Body& own, int i, double d2, int edge_index, double t,
                                      bool own_is_a) {
  ++work_.point_edge_tests;
  const auto k = static_cast<std::size_t>(i);
  if (own.best_stamp[k] != stamp_) {
    own.best_stamp[k] = stamp_;
    own.best_d2[k] = d2;
    own.best_edge[k] = edge_index;
    own.best_t[k] = t;
    own.touched[static_cast<std::size_t>(own.touched_count++)] = i;
  } else if (d2 < own.best_d2[k] || (d2 == own.best_d2[k] && edge_index < own.best_edge[k])) {
    own.best_d2[k] = d2;
    own.best_edge[k] = edge_index;
    own.best_t[k] = t;
  }
  if (d2 < best_d2_) {
    best_d2_ = d2;
    bound_m_ = std::max(std::sqrt(d2), margin_m_);
    best_of_a_ = own_is_a;
    best_vertex_ = i;
    best_edge_ = edge_index;
  }
}

// The last evaluation's closest (point, edge) pair, then a greedy descent over
// the neighbouring points and edges: every pair computed is a true distance,
// so the least of them is an upper bound U on this evaluation's closest one.
void FastOutlineContactSearch::seed_from_history() {
  Body& own = best_of_a_ ? a_ : b_;
  Body& other = best_of_a_ ? b_ : a_;
  const bool own_is_a = best_of_a_;
  const int n_own = own.size();
  const int n_other = other.size();
  auto distance2 = [&](int v, int e) {
    vertex(own, v);
    edge(other, e);
    const auto kv = static_cast<std::size_t>(v);
    const auto ke = static_cast<std::size_t>(e);
    double t = 0.0;
    const double d2 = internal::point_edge_distance2(own.x[kv], own.y[kv], other.x[ke], other.y[ke],
                                                     other.ex[ke], other.ey[ke], other.inv_len2[ke], t);
    record(own, v, d2, e, t, own_is_a);
    return d2;
  };
  int v = best_vertex_;
  int e = best_edge_;
  double d2 = distance2(v, e);
  for (int step = 0; step < kDescentSteps; ++step) {
    const int moves[4][2] = {{(v + n_own - 1) % n_own, e},
                             {(v + 1) % n_own, e},
                             {v, (e + n_other - 1) % n_other},
                             {v, (e + 1) % n_other}};
    int best_move = -1;
    double best_move_d2 = d2;
    for (int m = 0; m < 4; ++m) {
      const double dm = distance2(moves[m][0], moves[m][1]);
      if (dm < best_move_d2) {
        best_move_d2 = dm;
        best_move = m;
      }
    }
    if (best_move < 0) break;
    v = moves[best_move][0];
    e = moves[best_move][1];
    d2 = best_move_d2;
  }
}

// ---- simultaneous descent of both trees ------------------------------------

// A node pair with a lower bound on the distance of its capsules: first the
// circles about the axis midpoints (cheap; enough when already beyond the
// bound), else the distance of the two axes - zero when they cross, else the
// least of the four end-to-segment distances - less both radii.
FastOutlineContactSearch::PairEntry FastOutlineContactSearch::pair_entry(int na, int nb) {
  place_node(a_, na);
  place_node(b_, nb);
  const auto ka = static_cast<std::size_t>(na);
  const auto kb = static_cast<std::size_t>(nb);
  const double a0x = a_.ax[ka], a0y = a_.ay[ka], adx = a_.adx[ka], ady = a_.ady[ka];
  const double b0x = b_.ax[kb], b0y = b_.ay[kb], bdx = b_.adx[kb], bdy = b_.ady[kb];
  {
    const double mx = (a0x + 0.5 * adx) - (b0x + 0.5 * bdx);
    const double my = (a0y + 0.5 * ady) - (b0y + 0.5 * bdy);
    const double reach = a_.reach_m[ka] + b_.reach_m[kb] + margin_m_;
    if (beyond_pair(mx * mx + my * my, reach, bound_m_)) {
      return PairEntry{na, nb, std::sqrt(mx * mx + my * my) - reach};
    }
  }
  const double a1x = a0x + adx, a1y = a0y + ady;
  const double b1x = b0x + bdx, b1y = b0y + bdy;
  double d2 = 0.0;
  if (!segments_cross(a0x, a0y, a1x, a1y, b0x, b0y, b1x, b1y)) {
    const double ia = a_.axis_inv_len2[ka], ib = b_.axis_inv_len2[kb];
    double t = 0.0;
    d2 = std::min({internal::point_edge_distance2(a0x, a0y, b0x, b0y, bdx, bdy, ib, t),
                   internal::point_edge_distance2(a1x, a1y, b0x, b0y, bdx, bdy, ib, t),
                   internal::point_edge_distance2(b0x, b0y, a0x, a0y, adx, ady, ia, t),
                   internal::point_edge_distance2(b1x, b1y, a0x, a0y, adx, ady, ia, t)});
  }
  return PairEntry{na, nb, std::sqrt(d2) - a_.radius_m[ka] - b_.radius_m[kb] - margin_m_};
}

// One edge of a against one edge of b: both start vertices and both end
// vertices against the other edge (four true point-edge distances), and
// whether the edges come within the margin of each other.
void FastOutlineContactSearch::leaf_pair(int ia, int jb) {
  edge(a_, ia);
  edge(b_, jb);
  const int ia1 = ia + 1 == a_.size() ? 0 : ia + 1;
  const int jb1 = jb + 1 == b_.size() ? 0 : jb + 1;
  const auto i = static_cast<std::size_t>(ia), i1 = static_cast<std::size_t>(ia1);
  const auto j = static_cast<std::size_t>(jb), j1 = static_cast<std::size_t>(jb1);
  double t = 0.0;
  const double d_a0 = internal::point_edge_distance2(a_.x[i], a_.y[i], b_.x[j], b_.y[j], b_.ex[j],
                                                     b_.ey[j], b_.inv_len2[j], t);
  record(a_, ia, d_a0, jb, t, true);
  const double d_a1 = internal::point_edge_distance2(a_.x[i1], a_.y[i1], b_.x[j], b_.y[j], b_.ex[j],
                                                     b_.ey[j], b_.inv_len2[j], t);
  record(a_, ia1, d_a1, jb, t, true);
  const double d_b0 = internal::point_edge_distance2(b_.x[j], b_.y[j], a_.x[i], a_.y[i], a_.ex[i],
                                                     a_.ey[i], a_.inv_len2[i], t);
  record(b_, jb, d_b0, ia, t, false);
  const double d_b1 = internal::point_edge_distance2(b_.x[j1], b_.y[j1], a_.x[i], a_.y[i], a_.ex[i],
                                                     a_.ey[i], a_.inv_len2[i], t);
  record(b_, jb1, d_b1, ia, t, false);

  // near: the statuses of the edges' endpoints may differ (header comment)
  const bool near = std::min({d_a0, d_a1, d_b0, d_b1}) <= margin_m_ * margin_m_ ||
                    segments_cross(a_.x[i], a_.y[i], a_.x[i1], a_.y[i1], b_.x[j], b_.y[j],
                                   b_.x[j1], b_.y[j1]);
  if (!near) return;
  if (a_.near_stamp[i] != stamp_) {
    a_.near_stamp[i] = stamp_;
    a_.near_edges[static_cast<std::size_t>(a_.near_count++)] = ia;
  }
  if (b_.near_stamp[j] != stamp_) {
    b_.near_stamp[j] = stamp_;
    b_.near_edges[static_cast<std::size_t>(b_.near_count++)] = jb;
  }
}

// Depth first over node pairs, the nearer child pair first. A pair is
// skipped when its capsules are farther apart than T = max(U, margin): no
// point-edge distance in it can be <= U (the closest pair), nor can any of its
// edges come within the margin of the other outline (the near edges).
void FastOutlineContactSearch::descend_pairs() {
  int top = 0;
  pair_stack_[static_cast<std::size_t>(top++)] = pair_entry(0, 0);
  while (top > 0) {
    const PairEntry e = pair_stack_[static_cast<std::size_t>(--top)];
    if (e.lower_bound_m > bound_m_) continue;
    ++work_.node_pairs;
    const bool leaf_a = a_.leaf(e.node_a);
    const bool leaf_b = b_.leaf(e.node_b);
    if (leaf_a && leaf_b) {
      leaf_pair(a_.first_edge[static_cast<std::size_t>(e.node_a)],
                b_.first_edge[static_cast<std::size_t>(e.node_b)]);
      continue;
    }
    // split the larger node (a leaf cannot be split)
    const bool split_a = !leaf_a && (leaf_b || a_.reach_m[static_cast<std::size_t>(e.node_a)] >=
                                                   b_.reach_m[static_cast<std::size_t>(e.node_b)]);
    PairEntry c1{}, c2{};
    if (split_a) {
      const auto k = static_cast<std::size_t>(e.node_a);
      c1 = pair_entry(a_.left[k], e.node_b);
      c2 = pair_entry(a_.right[k], e.node_b);
    } else {
      const auto k = static_cast<std::size_t>(e.node_b);
      c1 = pair_entry(e.node_a, b_.left[k]);
      c2 = pair_entry(e.node_a, b_.right[k]);
    }
    // c2 the nearer, pushed last, popped first
    if (c2.lower_bound_m > c1.lower_bound_m) std::swap(c1, c2);
    if (!(c1.lower_bound_m > bound_m_)) pair_stack_[static_cast<std::size_t>(top++)] = c1;
    if (!(c2.lower_bound_m > bound_m_)) pair_stack_[static_cast<std::size_t>(top++)] = c2;
  }
}

// ---- one point against the other outline -----------------------------------

void FastOutlineContactSearch::set_status(Body& own, int i, bool in) {
  const auto k = static_cast<std::size_t>(i);
  own.status_stamp[k] = stamp_;
  own.inside[k] = in ? 1 : 0;
}

// The brute force's crossing-number test over the edges whose capsule can
// meet the ray from the point towards +x (the others cannot cross it).
bool FastOutlineContactSearch::crossing_inside(Body& own, int i, Body& other) {
  const auto k = static_cast<std::size_t>(i);
  if (own.status_stamp[k] == stamp_) return own.inside[k] != 0;
  ++work_.crossing_queries;
  vertex(own, i);
  const double px = own.x[k];
  const double py = own.y[k];
  bool in = false;
  int top = 0;
  node_stack_[static_cast<std::size_t>(top++)] = NodeEntry{0, 0.0};
  while (top > 0) {
    const int node = node_stack_[static_cast<std::size_t>(--top)].node;
    const auto kn = static_cast<std::size_t>(node);
    if (other.leaf(node)) {
      const int j = other.first_edge[kn];
      edge(other, j);
      const auto kj = static_cast<std::size_t>(j);
      const auto kj1 = static_cast<std::size_t>(j + 1 == other.size() ? 0 : j + 1);
      if (internal::ray_crosses_edge(px, py, other.x[kj], other.y[kj], other.y[kj1],
                                     other.x_per_y[kj])) {
        in = !in;
      }
      continue;
    }
    // the capsule's bounding box must reach the ray's line, right of the point
    place_node(other, node);
    const double r = other.radius_m[kn] + margin_m_;
    const double y0 = other.ay[kn], y1 = other.ay[kn] + other.ady[kn];
    const double x0 = other.ax[kn], x1 = other.ax[kn] + other.adx[kn];
    if (std::min(y0, y1) - r > py || std::max(y0, y1) + r < py || std::max(x0, x1) + r < px) {
      continue;
    }
    node_stack_[static_cast<std::size_t>(top++)] = NodeEntry{other.left[kn], 0.0};
    node_stack_[static_cast<std::size_t>(top++)] = NodeEntry{other.right[kn], 0.0};
  }
  set_status(own, i, in);
  return in;
}

// The brute force's nearest boundary point (least distance, lowest edge index
// among equal ones) by branch and bound. It starts from the best pair already
// computed for this point and from `guess_edge` (a neighbour's, or -1), then
// climbs from that edge's leaf to the root, searching each sibling subtree
// on the way: every edge is in exactly one of them, and a subtree whose
// capsule lies beyond the best distance so far is skipped whole.
const BoundaryHit& FastOutlineContactSearch::exact_hit(Body& own, int i, Body& other,
                                                       int guess_edge) {
  const auto k = static_cast<std::size_t>(i);
  if (own.hit_stamp[k] == stamp_) return own.hit[k];
  ++work_.nearest_queries;
  vertex(own, i);
  const double px = own.x[k];
  const double py = own.y[k];
  double best2 = kInf;
  double best_m = kInf;
  int best_edge = -1;
  double best_t = 0.0;
  auto consider = [&](int j) {
    edge(other, j);
    const auto kj = static_cast<std::size_t>(j);
    double t = 0.0;
    const double d2 = internal::point_edge_distance2(px, py, other.x[kj], other.y[kj], other.ex[kj],
                                                     other.ey[kj], other.inv_len2[kj], t);
    ++work_.point_edge_tests;
    if (d2 < best2 || (d2 == best2 && j < best_edge)) {
      best2 = d2;
      best_m = std::sqrt(d2);
      best_edge = j;
      best_t = t;
    }
  };
  // a node's axis against the point: squared distance (leaves: not used)
  auto axis_d2 = [&](int node) {
    place_node(other, node);
    const auto kn = static_cast<std::size_t>(node);
    double t = 0.0;
    return internal::point_edge_distance2(px, py, other.ax[kn], other.ay[kn], other.adx[kn],
                                          other.ady[kn], other.axis_inv_len2[kn], t);
  };
  auto reach = [&](int node) { return other.radius_m[static_cast<std::size_t>(node)] + margin_m_; };
  // branch and bound over one subtree, nearer child first
  auto search = [&](int root) {
    if (other.leaf(root)) {
      consider(other.first_edge[static_cast<std::size_t>(root)]);
      return;
    }
    const double d2_root = axis_d2(root);
    if (beyond_pair(d2_root, reach(root), best_m)) return;
    int top = 0;
    node_stack_[static_cast<std::size_t>(top++)] = NodeEntry{root, d2_root};
    while (top > 0) {
      const NodeEntry e = node_stack_[static_cast<std::size_t>(--top)];
      if (beyond_pair(e.axis_d2_m2, reach(e.node), best_m)) continue;
      const auto kn = static_cast<std::size_t>(e.node);
      NodeEntry near_kid{-1, 0.0}, far_kid{-1, 0.0};
      for (const int kid : {other.left[kn], other.right[kn]}) {
        if (other.leaf(kid)) {
          consider(other.first_edge[static_cast<std::size_t>(kid)]);
          continue;
        }
        const double d2 = axis_d2(kid);
        if (beyond_pair(d2, reach(kid), best_m)) continue;
        if (near_kid.node < 0) {
          near_kid = NodeEntry{kid, d2};
        } else if (d2 < near_kid.axis_d2_m2) {
          far_kid = near_kid;
          near_kid = NodeEntry{kid, d2};
        } else {
          far_kid = NodeEntry{kid, d2};
        }
      }
      if (far_kid.node >= 0) node_stack_[static_cast<std::size_t>(top++)] = far_kid;
      if (near_kid.node >= 0) node_stack_[static_cast<std::size_t>(top++)] = near_kid;
    }
  };

  if (own.best_stamp[k] == stamp_) {
    best2 = own.best_d2[k];
    best_m = std::sqrt(best2);
    best_edge = own.best_edge[k];
    best_t = own.best_t[k];
  }
  if (guess_edge >= 0) consider(guess_edge);
  if (best_edge < 0) consider(0);
  int node = other.tree.leaf_of_edge(best_edge);
  while (other.parent[static_cast<std::size_t>(node)] >= 0) {
    const auto kp = static_cast<std::size_t>(other.parent[static_cast<std::size_t>(node)]);
    search(other.left[kp] == node ? other.right[kp] : other.left[kp]);
    node = static_cast<int>(kp);
  }
  const bool in = own.status_stamp[k] == stamp_ && own.inside[k] != 0;
  own.hit[k] = BoundaryHit{std::sqrt(best2), best_edge, best_t, in};
  own.hit_stamp[k] = stamp_;
  return own.hit[k];
}

// ---- inside points ---------------------------------------------------------

// Every point of `own` inside `other`, each with its exact hit; `deepest` the
// deepest (the lowest index among equal depths), -1 for none.
void FastOutlineContactSearch::classify(Body& own, Body& other, int& deepest) {
  deepest = -1;
  if (own.near_count == 0) {
    // no edge comes near the other outline: every point has point 0's status;
    // outside the other's root capsule it is outside without a crossing test
    vertex(own, 0);
    place_node(other, 0);
    double t = 0.0;
    const double d2 = internal::point_edge_distance2(own.x[0], own.y[0], other.ax[0], other.ay[0],
                                                     other.adx[0], other.ady[0],
                                                     other.axis_inv_len2[0], t);
    if (beyond_pair(d2, other.radius_m[0] + margin_m_, 0.0)) return;
    if (crossing_inside(own, 0, other)) walk_run(own, 0, other, deepest);
    return;
  }
  for (int k = 0; k < own.near_count; ++k) {
    const int e = own.near_edges[static_cast<std::size_t>(k)];
    for (const int v : {e, e + 1 == own.size() ? 0 : e + 1}) {
      if (own.walk_stamp[static_cast<std::size_t>(v)] == stamp_) continue;
      if (crossing_inside(own, v, other)) walk_run(own, v, other, deepest);
    }
  }
}

// The run of inside points through `start` (inside), both ways. Across an
// edge that is not near the other outline the status carries over; across a
// near edge the next point is tested.
void FastOutlineContactSearch::walk_run(Body& own, int start, Body& other, int& deepest) {
  const int n = own.size();
  auto visit = [&](int v, int guess_edge) {
    own.walk_stamp[static_cast<std::size_t>(v)] = stamp_;
    own.inside_walked[static_cast<std::size_t>(own.inside_walked_count++)] = v;
    ++work_.inside_points;
    const BoundaryHit& h = exact_hit(own, v, other, guess_edge);
    if (deepest < 0) {
      deepest = v;
      return;
    }
    const double best = own.hit[static_cast<std::size_t>(deepest)].distance_m;
    if (h.distance_m > best || (h.distance_m == best && v < deepest)) deepest = v;
  };
  auto inside_across = [&](int v, int edge_between) {
    const auto kv = static_cast<std::size_t>(v);
    if (own.status_stamp[kv] == stamp_) return own.inside[kv] != 0;
    if (own.near_stamp[static_cast<std::size_t>(edge_between)] == stamp_) {
      return crossing_inside(own, v, other);
    }
    set_status(own, v, true);
    return true;
  };
  visit(start, -1);
  int prev = start;
  for (int step = 1; step < n; ++step) {
    const int v = prev == 0 ? n - 1 : prev - 1;
    if (own.walk_stamp[static_cast<std::size_t>(v)] == stamp_ || !inside_across(v, v)) break;
    visit(v, own.hit[static_cast<std::size_t>(prev)].edge);
    prev = v;
  }
  prev = start;
  for (int step = 1; step < n; ++step) {
    const int v = prev + 1 == n ? 0 : prev + 1;
    if (own.walk_stamp[static_cast<std::size_t>(v)] == stamp_ || !inside_across(v, prev)) break;
    visit(v, own.hit[static_cast<std::size_t>(prev)].edge);
    prev = v;
  }
}

// ---- the result --------------------------------------------------------------

ContactGeometry FastOutlineContactSearch::geometry_of(Body& own, int i, Body& other, bool own_is_a,
                                                      bool overlapping) {
  const auto k = static_cast<std::size_t>(i);
  const Vec2 p(own.x[k], own.y[k]);
  return internal::hit_geometry(p, own.hit[k], own_is_a, overlapping, other.size(), [&](int e) {
    edge(other, e);
    const auto ke = static_cast<std::size_t>(e);
    return internal::EdgeView{other.x[ke], other.y[ke], other.ex[ke], other.ey[ke],
                              internal::edge_outward_normal(other.ex[ke], other.ey[ke])};
  });
}

// The brute force sweeps the body with the smaller world bounding box first
// (ties: a first); needed only to break an exact tie between a point of each
// body, so the O(N) boxes are computed only then.
bool FastOutlineContactSearch::a_sweeps_first() {
  auto area = [&](Body& body) {
    double x_min = kInf, x_max = -kInf, y_min = kInf, y_max = -kInf;
    for (int i = 0; i < body.size(); ++i) {
      vertex(body, i);
      const auto k = static_cast<std::size_t>(i);
      x_min = std::min(x_min, body.x[k]);
      x_max = std::max(x_max, body.x[k]);
      y_min = std::min(y_min, body.y[k]);
      y_max = std::max(y_max, body.y[k]);
    }
    return (x_max - x_min) * (y_max - y_min);
  };
  const double area_a = area(a_);
  const double area_b = area(b_);
  return !(area_b < area_a);
}

ContactGeometry FastOutlineContactSearch::evaluate(const Pose& pose_a, const Pose& pose_b) {
  ++stamp_;
  work_ = FastSearchWork{};
  begin(a_, pose_a);
  begin(b_, pose_b);
  // the size of the world coordinates bounds every rounding error
  const double scale_m =
      std::max(pose_a.position_m.cwiseAbs().maxCoeff() + a_.tree.extent_m(),
               pose_b.position_m.cwiseAbs().maxCoeff() + b_.tree.extent_m());
  margin_m_ = internal::rounding_margin_m(scale_m);

  // U from the last evaluation's closest pair, then the trees
  best_d2_ = kInf;
  bound_m_ = kInf;
  if (has_history_) {
    seed_from_history();
  } else {
    best_vertex_ = -1;
  }
  descend_pairs();
  has_history_ = best_vertex_ >= 0;

  int deepest_a = -1, deepest_b = -1;
  classify(a_, b_, deepest_a);
  classify(b_, a_, deepest_b);

  if (deepest_a < 0 && deepest_b < 0) {
    // apart: the least distance over both bodies' points (every point whose
    // distance can be the least was paired with its nearest edges above)
    auto closest_of = [](const Body& body, double& d_m) {
      int best = -1;
      d_m = kInf;
      for (int k = 0; k < body.touched_count; ++k) {
        const int i = body.touched[static_cast<std::size_t>(k)];
        const double d = std::sqrt(body.best_d2[static_cast<std::size_t>(i)]);
        if (best < 0 || d < d_m || (d == d_m && i < best)) {
          best = i;
          d_m = d;
        }
      }
      return best;
    };
    double da = kInf, db = kInf;
    const int ia = closest_of(a_, da);
    const int ib = closest_of(b_, db);
    const bool use_a = ib < 0 || (ia >= 0 && (da < db || (da == db && a_sweeps_first())));
    Body& own = use_a ? a_ : b_;
    Body& other = use_a ? b_ : a_;
    const int i = use_a ? ia : ib;
    if (i < 0) return ContactGeometry{};  // unreachable: the descent pairs at least two edges
    // Its best pair is its exact hit: a pair is skipped only when its lower
    // bound exceeds some computed distance >= the least one, so every pair at
    // the least distance - this point's nearest edge and every edge tied with
    // it - was computed and compared (lowest edge index among equals).
    const auto k = static_cast<std::size_t>(i);
    own.hit[k] = BoundaryHit{std::sqrt(own.best_d2[k]), own.best_edge[k], own.best_t[k], false};
    own.hit_stamp[k] = stamp_;
    return geometry_of(own, i, other, use_a, false);
  }

  // overlapping: delta and normal of the deepest point overall
  const double depth_a = deepest_a >= 0 ? a_.hit[static_cast<std::size_t>(deepest_a)].distance_m : -1.0;
  const double depth_b = deepest_b >= 0 ? b_.hit[static_cast<std::size_t>(deepest_b)].distance_m : -1.0;
  const bool a_deepest = depth_a >= depth_b;
  ContactGeometry g = a_deepest ? geometry_of(a_, deepest_a, b_, true, true)
                                : geometry_of(b_, deepest_b, a_, false, true);
  // line of action through the depth-weighted centroid of the inside points
  // of the body that has more of them (every one was walked by classify)
  auto run_of = [&](Body& body, int start) {
    internal::Run r = internal::inside_run(
        body.size(), start,
        [&](int i) {
          const auto k = static_cast<std::size_t>(i);
          return body.status_stamp[k] == stamp_ && body.inside[k] != 0;
        },
        [&](int i) { return body.hit[static_cast<std::size_t>(i)].distance_m; },
        [&](int i) {
          const auto k = static_cast<std::size_t>(i);
          return Vec2(body.x[k], body.y[k]);
        });
    if (r.first < 0 || body.inside_walked_count == r.run_points) return r;
    const auto walked = std::span<int>(body.inside_walked.data(),
                                       static_cast<std::size_t>(body.inside_walked_count));
    std::sort(walked.begin(), walked.end());
    internal::add_other_inside(
        r, body.size(), walked,
        [&](int i) { return body.hit[static_cast<std::size_t>(i)].distance_m; },
        [&](int i) {
          const auto k = static_cast<std::size_t>(i);
          return Vec2(body.x[k], body.y[k]);
        });
    return r;
  };
  const internal::Run run_a = run_of(a_, deepest_a);
  const internal::Run run_b = run_of(b_, deepest_b);
  internal::place_line_of_action(g, run_a, run_b, a_deepest, action_points_);
  return g;
}

}  // namespace pb
