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

// A case's free text (its file's description, paper, assumptions, its name
// from the file name, --set values) is the user's, not the report's: it must
// reach report.md as text, never as HTML or Markdown (issue 24). The
// expected strings are written out by hand: '<', '>' and '&' as HTML
// entities, Markdown's punctuation with CommonMark's backslash escapes.
TEST(ReportMarkdown, CaseFreeTextIsEscapedNotMarkup) {
  Report r;
  r.results_file = "r.h5";
  CaseSection c;
  c.name = "<img src=x onerror=alert(1)>";
  c.description = "# not a heading <script>alert(1)</script> [link](http://e.example) *x*";
  c.paper = "![img](http://e.example/i.png)";
  c.assumptions = {"<b>bold</b> & `code` _under_ a_b", "- not a sub-item"};
  c.overrides = {{"duration", "1`<i>x</i>`"}};
  r.cases.push_back(c);
  Table t;
  t.title = "Timings";
  t.columns = {"case"};
  t.rows = {{"<script>x</script>"}};
  t.row_status = {""};
  r.tables.push_back(t);
  const std::string md = report_markdown(r);
  // (the override is in a code span, where nothing is markup)
  for (const char* raw : {"<script>", "<img", "<b>", "[link](", "![img](", "\n# not", "\n- not"}) {
    EXPECT_EQ(md.find(raw), std::string::npos) << raw << " reached report.md as markup:\n" << md;
  }
  EXPECT_NE(md.find("## &lt;img src=x onerror=alert(1)&gt;\n"), std::string::npos) << md;
  EXPECT_NE(md.find("\\# not a heading &lt;script&gt;alert(1)&lt;/script&gt; \\[link\\](http://e.example) \\*x\\*"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("Paper: !\\[img\\](http://e.example/i.png)"), std::string::npos) << md;
  // an underscore inside a word is no emphasis and stays as it is (falling_ball)
  EXPECT_NE(md.find("- &lt;b&gt;bold&lt;/b&gt; &amp; \\`code\\` \\_under\\_ a_b\n"), std::string::npos) << md;
  EXPECT_NE(md.find("- \\- not a sub-item\n"), std::string::npos) << md;
  // a code span holding a backtick is fenced with two, and padded with a
  // space on both sides as it ends with one (CommonMark strips the pair)
  EXPECT_NE(md.find("`` duration=1`<i>x</i>` ``"), std::string::npos) << md;
  EXPECT_NE(md.find("| &lt;script&gt;x&lt;/script&gt; |"), std::string::npos) << md;
}

}  // namespace
}  // namespace pb::internal
