#include "report_work_precision.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "report_figures.hpp"
#include "report_tables.hpp"
#include "report_work_precision_svg.hpp"
#include "file_id.hpp"

namespace pb::internal {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool positive_finite(double v) {
  return std::isfinite(v) && v > 0.0;
}

// a rung usable on a work-precision diagram: an error (0 allowed) and a wall time
bool usable(double wall_s, double error_m) {
  return positive_finite(wall_s) && std::isfinite(error_m) && error_m >= 0.0;
}

std::string knob_text(const SweepSeries& s, double value) {
  return fmt::format("{}={}", s.knob, compact_number(value));
}

// the reference rk45's wall per simulated second at its default rtol, NaN if not swept
double reference_cost_per_sim_s(const SweepCase& c) {
  for (const auto& s : c.series) {
    if (s.name != "reference_rk45") continue;
    const int d = default_rung(s);
    if (d >= 0 && s.rungs[static_cast<std::size_t>(d)].status == RunStatus::ok &&
        c.duration_s > 0.0) {
      return s.rungs[static_cast<std::size_t>(d)].wall_time_s / c.duration_s;
    }
  }
  return kNaN;
}

std::string target_text(double target_m) {
  return compact_number(target_m) + " m";
}

}  // namespace

const std::vector<double>& work_precision_targets() {
  static const std::vector<double> v = {1e-3, 1e-5};
  return v;
}

Reach time_to_reach(const std::vector<double>& wall_s, const std::vector<double>& error_m,
                    double target_m) {
  Reach r;
  r.wall_time_s = kNaN;
  bool any = false;               // a usable rung was seen
  bool crossed = false;           // the first crossing was interpolated
  double t_a = kNaN, e_a = kNaN;  // the last usable rung above the level
  for (std::size_t i = 0; i < wall_s.size() && i < error_m.size(); ++i) {
    const double t_b = wall_s[i], e_b = error_m[i];
    if (!usable(t_b, e_b)) continue;
    if (e_b <= target_m) {
      double t = t_b;
      if (!any) {
        r.kind = Reach::Kind::at_first_rung;
      } else if (!crossed && r.kind != Reach::Kind::at_first_rung) {
        // the first crossing, log-log between (t_a, e_a) and (t_b, e_b); e_a > target >= e_b
        crossed = true;
        r.kind = Reach::Kind::interpolated;
        if (e_b > 0.0) {
          const double f = std::log(target_m / e_a) / std::log(e_b / e_a);
          t = std::exp(std::log(t_a) + f * std::log(t_b / t_a));
        }
      }
      // any cheaper rung at or below the level bounds the time too (wall times are noisy)
      r.wall_time_s = std::isnan(r.wall_time_s) ? t : std::min(r.wall_time_s, t);
    } else {
      t_a = t_b;
      e_a = e_b;
    }
    any = true;
  }
  if (std::isnan(r.wall_time_s)) r.kind = any ? Reach::Kind::not_reached : Reach::Kind::no_data;
  return r;
}

std::string reach_text(const Reach& r) {
  switch (r.kind) {
    case Reach::Kind::interpolated:
      return format_number(r.wall_time_s);
    case Reach::Kind::at_first_rung:
      return "<= " + format_number(r.wall_time_s);
    case Reach::Kind::not_reached:
      return "not reached";
    case Reach::Kind::no_data:
      return "no data";
  }
  return "";
}

int default_rung(const SweepSeries& s) {
  for (std::size_t i = 0; i < s.rungs.size(); ++i) {
    const double v = s.rungs[i].value;
    if (std::abs(v - s.default_value) <= 1e-9 * std::abs(s.default_value)) {
      return static_cast<int>(i);
    }
  }
  return -1;
}

WorkPrecisionCase work_precision_case(const SweepCase& c) {
  WorkPrecisionCase w;
  w.name = c.case_name;
  w.id = file_id(c.case_name) + "_work_precision";
  w.truth = c.truth;
  w.truth_note = c.truth_note;
  w.targets_m = work_precision_targets();

  // the plot: every rung with a positive error and wall time
  for (std::size_t k = 0; k < c.series.size(); ++k) {
    const SweepSeries& s = c.series[k];
    WorkPrecisionSeries ps;
    ps.name = s.name;
    ps.engine = s.engine;
    for (std::size_t j = 0; j < k; ++j) ps.dashed = ps.dashed || c.series[j].engine == s.engine;
    const int d = default_rung(s);
    for (std::size_t i = 0; i < s.rungs.size(); ++i) {
      const SweepRung& r = s.rungs[i];
      if (r.status != RunStatus::ok || !positive_finite(r.position_error_m) ||
          !positive_finite(r.wall_time_s)) {
        std::string why = r.status != RunStatus::ok   ? run_status_name(r.status)
                          : r.position_error_m == 0.0 ? "error exactly 0 (no log scale)"
                                                      : "no error (no truth)";
        if (!r.reason.empty()) why += ": " + r.reason;
        w.not_plotted.push_back(fmt::format("{} {}: {}", s.name, knob_text(s, r.value), why));
        continue;
      }
      if (static_cast<int>(i) == d) ps.default_index = static_cast<int>(ps.wall_s.size());
      ps.wall_s.push_back(r.wall_time_s);
      ps.error_m.push_back(r.position_error_m);
      ps.labels.push_back(knob_text(s, r.value));
    }
    w.series.push_back(std::move(ps));
  }

  // the summary: one row per series
  const double ref_cost = reference_cost_per_sim_s(c);
  Table& t = w.summary;
  t.id = w.id + "_summary";
  t.title = c.case_name + ": work-precision summary";
  t.note = fmt::format(
      "Position error against {}. Time to reach an error: wall time, s, interpolated log-log "
      "between the rungs that bracket it. Cost per simulated second: wall time / {:g} s at the "
      "engine's default setting{}.",
      c.truth, c.duration_s,
      std::isfinite(ref_cost)
          ? fmt::format("; the reference (rk45 at its default rtol) costs {} s per simulated s",
                        format_number(ref_cost))
          : "");
  t.columns = {"series",
               "knob",
               "default",
               "error at default, m",
               "wall per simulated s at default",
               "relative to reference rk45"};
  for (const double target : w.targets_m) {
    t.columns.push_back("time to " + target_text(target) + ", s");
  }
  for (std::size_t k = 0; k < c.series.size(); ++k) {
    const SweepSeries& s = c.series[k];
    std::vector<double> wall, error;
    for (const auto& r : s.rungs) {
      const bool ok = r.status == RunStatus::ok;
      wall.push_back(ok ? r.wall_time_s : kNaN);
      error.push_back(ok ? r.position_error_m : kNaN);
    }
    const int d = default_rung(s);
    std::string err_default = "default not in ladder", cost = "", ratio = "";
    if (d >= 0) {
      const SweepRung& r = s.rungs[static_cast<std::size_t>(d)];
      if (r.status == RunStatus::ok) {
        err_default = format_number(r.position_error_m);
        const double per_sim = c.duration_s > 0.0 ? r.wall_time_s / c.duration_s : kNaN;
        cost = format_number(per_sim);
        if (std::isfinite(ref_cost) && ref_cost > 0.0) {
          ratio = format_number(per_sim / ref_cost) + "x";
        }
      } else {
        err_default = run_status_name(r.status);
      }
    }
    std::vector<std::string> row = {s.name,      s.knob, compact_number(s.default_value),
                                    err_default, cost,   ratio};
    for (const double target : w.targets_m) {
      w.series[k].reach.push_back(time_to_reach(wall, error, target));
      row.push_back(reach_text(w.series[k].reach.back()));
    }
    t.rows.push_back(std::move(row));
    t.row_status.push_back("");
  }

  // every rung, as in the file
  Table& all = w.rungs;
  all.id = w.id + "_rungs";
  all.title = c.case_name + ": every rung";
  all.note = "One row per run of the sweep (wall time: median of the repeats).";
  all.columns = {"series", "knob", "value", "status", "wall time, s", "steps", "position error, m",
                 "reason"};
  for (const auto& s : c.series) {
    for (const auto& r : s.rungs) {
      all.rows.push_back({s.name, s.knob, compact_number(r.value), run_status_name(r.status),
                          format_number(r.wall_time_s), std::to_string(r.steps),
                          format_number(r.position_error_m), r.reason});
      all.row_status.push_back(r.status == RunStatus::diverged ? "fail" : "");
    }
  }
  return w;
}

std::string work_precision_file(const WorkPrecisionCase& c) {
  return "figures/" + c.id + ".svg";
}

std::string work_precision_note(const SweepFile& sweep, const std::string& path) {
  std::string dts, rtols;
  for (const double v : sweep.dt_ladder) dts += (dts.empty() ? "" : ", ") + compact_number(v);
  for (const double v : sweep.rtol_ladder) rtols += (rtols.empty() ? "" : ", ") + compact_number(v);
  return fmt::format(
      "From the sweep file {}{}: each engine over the time steps dt = {} s (the reference's fixed "
      "RK4 too) and the reference's rk45 over rtol = {} (atol = rtol x 1e-2). Error: the largest "
      "distance over bodies and output samples between a run's body centres and the truth's, at "
      "the samples where the engine has a state (an engine stepping coarser than the output grid "
      "is not interpolated). Wall time: model build and stepping, the median of {} run{} per "
      "rung, on the machine and with the --jobs of the sweep's command line; compare runs of one "
      "machine only. Every other setting is the engine's default under the case and the sweep's "
      "--set (see the provenance): the reference's default geometry is the case's outline points, "
      "whose discretisation puts a floor under its error that no step or tolerance lowers "
      "(--set reference.geometry=exact sweeps its integrators alone). A circle marks each rung, "
      "a ring the engine's default setting; a dashed line is the reference's second integrator.",
      path, sweep.quick ? " (--quick: two rungs per series)" : "", dts, rtols, sweep.repeat,
      sweep.repeat == 1 ? "" : "s");
}

Table sweep_provenance_table(const FileProvenance& provenance, const SweepFile& sweep) {
  Table t;
  t.id = "sweep_provenance";
  t.title = "Sweep provenance";
  t.note = "From the sweep file: /parameters and each case's file.";
  t.columns = {"item", "value"};
  for (const auto& [k, v] : provenance.parameters) t.rows.push_back({k, v});
  t.rows.push_back({"repeat", std::to_string(sweep.repeat)});
  for (const auto& c : sweep.cases) {
    t.rows.push_back({c.case_name + " case file", c.case_path});
    if (!c.overrides.empty()) {
      std::string text;
      for (const auto& [k, v] : c.overrides) text += (text.empty() ? "" : ", ") + k + "=" + v;
      t.rows.push_back({c.case_name + " --set", text});
    }
  }
  t.row_status.assign(t.rows.size(), "");
  return t;
}

}  // namespace pb::internal
