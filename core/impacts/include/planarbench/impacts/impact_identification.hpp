// What the data identify (issue 34, item 4): each fitted parameter's spread
// over the cross-validation's fold fits. The k fold fits, each leaving out
// one of k disjoint groups of impacts, are the grouped (delete-a-group)
// jackknife, whose variance estimate of the estimate is
//   SE^2 = (k - 1) / k sum_i (p_i - mean)^2
// (Efron, "The Jackknife, the Bootstrap and Other Resampling Plans", SIAM
// 1982, ch. 2-3; Kott, "The delete-a-group jackknife", J. Official
// Statistics 17, 2001), taken on
// log p for a parameter fitted on a log scale. A parameter counts as
// identified when its 95 % interval, +-2 SE, lies within +-20 % of the
// whole-file value (kIdentifiedHalfWidth): a property the data pin down,
// not a direction along which the objective is flat.
#pragma once

#include <string>
#include <vector>

#include "planarbench/impacts/impact_model.hpp"

namespace pb {

inline constexpr double kIdentifiedHalfWidth = 0.2;

struct ParameterSpread {
  std::string name;
  std::string unit;
  bool log_scale = false;
  double whole = 0.0;         // the whole-file fit's value
  double fold_min = 0.0;      // over the fold fits
  double fold_max = 0.0;
  int folds = 0;
  double jackknife_se = 0.0;  // of the value, or of its natural log (log_scale)
  // relative half-width of the +-2 SE interval: 2 SE / |whole|, or
  // exp(2 SE) - 1 on a log scale; for a value at zero (|whole| below 1e-6
  // of the search range: a slope or a coefficient the data set to 0, where a
  // relative width means nothing) 2 SE / (upper - lower), relative_to "range"
  double half_width = 0.0;
  std::string relative_to = "value";  // "value", "log" or "range"
  bool identified = false;    // half_width <= kIdentifiedHalfWidth
  bool whole_outside_folds = false;  // the whole-file optimum outside every fold's range
};

// one entry per parameter the fit searches (lower < upper; a fixed one is
// no parameter); `folds` the fold fits' parameter vectors (>= 2 of them)
[[nodiscard]] std::vector<ParameterSpread> parameter_spread(
    const std::vector<ImpactParameter>& specs, const std::vector<double>& whole,
    const std::vector<std::vector<double>>& folds);

}  // namespace pb
