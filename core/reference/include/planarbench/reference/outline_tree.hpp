// A bounding-volume hierarchy over the edges of one closed outline, in its
// body frame, for the fast contact search (fast_outline_contact.hpp).
//
// Outlines are spatially coherent: consecutive points are close. Every node
// therefore covers a contiguous range of edges [first_edge, end_edge), i.e.
// the vertices first_edge .. end_edge (end_edge taken modulo n), and the
// leaves are single edges. A node's volume is a capsule (a segment inflated by
// a radius: the set of points within radius_m of the axis), which is rotation
// invariant: placing it in the world moves two points, never the vertices.
// Why capsules and not circles: two smooth outlines near contact are almost
// tangent, and the number of circles of radius r within a given distance of a
// tangent curve grows like 1/sqrt(r), so circle hierarchies open O(sqrt N)
// leaves; a capsule fitted along an arc of length l has a thickness of only
// its sagitta, kappa l^2 / 8, and only the O(1) nodes around the point of
// closest approach stay within the distance at every level (O(log N)).
// Each internal node keeps the smaller (by area) of two capsules that both
// contain its vertices, hence its edges (a capsule is convex): one along the
// chord of its range, centred between the extreme vertices across it; and
// the bounding circle of the range (a capsule with a zero-length axis).
//
// Splits balance the arc length of the two halves (so that a long closing
// edge, as in a half-plane's outline, does not sit in a node with many short
// ones), clamped to the middle half of the range so that the depth stays
// O(log N).
#pragma once

#include <vector>

#include "planarbench/case.hpp"

namespace pb {

class OutlineTree {
 public:
  struct Node {
    int first_edge = 0;     // edges [first_edge, end_edge), vertices first .. end
    int end_edge = 0;
    int left = -1;          // child nodes; -1 for a leaf (one edge, first_edge)
    int right = -1;
    int parent = -1;        // -1 for the root (node 0)
    Vec2 axis_start_m = Vec2::Zero();  // m, body frame, capsule axis start
    Vec2 axis_m = Vec2::Zero();        // m, capsule axis vector (zero: a circle)
    double axis_inv_len2 = 0.0;        // 1/m^2, 1 / |axis|^2 (0 for a circle)
    double axis_len_m = 0.0;           // m, |axis|
    double radius_m = 0.0;             // m, every vertex of the range lies within it
    [[nodiscard]] bool leaf() const { return left < 0; }
  };

  // points of a closed outline in its body frame (at least one)
  explicit OutlineTree(std::vector<Vec2> outline_m);

  [[nodiscard]] const std::vector<Vec2>& points() const { return points_; }
  [[nodiscard]] int size() const { return static_cast<int>(points_.size()); }
  [[nodiscard]] const std::vector<Node>& nodes() const { return nodes_; }
  // the leaf node of edge j
  [[nodiscard]] int leaf_of_edge(int j) const { return leaf_of_edge_[static_cast<std::size_t>(j)]; }
  // levels from the root (1) to the deepest leaf
  [[nodiscard]] int depth() const { return depth_; }
  // m, the largest distance of a vertex from the body origin
  [[nodiscard]] double extent_m() const { return extent_m_; }

 private:
  int build(int first_edge, int end_edge, int level, const std::vector<double>& arc_m);
  void fit_capsule(Node& node) const;

  std::vector<Vec2> points_;
  std::vector<Node> nodes_;
  std::vector<int> leaf_of_edge_;
  int depth_ = 0;
  double extent_m_ = 0.0;
};

}  // namespace pb
