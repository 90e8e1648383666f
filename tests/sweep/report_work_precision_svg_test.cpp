// Tests for reports/src/report_work_precision_svg.cpp
#include "report_work_precision_svg.hpp"

#include <gtest/gtest.h>

#include <string>

namespace {

std::size_t count(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (auto at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

// Two series over exact decades: wall 0.01 .. 1 s, error 1e-6 .. 1e-2 m, so
// the axes span exactly those decades (the 1e-3 and 1e-5 m targets inside).
pb::internal::WorkPrecisionCase sample() {
  pb::internal::WorkPrecisionCase c;
  c.name = "falling_ball";
  c.id = "falling_ball_work_precision";
  c.targets_m = {1e-3, 1e-5};
  pb::internal::WorkPrecisionSeries a;
  a.name = "reference_rk45";
  a.engine = "reference";
  a.wall_s = {0.01, 0.1, 1.0};
  a.error_m = {1e-2, 1e-4, 1e-6};
  a.labels = {"rtol=1e-4", "rtol=1e-6", "rtol=1e-8"};
  a.default_index = 2;
  pb::internal::WorkPrecisionSeries b = a;
  b.name = "reference_fixed";
  b.dashed = true;
  b.default_index = -1;
  c.series = {a, b};
  return c;
}

TEST(Decades, CoverTheRangeWithWholeDecades) {
  const auto d = pb::internal::decades_of(0.02, 3.0);
  EXPECT_EQ(d.lo, -2);
  EXPECT_EQ(d.hi, 1);
  // an exact power of ten is its own bound
  const auto e = pb::internal::decades_of(1e-6, 1e-2);
  EXPECT_EQ(e.lo, -6);
  EXPECT_EQ(e.hi, -2);
  // a single value still gets one decade
  const auto f = pb::internal::decades_of(1e-3, 1e-3);
  EXPECT_EQ(f.hi - f.lo, 1);
}

TEST(Decades, LabelsReadAsNumbers) {
  EXPECT_EQ(pb::internal::decade_label(-3), "1e-3");
  EXPECT_EQ(pb::internal::decade_label(0), "1");
  EXPECT_EQ(pb::internal::decade_label(2), "100");
  EXPECT_EQ(pb::internal::decade_label(4), "1e4");
}

TEST(CompactNumber, ShortScientificBelowOneHundredth) {
  EXPECT_EQ(pb::internal::compact_number(5e-4), "5e-4");
  EXPECT_EQ(pb::internal::compact_number(1e-10), "1e-10");
  EXPECT_EQ(pb::internal::compact_number(2.5e-5), "2.5e-5");
  EXPECT_EQ(pb::internal::compact_number(0.25), "0.25");
  EXPECT_EQ(pb::internal::compact_number(1.0), "1");
}

TEST(WorkPrecisionSvg, OnePolylinePerSeriesACirclePerRungARingAtTheDefault) {
  const std::string svg = pb::internal::work_precision_svg(sample());
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_EQ(count(svg, "<polyline"), 2u);
  // 3 + 3 points, and one ring for the one series with a default rung
  EXPECT_EQ(count(svg, "r=\"3\""), 6u);
  EXPECT_EQ(count(svg, "r=\"6.5\""), 1u);
  // the dashed second series: its polyline and its legend entry
  EXPECT_EQ(count(svg, "stroke-dasharray=\"6 4\""), 2u);
  // the targets, labelled
  EXPECT_NE(svg.find(">1e-3 m<"), std::string::npos);
  EXPECT_NE(svg.find(">1e-5 m<"), std::string::npos);
}

TEST(WorkPrecisionSvg, PointsSitOnTheirDecades) {
  // plot box: x from 78 to 744 px over decades -2..0, y from 62 to 374 px
  // over decades -2..-6 (top to bottom); (0.01 s, 1e-2 m) is the top-left corner
  // and (1 s, 1e-6 m) the bottom-right one
  const std::string svg = pb::internal::work_precision_svg(sample());
  EXPECT_NE(svg.find("cx=\"78.00\" cy=\"62.00\""), std::string::npos) << svg;
  EXPECT_NE(svg.find("cx=\"744.00\" cy=\"374.00\""), std::string::npos) << svg;
  // (0.1 s, 1e-4 m): the middle of both axes
  EXPECT_NE(svg.find("cx=\"411.00\" cy=\"218.00\""), std::string::npos) << svg;
}

TEST(WorkPrecisionSvg, SameCaseSameBytesAndTextIsEscaped) {
  auto c = sample();
  c.name = "a<b&c";
  const std::string svg = pb::internal::work_precision_svg(c);
  EXPECT_EQ(svg, pb::internal::work_precision_svg(c));
  EXPECT_NE(svg.find("a&lt;b&amp;c"), std::string::npos);
  EXPECT_EQ(svg.find("a<b"), std::string::npos);
}

TEST(WorkPrecisionSvg, NothingToPlotSaysSo) {
  auto c = sample();
  for (auto& s : c.series) {
    s.wall_s.clear();
    s.error_m.clear();
    s.labels.clear();
  }
  const std::string svg = pb::internal::work_precision_svg(c);
  EXPECT_NE(svg.find("no rung has an error to plot"), std::string::npos);
  EXPECT_EQ(count(svg, "<polyline"), 0u);
}

}  // namespace
