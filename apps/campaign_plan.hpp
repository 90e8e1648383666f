// What `planarbench campaign` runs: a campaign file (TOML) read and validated
// into its runs, their --set assignments, their estimated cost and the
// partition of the runs into shards. No running here.
//
//   [campaign]
//   cases = ["falling_ball", "cases/mine.toml", "studies/*.toml"]  # names, paths, globs, "all"
//   engines = ["reference", "mujoco", "box2d", "ode"]                # or "all"
//   metrics = ["position_error_m", "first_restitution", "trace"]     # see campaign_metrics()
//   trace_points = 50                       # samples of the trajectory trace (metric "trace")
//   set = { "reference.integrator" = "fixed" }   # --set of every run
//
//   [[axis]]                                # any --set key; one of values, linear, log, perturb
//   key = "dt"
//   log = { from = 1e-3, to = 1e-5, points = 6 }
//
//   [[axis]]
//   name = "state"
//   key = "bodies.*.position"               # '*': every moving body of the case
//   perturb = { sigma = 1e-4, samples = 20, seed = 1 }   # nominal + N(0, sigma^2) per component
//
// The runs are every case x engine x axis point, numbered in that order (the
// case outermost, the last axis innermost): a run's id, and so its settings,
// do not depend on the shards.
//
// Size: an axis has at most 1,000,000 points, and a campaign at most
// 33,554,432 runs: planning it takes 32 bytes per run (a run's estimated cost
// and id while the runs are dealt to shards, 16 bytes, and its id in its
// shard's list, 8 bytes that a growing list may double), and the plan is
// held to 1 GiB (campaign_size.hpp). A larger campaign is refused when it is
// read, with that formula and the limit in the message; split it.
#pragma once

#include <fmt/format.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "planarbench/campaign_table.hpp"
#include "planarbench/case.hpp"

namespace pb::cli {

struct CampaignAxisPlan {
  CampaignAxis axis;    // name, key, kind, unit, spec, values (a random axis: 0..samples-1)
  bool case_key = false;  // addresses the case (bodies.*, contact.*, ...), not an engine
  // perturb only
  double sigma = 0.0;
  std::uint64_t seed = 0;
  std::string field;  // "position", "velocity", "angle", "angular_velocity"
  std::string body;   // a body name, or "*"
};

struct CampaignCasePlan {
  std::filesystem::path path;
  Case c;  // loaded with the campaign's `set` (its case keys)
  std::vector<std::string> moving_bodies;
  std::vector<double> default_dt;  // per engine: its step under the case and `set` (NaN: none)
};

struct CampaignPlan {
  std::string file;  // as given
  std::string text;  // the campaign file's text
  std::vector<CampaignCasePlan> cases;
  std::vector<std::string> engines;
  std::vector<std::pair<std::string, std::string>> set;  // --set of every run, in file order
  std::vector<CampaignAxisPlan> axes;
  std::vector<int> axis_lines;  // the line of each [[axis]] in the file (per axes)
  std::vector<CampaignMetric> metrics;  // the columns, in file order ("trace" is not one)
  int trace_points = 0;                 // > 0 when "trace" is recorded

  [[nodiscard]] std::int64_t size() const;
  [[nodiscard]] bool needs_truth() const;

  struct RunRef {
    std::size_t case_index = 0;
    std::size_t engine_index = 0;
    std::vector<std::size_t> point;  // per axis
  };
  [[nodiscard]] RunRef decode(std::int64_t id) const;
  // the run's --set assignments from its axes, in axis order (a random axis
  // gives one per moving body it perturbs)
  [[nodiscard]] std::vector<std::pair<std::string, std::string>> assignments(
      const RunRef& r) const;
  // the assignments of the axes that address the case: runs sharing them
  // share one truth
  [[nodiscard]] std::vector<std::pair<std::string, std::string>> case_assignments(
      const RunRef& r) const;
  // the run's point on each axis (the axis value; a random axis: the sample)
  [[nodiscard]] std::vector<double> axis_values(const RunRef& r) const;
  // s of one CPU: the engine's measured cost on the case (task_scheduler.cpp)
  // scaled by default step / step when an axis sets the step
  [[nodiscard]] double cost(std::int64_t id) const;
  // the sum of cost() over every run, per engine (in `engines` order), in
  // closed form: a run's cost is its case and engine's times one factor per
  // axis, so the sum is their sums' product (issue 49: summed run by run, a
  // 1e6-point axis took a minute before the plan stated its cost)
  [[nodiscard]] std::vector<double> cost_by_engine() const;
  // "falling_ball x mujoco, dt=0.001, state=3"
  [[nodiscard]] std::string describe(std::int64_t id) const;
};

// a number as --set text: the shortest decimal that reads back to the same double
[[nodiscard]] inline std::string number_text(double v) { return fmt::format("{}", v); }

// The run `id` of a campaign of `engines` engines and axes of `axis_sizes`
// points: the case outermost, the last axis innermost.
[[nodiscard]] CampaignPlan::RunRef decode_run(std::int64_t id, std::size_t engines,
                                              const std::vector<std::size_t>& axis_sizes);

// "run 7: falling_ball x ode, dt=0.001, state=1" from a campaign file's header
// (what merge names, without the campaign's case files)
[[nodiscard]] std::string describe_run(const CampaignTable& t, std::int64_t id);

// Reads and validates the campaign file: every error is an InputError naming
// the file, the line, the field and what is allowed; every case is loaded and
// every axis point checked against every case and engine before anything runs.
// A campaign whose plan would not fit its memory limit is refused
// (campaign_size.hpp: 32 bytes per run, 1 GiB, at most 33,554,432 runs).
// With `quiet` false, a long check says how far it is on stderr.
[[nodiscard]] CampaignPlan load_campaign(const std::filesystem::path& file,
                                         const std::string& cases_dir_option, bool quiet = true);

// The metrics a campaign may record (name, unit, what), "trace" included.
[[nodiscard]] const std::vector<CampaignMetric>& campaign_metrics();

// The table's header for this plan: cases, axes, metrics, engines (no runs).
[[nodiscard]] CampaignTable campaign_header(const CampaignPlan& plan);

}  // namespace pb::cli
