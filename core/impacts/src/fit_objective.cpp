#include "planarbench/impacts/fit_objective.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "planarbench/impacts/impact_error.hpp"

namespace pb {

double fit_objective(const std::vector<double>& eps, FitObjective objective) {
  if (eps.empty()) return std::numeric_limits<double>::quiet_NaN();
  const double median = quantile(eps, 0.5);
  if (objective == FitObjective::median) return median;
  double sum = 0.0;
  for (double e : eps) sum += std::isnan(e) ? 1.0 : std::min(e, 1.0);
  return median + sum / static_cast<double>(eps.size());
}

const char* fit_objective_words(FitObjective objective) {
  return objective == FitObjective::median
             ? "the median eps"
             : "the median eps plus the mean of min(eps, 1) (a failed impact: +inf and 1)";
}

const char* fit_objective_name(FitObjective objective) {
  return objective == FitObjective::median ? "median" : "median+mean";
}

std::optional<FitObjective> parse_fit_objective(const std::string& words) {
  for (FitObjective o : {FitObjective::median_plus_mean, FitObjective::median}) {
    if (words == fit_objective_words(o) || words == fit_objective_name(o)) return o;
  }
  return std::nullopt;
}

}  // namespace pb
