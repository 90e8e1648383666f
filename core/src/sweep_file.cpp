// The sweep's file is a results file whose /campaign table holds one row per
// rung (campaign_table.hpp): the ladders are the axes `dt` and `rtol`, a
// series is a run's `series`, the error is the metric `position_error_m`.
// No HDF5 here: the results file's writer and reader do it.
#include "planarbench/sweep_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "planarbench/errors.hpp"
#include "planarbench/json_integer.hpp"
#include "planarbench/results_file.hpp"

namespace pb {

namespace fs = std::filesystem;

namespace {

constexpr const char* kErrorMetric = "position_error_m";

CampaignAxis ladder_axis(const std::string& knob, const std::string& unit,
                         const std::vector<double>& values) {
  CampaignAxis a;
  a.name = knob;
  a.key = knob;
  a.kind = "values";
  a.unit = unit;
  a.spec = nlohmann::ordered_json{{"values", values}};
  a.values = values;
  return a;
}

nlohmann::ordered_json series_json(const SweepSeries& s) {
  return {{"name", s.name},
          {"engine", s.engine},
          {"knob", s.knob},
          {"knob_key", s.knob_key},
          {"knob_unit", s.knob_unit},
          {"default_value", s.default_value},
          {"fixed_settings", s.fixed_settings}};
}

}  // namespace

void write_sweep_file(const fs::path& path, const SweepFile& sweep) {
  CampaignTable t;
  t.kind = "sweep";
  t.description = {{"repeat", sweep.repeat},
                   {"quick", sweep.quick},
                   {"dt_ladder", sweep.dt_ladder},
                   {"rtol_ladder", sweep.rtol_ladder},
                   {"ladder_stop_rule", sweep.ladder_stop_rule}};
  t.axes = {ladder_axis("dt", "s", sweep.dt_ladder), ladder_axis("rtol", "1", sweep.rtol_ladder)};
  t.metrics = {{kErrorMetric, "m",
                "max over the output samples and bodies of |p - p_truth| (sweep_error.hpp)"}};
  for (const SweepCase& c : sweep.cases) {
    CampaignCase cc;
    cc.name = c.case_name;
    cc.text = c.case_text;
    cc.path = c.case_path;
    cc.overrides = c.overrides;
    cc.duration_s = c.duration_s;
    cc.truth = c.truth;
    cc.truth_note = c.truth_note;
    cc.extra["series"] = nlohmann::ordered_json::array();
    for (const SweepSeries& s : c.series) {
      cc.extra["series"].push_back(series_json(s));
      if (std::find(t.engines.begin(), t.engines.end(), s.engine) == t.engines.end()) {
        t.engines.push_back(s.engine);
      }
      for (const SweepRung& rung : s.rungs) {
        CampaignRun r;
        r.id = static_cast<std::int64_t>(t.runs.size());
        r.case_name = c.case_name;
        r.engine = s.engine;
        r.series = s.name;
        r.overrides = nlohmann::ordered_json{{s.knob_key, rung.value}}.dump();
        r.status = rung.status;
        r.reason = rung.reason;
        r.steps = rung.steps;
        r.wall_time_s = rung.wall_time_s;
        r.axis_values = {s.knob == "dt" ? rung.value : std::nan(""),
                         s.knob == "rtol" ? rung.value : std::nan("")};
        r.metrics = {rung.position_error_m};
        t.runs.push_back(std::move(r));
      }
    }
    t.cases.push_back(std::move(cc));
  }
  t.planned_runs = static_cast<std::int64_t>(t.runs.size());
  ResultsFile f;
  f.provenance = sweep.provenance;
  f.campaign = std::move(t);
  write_results_file(path, f);
}

SweepFile read_sweep_file(const fs::path& path) {
  const ResultsFile f = read_results_file(path);
  const std::string file = path.string();
  if (!f.campaign || f.campaign->kind != "sweep") {
    throw InputError(file, 0, "/campaign",
                     "has no sweep (kind 'sweep'): not a file written by `planarbench sweep`");
  }
  const CampaignTable& t = *f.campaign;
  SweepFile s;
  s.provenance = f.provenance;
  try {
    s.repeat = json_integer<int>(t.description.at("repeat"), "repeat");
    s.quick = t.description.at("quick").get<bool>();
    s.dt_ladder = t.description.at("dt_ladder").get<std::vector<double>>();
    s.rtol_ladder = t.description.at("rtol_ladder").get<std::vector<double>>();
    s.ladder_stop_rule = t.description.at("ladder_stop_rule").get<std::string>();
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file, 0, "/campaign@description",
                     fmt::format("is not a sweep's description ({})", e.what()));
  } catch (const std::runtime_error& e) {  // an integer not as written (json_integer.hpp)
    throw InputError(file, 0, "/campaign@description", e.what());
  }
  const auto metric = std::find_if(t.metrics.begin(), t.metrics.end(),
                                    [](const CampaignMetric& m) { return m.name == kErrorMetric; });
  if (metric == t.metrics.end() || t.axes.size() != 2) {
    throw InputError(file, 0, "/campaign/runs", "has not the sweep's axes dt, rtol and its error");
  }
  const auto error_column = static_cast<std::size_t>(metric - t.metrics.begin());
  for (const CampaignCase& c : t.cases) {
    SweepCase sc;
    sc.case_name = c.name;
    sc.case_text = c.text;
    sc.case_path = c.path;
    sc.overrides = c.overrides;
    sc.duration_s = c.duration_s;
    sc.truth = c.truth;
    sc.truth_note = c.truth_note;
    try {
      for (const auto& j : c.extra.at("series")) {
        SweepSeries ss;
        ss.name = j.at("name").get<std::string>();
        ss.engine = j.at("engine").get<std::string>();
        ss.knob = j.at("knob").get<std::string>();
        ss.knob_key = j.at("knob_key").get<std::string>();
        ss.knob_unit = j.at("knob_unit").get<std::string>();
        ss.default_value = j.at("default_value").get<double>();
        ss.fixed_settings = j.at("fixed_settings").get<std::string>();
        const std::size_t axis = ss.knob == "dt" ? 0 : 1;
        for (const CampaignRun& r : t.runs) {
          if (r.case_name != c.name || r.series != ss.name) continue;
          SweepRung rung;
          rung.value = r.axis_values.at(axis);
          rung.wall_time_s = r.wall_time_s;
          rung.steps = static_cast<long>(r.steps);
          rung.position_error_m = r.metrics.at(error_column);
          rung.status = r.status;
          rung.reason = r.reason;
          ss.rungs.push_back(std::move(rung));
        }
        sc.series.push_back(std::move(ss));
      }
    } catch (const nlohmann::json::exception& e) {
      throw InputError(file, 0, "/campaign/cases/" + c.name + "@extra",
                       fmt::format("has no valid sweep series ({})", e.what()));
    }
    s.cases.push_back(std::move(sc));
  }
  return s;
}

}  // namespace pb
