// The runs of a campaign (`planarbench campaign`, and `planarbench sweep`,
// whose ladders are a campaign's axes) as one table: a row per run, a column
// per axis and per metric. The in-memory form of /campaign in a results file
// (results_file.hpp), written by the same writer as /runs:
//
//   /campaign                     attributes: kind ("campaign" | "sweep"), source_text,
//                                 source_sha256, source_path (the campaign file),
//                                 description (JSON: what the producer adds, e.g. the
//                                 sweep's ladders), planned_runs (every run of the
//                                 campaign, not only this file's), engines, shard
//   /campaign/cases/<case>        attributes: case_text, case_sha256, case_path, overrides
//                                 (JSON), duration_s, truth, truth_note, moving_bodies,
//                                 extra (JSON)
//   /campaign/axes/<axis>         attributes: key (the --set key), kind, unit, spec (JSON);
//                                 values [k]: the axis' points (for a random axis the
//                                 sample index)
//   /campaign/runs/               attributes: wall_time_s [n] s (measured on this machine,
//                                 so an attribute: the datasets are the same bits on any
//                                 machine, any shard layout, any --jobs)
//     id [n]                      the run's index in the campaign's plan
//     case, engine, series [n]    strings; series names a sweep's ladder ("" otherwise)
//     overrides [n]               JSON: the --set assignments the run got from its axes
//     physics [n]                 JSON: whose collision and contact force made the run
//                                 (mode, collision_by, contact_force_by, foreknowledge: the
//                                 adapter's mapping.physics, SPEC §5b); {} for a sweep's rung
//     status, reason [n]          ok | diverged | unsupported, and why
//     steps [n]                   the engine's steps
//     axis/<axis> [n]             the run's point on that axis (NaN: not on it)
//     metric/<metric> [n]         one value per run, with its unit (NaN: none)
//     trace_time_s [n, T]         s, when `trace` is recorded: T samples evenly over the run
//     trace_position_m [n, 2 B T] m, x and y of each moving body (moving_bodies order,
//                                 padded with NaN) at each trace time: reshape (n, B, T, 2)
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace pb {

enum class RunStatus;

struct CampaignCase {
  std::string name;
  std::string text;
  std::string path;
  std::vector<std::pair<std::string, std::string>> overrides;  // the campaign's fixed --set
  double duration_s = 0.0;
  std::string truth;       // what position errors are measured against
  std::string truth_note;  // why that truth, how far it holds
  std::vector<std::string> moving_bodies;  // the trace's body order
  nlohmann::ordered_json extra = nlohmann::ordered_json::object();
};

struct CampaignAxis {
  std::string name;
  std::string key;   // the --set key it drives
  std::string kind;  // "values", "linear", "log", "random"
  std::string unit;
  nlohmann::ordered_json spec = nlohmann::ordered_json::object();  // as the file gave it
  std::vector<double> values;
};

struct CampaignRun {
  std::int64_t id = 0;
  std::string case_name;
  std::string engine;
  std::string series;
  std::string overrides;  // JSON object text
  std::string physics = "{}";  // JSON object text: mode, collision_by, contact_force_by, foreknowledge
  RunStatus status{};
  std::string reason;
  std::int64_t steps = 0;
  double wall_time_s = 0.0;
  std::vector<double> axis_values;  // one per CampaignTable::axes
  std::vector<double> metrics;      // one per CampaignTable::metrics
  std::vector<double> trace_time_s;      // trace_points values, or empty
  std::vector<double> trace_position_m;  // 2 * trace_bodies * trace_points, or empty
};

struct CampaignMetric {
  std::string name;
  std::string unit;
  std::string doc;
};

struct CampaignTable {
  std::string kind = "campaign";
  std::string source_text;
  std::string source_path;
  nlohmann::ordered_json description = nlohmann::ordered_json::object();
  std::int64_t planned_runs = 0;
  std::vector<std::string> engines;
  std::string shard;  // "K/N" of a shard's file, "" for a whole campaign
  std::vector<CampaignCase> cases;
  std::vector<CampaignAxis> axes;
  std::vector<CampaignMetric> metrics;
  int trace_points = 0;  // 0: no trace recorded
  int trace_bodies = 0;
  std::vector<CampaignRun> runs;
};

}  // namespace pb
