// The report (SPEC §6): `planarbench report results.h5 --out DIR` writes
// DIR/report.html (self-contained, zoomable figures with uPlot inlined, data
// embedded), DIR/report.md and DIR/figures/*.svg (static figures): the paper's
// figures with the truth and every engine overlaid, every metric with its
// pass/fail against a thresholds file, the parameter mapping of each engine,
// the capability matrix, timings and provenance; with a sweep file, the
// work-precision plots and tables of each case.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "planarbench/reports/thresholds.hpp"
#include "planarbench/run_result.hpp"

namespace pb {

struct ReportOptions {
  std::filesystem::path results;     // results file written by `planarbench run`; empty: none
  // sweep file written by `planarbench sweep`: adds the work-precision section;
  // empty: none (one of results and sweep must be given)
  std::filesystem::path sweep;
  // campaigns' results files (`planarbench campaign merge`) beside the
  // results: the first's campaign section; the friction curve from one that
  // sweeps a pair's friction and records slide_acceleration_mps2
  // (campaigns/friction_curve.toml), the block family from one that records
  // its friction errors (campaigns/block_family.toml)
  std::vector<std::filesystem::path> campaigns;
  // a file of `planarbench impacts fit` or `impacts score`: adds the
  // measured-impacts section (such a file given as `results` does too); empty: none
  std::filesystem::path impacts;
  // a results file of scenes (`planarbench run --case scenes`): adds the
  // scenes section (SPEC §11); empty: the scenes of `results`, if any
  std::filesystem::path scenes;
  std::filesystem::path out_dir;     // created when missing
  std::filesystem::path thresholds;  // empty: no pass/fail column
  // folder with report_template.html, report.js, report.css and
  // node_modules/uplot; empty: $PLANARBENCH_WEB_DIR, else the source tree's
  // reports/web
  std::filesystem::path web_dir;
  // per series, in the page: a chart is at most ~1450 px wide (the page's
  // 1480 px column), so 1500 evenly spaced samples draw a smooth stretch as
  // the full series would
  std::size_t max_points_outside_contact = 1500;
  // per series inside contact windows: an impact's window is kept whole (the
  // shipped cases' impacts span at most ~700 output samples, padding included);
  // a sustained contact longer than this keeps each block's extremes
  std::size_t max_points_inside_contact = 3000;
  // called with the thresholds and the results once both are read, before
  // anything is computed or written (the command line checks the names the
  // thresholds use); empty: no check
  std::function<void(const std::vector<Threshold>&, const ResultsFile&)> check_thresholds;
};

struct ReportSummary {
  std::filesystem::path html;      // DIR/report.html
  std::filesystem::path markdown;  // DIR/report.md
  std::size_t figures = 0;         // figures in the page
  std::size_t svg_files = 0;       // files in DIR/figures
  std::size_t metrics = 0;         // metric rows
  std::size_t checks = 0;          // checked (threshold, metric) pairs
  std::size_t checks_failed = 0;  // failing the gate
  std::size_t checks_known = 0;   // failing, declared before the run (known_breach)
  std::size_t work_precision_cases = 0;  // cases of the sweep file
  std::size_t campaign_cases = 0;        // cases of the campaign table
  std::size_t friction_figures = 0;      // figures of the friction section
  std::size_t validity_figures = 0;      // figures of the physical-validity section
  std::size_t impacts_figures = 0;       // figures of the measured-impacts section
};

// Writes the report. Throws InputError (exit 2) for a missing or foreign
// results or sweep file (or neither given), a bad thresholds file, missing web assets (the message says
// to run scripts/setup_web.sh) or an output folder that cannot be written.
// Every file is written to a temporary name and renamed.
ReportSummary write_report(const ReportOptions& options);

}  // namespace pb
