// The content of a report (SPEC §6), independent of how it is rendered: the
// HTML page, the Markdown file and the SVG figures all read this.
#pragma once

#include <cstddef>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace pb::internal {

// what a figure plots against time
enum class Quantity { force, x, y, vx, vy };

// one plotted line: one engine's quantity over time, already down-sampled
struct PlotSeries {
  std::string engine;
  std::vector<double> time_s;   // s
  std::vector<double> value;    // in the figure's unit (N, m or m/s)
  std::size_t full_points = 0;  // samples before down-sampling
  std::string note;             // e.g. "truth valid until t = 0.4965 s"
  double peak = 0.0;            // largest finite value, in the figure's unit
  bool off_scale = false;       // beyond the figure's y_clip
};

// a time window a figure can zoom to: one contact episode
struct ZoomWindow {
  std::string label;  // "episode 0" (counted from 0, as the metrics)
  double t0_s = 0.0;  // s
  double t1_s = 0.0;  // s
};

struct Figure {
  std::string id;  // unique in the report and file-name safe, e.g. "falling_ball_fig5"
  std::string case_name;
  std::string title;         // e.g. "Fig. 5 Contact force"
  std::string paper_figure;  // "Fig. 5", or "" for a figure the paper does not have
  std::string y_label;       // with unit, e.g. "contact force, N"
  Quantity quantity = Quantity::x;
  double t_end_s = 0.0;  // s, end of the case's time axis
  std::vector<PlotSeries> series;
  std::vector<ZoomWindow> episodes;
  // Default upper end of the value axis when some series is far off the
  // others' scale (an impulsive engine's force = impulse / step); NaN: fit all.
  double y_clip = std::numeric_limits<double>::quiet_NaN();
};

// A table shared by the HTML and Markdown renderings: cells are text, and
// each row may carry a status ("pass", "fail" or "") that colours it.
struct Table {
  std::string id;
  std::string title;
  std::string note;
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> row_status;  // one per row
};

// how one engine expressed one case's contact law (SPEC §5 `mapping`)
struct MappingEntry {
  std::string case_name;
  std::string engine;
  std::string status;  // ok | diverged | unsupported
  nlohmann::json mapping;
  std::vector<std::string> not_expressed;  // what the engine could not express
};

struct CaseSection {
  std::string name;
  std::string description;
  std::string paper;
  std::string truth;
  std::vector<std::string> assumptions;
  std::vector<std::pair<std::string, std::string>> overrides;  // --set given
  std::vector<Figure> figures;
};

// How a series reaches an error level, its rungs taken coarse to fine.
struct Reach {
  enum class Kind {
    interpolated,   // between two consecutive rungs that bracket the level
    at_first_rung,  // the first rung with an error is already at or below it
    not_reached,    // no rung is at or below it
    no_data,        // no rung has an error
  };
  Kind kind = Kind::no_data;
  double wall_time_s = 0.0;  // s; NaN for not_reached and no_data
};

// one series of a work-precision plot: an engine (or one integrator of the
// reference) over its ladder, the rungs with a positive finite error only
struct WorkPrecisionSeries {
  std::string name;                 // "mujoco", "reference_rk45", "reference_fixed"
  std::string engine;               // for its colour: "mujoco", "reference"
  bool dashed = false;              // a second series of the same engine
  std::vector<double> wall_s;       // s
  std::vector<double> error_m;      // m
  std::vector<std::string> labels;  // each point's knob, e.g. "dt=1e-4"
  int default_index = -1;           // the point at the engine's default setting, -1 if none
  std::vector<Reach> reach;         // how it reaches each of its case's targets_m
};

// the work-precision section of one case (`planarbench sweep`)
struct WorkPrecisionCase {
  std::string name;   // the case
  std::string id;     // file-name safe, e.g. "falling_ball_work_precision"
  std::string truth;  // what the errors are measured against
  std::string truth_note;
  std::vector<WorkPrecisionSeries> series;
  std::vector<double> targets_m;         // m, error levels drawn and tabulated
  std::vector<std::string> not_plotted;  // "box2d dt=1e-3: diverged ..."
  Table summary;                         // time to each target, cost per simulated s
  Table rungs;                           // every rung
};

// the campaign section (report_campaign.hpp): per case, its figures as SVG
// text and its tables
struct CampaignFigure {
  std::string id;  // file-name safe, unique in the report
  std::string title;
  std::string svg;
};

struct CampaignCaseSection {
  std::string name;
  std::string truth;
  std::vector<CampaignFigure> figures;
  std::vector<Table> tables;
};

struct CampaignSection {
  std::string file;
  std::string note;
  std::vector<CampaignCaseSection> cases;
};

// the friction section (report_friction.hpp): figures as SVG text, one table
struct FrictionSection {
  std::string note;
  std::string curve_file;  // the campaign file of the friction curve, "" when none
  std::vector<CampaignFigure> figures;
  Table curve;
  Table family;  // the block family's table, empty when none (report_friction.hpp)
};

// the measured-impacts section (report_impacts.hpp)
struct ImpactsSection {
  std::string file;  // the fit or score file, "" when none
  std::string note;
  std::vector<CampaignFigure> figures;
  std::vector<Table> tables;
};

// the physical-validity section (report_validity.hpp)
struct ValiditySection {
  std::string note;
  std::vector<std::string> readings;  // one line per engine
  Table table;
  std::vector<CampaignFigure> figures;
};

// the scenes section (report_scenes.hpp)
struct ScenesSection {
  std::string note;
  std::vector<Table> tables;  // one per family
  std::vector<CampaignFigure> figures;
};

struct Report {
  std::string results_file;                                     // as given on the command line
  std::string thresholds_file;                                  // "" when none
  std::string check_summary;                                    // "12 of 14 checks passed" or ""
  std::vector<std::pair<std::string, std::string>> provenance;  // key, value
  std::string downsampling_note;
  std::vector<CaseSection> cases;
  Table verdict;              // first on the page: per case, engines ranked (report_verdict.hpp)
  std::vector<Table> tables;  // capability, timings, metrics, checks, provenance
  std::vector<MappingEntry> mappings;
  std::string sweep_file;           // "" when no --sweep
  std::string work_precision_note;  // how the sweep was made and read
  std::vector<WorkPrecisionCase> work_precision;
  Table sweep_provenance;  // /parameters of the sweep file
  CampaignSection campaign;  // empty unless the results file holds a campaign
  FrictionSection friction;  // empty without friction cases or a friction curve
  ImpactsSection impacts;    // empty without a file of `planarbench impacts`
  ValiditySection validity;  // empty without contact rows (report_validity.hpp)
  ScenesSection scenes;      // empty without scenes (report_scenes.hpp)
};

}  // namespace pb::internal
