// planarbench impacts: measured impacts (SPEC §8). `fit` identifies each
// engine's contact parameters on a file of impacts (k-fold cross-validated,
// then on the whole file), `score` judges frozen parameters on another file,
// `merge` assembles a fit run as shards (scripts/slurm/submit_impacts.sh).
#include <fmt/format.h>

#include <cmath>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>

#include "campaign_plan.hpp"
#include "campaign_shards.hpp"
#include "cli_common.hpp"
#include "commands.hpp"
#include "impact_models.hpp"
#include "impact_tasks.hpp"
#include "planarbench/did_you_mean.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/impacts/impact_data.hpp"
#include "planarbench/impacts/impact_identification.hpp"
#include "planarbench/output_file.hpp"
#include "planarbench/results_file.hpp"

namespace pb::cli {

namespace fs = std::filesystem;

namespace {

struct ImpactsOptions {
  std::string data;
  std::string engine = "all";
  std::string out;
  std::string work;
  std::string shard;
  std::string params;
  std::string training_data;  // score: a learned model's training file (default: the fit's)
  int folds = 5;
  std::uint64_t seed = 23;
  int max_evaluations = 40;
  std::string objective = "median+mean";
  int jobs = 1;
  bool quiet = false;
  ResultsProvenance provenance;
};

// the data, checked: read, its convention measured and printed
// how many parameters the model named `name` fits (0 when none is named so)
std::size_t parameter_count(const std::vector<std::unique_ptr<ImpactModel>>& models,
                            const std::string& name) {
  for (const auto& m : models) {
    if (m->name() == name) return m->parameters().size();
  }
  return 0;
}

bool has_model(const std::vector<std::unique_ptr<ImpactModel>>& models, const std::string& name) {
  return std::any_of(models.begin(), models.end(), [&](const auto& m) { return m->name() == name; });
}

struct LoadedData {
  ImpactSet set;
  ConventionCheck convention;
  ImpactTable table;
};

LoadedData load_data(const ImpactsOptions& opt, const std::string& option = "--data") {
  LoadedData d;
  d.set = read_impacts(opt.data, option);
  const ImpactObject object;
  d.convention = check_convention(d.set, object);
  d.table = make_impact_table(d.set, object, d.convention.best().convention);
  if (!opt.quiet) {
    std::fprintf(stderr, "impacts: %s: %zu impacts (sha256 %.12s)\n", opt.data.c_str(), d.set.size(),
                 d.set.sha256.c_str());
    for (std::size_t k = 0; k < d.convention.fits.size(); ++k) {
      const ConventionFit& f = d.convention.fits[k];
      std::fprintf(stderr, "  angular momentum about the contact point, %-44s slope %6.3f  r %6.3f%s\n",
                   (f.label() + ":").c_str(), f.slope, f.correlation,
                   static_cast<int>(k) == d.convention.chosen ? "  <- the convention" : "");
    }
  }
  return d;
}

// the --engine spelling of a list of engine models ("none" when empty)
std::string engine_list(const std::vector<std::string>& engines) {
  return engines.empty() ? std::string("none") : fmt::format("{}", fmt::join(engines, ","));
}

std::vector<const ImpactModel*> pointers(const std::vector<std::unique_ptr<ImpactModel>>& models) {
  std::vector<const ImpactModel*> out;
  for (const auto& m : models) out.push_back(m.get());
  return out;
}

const ImpactModel& model_named(const std::vector<std::unique_ptr<ImpactModel>>& models,
                               const std::string& name) {
  for (const auto& m : models) {
    if (m->name() == name) return *m;
  }
  throw InputError("--engine", 0, name, "is not among the models of this study");
}

std::string parameters_text(const ImpactModel& m, const std::vector<double>& values) {
  std::string s;
  const auto specs = m.parameters();
  for (std::size_t j = 0; j < specs.size() && j < values.size(); ++j) {
    s += fmt::format("{}{} {:.4g}", j ? ", " : "", specs[j].name, values[j]);
  }
  return s.empty() ? "-" : s;
}

// --objective, checked where it is read (run_fit)
FitObjective objective_of(const ImpactsOptions& opt) {
  const std::optional<FitObjective> o = parse_fit_objective(opt.objective);
  if (!o) {
    throw InputError("--objective", 0, opt.objective,
                     "is no objective: median+mean (the default) or median");
  }
  return *o;
}

nlohmann::ordered_json study_json(const ImpactsOptions& opt, const LoadedData& d,
                                  const std::vector<std::unique_ptr<ImpactModel>>& models) {
  nlohmann::ordered_json s;
  s["data_sha256"] = d.set.sha256;
  s["impacts"] = d.set.size();
  s["folds"] = opt.folds;
  s["seed"] = opt.seed;
  s["max_evaluations"] = opt.max_evaluations;
  s["objective"] = fit_objective_words(objective_of(opt));
  nlohmann::ordered_json names = nlohmann::ordered_json::array();
  for (const auto& m : models) names.push_back(m->name());
  s["models"] = names;
  return s;
}

void print_summary(const CampaignTable& t, const char* section) {
  // eps (relative to the velocity change; the fit's objective) and e_F
  // (relative to the post-impact velocity, the published metric), and the
  // spin's own relative error
  std::printf("%-30s %-52s %8s %8s %8s %8s %8s %8s %6s %9s\n", "model",
              "parameters (whole-file fit)", "eps med", "eps mean", "eps p90", "e_F med",
              "e_F mean", "spin med", "failed", "wall s");
  for (const auto& m : t.description.at("models")) {
    std::string params = "-";
    for (const auto& f : m.at("fits")) {
      if (f.at("fold").get<int>() != kWholeFile && f.at("fold").get<int>() != kScored) continue;
      params.clear();
      const auto& names = m.at("parameters");
      const auto values = f.at("parameters").get<std::vector<double>>();
      for (std::size_t j = 0; j < values.size(); ++j) {
        params += fmt::format("{}{} {:.4g}", j ? ", " : "", names.at(j).at("name").get<std::string>(),
                              values[j]);
      }
    }
    const auto& s = m.at(section);
    auto num = [&s](const char* key) {
      const auto v = s.find(key);
      return v == s.end() || v->is_null() ? std::string("n/a") : fmt::format("{:.4f}", v->get<double>());
    };
    std::printf("%-30s %-52s %8s %8s %8s %8s %8s %8s %6d %9.1f\n",
                m.at("name").get<std::string>().c_str(), params.empty() ? "-" : params.c_str(),
                num("eps_median").c_str(), num("eps_mean").c_str(), num("eps_p90").c_str(),
                num("e_f_median").c_str(), num("e_f_mean").c_str(), num("spin_eps_median").c_str(),
                s.at("failed").get<int>(), m.at("wall_time_s").get<double>());
  }
  // what the data do not identify (impact_identification.hpp)
  std::string weak;
  for (const auto& m : t.description.at("models")) {
    if (!m.contains("identification")) continue;
    for (const auto& p : m.at("identification")) {
      if (p.at("identified").get<bool>()) continue;
      const double w = p.at("half_width").get<double>();
      weak += fmt::format("{}  {} {} ({}: folds {:.4g} .. {:.4g})", weak.empty() ? "" : "\n",
                          m.at("name").get<std::string>(), p.at("name").get<std::string>(),
                          p.at("log_scale").get<bool>() ? fmt::format("x/ {:.2f}", 1.0 + w)
                          : p.value("relative_to", "value") == "range"
                              ? fmt::format("+-{:.0f} % of the range", 100.0 * w)
                              : fmt::format("+-{:.0f} %", 100.0 * w),
                          p.at("fold_min").get<double>(), p.at("fold_max").get<double>());
    }
  }
  if (!weak.empty()) {
    std::printf("not identified by the data (the folds' jackknife 95 %% interval wider than +-%.0f %%, "
                "x/ %.1f on a log scale):\n%s\n",
                100.0 * kIdentifiedHalfWidth, 1.0 + kIdentifiedHalfWidth, weak.c_str());
  }
}

// A --work folder's own files, which fit and merge read and write:
// WORK/study.json and WORK/tasks/*.json (impact_tasks.hpp).
bool in_work_folder(const fs::path& work, const fs::path& p) {
  std::error_code ec, ec2;
  const fs::path w = fs::weakly_canonical(work, ec);
  const fs::path c = fs::weakly_canonical(p, ec2);
  if (ec || ec2) return false;
  return c == w / "study.json" || (c.parent_path() == w / "tasks" && c.extension() == ".json");
}

// --data and --out against each other and against the --work folder's files
// (issue 24): a task or the study written over the data, the fit file
// written over the study or a task
void check_work_spares_inputs(const ImpactsOptions& opt) {
  if (!opt.out.empty()) check_not_an_input("--out", opt.out, {opt.data});
  if (opt.work.empty()) return;
  const std::string allowed = fmt::format(
      "a file of the --work folder '{}' (its study.json and tasks/*.json); give another file",
      opt.work);
  if (in_work_folder(opt.work, opt.data)) {
    throw InputError("--data", 0, opt.data,
                     "names a file this command also reads or writes: " + allowed);
  }
  if (!opt.out.empty() && in_work_folder(opt.work, opt.out)) {
    throw InputError("--out", 0, opt.out,
                     "names a file this command also reads or writes: " + allowed);
  }
}

// prints the table's summary (unless quiet) and writes it to --out
int write_study(const ImpactsOptions& opt, CampaignTable table, const char* section) {
  if (!opt.quiet) print_summary(table, section);
  ResultsFile r;
  r.provenance = opt.provenance;
  r.campaign = std::move(table);
  write_results_file(opt.out, r);
  if (!opt.quiet) std::fprintf(stderr, "wrote %s\n", opt.out.c_str());
  return kExitOk;
}

// the engine models among a study's model names
std::vector<std::string> engines_among(const std::vector<std::string>& names) {
  std::vector<std::string> engines;
  const auto& known = impact_engine_names();
  for (const std::string& n : names) {
    if (std::find(known.begin(), known.end(), n) != known.end()) engines.push_back(n);
  }
  return engines;
}

// runs `tasks`, skipping those already in `work` (when given)
std::vector<FoldFit> run_tasks(const ImpactsOptions& opt, const LoadedData& d,
                               const std::vector<std::unique_ptr<ImpactModel>>& models,
                               const std::vector<ImpactTask>& tasks, const fs::path& work) {
  const auto folds = impact_folds(d.table.size(), opt.folds, opt.seed);
  std::vector<FoldFit> out;
  std::size_t k = 0;
  for (const ImpactTask& t : tasks) {
    ++k;
    if (!work.empty() && task_done(work, t)) {
      if (!opt.quiet) std::fprintf(stderr, "[%zu/%zu] %s: already done\n", k, tasks.size(), t.label().c_str());
      continue;
    }
    const ImpactModel& m = model_named(models, t.model);
    FitOptions fo;
    fo.max_evaluations = opt.max_evaluations;
    fo.objective = objective_of(opt);
    fo.jobs = opt.jobs;
    if (!opt.quiet && isatty(STDERR_FILENO) != 0) {  // a log gets one line per task
      fo.progress = [&](int evaluation, double objective) {
        std::fprintf(stderr, "\r[%zu/%zu] %s: evaluation %d, objective %.4f   ", k, tasks.size(),
                     t.label().c_str(), evaluation, objective);
      };
    }
    FoldFit f = run_fold_fit(m, d.table, folds, t.fold, fo);
    if (!opt.quiet) {
      std::fprintf(stderr, "%s[%zu/%zu] %s: %s, objective (%s eps) %.4f after %d evaluations (%.1f s)\n",
                   fo.progress ? "\r" : "", k, tasks.size(), t.label().c_str(),
                   parameters_text(m, f.fit.parameters).c_str(), fit_objective_name(fo.objective),
                   f.fit.objective, f.fit.evaluations, f.wall_time_s);
    }
    if (!work.empty()) write_task(work, t, f);
    out.push_back(std::move(f));
  }
  return out;
}

CampaignTable assemble_fit(const ImpactsOptions& opt, const LoadedData& d,
                           const std::vector<std::unique_ptr<ImpactModel>>& models,
                           const std::vector<FoldFit>& fits) {
  ImpactStudyHeader h;
  h.kind = "impacts_fit";
  h.data = &d.set;
  h.convention = &d.convention;
  h.folds = opt.folds;
  h.seed = opt.seed;
  h.objective = objective_of(opt);
  h.command_line = opt.provenance.command_line;
  return impact_study_table(h, pointers(models), d.table, fits);
}

int run_fit(const ImpactsOptions& opt) {
  check_jobs(opt.jobs);
  if (opt.folds < 2 || opt.folds > 20) {
    throw InputError("--folds", 0, std::to_string(opt.folds), "must be in [2, 20]");
  }
  if (opt.max_evaluations < 1 || opt.max_evaluations > 10000) {
    throw InputError("--max-evaluations", 0, std::to_string(opt.max_evaluations), "must be in [1, 10000]");
  }
  (void)objective_of(opt);  // refused before any work
  if (opt.shard.empty() == opt.out.empty()) {
    throw InputError("impacts fit", 0, "--out, --shard",
                     "give --out FILE (the whole fit here) or --shard K/N with --work DIR (one "
                     "shard; `impacts merge DIR` writes the file)");
  }
  if (!opt.shard.empty() && opt.work.empty()) {
    throw InputError("--shard", 0, opt.shard, "needs --work DIR, the folder the shards share");
  }
  if (!opt.out.empty()) check_output_file("--out", opt.out);
  check_work_spares_inputs(opt);
  const LoadedData d = load_data(opt);
  const auto models = impact_models(opt.engine, !d.set.models.empty());
  std::vector<std::string> names;
  for (const auto& m : models) names.push_back(m->name());
  std::vector<ImpactTask> tasks = impact_tasks(names, opt.folds);
  fs::path work = opt.work;
  if (!work.empty()) prepare_work_folder(work, study_json(opt, d, models));
  if (!opt.shard.empty()) {
    const auto [k, n] = parse_shard(opt.shard, "--shard");
    tasks = shard_tasks(tasks, k, n);
    (void)run_tasks(opt, d, models, tasks, work);
    if (!opt.quiet) std::fprintf(stderr, "shard %d/%d: %zu tasks in %s\n", k, n, tasks.size(), opt.work.c_str());
    return kExitOk;
  }
  std::vector<FoldFit> fits = run_tasks(opt, d, models, tasks, work);
  if (!work.empty()) {  // some tasks came from the folder
    fits.clear();
    for (const ImpactTask& t : tasks) {
      fits.push_back(read_task(work, t, d.table.size(), parameter_count(models, t.model)));
    }
  }
  return write_study(opt, assemble_fit(opt, d, models, fits), "cross_validated");
}

int run_merge(const ImpactsOptions& opt) {
  check_output_file("--out", opt.out);
  check_work_spares_inputs(opt);
  const StudyPins pins = read_study_pins(opt.work);  // study.json is input (issue 35)
  const LoadedData d = load_data(opt);
  ImpactsOptions o = opt;
  o.folds = pins.folds;
  o.seed = pins.seed;
  o.objective = fit_objective_name(pins.objective);
  const std::vector<std::string>& names = pins.models;
  const std::string& fitted_sha256 = pins.data_sha256;
  if (fitted_sha256 != d.set.sha256) {
    throw InputError(opt.data, 0, "--data",
                     fmt::format("has sha256 {}, but the shards in {} fitted a file of sha256 {}",
                                 d.set.sha256, opt.work, fitted_sha256));
  }
  const auto models = impact_models(engine_list(engines_among(names)), !d.set.models.empty());
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (!has_model(models, names[k])) {
      std::vector<std::string> known;
      for (const auto& m : models) known.push_back(m->name());
      throw InputError((fs::path(opt.work) / "study.json").string(), 0, fmt::format("models[{}]", k),
                       fmt::format("'{}' is no model of `impacts fit` on this file: one of {}",
                                   names[k], fmt::join(known, ", ")));
    }
  }
  std::vector<FoldFit> fits;
  std::vector<std::string> missing;
  for (const ImpactTask& t : impact_tasks(names, o.folds)) {
    if (!task_done(opt.work, t)) {
      missing.push_back(t.label());
      continue;
    }
    fits.push_back(read_task(opt.work, t, d.table.size(), parameter_count(models, t.model)));
  }
  if (!missing.empty()) {
    throw InputError(opt.work, 0, "tasks",
                     fmt::format("{} of the study's tasks have not finished: {} (run their shards "
                                 "again: finished tasks are kept)",
                                 missing.size(), fmt::join(missing, ", ")));
  }
  return write_study(opt, assemble_fit(o, d, models, fits), "cross_validated");
}

int run_score(const ImpactsOptions& opt) {
  check_jobs(opt.jobs);
  check_output_file("--out", opt.out);
  check_not_an_input("--out", opt.out, {opt.data, opt.params, opt.training_data});
  const ResultsFile fit_file = read_results_file(opt.params);
  if (!fit_file.campaign) {
    throw InputError(opt.params, 0, "/campaign", "missing: a fit file of `planarbench impacts fit` is expected");
  }
  const FrozenParameters frozen = frozen_parameters(*fit_file.campaign, opt.params);
  const LoadedData d = load_data(opt);
  if (!opt.quiet && frozen.data_sha256 == d.set.sha256) {
    std::fprintf(stderr,
                 "impacts: note: %s is the file the parameters were fitted to: these scores are "
                 "in-sample (labelled so), not predictions\n",
                 opt.data.c_str());
  }
  std::vector<std::string> names;
  for (const auto& [name, values] : frozen.models) names.push_back(name);
  auto all = impact_models(engine_list(engines_among(names)), !d.set.models.empty());
  // every model of the fit file is scored, once (issue 49: a renamed one was
  // silently skipped, one listed twice accepted with no word of which counts)
  for (std::size_t k = 0; k < names.size(); ++k) {
    for (std::size_t j = 0; j < k; ++j) {
      if (names[j] == names[k]) {
        throw InputError(opt.params, 0, "/campaign models",
                         fmt::format("lists model '{}' twice (rows {} and {}): a fit file holds "
                                     "each model's parameters once",
                                     names[k], j, k));
      }
    }
    if (!has_model(all, names[k])) {
      std::vector<std::string> known;
      for (const auto& m : all) known.push_back(m->name());
      throw InputError(opt.params, 0, "/campaign models",
                       fmt::format("'{}' is no model `impacts score` knows{}; one of {}", names[k],
                                   did_you_mean(names[k], known), fmt::join(known, ", ")));
    }
  }
  // A learned model's frozen form is the file it learned from (named and
  // hashed in the fit file) and the fit's training, which is deterministic:
  // it is trained again on that whole file, as the fit's fold "all" was.
  // Read once, when a learned model is scored; without it the model's rows
  // fail, saying why, and the others are scored.
  std::optional<LoadedData> training;
  std::string training_problem;
  auto training_table = [&]() -> const ImpactTable* {
    if (frozen.data_sha256 == d.set.sha256) return &d.table;
    if (!training && training_problem.empty()) {
      ImpactsOptions t = opt;
      t.data = opt.training_data.empty() ? frozen.data_path : opt.training_data;
      t.quiet = true;
      try {
        LoadedData loaded = load_data(t, opt.training_data.empty() ? "the fit's data_path" : "--training-data");
        if (loaded.set.sha256 != frozen.data_sha256) {
          training_problem = fmt::format("{} has sha256 {}, the fit's training file {}", t.data,
                                         loaded.set.sha256.substr(0, 16),
                                         frozen.data_sha256.substr(0, 16));
        } else {
          training = std::move(loaded);
        }
      } catch (const std::exception& e) {
        training_problem = e.what();
      }
    }
    return training ? &training->table : nullptr;
  };
  std::vector<std::unique_ptr<ImpactModel>> models;
  std::vector<FoldFit> fits;
  for (auto& m : all) {
    const std::vector<double>* values = nullptr;
    for (const auto& [name, v] : frozen.models) {
      if (name == m->name()) values = &v;
    }
    if (values == nullptr && m->kind() != "stored") continue;  // not in the fit file
    const std::vector<double> none;
    if (values != nullptr && values->size() != m->parameters().size()) {
      throw InputError(opt.params, 0, m->name(),
                       fmt::format("has {} parameters, the model takes {}", values->size(),
                                   m->parameters().size()));
    }
    // frozen parameters are input (issue 35): each within the bounds the fit
    // searches, before an engine is built with them (an ODE stiffness of
    // 5e-324 aborted inside the library)
    if (values != nullptr) {
      const auto params = m->parameters();
      for (std::size_t k = 0; k < params.size(); ++k) {
        const double v = (*values)[k];
        if (!(std::isfinite(v) && v >= params[k].lower && v <= params[k].upper)) {
          throw InputError(opt.params, 0, fmt::format("{} {}", m->name(), params[k].name),
                           fmt::format("is {}: the model's {} lies in [{}, {}] {} (the bounds "
                                       "its fit searches)",
                                       v, params[k].name, params[k].lower, params[k].upper,
                                       params[k].unit));
        }
      }
    }
    std::unique_ptr<ImpactModel> trained;
    if (m->kind() == "learned") {
      if (const ImpactTable* t = training_table()) {
        std::vector<std::size_t> every(t->size());
        for (std::size_t i = 0; i < every.size(); ++i) every[i] = i;
        FitOptions fo;
        fo.objective = frozen.objective;
        fo.jobs = opt.jobs;
        trained = m->trained(*t, every, fo);
      } else if (!opt.quiet) {
        std::fprintf(stderr, "impacts: %s is not scored: its training file is not available (%s; "
                     "give it with --training-data)\n", m->name().c_str(), training_problem.c_str());
      }
    }
    FoldFit f = score_model(trained ? *trained : *m, d.table, values ? *values : none, opt.jobs);
    if (!opt.quiet) std::fprintf(stderr, "%s: scored %zu impacts (%.1f s)\n", m->name().c_str(), f.outcomes.size(), f.wall_time_s);
    fits.push_back(std::move(f));
    models.push_back(std::move(m));
  }
  ImpactStudyHeader h;
  h.kind = "impacts_score";
  h.data = &d.set;
  h.convention = &d.convention;
  h.command_line = opt.provenance.command_line;
  h.in_sample = frozen.data_sha256 == d.set.sha256;
  h.parameters_from = {{"path", opt.params},
                       {"data_path", frozen.data_path},
                       {"data_sha256", frozen.data_sha256}};
  return write_study(opt, impact_study_table(h, pointers(models), d.table, fits), "scored");
}

}  // namespace

Action add_impacts_command(CLI::App& app, int argc, char** argv) {
  auto opt = std::make_shared<ImpactsOptions>();
  opt->provenance = provenance(argc, argv);
  auto* cmd = app.add_subcommand(
      "impacts",
      "Measured impacts (a MAT v5 file of planar impacts, e.g. the MCube ellipse drops): fit each "
      "engine's contact parameters (cross-validated), score frozen parameters on another file");
  cmd->require_subcommand(1);
  auto data_option = [&](CLI::App* c) {
    c->add_option("--data", opt->data,
                  "MAT v5 file of impacts: data.states_i, data.states_f, data.n, data.d, data.drop "
                  "(and optionally v_models), as ../shared/data/mcube/README.md describes")
        ->required();
    c->add_flag("--quiet,-q", opt->quiet, "No progress and no summary");
  };

  auto* fit = cmd->add_subcommand(
      "fit",
      "Fit every engine's contact parameters (Kelvin-Voigt K, damping ratio, Coulomb mu) and the "
      "rigid baselines by NLopt's simplex (--objective: the median plus the mean error): per model one fit per "
      "cross-validation fold (judged on the fold held out) and one on the whole file (the "
      "parameters `impacts score` uses)");
  data_option(fit);
  fit->add_option("--engine", opt->engine,
                  "reference, reference_exact, reference_ln, reference_hc, mujoco, box2d, ode, all, none, or a comma-separated "
                  "list (the baselines and the file's stored predictions are always included)")
      ->default_val("all");
  fit->add_option("--out", opt->out, "Fit file to write (HDF5, written atomically)");
  fit->add_option("--folds", opt->folds, "Cross-validation folds, in [2, 20]")->default_val(5);
  check_unsigned_64_text(
      fit->add_option("--seed", opt->seed, "Seed of the fold split, in [0, 2^64 - 1]")->default_val(23));
  fit->add_option("--max-evaluations", opt->max_evaluations,
                  "Objective evaluations per fit (each runs every impact fitted to); a closed-form "
                  "law takes at least its own number (rigid_compliant: 2000, about 0.5 ms each)")
      ->default_val(40);
  fit->add_option("--objective", opt->objective,
                  "What each fit minimises over the eps of its impacts: median+mean (the median "
                  "plus the mean of min(eps, 1)) or median (the fits before issue 34)")
      ->default_val("median+mean");
  fit->add_option("--jobs,-j", opt->jobs, "Worker threads (Slurm: $SLURM_CPUS_PER_TASK)")->default_val(1);
  fit->add_option("--shard", opt->shard,
                  "Run only shard K of N (0-based) of the fit's tasks into --work; `impacts merge` "
                  "assembles the file");
  fit->add_option("--work", opt->work,
                  "Folder of finished tasks (resumable: a task already there is not run again)");

  auto* merge = cmd->add_subcommand("merge", "Assemble the fit file of a fit run as shards");
  merge->add_option("DIR", opt->work, "The shards' --work folder")->required()->check(CLI::ExistingDirectory);
  data_option(merge);
  merge->add_option("--out", opt->out, "Fit file to write (HDF5, written atomically)")->required();

  auto* score = cmd->add_subcommand(
      "score", "Score the parameters of a fit file, frozen, on a file of impacts (no refitting)");
  data_option(score);
  score->add_option("--params", opt->params, "Fit file written by `impacts fit` or `impacts merge`")
      ->required()
      ->check(CLI::ExistingFile);
  score->add_option("--out", opt->out, "Score file to write (HDF5, written atomically)")->required();
  score->add_option("--training-data", opt->training_data,
                    "The fit's training file, from which a learned model (learned_residual) is "
                    "trained again (default: the path the fit file names; its sha256 must match)");
  score->add_option("--jobs,-j", opt->jobs, "Worker threads")->default_val(1);

  return [opt, fit, merge, score]() {
    if (fit->parsed()) return run_fit(*opt);
    if (merge->parsed()) return run_merge(*opt);
    if (score->parsed()) return run_score(*opt);
    return static_cast<int>(kExitBadInput);
  };
}

}  // namespace pb::cli
