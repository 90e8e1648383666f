// The cost of one contact force evaluation (pb::contact_force_n, paper eqs. 1-7)
// for each law the cases use, over a sweep of penetrations and penetration
// rates: force_laws/<law>.
//
// The laws are read from the case files, so that the bench evaluates exactly
// what the engines do: Kelvin-Voigt from falling_ball (eq. 1), Kelvin-Voigt
// with the 0.1 m cubic damping ramp from falling_ball_paper, and
// Lankarani-Nikravesh from dual_pendulum (eq. 7, K of eqs. 3-4). No case uses
// plain Hertz; it is benchmarked with dual_pendulum's K and exponent (F = K
// delta^n), the Lankarani-Nikravesh law without its damping factor.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <memory>
#include <utility>
#include <string>
#include <variant>
#include <vector>

#include "deferred_registration.hpp"
#include "planarbench/case.hpp"
#include "planarbench/case_loader.hpp"
#include "planarbench/contact_force.hpp"
#include "planarbench/errors.hpp"

namespace pb::bench {

namespace {

// points of the sweep along penetration and along penetration rate: 64 x 64
// evaluations per iteration, enough to amortise the loop and the timer
constexpr int kSweepPoints = 64;

struct LawSweep {
  ContactLaw law;
  std::vector<double> delta_m;          // penetrations, m
  std::vector<double> delta_dot_mps;    // penetration rates, m/s
  double approach_speed_mps = 1.0;      // m/s, latched onset speed (Lankarani-Nikravesh)
};

// n points evenly spaced from lo to hi
std::vector<double> linspace(double lo, double hi, int n) {
  std::vector<double> v(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) v[static_cast<std::size_t>(i)] = lo + (hi - lo) * i / (n - 1);
  return v;
}

// Sweep: penetrations from -10 % of depth_m (no contact, the early return)
// to depth_m, rates from -speed to +speed (separating and approaching, so
// that the F >= 0 clamp is exercised).
LawSweep sweep(const ContactLaw& law, double depth_m, double speed_mps) {
  return LawSweep{law, linspace(-0.1 * depth_m, depth_m, kSweepPoints),
                  linspace(-speed_mps, speed_mps, kSweepPoints), speed_mps};
}

void evaluate_sweep(benchmark::State& state, const LawSweep& s) {
  for (auto _ : state) {
    double sum_n = 0.0;  // N, kept so the evaluations cannot be optimised away
    for (const double d : s.delta_m) {
      for (const double v : s.delta_dot_mps) sum_n += contact_force_n(s.law, d, v, s.approach_speed_mps);
    }
    benchmark::DoNotOptimize(sum_n);
  }
  const double per_iteration = static_cast<double>(s.delta_m.size() * s.delta_dot_mps.size());
  state.counters["evaluations_per_s"] =
      benchmark::Counter(per_iteration, benchmark::Counter::kIsIterationInvariantRate);
}

// the law of the case's first contact pair
ContactLaw first_law(const std::string& case_name) {
  const Case c = load_case(std::filesystem::path(PB_CASES_DIR) / (case_name + ".toml"));
  if (c.contacts.empty()) throw InputError(c.source_path, 0, "contacts", "the case has no contact pair");
  return c.contacts.front().law;
}

void register_force_law_benchmarks() {
  // depths and speeds span each case's contacts: the falling ball penetrates
  // ~3 cm at ~3.8 m/s (Table 1: K = 1e4 N/m, 1 kg); the steel dual pendulum
  // penetrates ~10 um at ~1 m/s (K ~ 1e10 N/m^1.5)
  const ContactLaw kv = first_law("falling_ball");
  const ContactLaw kv_ramp = first_law("falling_ball_paper");
  const ContactLaw ln = first_law("dual_pendulum");
  const auto& lnp = std::get<LankaraniNikravesh>(ln);
  const ContactLaw hertz = Hertz{lnp.stiffness, lnp.exponent, lnp.material};

  const std::vector<std::pair<std::string, LawSweep>> sweeps = {
      {"kelvin_voigt", sweep(kv, 0.05, 4.0)},
      {"kelvin_voigt_ramp", sweep(kv_ramp, 0.05, 4.0)},
      {"hertz", sweep(hertz, 2e-5, 1.0)},
      {"lankarani_nikravesh", sweep(ln, 2e-5, 1.0)},
  };
  for (const auto& [name, s] : sweeps) {
    auto shared = std::make_shared<const LawSweep>(s);
    benchmark::RegisterBenchmark(("force_laws/" + name).c_str(),
                                 [shared](benchmark::State& state) { evaluate_sweep(state, *shared); })
        ->Unit(benchmark::kMicrosecond);
  }
}

const DeferredRegistration kRegistration(register_force_law_benchmarks);

}  // namespace

}  // namespace pb::bench
