// Tests for the work-precision hooks of reports/src/report_markdown.cpp and
// reports/src/report_html.cpp: the section a sweep file adds to report.md and
// to the page's data.
#include <gtest/gtest.h>

#include "report_html.hpp"
#include "report_markdown.hpp"
#include "report_work_precision.hpp"

namespace {

// a report with one swept case and no results file (`report --sweep` alone)
pb::internal::Report sweep_only_report() {
  pb::SweepCase c;
  c.case_name = "sliding";
  c.duration_s = 1.0;
  c.truth = "analytic";
  c.truth_note = "closed form";
  pb::SweepSeries s;
  s.name = "ode";
  s.engine = "ode";
  s.knob = "dt";
  s.knob_unit = "s";
  s.default_value = 1e-4;
  s.rungs = {{1e-3, 0.01, 1000, 3.5e-3, pb::RunStatus::ok, ""},
             {1e-4, 0.1, 10000, 3.5e-4, pb::RunStatus::ok, ""}};
  c.series = {s};
  pb::internal::Report r;
  r.sweep_file = "sweep.h5";
  r.work_precision_note = "how the sweep was made";
  r.work_precision.push_back(pb::internal::work_precision_case(c));
  r.sweep_provenance.title = "Sweep provenance";
  r.sweep_provenance.columns = {"item", "value"};
  r.sweep_provenance.rows = {{"host", "vm"}};
  r.sweep_provenance.row_status = {""};
  return r;
}

TEST(WorkPrecisionMarkdown, SectionHasPlotTableAndEveryRung) {
  const std::string md = pb::internal::report_markdown(sweep_only_report());
  for (const char* part : {"Sweep file: `sweep.h5`", "- [Work-precision](#work-precision)",
                           "## Work-precision", "how the sweep was made", "### sliding",
                           "![sliding: position error vs wall time]"
                           "(figures/sliding_work_precision.svg)",
                           "| series | knob | default |", "time to 1e-3 m, s", "every rung",
                           "### Sweep provenance", "| host | vm |"}) {
    EXPECT_NE(md.find(part), std::string::npos) << part << "\n" << md;
  }
  // no runs: no results line and no parameter mapping
  EXPECT_EQ(md.find("Results file"), std::string::npos);
  EXPECT_EQ(md.find("## Parameter mapping"), std::string::npos);
}

TEST(WorkPrecisionMarkdown, AbsentWithoutASweep) {
  pb::internal::Report r;
  r.results_file = "r.h5";
  const std::string md = pb::internal::report_markdown(r);
  EXPECT_EQ(md.find("Work-precision"), std::string::npos);
  EXPECT_NE(md.find("## Parameter mapping"), std::string::npos);
}

TEST(WorkPrecisionHtml, PageDataCarriesTheSvgAndTables) {
  const auto data = pb::internal::report_data_json(sweep_only_report());
  EXPECT_EQ(data.at("sweep_file"), "sweep.h5");
  const auto& wp = data.at("work_precision");
  EXPECT_EQ(wp.at("note"), "how the sweep was made");
  ASSERT_EQ(wp.at("cases").size(), 1u);
  const auto& c = wp.at("cases")[0];
  EXPECT_EQ(c.at("name"), "sliding");
  EXPECT_EQ(c.at("svg").get<std::string>().rfind("<svg", 0), 0u);
  EXPECT_EQ(c.at("summary").at("rows").size(), 1u);
  EXPECT_EQ(c.at("rungs").at("rows").size(), 2u);
  EXPECT_EQ(wp.at("provenance").at("rows").size(), 1u);
}

}  // namespace
