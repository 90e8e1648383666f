#include "planarbench/impacts/impact_identification.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pb {

std::vector<ParameterSpread> parameter_spread(const std::vector<ImpactParameter>& specs,
                                              const std::vector<double>& whole,
                                              const std::vector<std::vector<double>>& folds) {
  if (folds.size() < 2) throw std::invalid_argument("parameter_spread: needs at least 2 fold fits");
  std::vector<ParameterSpread> out;
  for (std::size_t j = 0; j < specs.size() && j < whole.size(); ++j) {
    const ImpactParameter& p = specs[j];
    if (!(p.lower < p.upper)) continue;  // fixed: not fitted
    ParameterSpread s;
    s.name = p.name;
    s.unit = p.unit;
    s.log_scale = p.log_scale;
    s.whole = whole[j];
    s.folds = static_cast<int>(folds.size());
    s.fold_min = s.fold_max = folds.front().at(j);
    double mean = 0.0;
    for (const auto& f : folds) {
      const double v = f.at(j);
      s.fold_min = std::min(s.fold_min, v);
      s.fold_max = std::max(s.fold_max, v);
      mean += p.log_scale ? std::log(v) : v;
    }
    const double k = static_cast<double>(folds.size());
    mean /= k;
    double sum = 0.0;
    for (const auto& f : folds) {
      const double d = (p.log_scale ? std::log(f.at(j)) : f.at(j)) - mean;
      sum += d * d;
    }
    s.jackknife_se = std::sqrt((k - 1.0) / k * sum);
    const double range = p.upper - p.lower;
    if (p.log_scale) {
      s.half_width = std::expm1(2.0 * s.jackknife_se);
      s.relative_to = "log";
    } else if (std::abs(s.whole) <= 1e-6 * range) {
      s.half_width = 2.0 * s.jackknife_se / range;
      s.relative_to = "range";
    } else {
      s.half_width = 2.0 * s.jackknife_se / std::abs(s.whole);
    }
    s.identified = s.half_width <= kIdentifiedHalfWidth;
    s.whole_outside_folds = s.whole < s.fold_min || s.whole > s.fold_max;
    out.push_back(s);
  }
  return out;
}

}  // namespace pb
