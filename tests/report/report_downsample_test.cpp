// Tests for reports/src/report_downsample.cpp
#include "report_downsample.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pb::internal {
namespace {

// a grid t_k = k dt, k = 0 .. n-1
std::vector<double> grid(std::size_t n, double dt) {
  std::vector<double> t(n);
  for (std::size_t k = 0; k < n; ++k) t[k] = static_cast<double>(k) * dt;
  return t;
}

TEST(MergeWindows, SortsMergesOverlapsAndDropsEmpty) {
  const auto m = merge_windows({{0.5, 0.6},
                                {0.1, 0.2},
                                {0.15, 0.3},
                                {0.6, 0.7},
                                {0.9, 0.8},  // reversed: empty
                                {std::nan(""), 1.0}});
  ASSERT_EQ(m.size(), 2u);
  EXPECT_DOUBLE_EQ(m[0].t0_s, 0.1);
  EXPECT_DOUBLE_EQ(m[0].t1_s, 0.3);
  EXPECT_DOUBLE_EQ(m[1].t0_s, 0.5);  // touching windows merge
  EXPECT_DOUBLE_EQ(m[1].t1_s, 0.7);
}

// 25001 samples (falling_ball's grid), one 31 ms contact window: every
// sample in the window survives, the rest is thinned to the budget
TEST(DownsampleIndices, KeepsEverySampleInsideWindowsAndThinsOutside) {
  const auto t = grid(25001, 1e-4);
  const TimeWindow w{0.7249, 0.7561};
  const auto keep = downsample_indices(t, {w}, 5000, 100000);
  std::size_t inside_total = 0;
  for (const double x : t) inside_total += (x >= w.t0_s && x <= w.t1_s) ? 1 : 0;
  std::size_t inside_kept = 0;
  std::size_t outside_kept = 0;
  for (std::size_t i = 0; i < keep.size(); ++i) {
    if (i > 0) {
      ASSERT_LT(keep[i - 1], keep[i]);  // ascending, unique
    }
    const double x = t[keep[i]];
    ((x >= w.t0_s && x <= w.t1_s) ? inside_kept : outside_kept)++;
  }
  EXPECT_EQ(inside_kept, inside_total);
  EXPECT_LE(outside_kept, 5000u);
  // the budget is used, not wasted: an even integer stride over the ~24 690
  // outside samples is 5 (4938 kept); one stride coarser (6) keeps 4115
  EXPECT_GE(outside_kept, 4500u);
  EXPECT_EQ(keep.front(), 0u);
  EXPECT_EQ(keep.back(), t.size() - 1);
}

TEST(DownsampleIndices, ShortSeriesIsKeptWhole) {
  const auto t = grid(100, 0.01);
  EXPECT_EQ(downsample_indices(t, {}, 5000, 5000).size(), 100u);
  EXPECT_TRUE(downsample_indices({}, {}, 10, 10).empty());
}

TEST(DownsampleIndices, InsideBudgetGuardsHugeWindows) {
  const auto t = grid(10001, 1e-4);
  // the whole run is one window (a sustained contact), budget 1000 inside
  const auto keep = downsample_indices(t, {{0.0, 1.0}}, 5000, 1000);
  EXPECT_LE(keep.size(), 1001u);  // the budget and the last sample
  // an even integer stride of 11 keeps 910; one coarser (12) keeps 834
  EXPECT_GE(keep.size(), 900u);
  EXPECT_EQ(keep.back(), 10000u);
}

// a sustained contact thinned with its values keeps a one-sample spike and a
// one-sample dip that an even stride would step over, within the same budget
TEST(DownsampleIndices, InsideBudgetWithValuesKeepsPeaks) {
  const auto t = grid(10001, 1e-4);
  std::vector<double> v(t.size());
  for (std::size_t k = 0; k < v.size(); ++k) v[k] = std::sin(3.0 * t[k]);
  const std::size_t spike = 4567;  // not a multiple of the stride (11): an even stride misses it
  const std::size_t dip = 7891;
  v[spike] = 50.0;
  v[dip] = -50.0;
  const auto even = downsample_indices(t, {{0.0, 1.0}}, 5000, 1000);
  ASSERT_EQ(std::count(even.begin(), even.end(), spike), 0);  // the case this mode exists for
  const auto keep = downsample_indices(t, {{0.0, 1.0}}, 5000, 1000, &v);
  EXPECT_EQ(std::count(keep.begin(), keep.end(), spike), 1);
  EXPECT_EQ(std::count(keep.begin(), keep.end(), dip), 1);
  // two per block of 2 x 11 samples: 10001 / 22 blocks x 2 = 910, + first and last
  EXPECT_LE(keep.size(), 1001u);
  EXPECT_GE(keep.size(), 900u);
  EXPECT_TRUE(std::is_sorted(keep.begin(), keep.end()));
  EXPECT_EQ(keep.front(), 0u);
  EXPECT_EQ(keep.back(), 10000u);
  // a NaN is never chosen as an extreme and does not hide its block's peak
  v[100] = std::numeric_limits<double>::quiet_NaN();
  v[101] = 40.0;
  const auto with_nan = downsample_indices(t, {{0.0, 1.0}}, 5000, 1000, &v);
  EXPECT_EQ(std::count(with_nan.begin(), with_nan.end(), 100u), 0);
  EXPECT_EQ(std::count(with_nan.begin(), with_nan.end(), 101u), 1);
}

// a single-sample spike among 10000 smooth samples survives decimation into
// 50 buckets, and so do the samples just outside the range
TEST(MinmaxIndices, KeepsThePeakAndTheRangeEdges) {
  const auto t = grid(10000, 1e-3);
  std::vector<double> v(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) v[i] = std::sin(t[i]);
  v[4321] = 100.0;
  v[1234] = std::numeric_limits<double>::quiet_NaN();
  const auto keep = minmax_indices(t, v, 1.0, 8.0, 50);
  EXPECT_NE(std::find(keep.begin(), keep.end(), 4321u), keep.end());
  EXPECT_LE(keep.size(), 4u * 50u + 2u);  // first, min, max, last per bucket + the two edges
  EXPECT_EQ(keep.front(), 999u);  // the sample before t = 1.0
  EXPECT_EQ(keep.back(), 8001u);  // the sample after t = 8.0
}

}  // namespace
}  // namespace pb::internal
