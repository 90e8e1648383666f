// Tests for reports/src/report_html.cpp
#include "report_html.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace pb::internal {
namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(FillTemplate, OnePassAndForeignTokensKept) {
  const std::string page = "<a>@@A@@</a> @@unknown@@ <b>@@B@@</b>";
  // a value that looks like a token is not expanded again
  EXPECT_EQ(fill_template(page, {{"A", "@@B@@"}, {"B", "2"}}), "<a>@@B@@</a> @@unknown@@ <b>2</b>");
}

TEST(FillTemplate, MissingTokenThrows) {
  EXPECT_THROW((void)fill_template("no tokens", {{"A", "1"}}), std::invalid_argument);
}

Report one_figure_report() {
  Report r;
  r.results_file = "r.h5";
  CaseSection c;
  c.name = "case";
  Figure f;
  f.id = "case_fig";
  f.title = "</script><b>";
  PlotSeries a{"analytic", {0.0, 0.1 + 0.2, 1.0}, {1.0, std::nan(""), 3.0}, 3, "", 3.0, false};
  PlotSeries b{"mujoco", {0.0, 0.1 + 0.2, 1.0}, {1.0, 2.0, 1.0 / 3.0}, 3, "", 2.0, false};
  f.series = {a, b};
  c.figures.push_back(f);
  r.cases.push_back(c);
  return r;
}

TEST(ReportDataJson, SharesGridsAndRounds) {
  const auto data = report_data_json(one_figure_report());
  // equal time vectors are stored once
  ASSERT_EQ(data["grids"].size(), 1u);
  const auto& series = data["cases"][0]["figures"][0]["series"];
  EXPECT_EQ(series[0]["grid"], 0);
  EXPECT_EQ(series[1]["grid"], 0);
  // 0.1 + 0.2 = 0.30000000000000004 is kept to 9 digits: 0.3
  EXPECT_EQ(data["grids"][0][1].get<double>(), 0.3);
  // values to 7 digits; NaN becomes null
  EXPECT_EQ(series[1]["y"][2].get<double>(), 0.3333333);
  EXPECT_TRUE(series[0]["y"][1].is_null());
  EXPECT_TRUE(data["cases"][0]["figures"][0]["y_clip"].is_null());
}

TEST(ReportHtml, InlinesAssetsAndNothingClosesAScriptEarly) {
  WebAssets a;
  a.uplot_version = "9.9.9";
  a.uplot_js = "var uPlot = 1; // '</script>' in a string";
  a.uplot_css = ".u{}";
  a.uplot_license = "MIT licence */ text";
  a.page_js = "var page = 2;";
  a.page_css = "body{}";
  a.page_template =
      "<title>@@TITLE@@</title><style>@@UPLOT_CSS@@ @@PAGE_CSS@@</style>"
      "<script type=\"application/json\">@@DATA@@</script>"
      "<script>/* uPlot @@UPLOT_VERSION@@ @@UPLOT_LICENSE@@ */ @@UPLOT_JS@@</script>"
      "<script>@@PAGE_JS@@</script>";
  const std::string html = report_html(one_figure_report(), a);
  EXPECT_EQ(count(html, "</script"), 3u);  // the template's three, no more
  EXPECT_EQ(count(html, "*/"), 1u);        // the licence cannot end the comment
  EXPECT_NE(html.find("var page = 2;"), std::string::npos);
  EXPECT_NE(html.find("uPlot 9.9.9"), std::string::npos);
  // the title in the data is JSON-escaped, not markup
  EXPECT_NE(html.find("\\u003c/script>\\u003cb>"), std::string::npos);
  EXPECT_EQ(html.find("@@"), std::string::npos);
}

}  // namespace
}  // namespace pb::internal
