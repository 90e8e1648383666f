// What a fit of measured impacts minimises (issue 34) and the words that
// name it in a fit file and a --work folder. Apart from impact_fit.hpp so
// that what reads those files (apps/impact_tasks.cpp, its fuzz target) needs
// no optimiser.
#pragma once

#include <optional>
#include <string>
#include <vector>

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

// The objective a fit file's description or a --work folder's study.json (a
// JSON object) states: one written before issue 34 states none and minimised
// the median; nullopt when its words name no objective (the caller names
// file and field).
template <class Json>
[[nodiscard]] std::optional<FitObjective> stated_fit_objective(const Json& j) {
  if (!j.contains("objective")) return FitObjective::median;
  return parse_fit_objective(j.at("objective").template get<std::string>());
}

}  // namespace pb
