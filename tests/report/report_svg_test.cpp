// Tests for reports/src/report_svg.cpp
#include "report_svg.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pb::internal {
namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// tick steps are 1, 2 or 5 x 10^k nearest range / target
TEST(TickStep, NiceSteps) {
  EXPECT_DOUBLE_EQ(tick_step(2.5, 8), 0.2);      // 0.3125 -> 0.2
  EXPECT_DOUBLE_EQ(tick_step(581.0, 6), 100.0);  // 96.8 -> 100
  EXPECT_DOUBLE_EQ(tick_step(0.004, 4), 0.001);  // 0.001 -> 0.001
  EXPECT_DOUBLE_EQ(tick_step(35.0, 8), 5.0);     // 4.375 -> 5
}

Figure two_series_figure() {
  Figure f;
  f.id = "case_fig";
  f.title = "Force figure";
  f.y_label = "contact force, N";
  f.quantity = Quantity::force;
  f.t_end_s = 1.0;
  PlotSeries truth{"analytic", {0.0, 0.5, 1.0}, {0.0, 10.0, 0.0}, 3, "", 10.0, false};
  PlotSeries engine{
      "mujoco", {0.0, 0.25, 0.5, 0.75, 1.0}, {0.0, 5.0, std::nan(""), 5.0, 0.0}, 5, "", 5.0, false};
  f.series = {truth, engine};
  return f;
}

TEST(FigureSvg, DeterministicOnePolylinePerUnbrokenStretch) {
  const Figure f = two_series_figure();
  const std::string a = figure_svg(f, 0.0, 1.0, "Fig. <1> & co");
  EXPECT_EQ(a, figure_svg(f, 0.0, 1.0, "Fig. <1> & co"));
  EXPECT_EQ(a.rfind("<svg", 0), 0u);
  EXPECT_NE(a.find("Fig. &lt;1&gt; &amp; co"), std::string::npos);
  // the truth: one line; the engine: a NaN splits it in two
  EXPECT_EQ(count(a, "<polyline"), 3u);
  EXPECT_EQ(count(a, "stroke-dasharray"), 2u);  // the truth's line and legend entry
  EXPECT_NE(a.find("analytic (truth)"), std::string::npos);
  EXPECT_NE(a.find(">mujoco<"), std::string::npos);
  EXPECT_NE(a.find("contact force, N"), std::string::npos);
}

TEST(FigureSvg, OffScaleSeriesIsNamed) {
  Figure f = two_series_figure();
  f.y_clip = 11.0;
  f.series[1].value[1] = 1e5;
  f.series[1].peak = 1e5;
  f.series[1].off_scale = true;
  const std::string svg = figure_svg(f, 0.0, 1.0, "Force figure");
  EXPECT_NE(svg.find("off scale: mujoco (peak 1e+05)"), std::string::npos);
}

TEST(XmlEscape, EscapesMarkup) {
  EXPECT_EQ(xml_escape("a<b>&\"c\""), "a&lt;b&gt;&amp;&quot;c&quot;");
}

}  // namespace
}  // namespace pb::internal
