#include "planarbench/reference/outline_tree.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace pb {

namespace {

// distance from p to the segment a -> a + d (d may be zero)
double point_segment_distance(const Vec2& p, const Vec2& a, const Vec2& d, double inv_len2) {
  const double t = std::clamp((p - a).dot(d) * inv_len2, 0.0, 1.0);
  return (p - a - t * d).norm();
}

// area of a capsule: the rectangle along the axis plus the two half disks
double capsule_area_m2(double radius_m, double axis_len_m) {
  return std::numbers::pi * radius_m * radius_m + 2.0 * radius_m * axis_len_m;
}

}  // namespace

OutlineTree::OutlineTree(std::vector<Vec2> outline_m) : points_(std::move(outline_m)) {
  const int n = size();
  if (n < 1) throw std::invalid_argument("an outline tree needs at least one point");
  for (const Vec2& p : points_) extent_m_ = std::max(extent_m_, p.norm());
  // arc length at each vertex, for length-balanced splits
  std::vector<double> arc_m(static_cast<std::size_t>(n) + 1, 0.0);
  for (int i = 0; i < n; ++i) {
    const Vec2& p = points_[static_cast<std::size_t>(i)];
    const Vec2& q = points_[static_cast<std::size_t>((i + 1) % n)];
    arc_m[static_cast<std::size_t>(i) + 1] = arc_m[static_cast<std::size_t>(i)] + (q - p).norm();
  }
  nodes_.reserve(2 * static_cast<std::size_t>(n) - 1);
  leaf_of_edge_.assign(static_cast<std::size_t>(n), -1);
  build(0, n, 1, arc_m);
}

int OutlineTree::build(int first_edge, int end_edge, int level, const std::vector<double>& arc_m) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.push_back(Node{});
  nodes_.back().first_edge = first_edge;
  nodes_.back().end_edge = end_edge;
  depth_ = std::max(depth_, level);
  fit_capsule(nodes_.back());
  const int count = end_edge - first_edge;
  if (count == 1) {
    leaf_of_edge_[static_cast<std::size_t>(first_edge)] = index;
    return index;
  }

  // the split nearest half the arc length, within the middle half of the range
  const int slack = std::max(1, count / 4);
  const double half_m = 0.5 * (arc_m[static_cast<std::size_t>(first_edge)] +
                               arc_m[static_cast<std::size_t>(end_edge)]);
  const auto begin = arc_m.begin() + first_edge + slack;
  const auto end = arc_m.begin() + end_edge - slack + 1;
  int split = static_cast<int>(std::lower_bound(begin, end, half_m) - arc_m.begin());
  split = std::clamp(split, first_edge + slack, end_edge - slack);

  const int left = build(first_edge, split, level + 1, arc_m);
  const int right = build(split, end_edge, level + 1, arc_m);
  nodes_[static_cast<std::size_t>(index)].left = left;
  nodes_[static_cast<std::size_t>(index)].right = right;
  nodes_[static_cast<std::size_t>(left)].parent = index;
  nodes_[static_cast<std::size_t>(right)].parent = index;
  return index;
}

void OutlineTree::fit_capsule(Node& node) const {
  const int n = size();
  auto vertex = [&](int k) -> const Vec2& { return points_[static_cast<std::size_t>(k % n)]; };
  const Vec2& first = vertex(node.first_edge);
  const Vec2& last = vertex(node.end_edge);

  // the bounding circle about the centre of the range's bounding box
  Vec2 lo = first, hi = first;
  for (int k = node.first_edge; k <= node.end_edge; ++k) {
    lo = lo.cwiseMin(vertex(k));
    hi = hi.cwiseMax(vertex(k));
  }
  const Vec2 centre = 0.5 * (lo + hi);
  double circle_r = 0.0;
  for (int k = node.first_edge; k <= node.end_edge; ++k) {
    circle_r = std::max(circle_r, (vertex(k) - centre).norm());
  }
  node.axis_start_m = centre;
  node.axis_m = Vec2::Zero();
  node.axis_inv_len2 = 0.0;
  node.axis_len_m = 0.0;
  node.radius_m = circle_r;

  // the capsule along the chord, centred between the extremes across it
  const Vec2 chord = last - first;
  const double chord_len = chord.norm();
  if (!(chord_len > 0.0)) return;
  const Vec2 u = chord / chord_len;
  const Vec2 w(-u.y(), u.x());
  double s_min = 0.0, s_max = 0.0, h_min = 0.0, h_max = 0.0;
  for (int k = node.first_edge; k <= node.end_edge; ++k) {
    const Vec2 r = vertex(k) - first;
    s_min = std::min(s_min, r.dot(u));
    s_max = std::max(s_max, r.dot(u));
    h_min = std::min(h_min, r.dot(w));
    h_max = std::max(h_max, r.dot(w));
  }
  const double h_mid = 0.5 * (h_min + h_max);
  const Vec2 start = first + s_min * u + h_mid * w;
  const Vec2 axis = (s_max - s_min) * u;
  const double axis_len2 = axis.squaredNorm();
  const double inv_len2 = axis_len2 > 0.0 ? 1.0 / axis_len2 : 0.0;
  double capsule_r = 0.0;
  for (int k = node.first_edge; k <= node.end_edge; ++k) {
    capsule_r = std::max(capsule_r, point_segment_distance(vertex(k), start, axis, inv_len2));
  }
  if (capsule_area_m2(capsule_r, std::sqrt(axis_len2)) < capsule_area_m2(circle_r, 0.0)) {
    node.axis_start_m = start;
    node.axis_m = axis;
    node.axis_inv_len2 = inv_len2;
    node.axis_len_m = std::sqrt(axis_len2);
    node.radius_m = capsule_r;
  }
}

}  // namespace pb
