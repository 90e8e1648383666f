// What one (case, engine) run produces: the in-memory form of
// /runs/<case>/<engine>/ in the results file (SPEC §5).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "planarbench/campaign_table.hpp"
#include "planarbench/engine.hpp"

namespace pb {

class RunSpool;  // planarbench/run_spool.hpp

enum class RunStatus { ok, diverged, unsupported };

[[nodiscard]] const char* run_status_name(RunStatus s);

// trajectory of one body on the output grid
struct BodyTrajectory {
  std::string name;
  std::vector<double> time_s;                   // s, the engine's time at each sample
  std::vector<Vec2> position_m;                 // m
  std::vector<double> angle_rad;                // rad, continuous (not wrapped)
  std::vector<Vec2> velocity_mps;               // m/s
  std::vector<double> angular_velocity_radps;   // rad/s
};

// one row of the contacts table
struct ContactRow {
  double time_s = 0.0;
  ContactSample sample;
};

struct RunResult {
  std::string case_name;
  std::string engine_name;
  std::string engine_version;
  RunStatus status = RunStatus::ok;
  std::string reason;                 // why diverged / unsupported; empty when ok
  double diverged_at_s = -1.0;        // s, time of divergence, -1 if none
  nlohmann::json settings = nlohmann::json::object();
  nlohmann::json mapping = nlohmann::json::object();
  nlohmann::json extra = nlohmann::json::object();
  double wall_time_s = 0.0;           // s, wall clock for build + stepping
  // s, every repeat's wall time when the run was repeated (`run --repeat R`,
  // R > 1): wall_time_s is then their median; empty for a single run
  std::vector<double> wall_time_repeats_s;
  long steps = 0;
  std::vector<std::string> body_names;     // index = Case::bodies index
  std::vector<BodyTrajectory> bodies;      // moving bodies only
  std::vector<ContactRow> contacts;
  std::vector<ContactEpisode> events;
  // set when the samples went to disk as the run proceeded (RunOptions::
  // spool_dir): `bodies` and `contacts` are then empty and the results
  // writer takes the trajectories and the contacts table from here
  std::shared_ptr<const RunSpool> spool;
};

// Everything one `planarbench run` writes: per case, the case text and overrides.
struct CaseRuns {
  std::string case_name;
  std::string case_text;
  std::string case_path;
  std::vector<std::pair<std::string, std::string>> overrides;  // --set given
  std::vector<RunResult> runs;
};

struct ResultsProvenance {
  std::string command_line;
  std::string utc_time;  // ISO 8601
  std::string host;
};

struct ResultsFile {
  ResultsProvenance provenance;
  std::vector<CaseRuns> cases;
  // the runs of a campaign or a sweep, one row each (campaign_table.hpp)
  std::optional<CampaignTable> campaign;
};

}  // namespace pb
