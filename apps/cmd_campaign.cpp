// planarbench campaign plan | run | merge: parameter studies over any --set
// key, run as shards (one machine, or a Slurm job array: scripts/slurm/),
// merged into one results file whose /campaign table has a row per run.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>

#include "campaign_plan.hpp"
#include "campaign_shards.hpp"
#include "campaign_size.hpp"
#include "cli_common.hpp"
#include "commands.hpp"
#include "planarbench/case_loader.hpp"
#include "planarbench/engines.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/output_file.hpp"
#include "planarbench/reports/friction_metrics.hpp"
#include "planarbench/results_file.hpp"
#include "planarbench/runner.hpp"
#include "run_isolation.hpp"
#include "sweep_error.hpp"
#include "sweep_plan.hpp"
#include "truth_run.hpp"
#include "task_scheduler.hpp"

namespace pb::cli {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct CampaignOptionsCli {
  std::string file;
  std::string out;
  std::string dir;
  std::string shard = "0/1";
  int shards = 1;
  int jobs = 1;
  int checkpoint_runs = 64;
  double checkpoint_s = 60.0;
  bool quiet = false;
  std::string cases_dir;
  std::string isolation = "process";
  double run_timeout_s = kDefaultRunTimeout_s;
};

std::string part_prefix(const CampaignPlan& plan, int k, int n) {
  return fmt::format("{}.shard-{}-of-{}.part-", fs::path(plan.file).stem().string(), k, n);
}

// ---- plan --------------------------------------------------------------------

int plan_campaign(const CampaignOptionsCli& opt) {
  if (opt.shards < 1 || opt.shards > 100000) {
    throw InputError("--shards", 0, std::to_string(opt.shards), "must be in [1, 100000]");
  }
  const auto t0 = Clock::now();
  // a plan of millions of runs takes seconds: past the first, progress on
  // stderr (issue 24); its size is held to campaign_size.hpp's limit
  const CampaignPlan plan = load_campaign(opt.file, opt.cases_dir, opt.quiet);
  const std::int64_t n = plan.size();
  std::string shape = fmt::format("{} case(s) x {} engine(s)", plan.cases.size(), plan.engines.size());
  for (const auto& a : plan.axes) shape += fmt::format(" x {} ({})", a.axis.values.size(), a.axis.name);
  std::printf("campaign %s: %lld runs = %s\n", opt.file.c_str(), static_cast<long long>(n),
              shape.c_str());
  std::string metrics;
  for (const auto& m : plan.metrics) metrics += (metrics.empty() ? "" : ", ") + m.name;
  if (plan.trace_points > 0) metrics += fmt::format("{}trace ({} points)", metrics.empty() ? "" : ", ", plan.trace_points);
  std::printf("metrics: %s\n", metrics.empty() ? "none (status and steps only)" : metrics.c_str());
  if (plan.needs_truth()) {
    std::int64_t per_case = 1;
    for (const auto& a : plan.axes) per_case *= a.case_key ? static_cast<std::int64_t>(a.axis.values.size()) : 1;
    std::printf("truth runs: %lld (one per case and point of the axes that change the case)\n",
                static_cast<long long>(per_case * static_cast<std::int64_t>(plan.cases.size())));
  }
  // the estimate, by engine
  const std::vector<double> by_engine = plan.cost_by_engine();
  double total = 0.0;
  for (const double c : by_engine) total += c;
  std::printf("estimated cost: %.4g CPU-s (measured wall s per simulated s of each case and "
              "engine at its default step, scaled by default step / step)\n",
              total);
  for (std::size_t e = 0; e < plan.engines.size(); ++e) {
    std::printf("  %-10s %.4g CPU-s\n", plan.engines[e].c_str(), by_engine[e]);
  }
  if (opt.shards > 1) {
    const auto shards = partition(plan, opt.shards, opt.quiet);
    double most = 0.0;
    std::size_t fewest = shards.front().size();
    std::size_t largest = 0;
    for (const auto& s : shards) {
      double c = 0.0;
      for (const auto id : s) c += plan.cost(id);
      most = std::max(most, c);
      fewest = std::min(fewest, s.size());
      largest = std::max(largest, s.size());
    }
    std::printf("%d shards: %zu to %zu runs each, the costliest %.4g CPU-s (%.3f x the mean)\n",
                opt.shards, fewest, largest, most, most / (total / opt.shards));
  }
  if (!opt.quiet) {
    std::fprintf(stderr, "planned in %.3f s\n",
                 std::chrono::duration<double>(Clock::now() - t0).count());
  }
  return kExitOk;
}

// ---- run -----------------------------------------------------------------------

// the part files of a campaign folder (not the temporaries: those start with '.')
std::vector<fs::path> part_files(const fs::path& dir) {
  std::vector<fs::path> out;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (name.empty() || name[0] == '.' || e.path().extension() != ".h5") continue;
    out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// the name of the first case whose text differs between two headers of one
// campaign ("" when they agree): a case file edited between two shards' runs
std::string changed_case(const CampaignTable& a, const CampaignTable& b) {
  for (const auto& ca : a.cases) {
    for (const auto& cb : b.cases) {
      if (ca.name == cb.name && ca.text != cb.text) return ca.name;
    }
  }
  return "";
}

// first sample at or after t of a body, within its samples; 1e-12 s below t
// so that a trace time computed as duration * j / (T - 1) finds the sample at
// that grid time when the two differ by rounding (a few ulps of t <= 1e4 s:
// ~1e-12 s; 1e-8 of the shipped cases' 1e-4 s output interval)
std::size_t sample_at(const BodyTrajectory& b, double t) {
  const auto it = std::lower_bound(b.time_s.begin(), b.time_s.end(), t - 1e-12);
  return std::min<std::size_t>(static_cast<std::size_t>(it - b.time_s.begin()),
                               b.time_s.empty() ? 0 : b.time_s.size() - 1);
}

// a SPEC §7 friction metric's error against the truth (friction_metrics.hpp):
// hold_drift_m and creep_speed_mps as they are, the others' relative errors; NaN where the
// truth has no such figure
double friction_error(const Case& c, const RunResult& r, const RunResult& truth,
                      const std::string& campaign_metric) {
  const std::string name = campaign_metric == "slide_acceleration_error" ? "slide_acceleration_mps2"
                           : campaign_metric == "stop_time_error"        ? "stop_time_s"
                                                                         : campaign_metric;
  for (const MetricValue& m : friction_metrics(c, r, truth)) {
    if (m.metric == name) return m.error;
  }
  return std::nan("");
}

// the metrics of one run, in the plan's order
std::vector<double> metrics_of(const CampaignPlan& plan, const Case& c, const RunResult& r,
                               const RunResult* truth) {
  const double nan = std::nan("");
  const bool ok = r.status == RunStatus::ok;
  const ContactEpisode* first = ok && !r.events.empty() ? &r.events.front() : nullptr;
  std::vector<double> out;
  for (const auto& m : plan.metrics) {
    double v = nan;
    if (m.name == "position_error_m") {
      v = truth != nullptr ? sweep_position_error(c, r, *truth) : nan;
    } else if (m.name == "events") {
      v = ok ? static_cast<double>(r.events.size()) : nan;
    } else if (m.name == "first_onset_time_s") {
      v = first ? first->onset_time_s : nan;
    } else if (m.name == "first_restitution") {
      v = first ? first->restitution : nan;
    } else if (m.name == "first_peak_force_n") {
      v = first ? first->peak_force_n : nan;
    } else if (m.name == "first_impulse_ns") {
      v = first ? first->impulse_ns : nan;
    } else if (m.name == "slide_acceleration_mps2") {
      v = steady_slide_acceleration_mps2(c, r);
    } else if (m.name == "hold_drift_m" || m.name == "creep_speed_mps" ||
               m.name == "slide_acceleration_error" ||
               m.name == "stop_time_error") {
      v = truth != nullptr ? friction_error(c, r, *truth, m.name) : nan;
    } else if (m.name == "max_penetration_m") {
      if (ok && !r.events.empty()) {
        v = 0.0;
        for (const auto& e : r.events) v = std::max(v, e.max_penetration_m);
      }
    }
    out.push_back(v);
  }
  return out;
}

void trace_of(const CampaignPlan& plan, const CampaignCasePlan& cp, const RunResult& r,
              int bodies, CampaignRun& out) {
  const auto tp = static_cast<std::size_t>(plan.trace_points);
  const auto nb = static_cast<std::size_t>(bodies);
  out.trace_time_s.assign(tp, std::nan(""));
  out.trace_position_m.assign(2 * nb * tp, std::nan(""));
  for (std::size_t j = 0; j < tp; ++j) {
    out.trace_time_s[j] = cp.c.duration_s * static_cast<double>(j) / static_cast<double>(tp - 1);
  }
  if (r.status != RunStatus::ok) return;
  for (std::size_t b = 0; b < cp.moving_bodies.size() && b < nb; ++b) {
    const auto it = std::find_if(r.bodies.begin(), r.bodies.end(),
                                 [&](const BodyTrajectory& x) { return x.name == cp.moving_bodies[b]; });
    if (it == r.bodies.end() || it->time_s.empty()) continue;
    for (std::size_t j = 0; j < tp; ++j) {
      const std::size_t k = sample_at(*it, out.trace_time_s[j]);
      out.trace_position_m[(b * tp + j) * 2] = it->position_m[k].x();
      out.trace_position_m[(b * tp + j) * 2 + 1] = it->position_m[k].y();
    }
  }
}

std::string assignments_json(const std::vector<std::pair<std::string, std::string>>& a) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const auto& [k, v] : a) j[k] = v;
  return j.dump();
}

// whose collision and contact force made a run: the adapter's
// mapping.physics without its parameter text (SPEC §5b)
std::string physics_json(const nlohmann::json& mapping) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  if (!mapping.is_object() || !mapping.contains("physics")) return out.dump();
  const nlohmann::json& p = mapping.at("physics");
  for (const char* key : {"mode", "collision_by", "contact_force_by", "foreknowledge"}) {
    if (p.contains(key)) out[key] = p.at(key);
  }
  return out.dump();
}

int run_campaign(const CampaignOptionsCli& opt, int argc, char** argv) {
  check_jobs(opt.jobs);
  check_run_timeout(opt.run_timeout_s);
  // plain variables, not a structured binding: lambdas below capture them
  // (Clang 14 cannot capture a binding)
  const std::pair<int, int> shard = parse_shard(opt.shard, "--shard");
  const int k = shard.first;
  const int n = shard.second;
  if (opt.checkpoint_runs < 1) {
    throw InputError("--checkpoint-runs", 0, std::to_string(opt.checkpoint_runs), "must be >= 1");
  }
  if (!(opt.checkpoint_s > 0.0)) {
    throw InputError("--checkpoint-seconds", 0, fmt::format("{}", opt.checkpoint_s), "must be > 0");
  }
  const fs::path dir = opt.out;
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec)) {
    throw InputError("--out", 0, opt.out, "exists and is not a folder; give the campaign's folder");
  }
  // the campaign is read and checked whole before anything is made
  const CampaignPlan plan = load_campaign(opt.file, opt.cases_dir);
  fs::create_directories(dir, ec);
  if (ec) throw InputError("--out", 0, opt.out, fmt::format("cannot make the folder: {}", ec.message()));
  check_output_file("--out", dir / "probe.h5");
  const std::vector<std::int64_t> mine = partition(plan, n)[static_cast<std::size_t>(k)];

  const CampaignTable header = campaign_header(plan);
  // runs already in the folder (a resubmitted or preempted shard resumes)
  std::set<std::int64_t> done;
  const std::string prefix = part_prefix(plan, k, n);
  int next_part = 0;
  for (const auto& p : part_files(dir)) {
    const ResultsFile f = read_results_file(p);
    if (!f.campaign || f.campaign->kind != "campaign" || !f.campaign->shard.size()) {
      throw InputError(p.string(), 0, "/campaign",
                       "is not a shard's file of a campaign: the campaign folder holds only the "
                       "files `campaign run` writes (merge into a file outside it)");
    }
    if (f.campaign->source_text != plan.text) {
      throw InputError(p.string(), 0, "/campaign@source_text",
                       fmt::format("belongs to another campaign (its file differs from {}); give "
                                   "each campaign its own folder",
                                   opt.file));
    }
    const std::string edited = changed_case(*f.campaign, header);
    if (!edited.empty()) {
      throw InputError(p.string(), 0, "/campaign/cases/" + edited,
                       fmt::format("case '{}' was run from another text than its file has now: the "
                                   "folder's runs and new ones would not be one campaign; restore "
                                   "the case file or start a new folder",
                                   edited));
    }
    for (const auto& r : f.campaign->runs) done.insert(r.id);
    const std::string name = p.filename().string();
    if (name.rfind(prefix, 0) == 0) {
      next_part = std::max(next_part, std::atoi(name.c_str() + prefix.size()) + 1);
    }
  }
  std::vector<std::int64_t> todo;
  for (const auto id : mine) {
    if (done.count(id) == 0) todo.push_back(id);
  }
  const std::size_t skipped = mine.size() - todo.size();
  if (!opt.quiet) {
    std::fprintf(stderr, "shard %d/%d: %zu of %lld runs, %zu already in %s, %zu to run\n", k, n,
                 mine.size(), static_cast<long long>(plan.size()), skipped, opt.out.c_str(),
                 todo.size());
  }

  // ---- the runs ----
  if (opt.isolation == "process") remove_stale_child_folders(dir, dir / "campaign");
  std::vector<std::string> set_assignments;
  for (const auto& [key, v] : plan.set) set_assignments.push_back(key + "=" + v);
  const Overrides fixed = parse_overrides(set_assignments);
  const ResultsProvenance prov = provenance(argc, argv);

  std::mutex truth_mutex;
  std::map<std::string, std::shared_future<std::shared_ptr<const RunResult>>> truths;
  auto truth_for_run = [&](const CampaignCasePlan& cp, const Case& c,
                           const std::vector<std::pair<std::string, std::string>>& case_keys)
      -> std::shared_ptr<const RunResult> {
    const std::string key = cp.c.name + "|" + assignments_json(case_keys);
    std::promise<std::shared_ptr<const RunResult>> promise;
    std::shared_future<std::shared_ptr<const RunResult>> future;
    bool mine_to_run = false;
    {
      std::lock_guard<std::mutex> lock(truth_mutex);
      const auto it = truths.find(key);
      if (it == truths.end()) {
        future = promise.get_future().share();
        truths.emplace(key, future);
        mine_to_run = true;
      } else {
        future = it->second;
      }
    }
    if (mine_to_run) {
      try {
        TruthRun t = run_truth(c, truth_for(c), engine_settings_for(c, fixed.engine_keys));
        promise.set_value(std::make_shared<const RunResult>(std::move(t.result)));
      } catch (...) {
        promise.set_exception(std::current_exception());
      }
    }
    return future.get();
  };

  std::mutex pending_mutex;
  std::vector<CampaignRun> pending;
  auto last_flush = Clock::now();
  std::mutex write_mutex;  // one part file at a time (HDF5 is not thread-safe)
  int parts_written = 0;
  auto write_part = [&](std::vector<CampaignRun> runs) {
    if (runs.empty()) return;
    std::sort(runs.begin(), runs.end(),
              [](const CampaignRun& a, const CampaignRun& b) { return a.id < b.id; });
    std::lock_guard<std::mutex> lock(write_mutex);
    ResultsFile f;
    f.provenance = prov;
    CampaignTable t = header;
    t.shard = fmt::format("{}/{}", k, n);
    t.runs = std::move(runs);
    f.campaign = std::move(t);
    write_results_file(dir / fmt::format("{}{:04d}.h5", prefix, next_part), f);
    ++next_part;
    ++parts_written;
  };

  std::vector<SchedulerTask> tasks;
  for (const auto id : todo) {
    tasks.push_back(SchedulerTask{plan.cost(id), exclusive_group(plan.engines[plan.decode(id).engine_index])});
  }
  std::mutex print_mutex;
  std::size_t finished = 0;
  std::size_t diverged = 0;
  const auto t0 = Clock::now();
  run_parallel(tasks, opt.jobs, [&](std::size_t i) {
    const std::int64_t id = todo[i];
    const CampaignPlan::RunRef ref = plan.decode(id);
    const CampaignCasePlan& cp = plan.cases[ref.case_index];
    const std::string& engine_name = plan.engines[ref.engine_index];
    const auto own = plan.assignments(ref);
    std::vector<std::string> all = set_assignments;
    for (const auto& [key, v] : own) all.push_back(key + "=" + v);
    const Overrides o = parse_overrides(all);
    const Case c = load_case(cp.path, o.case_keys);
    const SettingsOverrides engine_settings = engine_settings_for(c, o.engine_keys);
    RunResult r;
    if (opt.isolation == "process") {
      // a process of its own (run_isolation.hpp): a library's abort ends this run only
      IsolatedRun spec;
      spec.case_path = fs::absolute(cp.path);
      spec.case_name = c.name;
      spec.engine = engine_name;
      spec.set = all;
      spec.duration_s = c.duration_s;
      spec.timeout_s = opt.run_timeout_s;
      spec.work_dir = dir;
      spec.target = dir / "campaign";
      r = run_isolated_whole(spec, c, engine_settings);
    } else {
      auto engine = make_engine(engine_name);
      r = run_engine(*engine, c, engine_settings);
    }
    std::shared_ptr<const RunResult> truth;
    if (plan.needs_truth() && r.status == RunStatus::ok) {
      truth = truth_for_run(cp, c, plan.case_assignments(ref));
      if (truth->status != RunStatus::ok) truth.reset();
    }
    CampaignRun row;
    row.id = id;
    row.case_name = c.name;
    row.engine = engine_name;
    row.overrides = assignments_json(own);
    row.physics = physics_json(r.mapping);
    row.status = r.status;
    row.reason = r.status == RunStatus::ok ? "" : r.reason;
    if (r.status == RunStatus::diverged && r.diverged_at_s >= 0.0) {
      row.reason = fmt::format("at t = {:.6g} s: {}", r.diverged_at_s, r.reason);
    }
    row.steps = r.steps;
    row.wall_time_s = r.wall_time_s;
    row.axis_values = plan.axis_values(ref);
    row.metrics = metrics_of(plan, c, r, truth.get());
    if (plan.trace_points > 0) trace_of(plan, cp, r, header.trace_bodies, row);
    std::vector<CampaignRun> flush;
    std::size_t count = 0;
    {
      std::lock_guard<std::mutex> lock(pending_mutex);
      pending.push_back(std::move(row));
      count = ++finished;
      diverged += r.status == RunStatus::diverged;
      if (pending.size() >= static_cast<std::size_t>(opt.checkpoint_runs) ||
          Clock::now() - last_flush >= std::chrono::duration<double>(opt.checkpoint_s)) {
        flush.swap(pending);
        last_flush = Clock::now();
      }
    }
    if (!opt.quiet) {
      std::lock_guard<std::mutex> lock(print_mutex);
      std::fprintf(stderr, "[%zu/%zu] %s %s (%.3f s, %ld steps)\n", count, todo.size(),
                   plan.describe(id).c_str(), run_status_name(r.status), r.wall_time_s, r.steps);
    }
    write_part(std::move(flush));
  });
  write_part(std::move(pending));
  if (!opt.quiet) {
    std::fprintf(stderr, "shard %d/%d: %zu runs in %.1f s (%zu diverged), %d file(s) written to %s\n",
                 k, n, finished, std::chrono::duration<double>(Clock::now() - t0).count(),
                 diverged, parts_written, opt.out.c_str());
  }
  return kExitOk;
}

// ---- merge -----------------------------------------------------------------------

int merge_campaign(const CampaignOptionsCli& opt, int argc, char** argv) {
  const fs::path dir = opt.dir;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    throw InputError(opt.dir, 0, "", "is not a folder; give the --out folder of `campaign run`");
  }
  check_output_file("--out", opt.out);
  const auto parts = part_files(dir);
  if (fs::weakly_canonical(folder_of(opt.out), ec) ==
          fs::weakly_canonical(dir, ec) &&
      fs::path(opt.out).extension() == ".h5") {
    throw InputError("--out", 0, opt.out,
                     "is inside the campaign folder, where a merged file would be read as a "
                     "shard's; write it elsewhere");
  }
  if (parts.empty()) {
    throw InputError(opt.dir, 0, "", "holds no shard files (*.h5 written by `campaign run`)");
  }
  // nor one of them elsewhere, through a link (issue 24)
  check_not_an_input("--out", opt.out, parts);
  const auto t0 = Clock::now();
  std::optional<CampaignTable> merged;
  std::map<std::int64_t, std::string> where;  // run id -> the file it came from
  std::vector<std::string> duplicates;
  std::set<std::string> shard_counts;  // the N of every part's "K/N"
  for (const auto& p : parts) {
    ResultsFile f = read_results_file(p);
    if (!f.campaign || f.campaign->kind != "campaign") {
      throw InputError(p.string(), 0, "/campaign", "has no campaign table: not a shard's file");
    }
    CampaignTable& t = *f.campaign;
    shard_counts.insert(t.shard.substr(t.shard.find('/') + 1));
    if (!merged) {
      merged = t;
      merged->runs.clear();
      merged->shard.clear();
    } else if (t.source_text != merged->source_text) {
      throw InputError(p.string(), 0, "/campaign@source_text",
                       fmt::format("belongs to another campaign than {}", parts.front().string()));
    } else if (const std::string edited = changed_case(t, *merged); !edited.empty()) {
      throw InputError(p.string(), 0, "/campaign/cases/" + edited,
                       fmt::format("case '{}' has another text than in {}: its file was edited "
                                   "between two shards' runs",
                                   edited, parts.front().string()));
    }
    for (auto& r : t.runs) {
      const auto [it, fresh] = where.emplace(r.id, p.filename().string());
      if (!fresh) {
        duplicates.push_back(fmt::format("{} (in {} and {})", describe_run(*merged, r.id),
                                         it->second, p.filename().string()));
        continue;
      }
      merged->runs.push_back(std::move(r));
    }
  }
  // the campaign file and the case files the parts name are inputs too: merge
  // reads them to name the shards of missing runs, and they are the user's
  // (issue 24)
  {
    std::vector<NamedInput> inputs = {{"the campaign file of the parts", merged->source_path}};
    for (const auto& c : merged->cases) inputs.push_back({"case file of the campaign", c.path});
    check_spares_inputs("--out", opt.out, inputs);
  }
  if (!duplicates.empty()) {
    // one line, like every error: the first 20 pairs, "; "-separated
    std::string list;
    for (std::size_t i = 0; i < duplicates.size() && i < 20; ++i) {
      list += (i ? "; " : "") + duplicates[i];
    }
    throw InputError(opt.dir, 0, "",
                     fmt::format("{} run(s) are in two files (two jobs ran the same shard?); "
                                 "remove one of each pair: {}{}",
                                 duplicates.size(), list,
                                 duplicates.size() > 20
                                     ? fmt::format("; ... and {} more", duplicates.size() - 20)
                                     : ""));
  }
  std::vector<std::int64_t> missing;
  for (std::int64_t id = 0; id < merged->planned_runs; ++id) {
    if (where.count(id) == 0) missing.push_back(id);
  }
  if (!missing.empty()) {
    // the shards to resubmit, when the parts agree on N and the campaign file
    // they name is still the one they ran
    std::string shards_hint;
    if (shard_counts.size() == 1 && !merged->source_path.empty()) {
      try {
        const int n = parse_shard("0/" + *shard_counts.begin(), "shard").second;
        const CampaignPlan plan = load_campaign(merged->source_path, opt.cases_dir);
        if (plan.text == merged->source_text) {
          const auto shards = partition(plan, n);
          std::set<int> to_redo;
          for (const auto id : missing) {
            for (int k = 0; k < n; ++k) {
              const auto& s = shards[static_cast<std::size_t>(k)];
              if (std::binary_search(s.begin(), s.end(), id)) to_redo.insert(k);
            }
          }
          std::string ks;
          for (const int k : to_redo) ks += (ks.empty() ? "" : ",") + std::to_string(k);
          shards_hint = fmt::format(" (shard(s) {} of {}: Slurm `sbatch --array={}`)", ks, n, ks);
        }
      } catch (const std::exception&) {
        // no hint: the campaign file moved or changed
      }
    }
    // one line, like every error: the first 20 runs, "; "-separated
    std::string list;
    for (std::size_t i = 0; i < missing.size() && i < 20; ++i) {
      list += (i ? "; " : "") + describe_run(*merged, missing[i]);
    }
    throw InputError(opt.dir, 0, "",
                     fmt::format("{} of {} runs are missing: resubmit their shards{} (`campaign "
                                 "run {} --shard K/N --out {}` runs only what is missing): {}{}",
                                 missing.size(), merged->planned_runs, shards_hint,
                                 merged->source_path.empty() ? "FILE" : merged->source_path,
                                 opt.dir, list,
                                 missing.size() > 20 ? fmt::format("; ... and {} more", missing.size() - 20) : ""));
  }
  std::sort(merged->runs.begin(), merged->runs.end(),
            [](const CampaignRun& a, const CampaignRun& b) { return a.id < b.id; });
  ResultsFile out;
  out.provenance = provenance(argc, argv);
  out.campaign = std::move(merged);
  write_results_file(opt.out, out);
  if (!opt.quiet) {
    std::fprintf(stderr, "wrote %s (%zu runs from %zu files in %.2f s)\n", opt.out.c_str(),
                 out.campaign->runs.size(), parts.size(),
                 std::chrono::duration<double>(Clock::now() - t0).count());
  }
  return kExitOk;
}

}  // namespace

Action add_campaign_command(CLI::App& app, int argc, char** argv) {
  auto opt = std::make_shared<CampaignOptionsCli>();
  auto* cmd = app.add_subcommand(
      "campaign",
      "Parameter studies: every case x engine x point of the axes of a campaign file (TOML), "
      "run as shards (a Slurm job array: scripts/slurm/) and merged into one results file");
  cmd->require_subcommand(1);
  auto* plan = cmd->add_subcommand(
      "plan",
      "Check every axis point against every case and engine (exit 2 naming the axis and the "
      "point refused), then print the campaign's runs and their estimated cost");
  plan->add_option("FILE", opt->file, "Campaign file (TOML)")->required();
  plan->add_option("--shards", opt->shards, "Also show the balance of N shards")->default_val(1);
  plan->add_option("--cases-dir", opt->cases_dir,
                   "Folder of case names (default: $PLANARBENCH_CASES_DIR or the source tree's cases/)");
  plan->add_flag("--quiet,-q", opt->quiet, "No progress or timing on stderr");

  auto* run = cmd->add_subcommand(
      "run",
      "Run shard K of N of the campaign into a folder: one file per checkpoint, written "
      "atomically; runs already in the folder are skipped (a resubmitted shard resumes); exit 0 "
      "even when runs diverge (that is data, recorded per run)");
  run->add_option("FILE", opt->file, "Campaign file (TOML)")->required();
  run->add_option("--out", opt->out, "The campaign's folder (made if missing)")->required();
  run->add_option("--shard", opt->shard,
                  "K/N: this shard (0-based) of N, the runs dealt by estimated cost")
      ->default_val("0/1");
  run->add_option("--jobs,-j", opt->jobs, "Worker threads (Slurm: $SLURM_CPUS_PER_TASK)")
      ->default_val(1);
  run->add_option("--checkpoint-runs", opt->checkpoint_runs,
                  "Write the finished runs to a new file after this many")
      ->default_val(64);
  run->add_option("--checkpoint-seconds", opt->checkpoint_s,
                  "... or after this many seconds, whichever comes first")
      ->default_val(60.0);
  run->add_flag("--quiet,-q", opt->quiet, "No progress on stderr");
  add_isolation_options(*run, opt->isolation, opt->run_timeout_s);
  run->add_option("--cases-dir", opt->cases_dir,
                  "Folder of case names (default: $PLANARBENCH_CASES_DIR or the source tree's cases/)");

  auto* merge = cmd->add_subcommand(
      "merge",
      "Check that every run of the campaign is in the folder exactly once and write them, in "
      "run order, into one results file (exit 2 naming the missing runs otherwise)");
  merge->add_option("DIR", opt->dir, "The campaign's folder")->required();
  merge->add_option("--out", opt->out, "Results file to write (HDF5; written atomically)")
      ->required();
  merge->add_flag("--quiet,-q", opt->quiet, "No summary on stderr");
  merge->add_option("--cases-dir", opt->cases_dir,
                    "Folder of case names, to name the shards of missing runs (default: "
                    "$PLANARBENCH_CASES_DIR or the source tree's cases/)");

  return [opt, argc, argv, plan, run, merge]() -> int {
    if (plan->parsed()) return plan_campaign(*opt);
    if (run->parsed()) return run_campaign(*opt, argc, argv);
    if (merge->parsed()) return merge_campaign(*opt, argc, argv);
    return kExitBadInput;
  };
}

}  // namespace pb::cli
