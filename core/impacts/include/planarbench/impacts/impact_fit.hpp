// Fitting a model's parameters to measured impacts and judging them on
// others (SPEC §8). The objective is fit_objective() of the eps
// (impact_error.hpp) over the impacts fitted to, minimised by NLopt's
// Nelder-Mead simplex on the parameters mapped to the unit cube (a median is
// flat in small steps: a derivative-free simplex suits it; NLopt is Debian's
// libnlopt). Every
// evaluation runs the impacts on `jobs` threads, each with its own
// predictor; results land by index, so the fit is the same at any `jobs`.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "planarbench/impacts/impact_error.hpp"
#include "planarbench/impacts/impact_model.hpp"

namespace pb {

// What a fit minimises over the eps of the impacts fitted to (a failed
// impact's eps is +inf in a median and 1 in a mean):
//   median_plus_mean  the median plus the mean of min(eps, 1): both figures the
//                     study is judged by (issue 34); the median alone leaves the
//                     tail free (rigid_compliant fitted on it: CV median 0.0438,
//                     mean 0.0672). Each impact's share of the mean is capped at
//                     1, what predicting no impact scores, so that one impact a
//                     law cannot represent does not steer it. The default.
//   median            the median alone (the fits before issue 34)
enum class FitObjective { median_plus_mean, median };
[[nodiscard]] double fit_objective(const std::vector<double>& eps, FitObjective objective);
// its words, as a fit file's description and a --work folder's study.json
// state them; parse_fit_objective reads them back (nullopt: no objective's)
[[nodiscard]] const char* fit_objective_words(FitObjective objective);
[[nodiscard]] std::optional<FitObjective> parse_fit_objective(const std::string& words);
// the command line's names: "median+mean", "median"
[[nodiscard]] const char* fit_objective_name(FitObjective objective);

struct FitOptions {
  FitObjective objective = FitObjective::median_plus_mean;
  int max_evaluations = 60;   // objective evaluations per fit
  double initial_step = 0.15; // simplex size on the unit cube
  int jobs = 1;
  // called after each evaluation: the evaluation's number and its objective
  std::function<void(int, double)> progress;
};

// Predictions of the impacts `indices` of `table` with `parameters`: one
// outcome per index, in order.
[[nodiscard]] std::vector<ImpactOutcome> predict_impacts(const ImpactModel& model,
                                                         const ImpactTable& table,
                                                         const std::vector<std::size_t>& indices,
                                                         const std::vector<double>& parameters,
                                                         int jobs);

// every error of each outcome against the measured impact (NaN for a failed one)
[[nodiscard]] std::vector<ImpactScore> impact_scores(const ImpactTable& table,
                                                     const std::vector<std::size_t>& indices,
                                                     const std::vector<ImpactOutcome>& outcomes);
// their eps alone (what the fit's objective reads)
[[nodiscard]] std::vector<double> impact_errors(const ImpactTable& table,
                                                const std::vector<std::size_t>& indices,
                                                const std::vector<ImpactOutcome>& outcomes);

struct FitResult {
  std::vector<double> parameters;  // the best found
  double objective = 0.0;          // its fit_objective over the impacts fitted to
  int evaluations = 0;
  std::string stop;                // NLopt's reason to stop
};

// Fits `model` on the impacts `indices`. A model without parameters returns
// at once with its objective.
[[nodiscard]] FitResult fit_impacts(const ImpactModel& model, const ImpactTable& table,
                                    const std::vector<std::size_t>& indices,
                                    const FitOptions& options);

// k folds of 0..n-1: a seeded shuffle (splitmix64 + Fisher-Yates, the same on
// every platform), dealt round-robin; fold f is the set held out.
[[nodiscard]] std::vector<std::vector<std::size_t>> impact_folds(std::size_t n, int k,
                                                                 std::uint64_t seed);
// every index of 0..n-1 not in `held_out`
[[nodiscard]] std::vector<std::size_t> complement(std::size_t n, const std::vector<std::size_t>& held_out);

}  // namespace pb
