// What `planarbench sweep` runs: the ladders of step sizes and tolerances,
// the series each engine is swept along, the settings of each rung, and the
// truth each case's errors are measured against. No running here.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/settings.hpp"

namespace pb::cli {

// s, the default step ladder of every fixed-step series, coarse to fine
[[nodiscard]] const std::vector<double>& default_dt_ladder();
// the reference's rk45 relative tolerances, loose to tight
[[nodiscard]] const std::vector<double>& default_rtol_ladder();
// --quick without --dt-ladder: two rungs a decade apart, s
[[nodiscard]] const std::vector<double>& quick_dt_ladder();
// --quick: the two loosest tolerances
[[nodiscard]] const std::vector<double>& quick_rtol_ladder();

// "a,b,c" as distinct positive finite numbers sorted coarse to fine (largest
// first); InputError naming `option` for an empty item, a non-number, a value
// <= 0 or a repeated value.
[[nodiscard]] std::vector<double> parse_ladder(const std::string& text, const std::string& option);

// The two largest rungs of a ladder (coarse to fine), or the ladder itself
// when it has fewer.
[[nodiscard]] std::vector<double> two_coarsest(const std::vector<double>& ladder);

// one engine (or one integrator of the reference) along one knob
struct SeriesPlan {
  std::string name;       // "mujoco", "reference_rk45", "reference_fixed"
  std::string engine;     // engine name
  std::string knob;       // "dt" or "rtol"
  std::string knob_key;   // the prefixed setting key: "mujoco.dt", "reference.rtol"
  std::string knob_unit;  // "s" or "1"
  std::vector<std::pair<std::string, std::string>> fixed;  // settings every rung shares
  std::vector<double> values;                              // the rungs, coarse to fine
};

// The series of an engine: the reference gives two (rk45 over `rtols`, and
// classic RK4 at fixed step over `dts`), mujoco, box2d and ode one each (their
// time step over `dts`). InputError for the analytic engine (it is the truth:
// there is nothing to sweep) or an unknown name.
[[nodiscard]] std::vector<SeriesPlan> series_for(const std::string& engine,
                                                 const std::vector<double>& dts,
                                                 const std::vector<double>& rtols);

// The fixed settings as a JSON object text, e.g. {"reference.integrator":"fixed"}.
[[nodiscard]] std::string fixed_settings_json(const SeriesPlan& s);

// The engine settings of one rung: `base` (the case's [settings] and --set),
// then the series' fixed settings, then the knob at `value`. For rtol the
// absolute tolerance follows it: atol = rtol * kAtolPerRtol.
// the engine keys a rung sets, KEY and VALUE as `--set` would give them
[[nodiscard]] std::vector<std::pair<std::string, std::string>> rung_assignments(const SeriesPlan& s,
                                                                                double value);
[[nodiscard]] SettingsOverrides rung_overrides(const SettingsOverrides& base, const SeriesPlan& s,
                                               double value);

// atol / rtol on the rk45 ladder, in the state's units (m, rad, m/s, rad/s):
// the rtol term governs for states of order 0.01 and up, and at rtol 1e-10
// this is the reference's default atol 1e-12
inline constexpr double kAtolPerRtol = 1e-2;

// InputError when --set gives a key the sweep sets itself (dt, rtol, atol,
// integrator, prefixed or not), naming the key and --dt-ladder.
void reject_swept_keys(const SettingsOverrides& given);

// What a case's errors are measured against.
struct TruthPlan {
  std::string engine;                                         // "analytic" or "reference"
  std::vector<std::pair<std::string, std::string>> settings;  // engine overrides
  std::string label;                                          // for the file's `truth` attribute
  std::string note;                                           // why, and how far it holds
};

// The closed form for a case with truth = analytic (valid over the whole
// run); otherwise (analytic_until_first_contact, none) the reference at exact
// geometry, rk45 rtol 1e-10, atol 1e-12 (SPEC §3: the truth after first contact).
[[nodiscard]] TruthPlan truth_for(const Case& c);
// the reference truth, whatever the case says (also the fallback when the
// closed form does not run)
[[nodiscard]] TruthPlan reference_truth(const std::string& why);

// the median of the values (the mean of the two middle ones for an even count)
[[nodiscard]] double median(std::vector<double> values);

// A coarse cost model for scheduling the longest rungs first: only the order
// matters. Fixed-step series cost steps = duration / dt, the reference more
// per step; rk45 steps grow like rtol^(-1/5) (a 5th-order method).
[[nodiscard]] double rung_cost(const SeriesPlan& s, double value, double duration_s);

// The ladder's stopping rule (issue 12). A series runs its rungs from the
// coarsest to the finest and stops once its last three rungs that ran ok
// (the newest among them) agree within kFlatTolerance: each step's change is
// at most a tenth of the smaller error. The knob shrank by 2 to 100 times per
// rung (every shipped ladder) and the error did not move: it sits on a floor
// (the geometry's resolution, the truth's own error, float rounding) that
// the finer rungs would only measure again, at a higher cost. One flat step
// is not enough: pre-asymptotic ladders rise, pause and fall again (ODE on
// dual_pendulum: 0.051, 0.12, 0.14, 0.14, 0.094, 0.026, 0.0069 m). On the
// landed sweep of every case and engine the rule keeps 263 of 352 rungs, and
// the smallest error of each series is within 0.9 % of the whole ladder's.
// Diverged and unsupported rungs never stop a ladder (a too coarse step is
// data). `errors`: the rungs run so far, NaN for a rung not ok.
inline constexpr double kFlatTolerance = 0.1;
[[nodiscard]] bool ladder_is_flat(const std::vector<double>& errors);
[[nodiscard]] const char* ladder_stop_rule();

}  // namespace pb::cli
