// planarbench run: every (case, engine) of the selection into one results file.
#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <memory>
#include <mutex>
#include <thread>

#include "cli_common.hpp"
#include "commands.hpp"
#include "planarbench/case_loader.hpp"
#include "planarbench/engines.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/output_file.hpp"
#include "planarbench/results_file.hpp"
#include "planarbench/runner.hpp"
#include "run_isolation.hpp"
#include "sweep_plan.hpp"
#include "task_scheduler.hpp"

namespace pb::cli {

namespace {

struct RunOptionsCli {
  std::string case_spec;
  std::string engine_spec;
  std::string out;
  std::vector<std::string> set;
  int jobs = 1;
  int repeat = 1;
  bool quiet = false;
  std::string cases_dir;
  std::string isolation = "process";
  double run_timeout_s = kDefaultRunTimeout_s;
  int progress_fd = -1;  // a child's: write the fraction done there
};

// a child's progress, one fraction per line on the descriptor its parent gave
void write_progress(int fd, double f) {
  const std::string line = fmt::format("{:.6f}\n", f);
  [[maybe_unused]] const auto n = ::write(fd, line.data(), line.size());
}

// one (case, engine) of the matrix
struct Task {
  std::size_t case_index = 0;
  std::string engine;
};

// progress lines on stderr: start and end of each run, and the fraction done
// at most every 2 s while a run takes longer
class Progress {
 public:
  Progress(bool quiet, std::size_t total) : quiet_(quiet), total_(total) {}

  void started(std::size_t i, const std::string& what) {
    print(fmt::format("[{}/{}] {} ...", i + 1, total_, what));
  }
  void fraction(std::size_t i, const std::string& what, double f,
                std::chrono::steady_clock::time_point& last) {
    const auto now = std::chrono::steady_clock::now();
    if (now - last < std::chrono::seconds(2)) return;
    last = now;
    print(fmt::format("[{}/{}] {} {:3.0f} %", i + 1, total_, what, 100.0 * f));
  }
  void finished(std::size_t i, const std::string& what, const RunResult& r) {
    std::string status = run_status_name(r.status);
    if (r.status != RunStatus::ok) status += ": " + r.reason;
    print(fmt::format("[{}/{}] {} {} ({:.2f} s, {} steps)", i + 1, total_, what, status,
                      r.wall_time_s, r.steps));
  }

 private:
  void print(const std::string& line) {
    if (quiet_) return;
    std::lock_guard<std::mutex> lock(mutex_);
    std::fprintf(stderr, "%s\n", line.c_str());
  }
  bool quiet_;
  std::size_t total_;
  std::mutex mutex_;
};

int run_matrix(const RunOptionsCli& opt, int argc, char** argv) {
  // every option is checked before a case is read or anything runs, the
  // output folder included (fail fast, write nothing)
  if (opt.progress_fd >= 0) die_with_parent();  // a child of an isolated run
  check_jobs(opt.jobs);
  check_repeat(opt.repeat);
  check_run_timeout(opt.run_timeout_s);
  // the runs' samples stream to the results file's folder as they are made
  const std::filesystem::path out_target = output_target("--out", opt.out);
  const std::filesystem::path work_dir = folder_of(out_target);
  check_engine_spec(opt.engine_spec);
  const Overrides overrides = parse_overrides(opt.set);
  // a comma-separated list of case specs is accepted too
  std::vector<std::filesystem::path> paths;
  for (std::size_t start = 0; start <= opt.case_spec.size();) {
    const auto comma = opt.case_spec.find(',', start);
    const auto item = opt.case_spec.substr(start, comma == std::string::npos ? std::string::npos
                                                                             : comma - start);
    for (auto& p : resolve_cases(item, cases_dir(opt.cases_dir))) paths.push_back(std::move(p));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  check_not_an_input("--out", opt.out, paths);
  const auto engines = resolve_engines(opt.engine_spec);
  check_engine_settings(overrides.engine_keys, engines);

  // everything is loaded and validated before anything runs
  std::vector<Case> cases;
  std::vector<SettingsOverrides> case_engine_settings;
  for (const auto& p : paths) {
    cases.push_back(load_case(p, overrides.case_keys));
    case_engine_settings.push_back(engine_settings_for(cases.back(), overrides.engine_keys));
    for (const auto& name : engines) make_engine(name)->settings().apply(case_engine_settings.back());
  }

  std::vector<Task> tasks;
  for (std::size_t ci = 0; ci < cases.size(); ++ci) {
    for (const auto& e : engines) tasks.push_back(Task{ci, e});
  }
  // the file's header and one group per run first; each run is written as
  // soon as it ends, while the other workers go on (no serial tail)
  ResultsFile layout;
  layout.provenance = provenance(argc, argv);
  for (const Case& c : cases) {
    CaseRuns cr;
    cr.case_name = c.name;
    cr.case_text = c.source_text;
    cr.case_path = c.source_path;
    cr.overrides = overrides.as_given;
    for (const auto& e : engines) {
      RunResult slot;
      slot.engine_name = e;
      cr.runs.push_back(std::move(slot));
    }
    layout.cases.push_back(std::move(cr));
  }
  ResultsFileWriter writer(opt.out, layout);
  if (opt.isolation == "process") remove_stale_child_folders(work_dir, out_target);
  std::vector<RunStatus> statuses(tasks.size(), RunStatus::ok);
  Progress progress(opt.quiet, tasks.size());
  std::vector<SchedulerTask> plan;
  for (const Task& t : tasks) {
    const Case& c = cases[t.case_index];
    plan.push_back(SchedulerTask{expected_cost(c.name, t.engine, c.duration_s),
                                 exclusive_group(t.engine)});
  }
  TaskScheduler scheduler(std::move(plan));
  std::mutex error_mutex;
  std::exception_ptr first_error;

  // workers take the longest tasks first; results land at the task's index,
  // so the file does not depend on the number of jobs or the order
  auto worker = [&] {
    while (const auto next = scheduler.acquire()) {
      const std::size_t i = *next;
      const Task& task = tasks[i];
      const Case& c = cases[task.case_index];
      const std::string what = fmt::format("{} x {}", c.name, task.engine);
      try {
        progress.started(i, what);
        auto last = std::chrono::steady_clock::now();
        auto on_progress = [&](double f) {
          if (opt.progress_fd >= 0) write_progress(opt.progress_fd, f);
          progress.fraction(i, what, f, last);
        };
        const SettingsOverrides& settings = case_engine_settings[task.case_index];
        RunResult r;
        IsolatedResult isolated;  // the run's own file, when a process of its own made it
        if (opt.isolation == "process") {
          IsolatedRun spec;
          spec.case_path = std::filesystem::absolute(paths[task.case_index]);
          spec.case_name = c.name;
          spec.engine = task.engine;
          spec.set = opt.set;
          spec.repeat = opt.repeat;
          spec.duration_s = c.duration_s;
          spec.timeout_s = opt.run_timeout_s;
          spec.work_dir = work_dir;
          spec.target = out_target;
          isolated = run_isolated(spec, on_progress);
          r = std::move(isolated.run);
          if (isolated.file.empty()) describe_lost_run(r, c, settings);
        } else {
          auto engine = make_engine(task.engine);
          RunOptions ro;
          ro.progress = on_progress;
          ro.spool_dir = work_dir;
          r = run_engine(*engine, c, settings, ro);
          // repeats of an ok run, for its cost only: the same bits each time
          // (deterministic engines; their samples spool and are dropped), the
          // median wall time is the run's, every one is kept
          if (opt.repeat > 1 && r.status == RunStatus::ok) {
            std::vector<double> walls{r.wall_time_s};
            RunOptions again = ro;
            again.progress = nullptr;
            for (int k = 1; k < opt.repeat; ++k) {
              auto fresh = make_engine(task.engine);
              walls.push_back(run_engine(*fresh, c, settings, again).wall_time_s);
            }
            r.wall_time_repeats_s = walls;
            r.wall_time_s = median(walls);
          }
        }
        progress.finished(i, what, r);
        statuses[i] = r.status;
        if (isolated.file.empty()) {
          writer.write_run(task.case_index, i % engines.size(), r);
        } else {
          writer.copy_run(task.case_index, i % engines.size(), isolated.file);
        }
      } catch (...) {
        std::lock_guard<std::mutex> lock(error_mutex);
        if (!first_error) first_error = std::current_exception();
        scheduler.cancel();
      }
      scheduler.release(i);
    }
  };
  const int n_threads = std::min<int>(opt.jobs, static_cast<int>(tasks.size()));
  std::vector<std::thread> threads;
  for (int t = 1; t < n_threads; ++t) threads.emplace_back(worker);
  worker();
  for (auto& t : threads) t.join();
  if (first_error) std::rethrow_exception(first_error);

  writer.commit();

  int diverged = 0;
  for (const RunStatus st : statuses) diverged += st == RunStatus::diverged;
  if (!opt.quiet) {
    std::fprintf(stderr, "wrote %s (%zu runs%s)\n", opt.out.c_str(), tasks.size(),
                 diverged ? fmt::format(", {} diverged", diverged).c_str() : "");
  }
  return diverged ? kExitEngineFailed : kExitOk;
}

}  // namespace

Action add_run_command(CLI::App& app, int argc, char** argv) {
  auto opt = std::make_shared<RunOptionsCli>();
  auto* cmd = app.add_subcommand("run", "Run cases on engines and write an HDF5 results file");
  cmd->add_option("--case", opt->case_spec,
                  "Case name (file stem in the cases folder), path to a case file, a comma-separated "
                  "list of those, or 'all'")
      ->required();
  cmd->add_option("--engine", opt->engine_spec,
                  "Engine: analytic, reference, mujoco, box2d, ode, a comma-separated list, or 'all'")
      ->required();
  cmd->add_option("--out", opt->out, "Results file to write (HDF5; written atomically)")->required();
  cmd->add_option("--set", opt->set,
                  "Override a case or engine setting, KEY=VALUE (repeatable), e.g. dt=1e-4, "
                  "outline_points=360, geometry=exact, contact.stiffness=2e4, "
                  "mujoco.solimp=\"0.9 0.95 0.001 0.5 2\"; see `planarbench list --settings`")
      ->take_all();
  cmd->add_option("--jobs,-j", opt->jobs, "Worker threads for the case x engine matrix")
      ->default_val(1);
  cmd->add_option("--repeat", opt->repeat,
                  "Runs per case x engine, for its cost: the results are the first run's, the "
                  "wall time the median of all (each is kept in wall_time_repeats_s)")
      ->default_val(1);
  cmd->add_flag("--quiet,-q", opt->quiet, "No progress on stderr");
  add_isolation_options(*cmd, opt->isolation, opt->run_timeout_s);
  cmd->add_option("--progress-fd", opt->progress_fd,
                  "(internal) file descriptor a child run writes its fraction done to")
      ->group("");
  cmd->add_option("--cases-dir", opt->cases_dir,
                  "Folder of case files (default: $PLANARBENCH_CASES_DIR or the source tree's cases/)");
  return [opt, argc, argv] { return run_matrix(*opt, argc, argv); };
}

}  // namespace pb::cli
