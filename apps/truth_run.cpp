#include "truth_run.hpp"

#include <fmt/format.h>

#include <cmath>

#include "planarbench/engines.hpp"
#include "planarbench/reports/metrics.hpp"
#include "planarbench/runner.hpp"

namespace pb::cli {

namespace {
// `base` with a settings list on top (the truth's own settings win)
SettingsOverrides overrides_of(const std::vector<std::pair<std::string, std::string>>& settings,
                               const SettingsOverrides& base) {
  SettingsOverrides out = base;
  for (const auto& [k, v] : settings) out.set(k, v, SettingSource{"sweep truth", 0});
  return out;
}
}  // namespace

TruthRun run_truth(const Case& c, const TruthPlan& plan, const SettingsOverrides& base) {
  TruthPlan t = plan;
  auto engine = make_engine(t.engine);
  RunResult r = run_engine(*engine, c, overrides_of(t.settings, base));
  // a closed form that does not run falls back to the reference
  if (r.status != RunStatus::ok && t.engine == "analytic") {
    t = reference_truth(fmt::format("the closed form did not run ({}: {}); the reference "
                                    "at exact geometry and tight tolerance instead",
                                    run_status_name(r.status), r.reason));
    engine = make_engine(t.engine);
    r = run_engine(*engine, c, overrides_of(t.settings, base));
  }
  // the reference truth checked against the closed form where it holds
  if (t.engine == "reference" && c.truth == TruthKind::analytic_until_first_contact &&
      r.status == RunStatus::ok) {
    auto analytic = make_engine("analytic");
    const RunResult a = run_engine(*analytic, c, base);
    const double until = a.extra.value("valid_until_s", std::nan(""));
    if (a.status == RunStatus::ok && std::isfinite(until)) {
      for (const auto& m : compare_runs(c, r, a, "analytic", until)) {
        if (m.metric == "position_max") {
          t.note += fmt::format(
              "; up to the first contact (t = {:.6g} s) it is within "
              "{:.3g} m of the closed form",
              until, m.error);
        }
      }
    }
  }
  if (r.status != RunStatus::ok) {
    t.note += fmt::format("; the truth run is {} ({}): no errors", run_status_name(r.status),
                          r.reason);
  }
  return TruthRun{std::move(r), t.label, t.note};
}

}  // namespace pb::cli
