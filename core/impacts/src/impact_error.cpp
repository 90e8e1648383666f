#include "planarbench/impacts/impact_error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pb {

double impact_eps(const ImpactObject& o, const Velocities& predicted, const Velocities& before,
                  const Velocities& measured) {
  const std::array<double, 3> weight = {o.mass_kg, o.mass_kg, o.inertia_kgm2()};
  double miss = 0.0;
  double change = 0.0;
  for (std::size_t j = 0; j < 3; ++j) {
    const double d = predicted[j] - measured[j];
    const double c = measured[j] - before[j];
    miss += weight[j] * d * d;
    change += weight[j] * c * c;
  }
  return std::sqrt(miss) / std::sqrt(change);
}

double quantile(std::vector<double> values, double q) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  for (double& v : values) {
    if (std::isnan(v)) v = std::numeric_limits<double>::infinity();
  }
  std::sort(values.begin(), values.end());
  const double pos = q * static_cast<double>(values.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(pos));
  const std::size_t hi = std::min(lo + 1, values.size() - 1);
  const double frac = pos - static_cast<double>(lo);
  if (frac == 0.0 || values[lo] == values[hi]) return values[lo];
  return values[lo] + frac * (values[hi] - values[lo]);
}

ErrorSummary summarize(const std::vector<double>& values) {
  ErrorSummary s;
  s.count = static_cast<int>(values.size());
  double sum = 0.0;
  for (double v : values) {
    if (std::isnan(v)) {
      ++s.failed;
    } else {
      sum += v;
    }
  }
  const int finite = s.count - s.failed;
  s.mean = finite > 0 ? sum / finite : std::numeric_limits<double>::quiet_NaN();
  s.median = quantile(values, 0.5);
  s.p90 = quantile(values, 0.9);
  return s;
}

}  // namespace pb
