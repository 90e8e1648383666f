// planarbench sweep: each engine over a ladder of step sizes (the reference
// also over rk45 tolerances), the position error of every rung against the
// case's truth and its wall time, into one HDF5 work-precision file.
#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <mutex>
#include <thread>

#include "cli_common.hpp"
#include "run_isolation.hpp"
#include "commands.hpp"
#include "planarbench/case_loader.hpp"
#include "planarbench/engines.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/output_file.hpp"
#include "planarbench/reports/metrics.hpp"
#include "planarbench/runner.hpp"
#include "planarbench/sweep_file.hpp"
#include "sweep_error.hpp"
#include "sweep_plan.hpp"
#include "truth_run.hpp"
#include "task_scheduler.hpp"

namespace pb::cli {

namespace {

namespace fs = std::filesystem;

struct SweepOptionsCli {
  std::string case_spec;
  std::string engine_spec;
  std::string out;
  std::vector<std::string> set;
  std::string dt_ladder;
  int jobs = 1;
  int repeat = 1;
  bool quick = false;
  bool quiet = false;
  std::string cases_dir;
  std::string isolation = "process";
  double run_timeout_s = kDefaultRunTimeout_s;
};

// one case of the sweep, everything loaded and planned before anything runs
struct CasePlan {
  fs::path path;
  Case c;
  SettingsOverrides base;  // the case's [settings] under the --set engine keys
  TruthPlan truth;
  std::vector<SeriesPlan> series;
  std::vector<double> defaults;  // the knob's default value per series
};

// one rung to run: (case, series, rung)
struct RungTask {
  std::size_t case_index = 0;
  std::size_t series_index = 0;
  std::size_t rung_index = 0;
};

// progress lines on stderr, one at the start and one at the end of each run
class Progress {
 public:
  Progress(bool quiet, std::size_t total) : quiet_(quiet), total_(total) {}
  void print(std::size_t i, const std::string& line) {
    if (quiet_) return;
    std::lock_guard<std::mutex> lock(mutex_);
    std::fprintf(stderr, "[%zu/%zu] %s\n", i + 1, total_, line.c_str());
  }

 private:
  bool quiet_;
  std::size_t total_;
  std::mutex mutex_;
};

std::string rung_label(const SeriesPlan& s, double value) {
  return fmt::format("{} {}={:g}", s.name, s.knob, value);
}

std::vector<fs::path> case_paths(const std::string& spec, const std::string& dir_option) {
  std::vector<fs::path> paths;
  for (std::size_t start = 0; start <= spec.size();) {
    const auto comma = spec.find(',', start);
    const auto item =
        spec.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    for (auto& p : resolve_cases(item, cases_dir(dir_option))) paths.push_back(std::move(p));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return paths;
}

std::vector<std::string> sweep_engines(const std::string& spec) {
  std::vector<std::string> out;
  for (const auto& e : resolve_engines(spec)) {
    // 'all' means every engine with something to sweep; the truth is not one
    if (spec == "all" && e == "analytic") continue;
    out.push_back(e);
  }
  return out;
}

int run_sweep(const SweepOptionsCli& opt, int argc, char** argv) {
  // ---- options, then every case and rung validated before anything runs ----
  check_jobs(opt.jobs);
  check_repeat(opt.repeat);
  check_run_timeout(opt.run_timeout_s);
  std::vector<double> dts =
      opt.dt_ladder.empty() ? default_dt_ladder() : parse_ladder(opt.dt_ladder, "--dt-ladder");
  std::vector<double> rtols = default_rtol_ladder();
  if (opt.quick) {
    dts = opt.dt_ladder.empty() ? quick_dt_ladder() : two_coarsest(dts);
    rtols = quick_rtol_ladder();
  }
  // the --out target must be writable before minutes are spent computing it
  check_output_file("--out", opt.out);
  const fs::path out_dir = folder_of(opt.out);
  const Overrides overrides = parse_overrides(opt.set);
  reject_swept_keys(overrides.engine_keys);
  const auto engines = sweep_engines(opt.engine_spec);
  // the sweep file must not replace a case file it reads (issue 24)
  const std::vector<fs::path> paths = case_paths(opt.case_spec, opt.cases_dir);
  check_not_an_input("--out", opt.out, paths);

  std::vector<CasePlan> plans;
  for (const auto& path : paths) {
    CasePlan p;
    p.path = path;
    p.c = load_case(path, overrides.case_keys);
    p.base = engine_settings_for(p.c, overrides.engine_keys);
    p.truth = truth_for(p.c);
    for (const auto& e : engines) {
      for (auto& s : series_for(e, dts, rtols)) {
        // the knob's value at the engine's defaults under the case and --set
        auto engine = make_engine(s.engine);
        engine->settings().apply(p.base);
        p.defaults.push_back(engine->settings().to_json().at(s.knob).get<double>());
        // each rung's settings must parse (ranges are the engine's own)
        for (const double v : s.values) {
          make_engine(s.engine)->settings().apply(rung_overrides(p.base, s, v));
        }
        p.series.push_back(std::move(s));
      }
    }
    plans.push_back(std::move(p));
  }

  // ---- the truths first: every rung's error is measured against them ----
  std::vector<RunResult> truths(plans.size());
  std::vector<std::string> truth_notes(plans.size());
  std::vector<std::string> truth_labels(plans.size());
  {
    Progress progress(opt.quiet, plans.size());
    std::vector<SchedulerTask> plan;
    for (const auto& p : plans) plan.push_back(SchedulerTask{p.c.duration_s, ""});
    run_parallel(plan, opt.jobs, [&](std::size_t i) {
      const CasePlan& p = plans[i];
      progress.print(i, fmt::format("{} truth: {} ...", p.c.name, p.truth.label));
      TruthRun t = run_truth(p.c, p.truth, p.base);
      progress.print(i, fmt::format("{} truth: {} {} ({:.2f} s)", p.c.name, t.label,
                                    run_status_name(t.result.status), t.result.wall_time_s));
      truths[i] = std::move(t.result);
      truth_notes[i] = t.note;
      truth_labels[i] = t.label;
    });
  }

  // ---- every series, longest first, its rungs coarse to fine until its
  // error is flat (ladder_is_flat); errors computed as each run ends ----
  std::vector<RungTask> tasks;  // every planned rung, in (case, series, rung) order
  std::vector<std::size_t> first_task;  // per series task: index of its first rung
  std::vector<SchedulerTask> plan;      // one per series
  std::vector<std::pair<std::size_t, std::size_t>> series_tasks;  // (case, series)
  for (std::size_t ci = 0; ci < plans.size(); ++ci) {
    for (std::size_t si = 0; si < plans[ci].series.size(); ++si) {
      const SeriesPlan& s = plans[ci].series[si];
      double cost = 0.0;
      first_task.push_back(tasks.size());
      for (std::size_t ri = 0; ri < s.values.size(); ++ri) {
        tasks.push_back(RungTask{ci, si, ri});
        cost += rung_cost(s, s.values[ri], plans[ci].c.duration_s);
      }
      series_tasks.emplace_back(ci, si);
      plan.push_back(SchedulerTask{cost, exclusive_group(s.engine)});
    }
  }
  if (opt.isolation == "process") remove_stale_child_folders(out_dir, opt.out);
  std::vector<SweepRung> rungs(tasks.size());
  std::vector<bool> ran(tasks.size(), false);
  Progress progress(opt.quiet, tasks.size());
  const auto t0 = std::chrono::steady_clock::now();
  run_parallel(plan, opt.jobs, [&](std::size_t series) {
    const auto [ci, si] = series_tasks[series];
    const CasePlan& p = plans[ci];
    const SeriesPlan& s = p.series[si];
    std::vector<double> errors;
    for (std::size_t ri = 0; ri < s.values.size(); ++ri) {
      const std::size_t i = first_task[series] + ri;
      const double value = s.values[ri];
      const std::string what = fmt::format("{} x {}", p.c.name, rung_label(s, value));
      progress.print(i, what + " ...");
      const SettingsOverrides settings = rung_overrides(p.base, s, value);
      // repeats: the same bits each time (deterministic engines), so the first
      // run's trajectory gives the error and the median of the wall times the cost
      std::vector<double> walls;
      RunResult first;
      for (int k = 0; k < opt.repeat; ++k) {
        RunResult r;
        if (opt.isolation == "process") {
          // a process of its own (run_isolation.hpp): a library's abort ends this rung only
          IsolatedRun spec;
          spec.case_path = fs::absolute(p.path);
          spec.case_name = p.c.name;
          spec.engine = s.engine;
          spec.set = opt.set;
          for (const auto& [key, v] : rung_assignments(s, value)) spec.set.push_back(key + "=" + v);
          spec.duration_s = p.c.duration_s;
          spec.timeout_s = opt.run_timeout_s;
          spec.work_dir = out_dir;
          spec.target = opt.out;
          r = run_isolated_whole(spec, p.c, settings);
        } else {
          auto engine = make_engine(s.engine);
          r = run_engine(*engine, p.c, settings);
        }
        walls.push_back(r.wall_time_s);
        if (k == 0) first = std::move(r);
      }
      SweepRung& out = rungs[i];
      ran[i] = true;
      out.value = value;
      out.wall_time_s = median(walls);
      out.steps = first.steps;
      out.status = first.status;
      out.reason = first.status == RunStatus::ok ? "" : first.reason;
      if (first.status == RunStatus::diverged && first.diverged_at_s >= 0.0) {
        out.reason = fmt::format("at t = {:.6g} s: {}", first.diverged_at_s, first.reason);
      }
      out.position_error_m = sweep_position_error(p.c, first, truths[ci]);
      std::string status = run_status_name(out.status);
      if (out.status != RunStatus::ok) status += ": " + out.reason;
      progress.print(i, fmt::format("{} {} ({:.3f} s, {} steps, error {:.3g} m)", what, status,
                                    out.wall_time_s, out.steps, out.position_error_m));
      errors.push_back(out.status == RunStatus::ok ? out.position_error_m : std::nan(""));
      if (ladder_is_flat(errors) && ri + 1 < s.values.size()) {
        progress.print(i, fmt::format("{} x {}: error flat ({:.3g} m after {:.3g} m), the {} "
                                      "finer rung(s) not run",
                                      p.c.name, s.name, errors.back(),
                                      errors[errors.size() - 2], s.values.size() - ri - 1));
        break;
      }
    }
  });
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  // ---- the file ----
  SweepFile file;
  file.provenance = provenance(argc, argv);
  file.repeat = opt.repeat;
  file.quick = opt.quick;
  file.dt_ladder = dts;
  file.rtol_ladder = rtols;
  file.ladder_stop_rule = ladder_stop_rule();
  std::size_t diverged = 0;
  for (std::size_t ci = 0; ci < plans.size(); ++ci) {
    const CasePlan& p = plans[ci];
    SweepCase sc;
    sc.case_name = p.c.name;
    sc.case_text = p.c.source_text;
    sc.case_path = p.c.source_path;
    sc.overrides = overrides.as_given;
    sc.duration_s = p.c.duration_s;
    sc.truth = truths[ci].status == RunStatus::ok ? truth_labels[ci] : "none";
    sc.truth_note = truth_notes[ci];
    for (std::size_t si = 0; si < p.series.size(); ++si) {
      const SeriesPlan& s = p.series[si];
      SweepSeries out;
      out.name = s.name;
      out.engine = s.engine;
      out.knob = s.knob;
      out.knob_key = s.knob_key;
      out.knob_unit = s.knob_unit;
      out.default_value = p.defaults[si];
      out.fixed_settings = fixed_settings_json(s);
      for (std::size_t i = 0; i < tasks.size(); ++i) {
        if (tasks[i].case_index != ci || tasks[i].series_index != si || !ran[i]) continue;
        diverged += rungs[i].status == RunStatus::diverged;
        out.rungs.push_back(rungs[i]);
      }
      sc.series.push_back(std::move(out));
    }
    file.cases.push_back(std::move(sc));
  }
  write_sweep_file(opt.out, file);

  int truth_failed = 0;
  for (const auto& t : truths) truth_failed += t.status != RunStatus::ok;
  if (!opt.quiet) {
    std::fprintf(stderr, "wrote %s (%zu rungs in %.1f s%s%s)\n", opt.out.c_str(),
                 static_cast<std::size_t>(std::count(ran.begin(), ran.end(), true)),
                 elapsed, diverged ? fmt::format(", {} diverged", diverged).c_str() : "",
                 truth_failed ? fmt::format(", {} truth runs failed", truth_failed).c_str() : "");
  }
  // a diverged rung is a measurement (too coarse a step); a failed truth is not
  return truth_failed ? kExitEngineFailed : kExitOk;
}

}  // namespace

Action add_sweep_command(CLI::App& app, int argc, char** argv) {
  auto opt = std::make_shared<SweepOptionsCli>();
  auto* cmd = app.add_subcommand(
      "sweep",
      "Work-precision sweep: each engine over a ladder of time steps (the reference also over "
      "rk45 tolerances), the max position error of each rung against the case's truth and its "
      "wall time, into one HDF5 file (exit 0 even when coarse rungs diverge: that is data)");
  cmd->add_option("--case", opt->case_spec,
                  "Case name, path to a case file, a comma-separated list of those, or 'all'")
      ->required();
  cmd->add_option("--engine", opt->engine_spec,
                  "Engine: reference, mujoco, box2d, ode, a comma-separated list, or 'all' "
                  "(the analytic engine is the truth, not swept)")
      ->required();
  cmd->add_option("--out", opt->out, "Sweep file to write (HDF5; written atomically)")->required();
  cmd->add_option("--set", opt->set,
                  "Override a case or engine setting, KEY=VALUE (repeatable), except the swept "
                  "ones (dt, rtol, atol, integrator); e.g. reference.geometry=exact sweeps the "
                  "reference's integrators without its outline discretisation error")
      ->take_all();
  cmd->add_option("--dt-ladder", opt->dt_ladder,
                  "Time steps, s, comma-separated (default 1e-3,5e-4,2e-4,1e-4,5e-5,2e-5,1e-5): "
                  "mujoco, box2d, ode and the reference's fixed RK4");
  cmd->add_option("--jobs,-j", opt->jobs, "Worker threads")->default_val(1);
  cmd->add_option("--repeat", opt->repeat, "Runs per rung; the wall time is their median")
      ->default_val(1);
  cmd->add_flag("--quick", opt->quick,
                "Two rungs per series (dt 1e-3 and 1e-4 s, or the two largest of --dt-ladder; "
                "rtol 1e-4 and 1e-6), for CI");
  cmd->add_flag("--quiet,-q", opt->quiet, "No progress on stderr");
  add_isolation_options(*cmd, opt->isolation, opt->run_timeout_s);
  cmd->add_option(
      "--cases-dir", opt->cases_dir,
      "Folder of case files (default: $PLANARBENCH_CASES_DIR or the source tree's cases/)");
  return [opt, argc, argv] { return run_sweep(*opt, argc, argv); };
}

}  // namespace pb::cli
