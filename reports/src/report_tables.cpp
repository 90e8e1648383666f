#include "report_tables.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

#include "report_figures.hpp"

namespace pb::internal {

namespace {

// the engines of a results file in report order, each once
std::vector<std::string> engines_of(const ResultsFile& results) {
  std::vector<std::string> names;
  CaseRuns all;
  for (const auto& cr : results.cases) {
    for (const auto& r : cr.runs) {
      bool seen = false;
      for (const auto& n : names) seen = seen || n == r.engine_name;
      if (!seen) {
        names.push_back(r.engine_name);
        RunResult stub;
        stub.engine_name = r.engine_name;
        all.runs.push_back(stub);
      }
    }
  }
  std::vector<std::string> ordered;
  for (const auto* r : runs_in_report_order(all)) ordered.push_back(r->engine_name);
  return ordered;
}

using MetricKey = std::tuple<std::string, std::string, std::string, std::string, int>;

MetricKey key_of(const MetricValue& m) {
  return {m.case_name, m.engine, m.against, m.metric, m.episode};
}

}  // namespace

std::string format_number(double v) {
  if (std::isnan(v)) return "";
  return fmt::format("{:.4g}", v);
}

std::string wall_runs(const RunResult& r) {
  return std::to_string(std::max<std::size_t>(1, r.wall_time_repeats_s.size()));
}

std::pair<double, double> wall_time_range(const RunResult& r) {
  if (r.wall_time_repeats_s.size() < 2) return {std::nan(""), std::nan("")};
  const auto [lo, hi] =
      std::minmax_element(r.wall_time_repeats_s.begin(), r.wall_time_repeats_s.end());
  return {*lo, *hi};
}

std::string wall_range(const RunResult& r) {
  const auto [lo, hi] = wall_time_range(r);
  return std::isnan(lo) ? "" : format_number(lo) + " - " + format_number(hi);
}

Table capability_table(const ResultsFile& results) {
  Table t;
  t.id = "capability";
  t.title = "Capability matrix";
  t.note = "Status of every run (case x engine): ok, diverged or unsupported, with the reason.";
  const auto engines = engines_of(results);
  t.columns.push_back("case");
  for (const auto& e : engines) t.columns.push_back(e);
  for (const auto& cr : results.cases) {
    std::vector<std::string> row{cr.case_name};
    bool diverged = false;
    for (const auto& e : engines) {
      std::string cell = "not run";
      for (const auto& r : cr.runs) {
        if (r.engine_name != e) continue;
        cell = run_status_name(r.status);
        if (r.status == RunStatus::diverged && r.diverged_at_s >= 0.0) {
          cell += fmt::format(" at t = {:.6g} s", r.diverged_at_s);
        }
        if (!r.reason.empty()) cell += ": " + r.reason;
        diverged = diverged || r.status == RunStatus::diverged;
      }
      row.push_back(cell);
    }
    t.rows.push_back(std::move(row));
    t.row_status.push_back(diverged ? "fail" : "");
  }
  return t;
}

Table timings_table(const ResultsFile& results, const std::vector<Case>& cases) {
  Table t;
  t.id = "timings";
  t.title = "Timings";
  t.note =
      "Wall-clock time of each run (model build and stepping) on the machine that ran it (CPU "
      "in the provenance); compare runs of one machine only. A run repeated (`run --repeat R`) "
      "shows the median of its R wall times and their range. Engine mujoco3 is MuJoCo 3.3.8's "
      "WebAssembly build run by Node, its steps exchanged with planarbench over a pipe (a round "
      "trip per step with a contact in the constraint): its times are those of that build and "
      "that exchange, not comparable with the native builds'.";
  t.columns = {"case",  "engine",       "status",       "wall time, s", "runs",
               "range, s", "steps", "simulated, s", "wall per simulated s"};
  for (std::size_t ci = 0; ci < results.cases.size(); ++ci) {
    const auto& cr = results.cases[ci];
    for (const auto* r : runs_in_report_order(cr)) {
      // simulated time: the whole case, or up to the divergence
      double simulated = ci < cases.size() ? cases[ci].duration_s : std::nan("");
      if (r->status == RunStatus::diverged && r->diverged_at_s >= 0.0) simulated = r->diverged_at_s;
      if (r->status == RunStatus::unsupported) simulated = 0.0;
      const double per_sim = simulated > 0.0 ? r->wall_time_s / simulated : std::nan("");
      t.rows.push_back({cr.case_name, r->engine_name, run_status_name(r->status),
                        format_number(r->wall_time_s), wall_runs(*r), wall_range(*r),
                        std::to_string(r->steps), format_number(simulated),
                        format_number(per_sim)});
      t.row_status.push_back(r->status == RunStatus::diverged ? "fail" : "");
    }
  }
  return t;
}

Table physics_table(const ResultsFile& results) {
  Table t;
  t.id = "physics";
  t.title = "Whose physics";
  t.note =
      "For every run: whose collision detection found the contacts and whose contact model "
      "made the force (the engine's own by default), how the law's parameters were set, and "
      "how many steps the engine took before t = 0 (a probe run looks into the run's future: "
      "only the opt-in oracle mode does).";
  t.columns = {"case",          "engine",     "mode",           "collision by", "contact force by",
               "foreknowledge", "steps before t = 0", "parameters"};
  for (const auto& cr : results.cases) {
    for (const auto* r : runs_in_report_order(cr)) {
      const nlohmann::json p =
          r->mapping.is_object() && r->mapping.contains("physics") ? r->mapping["physics"]
                                                                   : nlohmann::json::object();
      const bool future = p.value("foreknowledge", false);
      const long before = r->extra.is_object() ? r->extra.value("steps_before_start", 0L) : 0L;
      t.rows.push_back({cr.case_name, r->engine_name, p.value("mode", ""),
                        p.value("collision_by", ""), p.value("contact_force_by", ""),
                        future ? "YES: oracle" : "no", std::to_string(before),
                        p.value("parameters", "")});
      t.row_status.push_back(future ? "fail" : "");
    }
  }
  return t;
}

Table metrics_table(const std::vector<MetricValue>& metrics,
                    const std::vector<CheckOutcome>& outcomes, bool with_checks) {
  // the outcomes of each computed metric (several thresholds may check one)
  std::map<MetricKey, std::vector<const CheckOutcome*>> checked;
  for (const auto& o : outcomes) {
    if (!o.value.metric.empty()) checked[key_of(o.value)].push_back(&o);
  }
  Table t;
  t.id = "metrics";
  t.title = "Metrics";
  t.note =
      "Every SPEC §4 metric: each engine against the truth, against the reference and against "
      "each other engine, and each run's own metrics (against = self). value = the run's "
      "quantity, desired = the baseline's, both in `unit`; error is absolute or relative as the "
      "metric defines. Gated checks first (with the bound behind each limit), then the "
      "comparisons with the truth, then the rest. Episodes count from 0, as in the thresholds "
      "file.";
  t.columns = {"case",  "engine", "against",    "metric", "episode", "value",
               "desired", "unit",  "error", "error unit"};
  if (with_checks) {
    t.columns.push_back("limit");
    t.columns.push_back("result");
    t.columns.push_back("why (the bound the limit comes from)");
  }
  t.columns.push_back("note");
  // gated checks first, then the comparisons with the truth, then the rest;
  // each group in the metrics' own order
  std::vector<std::size_t> order(metrics.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  auto group = [&](const MetricValue& m) {
    if (checked.count(key_of(m)) != 0) return 0;
    return m.against == "truth" ? 1 : 2;
  };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return group(metrics[a]) < group(metrics[b]);
  });
  for (const std::size_t i : order) {
    const MetricValue& m = metrics[i];
    std::string limit;
    std::string result;
    std::string why;
    std::string note = m.note;
    const auto it = checked.find(key_of(m));
    if (it != checked.end()) {
      bool passed = true;
      std::string label = "pass";
      double tightest = std::numeric_limits<double>::infinity();
      for (const auto* o : it->second) {
        passed = passed && o->passed;
        tightest = std::min(tightest, o->limit);
        if (!o->message.empty()) note += (note.empty() ? "" : "; ") + o->message;
        if (!o->passed || fails_gate(*o)) label = outcome_label(*o);
        if (o->threshold.by_construction) note += (note.empty() ? "" : "; ") + std::string("holds by construction");
        if (!o->threshold.why.empty()) why += (why.empty() ? "" : "; ") + o->threshold.why;
        if (!o->threshold.known_breach.empty()) {
          why += (why.empty() ? "" : "; ") + std::string("known breach: ") + o->threshold.known_breach;
        }
      }
      limit = format_number(tightest);
      // a known breach is a failure to show, not a pass (SPEC §5b)
      result = passed && label == "pass" ? "pass" : label;
    }
    // "1" is a relative error's unit, or a dimensionless quantity's
    const bool relative = m.unit == "1" && !m.value_unit.empty() && m.value_unit != "1";
    std::vector<std::string> row{m.case_name,
                                 m.engine,
                                 m.against,
                                 m.metric,
                                 m.episode >= 0 ? std::to_string(m.episode) : "",
                                 format_number(m.actual),
                                 format_number(m.desired),
                                 m.value_unit.empty() ? m.unit : m.value_unit,
                                 format_number(m.error),
                                 relative ? "relative" : m.unit};
    if (with_checks) {
      row.push_back(limit);
      row.push_back(result);
      row.push_back(why);
    }
    row.push_back(note);
    t.rows.push_back(std::move(row));
    t.row_status.push_back(result.empty() || result == "pass" ? result : "fail");
  }
  return t;
}

Table unmatched_thresholds_table(const std::vector<CheckOutcome>& outcomes) {
  Table t;
  t.id = "unmatched_thresholds";
  t.title = "Thresholds without a computed metric";
  t.note = "A gate never passes silently: each of these counts as a failed check.";
  t.columns = {"case", "engine", "against", "metric", "episode", "line", "message"};
  for (const auto& o : outcomes) {
    if (!o.value.metric.empty()) continue;
    const auto& th = o.threshold;
    t.rows.push_back({th.case_name, th.engine, th.against, th.metric,
                      th.episode >= 0 ? std::to_string(th.episode) : "every",
                      std::to_string(th.line), o.message});
    t.row_status.push_back("fail");
  }
  return t;
}

Table provenance_table(const FileProvenance& provenance, const ResultsFile& results) {
  Table t;
  t.id = "provenance";
  t.title = "Provenance";
  t.note =
      "From the results file: /parameters, each case's file digest and overrides, each "
      "engine's version.";
  t.columns = {"item", "value"};
  for (const auto& [k, v] : provenance.parameters) t.rows.push_back({k, v});
  for (const auto& cr : results.cases) {
    const auto it = provenance.case_sha256.find(cr.case_name);
    t.rows.push_back(
        {cr.case_name + " case file",
         cr.case_path +
             (it != provenance.case_sha256.end() ? " (sha256 " + it->second + ")" : "")});
    if (!cr.overrides.empty()) {
      std::string text;
      for (const auto& [k, v] : cr.overrides) text += (text.empty() ? "" : ", ") + k + "=" + v;
      t.rows.push_back({cr.case_name + " --set", text});
    }
  }
  std::map<std::string, std::string> versions;  // engine -> version
  for (const auto& cr : results.cases) {
    for (const auto& r : cr.runs) {
      if (!r.engine_version.empty()) versions.emplace(r.engine_name, r.engine_version);
    }
  }
  for (const auto& [engine, version] : versions) t.rows.push_back({engine + " version", version});
  t.row_status.assign(t.rows.size(), "");
  return t;
}

}  // namespace pb::internal
