#include "sweep_error.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include "planarbench/reports/metrics.hpp"

namespace pb::cli {

namespace {

// grid indices k > 0 at which every body of `run` is at t_k
std::vector<bool> on_grid(const Case& c, const RunResult& run) {
  std::size_t n = 0;
  for (const auto& b : run.bodies) n = std::max(n, b.time_s.size());
  std::vector<bool> keep(n, !run.bodies.empty());
  const double tol = kSameTimeFraction * c.output_interval_s;
  for (const auto& b : run.bodies) {
    for (std::size_t k = 0; k < n; ++k) {
      keep[k] = keep[k] && k < b.time_s.size() &&
                std::abs(b.time_s[k] - c.output_time(static_cast<int>(k))) <= tol;
    }
  }
  return keep;
}

// `truth` with only the samples whose time is a kept grid time
RunResult restricted(const Case& c, const RunResult& truth, const std::vector<bool>& keep) {
  RunResult out = truth;
  const double tol = kSameTimeFraction * c.output_interval_s;
  for (auto& b : out.bodies) {
    BodyTrajectory kept;
    kept.name = b.name;
    for (std::size_t i = 0; i < b.time_s.size(); ++i) {
      // the truth's sample i is at grid index k = round(t / interval)
      const double k_real = b.time_s[i] / c.output_interval_s;
      const auto k = static_cast<std::size_t>(std::llround(std::max(0.0, k_real)));
      if (k >= keep.size() || !keep[k]) continue;
      if (std::abs(b.time_s[i] - c.output_time(static_cast<int>(k))) > tol) continue;
      kept.time_s.push_back(b.time_s[i]);
      kept.position_m.push_back(b.position_m[i]);
      kept.angle_rad.push_back(b.angle_rad[i]);
      kept.velocity_mps.push_back(b.velocity_mps[i]);
      kept.angular_velocity_radps.push_back(b.angular_velocity_radps[i]);
    }
    b = std::move(kept);
  }
  return out;
}

}  // namespace

std::size_t samples_on_grid(const Case& c, const RunResult& run) {
  const auto keep = on_grid(c, run);
  std::size_t count = 0;
  for (std::size_t k = 1; k < keep.size(); ++k) count += keep[k] ? 1 : 0;
  return count;
}

double sweep_position_error(const Case& c, const RunResult& run, const RunResult& truth) {
  if (run.status != RunStatus::ok || truth.status != RunStatus::ok) return std::nan("");
  const double inf = std::numeric_limits<double>::infinity();
  auto position_max = [&](const RunResult& baseline) {
    for (const auto& m : compare_runs(c, run, baseline, "truth", inf)) {
      if (m.metric == "position_max") return m.error;
    }
    return std::nan("");
  };
  // at the engine's own samples; every sample, interpolated, if it has none on the grid
  if (samples_on_grid(c, run) == 0) return position_max(truth);
  return position_max(restricted(c, truth, on_grid(c, run)));
}

}  // namespace pb::cli
