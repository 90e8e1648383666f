// Fitting a model's parameters to measured impacts and judging them on
// others (SPEC §8). The objective is fit_objective() of the eps
// (impact_error.hpp) over the impacts fitted to, minimised by NLopt's
// Nelder-Mead simplex on the parameters mapped to the unit cube (a median is
// flat in small steps: a derivative-free simplex suits it; NLopt is Debian's
// libnlopt). Every evaluation runs the impacts on `jobs` threads, each with
// its own predictor; results land by index, so the fit is the same at any
// `jobs`.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "planarbench/impacts/fit_objective.hpp"
#include "planarbench/impacts/impact_error.hpp"
#include "planarbench/impacts/impact_model.hpp"

namespace pb {

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
