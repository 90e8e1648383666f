#include "report_verdict.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "planarbench/reports/run_validity.hpp"
#include "report_figures.hpp"
#include "report_tables.hpp"
#include "report_work_precision_svg.hpp"

namespace pb::internal {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Entry {
  std::string engine;
  RunStatus status = RunStatus::ok;
  bool invalid_data = false;  // NaN or inf in its samples: failed, never ranked
  double error_m = kNaN;      // position_max against the baseline
  double cost = kNaN;         // wall s per simulated s (the median of the repeats)
  double cost_lo = kNaN;      // the repeats' range, wall s per simulated s
  double cost_hi = kNaN;
  std::string time_to_target;  // from the sweep, "" when not swept
};

// short: the case sections say the rest
const char* truth_text(TruthKind t) {
  switch (t) {
    case TruthKind::analytic:
      return "closed form";
    case TruthKind::analytic_until_first_contact:
      return "closed form, then numerical";
    case TruthKind::converged:
      return "numerical (no closed form)";
    case TruthKind::none:
      break;
  }
  return "none: vs the reference";
}

// what the truth run was, from its own mapping (physics.mode: "closed form",
// "converged reference", "closed form, then independent integrator" ...); the
// case's truth kind when the file has no truth run
std::string truth_source(const CaseRuns& cr, const Case& c) {
  for (const auto& r : cr.runs) {
    if (r.engine_name != "analytic" || r.status != RunStatus::ok) continue;
    const auto p = r.mapping.find("physics");
    if (p != r.mapping.end() && p->is_object() && p->contains("mode") &&
        (*p)["mode"].is_string()) {
      return (*p)["mode"].get<std::string>();
    }
  }
  return truth_text(c.truth);
}

// two significant digits: a ranking, not a measurement report
std::string short_number(double v) {
  return fmt::format("{:.2g}", v);
}

double position_max(const std::vector<MetricValue>& metrics, const std::string& case_name,
                    const std::string& engine, const std::string& against) {
  for (const auto& m : metrics) {
    if (m.case_name == case_name && m.engine == engine && m.against == against &&
        m.metric == "position_max" && m.episode < 0) {
      return m.error;
    }
  }
  return kNaN;
}

// the sweep's time to its first (largest) error target of an engine on a
// case, as "1e-3 m in 0.0032 s" (the reference: its rk45 series, its default
// integrator); "" when the sweep has no such series
std::string time_to_target(const std::vector<WorkPrecisionCase>& wp, const std::string& case_name,
                           const std::string& engine) {
  const std::string series = engine == "reference" ? "reference_rk45" : engine;
  for (const auto& w : wp) {
    if (w.name != case_name || w.targets_m.empty()) continue;
    for (const auto& s : w.series) {
      if (s.name != series || s.reach.empty()) continue;
      const Reach& r = s.reach.front();
      const std::string label = compact_number(w.targets_m.front()) + " m";
      switch (r.kind) {
        case Reach::Kind::interpolated:
          return fmt::format("{} in {} s", label, short_number(r.wall_time_s));
        case Reach::Kind::at_first_rung:
          return fmt::format("{} in <={} s", label, short_number(r.wall_time_s));
        case Reach::Kind::not_reached:
          return label + ": never";
        case Reach::Kind::no_data:
          return label + ": no data";
      }
    }
  }
  return "";
}

std::string ratio_text(double error, double best) {
  if (!std::isfinite(error) || !std::isfinite(best)) return "";
  if (best <= 0.0) return error <= 0.0 ? "x1" : "";
  const double r = error / best;
  // x1.3, x51, x406, x2.6e+08: two digits, whole numbers up to 1e5
  if (r >= 99.5 && r < 1e5) return fmt::format("x{:.0f}", r);
  return "x" + short_number(r);
}

}  // namespace

Table verdict_table(const ResultsFile& results, const std::vector<Case>& cases,
                    const std::vector<MetricValue>& metrics,
                    const std::vector<CheckOutcome>& outcomes,
                    const std::vector<MappingEntry>& mappings,
                    const std::vector<WorkPrecisionCase>& work_precision) {
  Table t;
  t.id = "verdict";
  t.title = "Verdict: which engine, how wrong, at what cost";
  t.note = fmt::format(
      "Engines at their default settings, ranked by their largest position error (m) against "
      "the truth; x = times the best one's error; ms/s = wall milliseconds per simulated second "
      "(the median \u00b1 half the range of `run --repeat R`, relative; else one run; the "
      "Timings table has every run){}. Caveats: runs not ok, known "
      "breaches (bands an engine's own model cannot meet), failed checks, unresolved impacts; a "
      "run with NaN or inf in its samples is FAILED and not ranked.",
      work_precision.empty() ? ""
                             : "; '1e-3 m in' = the sweep's wall time to reach that error");
  t.columns = {"case", "truth", "best", "engines: error, m (x best, ms/s)", "caveats"};
  for (std::size_t ci = 0; ci < results.cases.size() && ci < cases.size(); ++ci) {
    const CaseRuns& cr = results.cases[ci];
    const Case& c = cases[ci];
    const std::string against = c.truth == TruthKind::none ? "reference" : "truth";
    std::vector<Entry> entries;
    std::vector<std::string> caveats;
    const auto invalid = invalid_runs(cr);
    for (const auto& f : invalid) {
      caveats.push_back(fmt::format("{} FAILED: invalid data in {}", f.engine, f.what()));
    }
    for (const RunResult* r : runs_in_report_order(cr)) {
      if (r->engine_name == "analytic") continue;
      if (against == "reference" && r->engine_name == "reference") continue;
      Entry e;
      e.engine = r->engine_name;
      e.status = r->status;
      e.invalid_data = find_invalid(invalid, cr.case_name, r->engine_name) != nullptr;
      if (r->status == RunStatus::ok && !e.invalid_data) {
        e.error_m = position_max(metrics, cr.case_name, r->engine_name, against);
        if (c.duration_s > 0.0) {
          e.cost = r->wall_time_s / c.duration_s;
          const auto [lo, hi] = wall_time_range(*r);  // NaN for a single run
          e.cost_lo = lo / c.duration_s;
          e.cost_hi = hi / c.duration_s;
        }
      } else if (r->status != RunStatus::ok) {
        caveats.push_back(fmt::format("{} {}: {}", r->engine_name, run_status_name(r->status),
                                      r->reason));
      }
      if (!work_precision.empty()) {
        e.time_to_target = time_to_target(work_precision, cr.case_name, r->engine_name);
      }
      entries.push_back(std::move(e));
    }
    // ranked: finite errors ascending, then the rest in report order
    std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
      const bool fa = std::isfinite(a.error_m);
      const bool fb = std::isfinite(b.error_m);
      if (fa != fb) return fa;
      return fa && a.error_m < b.error_m;
    });
    const double best = entries.empty() ? kNaN : entries.front().error_m;
    std::string best_text = "none ok";
    if (!entries.empty() && std::isfinite(best)) best_text = entries.front().engine;
    std::string all;
    for (const Entry& e : entries) {
      if (!all.empty()) all += "; ";
      if (e.invalid_data) {
        all += fmt::format("{} FAILED (invalid data)", e.engine);
        continue;
      }
      if (!std::isfinite(e.error_m)) {
        all += fmt::format("{} {}", e.engine,
                           e.status == RunStatus::ok ? "no error computed" : run_status_name(e.status));
        continue;
      }
      all += fmt::format("{} {} ({}, {} ms/s", e.engine, short_number(e.error_m),
                         ratio_text(e.error_m, best), fmt::format("{:.3g}", 1e3 * e.cost));
      if (std::isfinite(e.cost_lo) && e.cost > 0.0) {
        // the spread: half the repeats' range, relative to the median
        all += fmt::format(" \u00b1{:.0f}%", 50.0 * (e.cost_hi - e.cost_lo) / e.cost);
      }
      if (!e.time_to_target.empty()) all += ", " + e.time_to_target;
      all += ")";
    }
    const std::string truth = against == "truth" ? truth_source(cr, c) : truth_text(c.truth);
    if (against == "reference") {
      caveats.push_back(
          "no truth: the reference is the yardstick, and its own error is not measured here");
    } else if (truth.find("converged reference") != std::string::npos) {
      // issue 25: say it in words where the ranking could be misread
      caveats.push_back(
          "the truth is the reference solver itself (exact geometry, rk45 at rtol 1e-12): the "
          "reference is judged against itself, so its error here measures its convergence, not "
          "its correctness");
    }
    for (const auto& o : outcomes) {
      if (o.threshold.case_name != cr.case_name || o.passed) continue;
      // the reason is in the metrics table and the mapping; here the fact
      caveats.push_back(fmt::format("{} {} vs {}: {}", o.threshold.engine, o.threshold.metric,
                                    o.threshold.against,
                                    fails_gate(o) ? "FAILS its check" : "known breach"));
    }
    for (const auto& m : mappings) {
      if (m.case_name != cr.case_name) continue;
      for (const auto& n : m.not_expressed) {
        if (n.find("not resolved") != std::string::npos) caveats.push_back(m.engine + ": " + n);
      }
    }
    std::string caveat_text;
    for (const auto& k : caveats) caveat_text += (caveat_text.empty() ? "" : "; ") + k;
    t.rows.push_back({cr.case_name, truth, best_text, all, caveat_text});
    t.row_status.push_back(invalid.empty() ? "" : "fail");
  }
  return t;
}

}  // namespace pb::internal
