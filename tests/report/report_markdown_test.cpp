// Tests for reports/src/report_markdown.cpp
#include "report_markdown.hpp"

#include <gtest/gtest.h>

namespace pb::internal {
namespace {

TEST(MarkdownTable, EscapesPipesFoldsNewlinesBoldsFailures) {
  Table t;
  t.columns = {"a", "b"};
  t.rows = {{"x|y", "line\nbreak"}, {"bad", "z"}};
  t.row_status = {"", "fail"};
  EXPECT_EQ(markdown_table(t), "| a | b |\n|---|---|\n| x\\|y | line break |\n| **bad** | z |\n");
}

TEST(FigureViews, ForceFiguresGetAZoomOnTheFirstEpisode) {
  Figure f;
  f.id = "falling_ball_fig5";
  f.title = "Fig. 5 Contact force";
  f.quantity = Quantity::force;
  f.t_end_s = 2.5;
  f.episodes = {{"episode 0", 0.70, 0.78}, {"episode 1", 1.9, 2.1}};
  const auto views = figure_views(f);
  ASSERT_EQ(views.size(), 2u);
  EXPECT_EQ(views[0].file, "figures/falling_ball_fig5.svg");
  EXPECT_DOUBLE_EQ(views[0].t1_s, 2.5);
  EXPECT_EQ(views[1].file, "figures/falling_ball_fig5_episode0.svg");
  EXPECT_DOUBLE_EQ(views[1].t0_s, 0.70);
  f.quantity = Quantity::y;
  EXPECT_EQ(figure_views(f).size(), 1u);
}

TEST(ReportMarkdown, SectionsFiguresTablesAndMapping) {
  Report r;
  r.results_file = "r.h5";
  r.check_summary = "1 of 2 checks passed, 1 failed";
  CaseSection c;
  c.name = "falling_ball";
  c.description = "A disk";
  c.assumptions = {"m = 1 kg"};
  Figure f;
  f.id = "falling_ball_fig6";
  f.title = "Fig. 6 y";
  f.t_end_s = 2.5;
  f.series.push_back(PlotSeries{"analytic", {0.0}, {1.0}, 1, "", 0.0, false});
  c.figures.push_back(f);
  r.cases.push_back(c);
  Table t;
  t.title = "Timings";
  t.columns = {"case"};
  t.rows = {{"falling_ball"}};
  t.row_status = {""};
  r.tables.push_back(t);
  r.mappings.push_back(
      MappingEntry{"falling_ball", "box2d", "ok", nlohmann::json{{"k", 1}}, {"stiffness"}});
  const std::string md = report_markdown(r);
  EXPECT_NE(md.find("**Check:** 1 of 2 checks passed, 1 failed"), std::string::npos);
  EXPECT_NE(md.find("## falling_ball\n"), std::string::npos);
  EXPECT_NE(md.find("- m = 1 kg"), std::string::npos);
  EXPECT_NE(md.find("![Fig. 6 y](figures/falling_ball_fig6.svg)"), std::string::npos);
  EXPECT_NE(md.find("## Timings\n"), std::string::npos);
  EXPECT_NE(md.find("- [Timings](#timings)"), std::string::npos);
  EXPECT_NE(md.find("### falling_ball / box2d (ok)"), std::string::npos);
  EXPECT_NE(md.find("- stiffness"), std::string::npos);
  EXPECT_NE(md.find("| k | 1 |"), std::string::npos);
}

}  // namespace
}  // namespace pb::internal
