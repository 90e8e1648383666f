#include "planarbench/impacts/impact_error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pb {

namespace {

// ||a - b||_M, M = diag(m, m, m k^2)
double m_distance(const ImpactObject& o, const Velocities& a, const Velocities& b) {
  const std::array<double, 3> weight = {o.mass_kg, o.mass_kg, o.inertia_kgm2()};
  double sum = 0.0;
  for (std::size_t j = 0; j < 3; ++j) sum += weight[j] * (a[j] - b[j]) * (a[j] - b[j]);
  return std::sqrt(sum);
}

}  // namespace

double impact_eps(const ImpactObject& o, const Velocities& predicted, const Velocities& before,
                  const Velocities& measured) {
  return m_distance(o, predicted, measured) / m_distance(o, measured, before);
}

ImpactScore impact_score(const ImpactObject& o, const Velocities& predicted,
                         const Velocities& before, const Velocities& measured) {
  ImpactScore s;
  const double miss = m_distance(o, predicted, measured);
  s.eps = miss / m_distance(o, measured, before);
  s.e_f = miss / m_distance(o, measured, Velocities{0.0, 0.0, 0.0});
  s.spin_eps = std::abs(predicted[2] - measured[2]) / std::abs(measured[2] - before[2]);
  return s;
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
