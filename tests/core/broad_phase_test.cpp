// Tests for core/src/broad_phase.cpp: sort and sweep against every pair
// tested directly (an independent O(n^2) loop), on boxes spread along x, along
// y (a stack) and in a heap; and the half-plane height of a box.
#include "planarbench/broad_phase.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>
#include <vector>

namespace pb {
namespace {

std::vector<std::pair<int, int>> brute(const std::vector<Aabb>& boxes, const std::vector<int>& ids) {
  std::vector<std::pair<int, int>> out;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    for (std::size_t j = i + 1; j < boxes.size(); ++j) {
      const Aabb& a = boxes[i];
      const Aabb& b = boxes[j];
      if (a.min_x <= b.max_x && b.min_x <= a.max_x && a.min_y <= b.max_y && b.min_y <= a.max_y) {
        out.emplace_back(std::min(ids[i], ids[j]), std::max(ids[i], ids[j]));
      }
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(BroadPhase, SortAndSweepFindsExactlyTheOverlappingBoxes) {
  std::mt19937 rng(7);  // seeded
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const double spread_x : {10.0, 0.01, 3.0}) {
    std::vector<Aabb> boxes;
    std::vector<int> ids;
    for (int k = 0; k < 300; ++k) {
      const double x = spread_x * u(rng);
      const double y = (13.0 - spread_x) * u(rng);
      const double w = 0.05 + 0.1 * u(rng);
      boxes.push_back(Aabb{x, y, x + w, y + w});
      ids.push_back(1000 - 3 * k);  // ids in no order
    }
    std::vector<std::pair<int, int>> got;
    std::vector<int> scratch;
    overlapping_pairs(boxes, ids, got, scratch);
    EXPECT_EQ(got, brute(boxes, ids)) << "spread along x " << spread_x;
  }
}

TEST(BroadPhase, ShapeBoxesAndHalfPlaneHeights) {
  const Aabb disk = shape_aabb(Circle{0.5}, Vec2(1.0, 2.0), 0.3);
  EXPECT_DOUBLE_EQ(disk.min_x, 0.5);
  EXPECT_DOUBLE_EQ(disk.max_y, 2.5);
  // an ellipse turned 90 deg: its extents swap (sqrt of the squared axes)
  const Aabb e = shape_aabb(Ellipse{2.0, 1.0}, Vec2::Zero(), std::acos(0.0));
  EXPECT_NEAR(e.max_x, 1.0, 1e-15);
  EXPECT_NEAR(e.max_y, 2.0, 1e-15);
  const Aabb square = shape_aabb(Polygon{{Vec2(-1, -1), Vec2(1, -1), Vec2(1, 1), Vec2(-1, 1)}}, Vec2::Zero(),
                                 std::atan(1.0));
  EXPECT_NEAR(square.max_x, std::sqrt(2.0), 1e-15);
  // a line through the origin tilted 30 deg: the box's lowest corner along its normal
  const Aabb box{1.0, 1.0, 2.0, 3.0};
  const double a = std::asin(0.5);
  const double expect = std::min({-std::sin(a) * 1.0 + std::cos(a) * 1.0, -std::sin(a) * 2.0 + std::cos(a) * 1.0});
  EXPECT_NEAR(height_above_half_plane(box, Vec2::Zero(), a), expect, 1e-15);
}

}  // namespace
}  // namespace pb
