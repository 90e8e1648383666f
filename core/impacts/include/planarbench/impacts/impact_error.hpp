// The error of one predicted impact (SPEC §8), in the energy norm of the
// object: M = diag(m, m, m k^2) over (x', y', theta'),
//   eps = ||v_pred - v_meas||_M / ||v_meas - v_pre||_M,
// so that predicting no impact (v_pred = v_pre) scores 1. Angular
// velocities must share one convention (any: M does not see the sign).
#pragma once

#include <array>
#include <vector>

#include "planarbench/impacts/impact_object.hpp"

namespace pb {

using Velocities = std::array<double, 3>;  // x' (m/s), y' (m/s), theta' (rad/s)

[[nodiscard]] double impact_eps(const ImpactObject& o, const Velocities& predicted,
                                const Velocities& before, const Velocities& measured);

// The summary of a set of errors: NaN entries (a run that failed) count as
// worse than any number, so a model that fails cannot look better for it.
struct ErrorSummary {
  int count = 0;
  int failed = 0;          // NaN entries
  double median = 0.0;
  double mean = 0.0;       // over the finite entries (NaN when every entry failed)
  double p90 = 0.0;        // 90th percentile, linear interpolation between order statistics
};
[[nodiscard]] ErrorSummary summarize(const std::vector<double>& values);

// q-quantile (0..1) with NaN sorted above every number (+inf then)
[[nodiscard]] double quantile(std::vector<double> values, double q);

}  // namespace pb
