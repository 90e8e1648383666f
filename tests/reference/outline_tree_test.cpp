// Tests for core/reference/src/outline_tree.cpp
//
// The tree's promises, checked node by node on the outlines the cases use
// (disk, ellipse, half-plane segment closed far below) and on random concave
// ones: the children split their parent's edge range, leaves are single
// edges, every vertex of a node's range lies in its capsule, the depth is
// logarithmic, and arcs get capsules much thinner than their bounding circle.
#include "planarbench/reference/outline_tree.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "planarbench/outline.hpp"
#include "planarbench/reference/outline_contact.hpp"

namespace pb {
namespace {

// distance from p to a node's capsule axis, written out independently
double axis_distance(const OutlineTree::Node& nd, const Vec2& p) {
  const Vec2 a = nd.axis_start_m;
  const Vec2 b = nd.axis_start_m + nd.axis_m;
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  if (len2 == 0.0) return (p - a).norm();
  const double t = std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

void check_tree(const std::vector<Vec2>& points) {
  const OutlineTree tree(points);
  const int n = tree.size();
  ASSERT_EQ(n, static_cast<int>(points.size()));
  const auto& nodes = tree.nodes();
  ASSERT_EQ(nodes.size(), 2 * points.size() - 1);  // a binary tree with one leaf per edge
  EXPECT_EQ(nodes[0].first_edge, 0);
  EXPECT_EQ(nodes[0].end_edge, n);
  int leaves = 0;
  for (const auto& nd : nodes) {
    if (nd.leaf()) {
      EXPECT_EQ(nd.end_edge - nd.first_edge, 1);
      ++leaves;
    } else {
      const auto& l = nodes[static_cast<std::size_t>(nd.left)];
      const auto& r = nodes[static_cast<std::size_t>(nd.right)];
      EXPECT_EQ(l.first_edge, nd.first_edge);
      EXPECT_EQ(l.end_edge, r.first_edge);
      EXPECT_EQ(r.end_edge, nd.end_edge);
    }
    // every vertex of the range, both ends included; 1e-12 m: the radius is
    // the largest of the same distances computed in the same way, up to the
    // rounding of a different formula (~1e-16 m at these sizes)
    for (int k = nd.first_edge; k <= nd.end_edge; ++k) {
      EXPECT_LE(axis_distance(nd, points[static_cast<std::size_t>(k % n)]), nd.radius_m + 1e-12);
    }
  }
  EXPECT_EQ(leaves, n);
  // splits within the middle half of each range: depth <= log_{4/3}(n) + 2
  EXPECT_LE(tree.depth(), std::log(static_cast<double>(n)) / std::log(4.0 / 3.0) + 2.0);
}

TEST(OutlineTree, NodesHoldTheirVerticesOnTheCasesOutlines) {
  for (const int n : {3, 4, 45, 180, 181, 1440}) {
    check_tree(contact_outline(Circle{0.5}, n));
    check_tree(contact_outline(Ellipse{1.0, 0.2}, n));
    check_tree(contact_outline(HalfPlane{40.0}, n));
  }
}

TEST(OutlineTree, NodesHoldTheirVerticesOnRandomConcaveOutlines) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 3 + static_cast<int>(u(rng) * 297);
    std::vector<double> angles;
    for (int i = 0; i < n; ++i) angles.push_back(2 * std::numbers::pi * u(rng));
    std::sort(angles.begin(), angles.end());
    std::vector<Vec2> p;
    for (const double t : angles) {
      const double r = 0.2 + 0.8 * u(rng);
      p.emplace_back(5.0 + r * std::cos(t), -3.0 + r * std::sin(t));
    }
    check_tree(p);
  }
}

TEST(OutlineTree, ArcsGetThinCapsules) {
  // A 1440-point circle of radius 0.5 m: a node of k edges spans the angle
  // 2 pi k / 1440, whose sagitta is R (1 - cos(pi k / 1440)); the fitted
  // capsule is half of it thick (it is centred between chord and arc) up to
  // the chord-end rounding, far below the node's half chord.
  const double r = 0.5;
  const int n = 1440;
  const OutlineTree tree(contact_outline(Circle{r}, n));
  int checked = 0;
  for (const auto& nd : tree.nodes()) {
    const int k = nd.end_edge - nd.first_edge;
    if (nd.leaf() || k > n / 8) continue;
    const double sagitta = r * (1.0 - std::cos(std::numbers::pi * k / n));
    // 1e-12 m: rounding of the fitted radius
    EXPECT_LE(nd.radius_m, 0.5 * sagitta + 1e-12) << k;
    ++checked;
  }
  EXPECT_GT(checked, 1000);
}

TEST(OutlineTree, HalfPlaneClosingEdgesSitInSmallNodes) {
  // The half-plane's two closing edges (28 m each, to the point 20 m below)
  // are split off early by the length-balanced split: their parent holds
  // only a few of the 0.22 m surface edges.
  const int n = 180;
  const OutlineTree tree(contact_outline(HalfPlane{40.0}, n));
  for (const auto& nd : tree.nodes()) {
    if (nd.leaf()) continue;
    const auto& l = tree.nodes()[static_cast<std::size_t>(nd.left)];
    const auto& r = tree.nodes()[static_cast<std::size_t>(nd.right)];
    if (r.first_edge == n - 1 && r.end_edge == n + 1) {
      EXPECT_LE(l.end_edge - l.first_edge, 12);
    }
  }
}

}  // namespace
}  // namespace pb
