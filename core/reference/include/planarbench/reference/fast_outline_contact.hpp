// Contact detection on outlines, fast: the same result as the brute-force
// search (OutlineContactSearch, outline_contact.hpp, the oracle: read its
// header for what is computed and why). Setting `detection = fast` of engine
// reference (the default) for every pair and pose that the closed form of
// convex_line_contact.hpp does not answer; `detection = brute` selects the
// oracle.
//
// Cost. Apart or touching, O(log N) tree nodes per evaluation for smooth
// outlines (the capsules of outline_tree.hpp keep O(1) nodes per level near
// the point of closest approach); overlapping, plus O(log N) for each outline
// point inside the other body: the line of action is the centroid of a whole
// run of inside points, so every one of them is visited. The worst case
// (e.g. two nearly coincident outlines, every pair within the bound) is the
// brute force's O(N M) plus the trees' overhead.
//
// How it stays exact. Both searches place the vertices they use in the world
// with the same expression and evaluate the same per-(point, edge) formulas
// (src/outline_kernels.hpp): every number this search computes is bit for
// bit the number the brute force computes for the same point and edge. What
// it adds is only which (point, edge) pairs it may skip, and a pair is skipped
// only when a conservative lower bound proves that it cannot matter:
// * Bounding volumes (outline_tree.hpp): one capsule hierarchy per outline in
//   its body frame. Only the nodes visited are placed in the world (two
//   points each), and only the vertices and edges visited (cached per
//   evaluation, stamped with an evaluation counter, so nothing is cleared).
//   Every lower bound subtracts a margin of 1e-10 times the size of the
//   scene's world coordinates plus 1e-12 m: four orders above the rounding of
//   the bounds (~1e-14 relative), far below any distance that matters.
// * Closest point. A simultaneous descent of both trees over node pairs,
//   nearer pair first, skips a pair whose capsules are farther apart than
//   T = max(U, margin), U the least point-edge distance computed so far.
//   Skipping is strict, so every pair at the least distance is computed and
//   ties are broken as the brute force breaks them: the lowest edge index for
//   a point; over points the brute force's sweep order (the body with the
//   smaller world bounding box first, then the vertex index; the boxes, O(N),
//   are computed only for an exact tie between the two bodies).
// * Inside points. Along one outline the inside/outside status can change
//   only across an edge that comes within the margin of the other outline
//   (a "near" edge, found by the same descent: T >= margin): the crossing
//   test is exact for points farther than its rounding (~1e-15 relative)
//   from the other boundary. The endpoints of near edges get the brute
//   force's crossing-number test (over the edges whose capsule can meet the
//   ray); from each inside one the run of inside points is walked both ways,
//   the status carried along edges that are not near. Each inside point gets
//   its exact nearest boundary point by branch and bound, climbing from its
//   neighbour's nearest edge to the root. With no near edge at all, every
//   vertex has the status of vertex 0: one test (one body deep inside the
//   other, or apart).
// * Temporal coherence. The last evaluation's closest (point, edge) pair and
//   a greedy descent over neighbouring points and edges give a small U before
//   the tree descent starts. It only tightens the bound: the result does not
//   depend on it (tested: a search with history and one without agree).
// The two searches agree to the last bit when built by the same compiler for
// a machine without fused multiply-add contraction (x86-64 without -march);
// the contract, and the tests, say 1e-12 m.
// Hot path: no allocation (scratch sized at construction), no throw.
#pragma once

#include <cstdint>
#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/reference/contact_geometry.hpp"
#include "planarbench/reference/outline_contact.hpp"
#include "planarbench/reference/outline_tree.hpp"

namespace pb {

// what one evaluation did, to check the search's cost without a clock
struct FastSearchWork {
  long node_pairs = 0;        // node pairs of the simultaneous descent examined
  long point_edge_tests = 0;  // point-edge distances computed
  long crossing_queries = 0;  // crossing-number tests (tree walks)
  long nearest_queries = 0;   // exact nearest-boundary searches (tree walks)
  int inside_points = 0;      // outline points found inside the other body
};

class FastOutlineContactSearch {
 public:
  // outlines in their body frames, closed, counter-clockwise
  FastOutlineContactSearch(std::vector<Vec2> outline_a_m, std::vector<Vec2> outline_b_m);
  // whose inside points place the line of action (outline_contact.hpp)
  void set_action_points(ActionPoints rule) { action_points_ = rule; }

  [[nodiscard]] ContactGeometry evaluate(const Pose& pose_a, const Pose& pose_b);

  // the next evaluation starts without the last one's closest pair
  void forget_history() { has_history_ = false; }
  [[nodiscard]] const FastSearchWork& last_work() const { return work_; }

 private:
  // one outline, its tree and its per-evaluation caches, stamped with the
  // evaluation counter (an entry is valid when its stamp is the current one)
  struct Body {
    explicit Body(std::vector<Vec2> outline_m);
    OutlineTree tree;
    Eigen::Matrix2d rotation = Eigen::Matrix2d::Identity();
    Vec2 position_m = Vec2::Zero();
    // the tree's nodes, structure of arrays: children, parent, leaf edge,
    // capsule radius, and radius + half axis (the reach from the midpoint)
    std::vector<int> left, right, parent, first_edge;
    std::vector<double> radius_m, reach_m, axis_inv_len2;  // m, m, 1/m^2
    // world vertices, edge data and node capsule axes
    std::vector<std::uint64_t> vertex_stamp, edge_stamp, node_stamp;
    std::vector<double> x, y;                        // m
    std::vector<double> ex, ey, inv_len2, x_per_y;   // m, m, 1/m^2, -
    std::vector<double> ax, ay, adx, ady;            // m, capsule axis start and vector
    // per vertex: least distance found to the other boundary (candidates)
    std::vector<std::uint64_t> best_stamp;
    std::vector<double> best_d2;                     // m^2
    std::vector<int> best_edge;
    std::vector<double> best_t;
    std::vector<int> touched;                        // vertices with a best entry
    int touched_count = 0;
    // per vertex: crossing-number status, exact boundary hit, run walk
    std::vector<std::uint64_t> status_stamp, hit_stamp, walk_stamp;
    std::vector<unsigned char> inside;
    std::vector<BoundaryHit> hit;
    // the inside points walked this evaluation, in walk order
    std::vector<int> inside_walked;
    int inside_walked_count = 0;
    // per edge: within the margin of the other outline
    std::vector<std::uint64_t> near_stamp;
    std::vector<int> near_edges;
    int near_count = 0;
    [[nodiscard]] int size() const { return tree.size(); }
    [[nodiscard]] bool leaf(int node) const { return left[static_cast<std::size_t>(node)] < 0; }
  };
  // a node pair of the simultaneous descent with a lower bound on the
  // distance of its capsules (m, negative when they overlap), margin included
  struct PairEntry {
    int node_a, node_b;
    double lower_bound_m;
  };
  // a node of one tree against a point
  struct NodeEntry {
    int node;
    double axis_d2_m2;
  };

  void begin(Body& body, const Pose& pose);
  // the world vertex i, edge j, node capsule axis: cached per evaluation
  void vertex(Body& body, int i) {
    if (body.vertex_stamp[static_cast<std::size_t>(i)] != stamp_) place_vertex(body, i);
  }
  void edge(Body& body, int j) {
    if (body.edge_stamp[static_cast<std::size_t>(j)] != stamp_) place_edge(body, j);
  }
  void place_node(Body& body, int node) {
    if (body.node_stamp[static_cast<std::size_t>(node)] != stamp_) place_node_axis(body, node);
  }
  void place_vertex(Body& body, int i);
  void place_edge(Body& body, int j);
  void place_node_axis(Body& body, int node);
  void record(Body& own, int i, double d2, int edge, double t, bool own_is_a);
  PairEntry pair_entry(int na, int nb);
  void seed_from_history();
  void descend_pairs();
  void leaf_pair(int edge_a, int edge_b);
  bool crossing_inside(Body& own, int i, Body& other);
  const BoundaryHit& exact_hit(Body& own, int i, Body& other, int guess_edge);
  void classify(Body& own, Body& other, int& deepest);
  void walk_run(Body& own, int start, Body& other, int& deepest);
  void set_status(Body& own, int i, bool in);
  ContactGeometry geometry_of(Body& own, int i, Body& other, bool own_is_a, bool overlapping);
  bool a_sweeps_first();

  Body a_, b_;
  std::uint64_t stamp_ = 0;
  double margin_m_ = 0.0;   // m, rounding allowance of every lower bound
  double best_d2_ = 0.0;    // m^2, U^2: least point-edge distance so far, squared
  double bound_m_ = 0.0;    // m, T = max(U, margin): node pairs farther apart are skipped
  // the pair of best_d2_: a vertex of a (edge on b) or of b (edge on a)
  bool best_of_a_ = true;
  int best_vertex_ = -1, best_edge_ = -1;
  bool has_history_ = false;
  std::vector<PairEntry> pair_stack_;
  std::vector<NodeEntry> node_stack_;
  FastSearchWork work_;
  ActionPoints action_points_ = ActionPoints::more;
};

}  // namespace pb
