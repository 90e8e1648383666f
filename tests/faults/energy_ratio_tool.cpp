// energy_ratio_tool RESULTS.h5 ...: for every run of each results file, the
// largest ratio of kinetic energy to the energy the case has made available
// (planarbench/energy_budget.hpp) over its output samples, where it occurs,
// and the two energies there. The measurements behind kRunawayEnergyFactor
// (README.md) come from it; it is a tool, not a test.
#include <cstdio>
#include <exception>

#include "planarbench/case_loader.hpp"
#include "planarbench/energy_budget.hpp"
#include "planarbench/results_file.hpp"

namespace {

// the largest KE / budget of one run, from its trajectories and its contacts at t = 0
void report_run(const pb::Case& c, const pb::RunResult& r) {
  if (r.bodies.empty() || r.bodies[0].time_s.empty()) return;
  // every body at its case state; moving ones are overwritten from the trajectories
  std::vector<pb::BodyState> states(c.bodies.size());
  for (std::size_t i = 0; i < c.bodies.size(); ++i) states[i].position_m = c.bodies[i].position_m;
  std::vector<std::size_t> index;
  for (const auto& tr : r.bodies) index.push_back(static_cast<std::size_t>(c.body_index(tr.name)));
  const auto fill = [&](std::size_t k) {
    for (std::size_t j = 0; j < r.bodies.size(); ++j) {
      pb::BodyState& s = states[index[j]];
      s.position_m = r.bodies[j].position_m[k];
      s.velocity_mps = r.bodies[j].velocity_mps[k];
      s.angular_velocity_radps = r.bodies[j].angular_velocity_radps[k];
    }
  };
  const std::vector<double>& time = r.bodies[0].time_s;
  std::vector<pb::ContactSample> initial;
  for (const auto& row : r.contacts) {
    if (row.time_s == time[0]) initial.push_back(row.sample);
  }
  pb::EnergyBudget budget(c);
  fill(0);
  budget.start(states, initial);
  double worst = 0.0, t_worst = 0.0, ke = 0.0, available = 0.0;
  for (std::size_t k = 1; k < time.size(); ++k) {
    fill(k);
    if (budget.update(states, time[k] - time[0]) <= worst) continue;
    worst = budget.ratio();
    t_worst = time[k];
    ke = budget.kinetic_now_j();
    available = budget.most_available_j();
  }
  std::printf("%-20s %-10s %-11s max KE/budget %.9f at t = %.4f s (KE %.6g J, budget %.6g J)\n",
              c.name.c_str(), r.engine_name.c_str(), pb::run_status_name(r.status), worst, t_worst,
              ke, available);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: energy_ratio_tool RESULTS.h5 ...\n");
    return 2;
  }
  try {
    for (int a = 1; a < argc; ++a) {
      const pb::ResultsFile f = pb::read_results_file(argv[a]);
      for (const auto& cr : f.cases) {
        const pb::Case c = pb::case_as_run(cr);
        for (const auto& r : cr.runs) report_run(c, r);
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "energy_ratio_tool: %s\n", e.what());
    return 2;
  }
  return 0;
}
