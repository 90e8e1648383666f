#include "planarbench/impacts/impact_study.hpp"

#include <fmt/format.h>

#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "planarbench/errors.hpp"
#include "planarbench/impacts/impact_identification.hpp"
#include "planarbench/json_integer.hpp"
#include "planarbench/run_result.hpp"

namespace pb {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

FoldFit run_fold_fit(const ImpactModel& model, const ImpactTable& table,
                     const std::vector<std::vector<std::size_t>>& folds, int fold,
                     const FitOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  FoldFit f;
  f.model = model.name();
  f.fold = fold;
  std::vector<std::size_t> every(table.size());
  for (std::size_t i = 0; i < every.size(); ++i) every[i] = i;
  const std::vector<std::size_t> fitted =
      fold == kWholeFile ? every : complement(table.size(), folds.at(static_cast<std::size_t>(fold)));
  // a learned model learns from the fold's training impacts only
  const std::unique_ptr<ImpactModel> trained = model.trained(table, fitted, options);
  const ImpactModel& used = trained ? *trained : model;
  f.fit = fit_impacts(used, table, fitted, options);
  f.predicted = fold == kWholeFile ? every : folds.at(static_cast<std::size_t>(fold));
  f.outcomes = predict_impacts(used, table, f.predicted, f.fit.parameters, options.jobs);
  f.wall_time_s = seconds_since(t0);
  return f;
}

FoldFit score_model(const ImpactModel& model, const ImpactTable& table,
                    const std::vector<double>& parameters, int jobs) {
  const auto t0 = std::chrono::steady_clock::now();
  FoldFit f;
  f.model = model.name();
  f.fold = kScored;
  f.fit.parameters = parameters;
  f.fit.objective = kNaN;
  f.fit.stop = "frozen";
  f.predicted.resize(table.size());
  for (std::size_t i = 0; i < table.size(); ++i) f.predicted[i] = i;
  f.outcomes = predict_impacts(model, table, f.predicted, parameters, jobs);
  f.wall_time_s = seconds_since(t0);
  return f;
}

const std::vector<CampaignMetric>& impact_metrics() {
  static const std::vector<CampaignMetric> metrics = {
      {"drop", "-", "the impact's row in the original file (data.drop)"},
      {"fold", "-", "the cross-validation fold that judged it (-1: every impact, -2: scored)"},
      {"eps", "-", "||v_pred - v_meas||_M / ||v_meas - v_pre||_M, M = diag(m, m, m k^2)"},
      {"e_f", "-", "||v_pred - v_meas||_M / ||v_meas||_M (Fazeli et al., CoRL 2017)"},
      {"spin_eps", "-", "|theta'_pred - theta'_meas| / |theta'_meas - theta'_pre|"},
      {"angle_rad", "rad", "the impact's angle, counter-clockwise"},
      {"pre_vx_mps", "m/s", "measured x' before"},
      {"pre_vy_mps", "m/s", "measured y' before"},
      {"pre_w_radps", "rad/s", "measured theta' before, counter-clockwise"},
      {"meas_vx_mps", "m/s", "measured x' after"},
      {"meas_vy_mps", "m/s", "measured y' after"},
      {"meas_w_radps", "rad/s", "measured theta' after, counter-clockwise"},
      {"pred_vx_mps", "m/s", "predicted x' after"},
      {"pred_vy_mps", "m/s", "predicted y' after"},
      {"pred_w_radps", "rad/s", "predicted theta' after, counter-clockwise"},
      {"contact_s", "s", "first contact onset to the last offset (engines)"},
      {"episodes", "-", "contact episodes of the impact (engines; > 1: chatter)"},
  };
  return metrics;
}

namespace {

struct Judged {
  std::vector<double> eps;
  std::vector<double> e_f;
  std::vector<double> spin_eps;
  std::array<std::vector<double>, 3> abs_error;  // |pred - meas| of x', y', theta'
};

nlohmann::ordered_json summary_json(const Judged& j) {
  auto number = [](double v) { return std::isfinite(v) ? nlohmann::ordered_json(v) : nullptr; };
  const ErrorSummary s = summarize(j.eps);
  nlohmann::ordered_json out;
  out["impacts"] = s.count;
  out["failed"] = s.failed;
  // median, mean and p90 of each relative error (eps first: the fit's objective reads it)
  for (const auto& [name, values] : {std::pair<const char*, const std::vector<double>*>{"eps", &j.eps},
                                     {"e_f", &j.e_f},
                                     {"spin_eps", &j.spin_eps}}) {
    const ErrorSummary e = summarize(*values);
    out[fmt::format("{}_median", name)] = number(e.median);
    out[fmt::format("{}_mean", name)] = number(e.mean);
    out[fmt::format("{}_p90", name)] = number(e.p90);
  }
  // each velocity component's absolute error
  constexpr std::array<const char*, 3> component = {"vx", "vy", "w"};
  constexpr std::array<const char*, 3> unit = {"mps", "mps", "radps"};
  for (std::size_t c = 0; c < 3; ++c) {
    for (const auto& [stat, q] : {std::pair<const char*, double>{"median", 0.5}, {"p90", 0.9}}) {
      out[fmt::format("abs_error_{}_{}_{}", component[c], stat, unit[c])] =
          number(quantile(j.abs_error[c], q));
    }
  }
  return out;
}

nlohmann::ordered_json parameters_json(const ImpactModel& m) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const ImpactParameter& p : m.parameters()) {
    out.push_back({{"name", p.name}, {"unit", p.unit}, {"lower", p.lower}, {"upper", p.upper},
                   {"start", p.start}, {"log_scale", p.log_scale}, {"doc", p.doc}});
  }
  return out;
}

// each fitted parameter's spread over the fold fits (impact_identification.hpp);
// empty without a whole-file fit and two fold fits
nlohmann::ordered_json identification_json(const ImpactModel& m, const std::vector<FoldFit>& fits) {
  std::vector<double> whole;
  std::vector<std::vector<double>> folds;
  for (const FoldFit& f : fits) {
    if (f.model != m.name()) continue;
    if (f.fold == kWholeFile) whole = f.fit.parameters;
    if (f.fold >= 0) folds.push_back(f.fit.parameters);
  }
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  if (whole.empty() || folds.size() < 2) return out;
  for (const ParameterSpread& p : parameter_spread(m.parameters(), whole, folds)) {
    out.push_back({{"name", p.name},
                   {"unit", p.unit},
                   {"log_scale", p.log_scale},
                   {"whole", p.whole},
                   {"fold_min", p.fold_min},
                   {"fold_max", p.fold_max},
                   {"folds", p.folds},
                   {"jackknife_se", p.jackknife_se},
                   {"half_width", p.half_width},
                   {"relative_to", p.relative_to},
                   {"identified", p.identified},
                   {"whole_outside_folds", p.whole_outside_folds}});
  }
  return out;
}

}  // namespace

CampaignTable impact_study_table(const ImpactStudyHeader& header,
                                 const std::vector<const ImpactModel*>& models,
                                 const ImpactTable& table, const std::vector<FoldFit>& fits) {
  CampaignTable t;
  t.kind = header.kind;
  t.source_path = header.data->path;
  t.metrics = impact_metrics();
  t.shard = "";
  const ConventionCheck& cc = *header.convention;
  nlohmann::ordered_json d;
  d["data"] = {{"path", header.data->path},
               {"sha256", header.data->sha256},
               {"impacts", header.data->size()},
               {"stored_models", !header.data->models.empty()}};
  d["object"] = {{"semi_axis_a_m", header.object.semi_axis_a_m},
                 {"semi_axis_b_m", header.object.semi_axis_b_m},
                 {"mass_kg", header.object.mass_kg},
                 {"gyration_radius_m", header.object.gyration_radius_m}};
  nlohmann::ordered_json conv = nlohmann::ordered_json::array();
  for (const ConventionFit& f : cc.fits) {
    conv.push_back({{"angle_sign", f.convention.angle_sign},
                    {"rate_sign", f.convention.rate_sign},
                    {"label", f.label()},
                    {"slope", f.slope},
                    {"intercept", f.intercept},
                    {"correlation", f.correlation}});
  }
  d["convention"] = {{"fits", conv},
                     {"chosen", cc.chosen},
                     {"rule", fmt::format("highest r; refused below r {} or outside slope 1 +- {}",
                                          kMinCorrelation, kSlopeBand)}};
  d["folds"] = header.folds;
  // a fitted parameter is identified when the folds' jackknife +-2 SE lies
  // within this share of its value (impact_identification.hpp)
  d["identified_half_width"] = kIdentifiedHalfWidth;
  d["seed"] = header.seed;
  if (header.kind == "impacts_fit") d["objective"] = fit_objective_words(header.objective);
  if (!header.parameters_from.empty()) d["parameters_from"] = header.parameters_from;
  if (header.kind == "impacts_score") d["in_sample"] = header.in_sample;
  d["command_line"] = header.command_line;

  nlohmann::ordered_json model_list = nlohmann::ordered_json::array();
  std::int64_t id = 0;
  double total_wall = 0.0;
  for (const ImpactModel* m : models) {
    nlohmann::ordered_json mj;
    mj["name"] = m->name();
    mj["kind"] = m->kind();
    mj["description"] = m->description();
    mj["version"] = m->version();
    mj["parameters"] = parameters_json(*m);
    nlohmann::ordered_json fold_list = nlohmann::ordered_json::array();
    Judged judged;
    Judged in_sample;
    double wall = 0.0;
    for (const FoldFit& f : fits) {
      if (f.model != m->name()) continue;
      wall += f.wall_time_s;
      const std::vector<ImpactScore> score = impact_scores(table, f.predicted, f.outcomes);
      Judged& into = f.fold == kWholeFile ? in_sample : judged;
      for (std::size_t k = 0; k < f.predicted.size(); ++k) {
        const std::size_t i = f.predicted[k];
        const ImpactOutcome& o = f.outcomes[k];
        into.eps.push_back(score[k].eps);
        into.e_f.push_back(score[k].e_f);
        into.spin_eps.push_back(score[k].spin_eps);
        const auto pred = o.after.velocities();
        const auto meas = table.after[i].velocities();
        for (std::size_t c = 0; c < 3; ++c) {
          into.abs_error[c].push_back(o.ok() ? std::abs(pred[c] - meas[c]) : kNaN);
        }
        if (f.fold == kWholeFile) continue;  // the rows are the judged predictions
        CampaignRun row;
        row.id = id++;
        row.case_name = "impact";
        row.engine = m->name();
        row.series = f.fold != kScored ? "cross_validated" : header.in_sample ? "in_sample" : "scored";
        row.overrides = "{}";
        row.status = o.ok() ? RunStatus::ok : RunStatus::diverged;
        row.reason = o.failure;
        row.steps = o.steps;
        const auto pre = table.before[i].velocities();
        const double nan = kNaN;
        row.metrics = {table.drop.empty() ? nan : table.drop[i],
                       static_cast<double>(f.fold),
                       score[k].eps,
                       score[k].e_f,
                       score[k].spin_eps,
                       table.before[i].angle_rad,
                       pre[0], pre[1], pre[2],
                       meas[0], meas[1], meas[2],
                       o.ok() ? pred[0] : nan, o.ok() ? pred[1] : nan, o.ok() ? pred[2] : nan,
                       o.ok() && m->kind() == "engine" ? o.contact_s : nan,
                       o.ok() && m->kind() == "engine" ? static_cast<double>(o.episodes) : nan};
        t.runs.push_back(std::move(row));
      }
      fold_list.push_back(fit_json(f));
    }
    mj["fits"] = fold_list;
    if (auto spread = identification_json(*m, fits); !spread.empty()) mj["identification"] = spread;
    if (!judged.eps.empty()) {
      mj[header.kind == "impacts_score" ? "scored" : "cross_validated"] = summary_json(judged);
    }
    if (!in_sample.eps.empty()) mj["in_sample"] = summary_json(in_sample);
    mj["wall_time_s"] = wall;
    total_wall += wall;
    model_list.push_back(mj);
    t.engines.push_back(m->name());
  }
  d["models"] = model_list;
  d["wall_time_s"] = total_wall;
  t.description = d;
  t.planned_runs = static_cast<std::int64_t>(t.runs.size());
  return t;
}

FrozenParameters frozen_parameters(const CampaignTable& fit, const std::string& path) {
  if (fit.kind != "impacts_fit") {
    throw InputError(path, 0, "/campaign kind",
                     fmt::format("is '{}': a fit file of `planarbench impacts fit` (kind "
                                 "impacts_fit) is expected",
                                 fit.kind));
  }
  FrozenParameters out;
  const auto& d = fit.description;
  try {
    out.data_sha256 = d.at("data").at("sha256").get<std::string>();
    out.data_path = d.at("data").at("path").get<std::string>();
    const std::optional<FitObjective> o = stated_fit_objective(d);
    if (!o) {
      throw InputError(path, 0, "/campaign description objective",
                       fmt::format("is '{}': no objective of `impacts fit`",
                                   d.at("objective").get<std::string>()));
    }
    out.objective = *o;
    for (const auto& m : d.at("models")) {
      for (const auto& f : m.at("fits")) {
        if (json_integer<int>(f.at("fold"), "fold") != kWholeFile) continue;
        out.models.emplace_back(m.at("name").get<std::string>(),
                                f.at("parameters").get<std::vector<double>>());
      }
    }
  } catch (const nlohmann::json::exception& e) {
    // a description that is not a fit's (issue 35: raw library text before)
    throw InputError(path, 0, "/campaign description",
                     fmt::format("is not the description of a fit of `planarbench impacts fit` "
                                 "({})",
                                 e.what()));
  } catch (const InputError&) {
    throw;
  } catch (const std::runtime_error& e) {  // an integer not as written (json_integer.hpp)
    throw InputError(path, 0, "/campaign description models", e.what());
  }
  if (out.models.empty()) {
    throw InputError(path, 0, "/campaign description models",
                     "has no whole-file fit: a file of `planarbench impacts fit` or `impacts "
                     "merge` is expected");
  }
  return out;
}

}  // namespace pb
