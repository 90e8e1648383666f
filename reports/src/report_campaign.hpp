// The campaign section of a report (`planarbench campaign`, issue 14), from a
// results file's /campaign table:
//  - per case and per axis with numeric points (values, linear, log): the
//    first recorded metric (position_error_m when recorded) and the wall time
//    per run against the axis, one line per engine: the median over the runs
//    at that point (every point of the other axes), with the band from the
//    smallest to the largest (the work-precision plot generalised);
//  - per case and per random axis (perturb), when the trace was recorded: the
//    spread of the trajectories over time, one line per engine, for each
//    point of the other axes: spread(t) = the largest, over the moving bodies,
//    of the root-mean-square distance of the samples' positions from their
//    mean at time t;
//  - tables: runs and their status per engine, each metric's median (min..max)
//    per engine and axis point, the spread's start, end and largest value.
#pragma once

#include <string>
#include <vector>

#include "planarbench/campaign_table.hpp"
#include "report_model.hpp"

namespace pb::internal {

// One line plot as a static SVG (deterministic: same plot, same bytes).
struct LinePlot {
  std::string title;
  std::string x_label;
  std::string y_label;
  bool x_log = false;
  bool y_log = false;
  struct Line {
    std::string name;
    std::string colour;
    std::vector<double> x;
    std::vector<double> y;
    std::vector<double> lo;  // band, empty for none
    std::vector<double> hi;
    bool scatter = false;  // points only (no line), each drawn however many there are
  };
  std::vector<Line> lines;
};
[[nodiscard]] std::string line_plot_svg(const LinePlot& p);

// root-mean-square distance of the points (x_i, y_i) from their mean; NaN
// without a finite point
[[nodiscard]] double rms_spread(const std::vector<double>& x, const std::vector<double>& y);

[[nodiscard]] CampaignSection campaign_section(const CampaignTable& t, const std::string& file);

}  // namespace pb::internal
