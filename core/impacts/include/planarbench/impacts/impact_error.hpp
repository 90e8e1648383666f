// The error of one predicted impact (SPEC §8), in the energy norm of the
// object: M = diag(m, m, m k^2) over (x', y', theta'),
//   eps = ||v_pred - v_meas||_M / ||v_meas - v_pre||_M,
// so that predicting no impact (v_pred = v_pre) scores 1. Angular
// velocities must share one convention (any: M does not see the sign).
// Beside it (issue 34) the published metric of Fazeli et al. (CoRL 2017,
// "Learning data-efficient rigid-body contact models: case study of planar
// impact", eq. of the error e_F), relative to the post-impact velocity:
//   e_F = ||v_pred - v_meas||_M / ||v_meas||_M,
// and the spin alone, which the M-norm hardly sees (m k^2 w^2 is about 1 %
// of ||dv||_M^2 on the MCube drops):
//   spin_eps = |w_pred - w_meas| / |w_meas - w_pre|.
#pragma once

#include <array>
#include <vector>

#include "planarbench/impacts/impact_object.hpp"

namespace pb {

using Velocities = std::array<double, 3>;  // x' (m/s), y' (m/s), theta' (rad/s)

[[nodiscard]] double impact_eps(const ImpactObject& o, const Velocities& predicted,
                                const Velocities& before, const Velocities& measured);

// every error of one predicted impact
struct ImpactScore {
  double eps = 0.0;
  double e_f = 0.0;
  double spin_eps = 0.0;
};
[[nodiscard]] ImpactScore impact_score(const ImpactObject& o, const Velocities& predicted,
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
