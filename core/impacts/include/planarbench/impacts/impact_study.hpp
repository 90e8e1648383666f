// A study of measured impacts (SPEC §8): per model, k fits each on every
// impact but one fold and judged on that fold (cross-validation: no impact
// is judged by parameters fitted to it), one fit on every impact (the
// parameters a fit file gives `impacts score`), or a scoring of frozen
// parameters on another file. Each fit is one unit of work (a shard's task),
// stored as JSON until the study is assembled into a results file's table.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "planarbench/campaign_table.hpp"
#include "planarbench/impacts/impact_convention.hpp"
#include "planarbench/impacts/impact_fit.hpp"
#include "planarbench/impacts/impact_model.hpp"

namespace pb {

// fold = kWholeFile: fitted on every impact; kScored: frozen parameters scored
inline constexpr int kWholeFile = -1;
inline constexpr int kScored = -2;

// One fit (or scoring) of one model and what it predicts.
struct FoldFit {
  std::string model;
  int fold = kWholeFile;
  FitResult fit;
  double wall_time_s = 0.0;               // s, the fit and its predictions
  std::vector<std::size_t> predicted;     // impact indices: the held-out fold, or every impact
  std::vector<ImpactOutcome> outcomes;    // one per predicted impact
};

// Fits `model` on every impact outside folds[fold] (every impact for
// kWholeFile) and predicts folds[fold] (every impact for kWholeFile).
[[nodiscard]] FoldFit run_fold_fit(const ImpactModel& model, const ImpactTable& table,
                                   const std::vector<std::vector<std::size_t>>& folds, int fold,
                                   const FitOptions& options);
// Predicts every impact of `table` with frozen `parameters`.
[[nodiscard]] FoldFit score_model(const ImpactModel& model, const ImpactTable& table,
                                  const std::vector<double>& parameters, int jobs);

// a task file's JSON (fold_fit_json.cpp), and the fit alone (fold,
// parameters, objective, evaluations, stop, wall time): a description's
[[nodiscard]] nlohmann::ordered_json fold_fit_json(const FoldFit& f);
[[nodiscard]] nlohmann::ordered_json fit_json(const FoldFit& f);
[[nodiscard]] FoldFit fold_fit_from_json(const nlohmann::json& j);

// What the table of a study records besides its fits.
struct ImpactStudyHeader {
  std::string kind;             // "impacts_fit" or "impacts_score"
  const ImpactSet* data = nullptr;
  const ConventionCheck* convention = nullptr;
  ImpactObject object;
  int folds = 0;                // cross-validation folds (0: none)
  std::uint64_t seed = 0;       // of the fold split
  FitObjective objective = FitObjective::median_plus_mean;  // fit: what it minimised
  nlohmann::ordered_json parameters_from = nlohmann::ordered_json::object();  // score: the fit file
  // score: the file scored is the one fitted to (its rows are "in_sample",
  // never shown as predictions; SPEC §8)
  bool in_sample = false;
  std::string command_line;
};

// The study as a results file's table (campaign_table.hpp): one row per
// (model, judged impact) and the whole study in `description`: the data (path,
// sha256, impacts), the convention check, every model with its parameters,
// each fit and the error summary of the judged predictions.
[[nodiscard]] CampaignTable impact_study_table(const ImpactStudyHeader& header,
                                               const std::vector<const ImpactModel*>& models,
                                               const ImpactTable& table,
                                               const std::vector<FoldFit>& fits);

// The fitted parameters of a fit file's table: model -> values (the
// whole-file fit); InputError naming `path` when the table is no fit.
struct FrozenParameters {
  std::string data_sha256;  // of the file fitted to
  std::string data_path;
  FitObjective objective = FitObjective::median_plus_mean;  // a learned model is trained on it
  std::vector<std::pair<std::string, std::vector<double>>> models;
};
[[nodiscard]] FrozenParameters frozen_parameters(const CampaignTable& fit, const std::string& path);

// the metric columns of a study's rows, in order
[[nodiscard]] const std::vector<CampaignMetric>& impact_metrics();

}  // namespace pb
