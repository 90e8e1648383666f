// The Markdown report: the same content as the page for people who read
// Markdown, with static SVG figures in figures/ and the same tables.
#pragma once

#include <string>
#include <vector>

#include "report_model.hpp"

namespace pb::internal {

// one static image of a figure: the whole run, or a zoom on a contact pulse
struct FigureView {
  std::string file;  // relative to the report folder, e.g. "figures/falling_ball_fig5.svg"
  std::string title;
  double t0_s = 0.0;  // s
  double t1_s = 0.0;  // s
};

// The views of a figure: the whole time axis, and for a force figure a zoom on
// its first contact episode as well (a pulse of milliseconds is a line at
// full scale).
[[nodiscard]] std::vector<FigureView> figure_views(const Figure& figure);

// A table as a GitHub-flavoured Markdown table ('|' escaped, newlines folded).
[[nodiscard]] std::string markdown_table(const Table& table);

// The "Work-precision" section: per case the plot, the summary table and
// every rung, then the sweep's provenance.
[[nodiscard]] std::string work_precision_markdown(const Report& report);

// The campaign section: per case its figures (figures/<id>.svg) and tables.
[[nodiscard]] std::string campaign_markdown(const Report& report);

// The whole report.md; figures are referenced by figure_views' file names.
[[nodiscard]] std::string report_markdown(const Report& report);

}  // namespace pb::internal
