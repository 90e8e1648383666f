#include "sweep_plan.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <nlohmann/json.hpp>

#include "planarbench/errors.hpp"

namespace pb::cli {

namespace {

// a number as settings text: the shortest decimal that reads back to the same double
std::string text_of(double v) {
  return fmt::format("{}", v);
}

const SettingSource kSweepSource{"--dt-ladder", 0};

}  // namespace

const std::vector<double>& default_dt_ladder() {
  // issue 6's ladder: 1, 2 and 5 times each power of ten from 1 ms (ten
  // times every engine's default step) down to 10 us (the reference's
  // fixed-step default); each divides the 1e-4 s output grid or is a
  // multiple of it, so the engines land on grid times
  static const std::vector<double> v = {1e-3, 5e-4, 2e-4, 1e-4, 5e-5, 2e-5, 1e-5};
  return v;
}

const std::vector<double>& default_rtol_ladder() {
  static const std::vector<double> v = {1e-4, 1e-6, 1e-8, 1e-10};
  return v;
}

const std::vector<double>& quick_dt_ladder() {
  // 1e-4 s is the default step of mujoco, box2d and ode: the quick sweep
  // still has each engine's default rung
  static const std::vector<double> v = {1e-3, 1e-4};
  return v;
}

const std::vector<double>& quick_rtol_ladder() {
  static const std::vector<double> v = {1e-4, 1e-6};
  return v;
}

std::vector<double> parse_ladder(const std::string& text, const std::string& option) {
  std::vector<double> out;
  std::size_t start = 0;
  while (true) {
    const auto comma = text.find(',', start);
    const std::string item =
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    // strtod accepts "1e-4", rejects trailing garbage here by the end check
    errno = 0;
    char* end = nullptr;
    const double v = item.empty() ? 0.0 : std::strtod(item.c_str(), &end);
    if (item.empty() || end != item.c_str() + item.size() || errno != 0 || !std::isfinite(v)) {
      throw InputError(option, 0, item,
                       fmt::format("'{}' is not a number; expected a comma-separated list of "
                                   "positive numbers, e.g. 1e-3,1e-4,1e-5",
                                   item));
    }
    if (v <= 0.0) {
      throw InputError(option, 0, item, "every value must be > 0");
    }
    if (std::find(out.begin(), out.end(), v) != out.end()) {
      throw InputError(option, 0, item, "value given twice");
    }
    out.push_back(v);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  std::sort(out.begin(), out.end(), std::greater<>());
  return out;
}

std::vector<double> two_coarsest(const std::vector<double>& ladder) {
  std::vector<double> v = ladder;
  std::sort(v.begin(), v.end(), std::greater<>());
  if (v.size() > 2) v.resize(2);
  return v;
}

std::vector<SeriesPlan> series_for(const std::string& engine, const std::vector<double>& dts,
                                   const std::vector<double>& rtols) {
  if (engine == "analytic") {
    throw InputError("--engine", 0, "analytic",
                     "the analytic engine is the truth and has no step to sweep; choose "
                     "reference, mujoco, box2d, ode or all");
  }
  if (engine == "reference") {
    SeriesPlan rk45{"reference_rk45",
                    "reference",
                    "rtol",
                    "reference.rtol",
                    "1",
                    {{"reference.integrator", "rk45"}},
                    rtols};
    SeriesPlan fixed{"reference_fixed",
                     "reference",
                     "dt",
                     "reference.dt",
                     "s",
                     {{"reference.integrator", "fixed"}},
                     dts};
    return {rk45, fixed};
  }
  if (engine == "mujoco" || engine == "box2d" || engine == "ode") {
    return {SeriesPlan{engine, engine, "dt", engine + ".dt", "s", {}, dts}};
  }
  throw InputError("--engine", 0, engine,
                   "unknown engine; allowed: reference, mujoco, box2d, ode, all");
}

std::string fixed_settings_json(const SeriesPlan& s) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const auto& [k, v] : s.fixed) j[k] = v;
  if (s.knob == "rtol") j["reference.atol"] = fmt::format("rtol * {}", kAtolPerRtol);
  return j.dump();
}

std::vector<std::pair<std::string, std::string>> rung_assignments(const SeriesPlan& s, double value) {
  std::vector<std::pair<std::string, std::string>> out(s.fixed.begin(), s.fixed.end());
  out.emplace_back(s.knob_key, text_of(value));
  if (s.knob == "rtol") out.emplace_back("reference.atol", text_of(value * kAtolPerRtol));
  return out;
}

SettingsOverrides rung_overrides(const SettingsOverrides& base, const SeriesPlan& s, double value) {
  SettingsOverrides out = base;
  for (const auto& [k, v] : rung_assignments(s, value)) out.set(k, v, kSweepSource);
  return out;
}

void reject_swept_keys(const SettingsOverrides& given) {
  static const std::vector<std::string> swept = {
      "dt",           "rtol",           "atol",           "integrator",
      "reference.dt", "reference.rtol", "reference.atol", "reference.integrator",
      "mujoco.dt",    "box2d.dt",       "ode.dt"};
  for (const auto& [key, value] : given.all()) {
    if (std::find(swept.begin(), swept.end(), key) != swept.end()) {
      throw InputError("--set", 0, key,
                       "the sweep sets this itself on every rung (step sizes: --dt-ladder; the "
                       "reference's rk45 tolerances: rtol 1e-4 to 1e-10 with atol = rtol * 1e-2); "
                       "leave it out");
    }
  }
}

TruthPlan reference_truth(const std::string& why) {
  TruthPlan t;
  t.engine = "reference";
  t.settings = {{"reference.integrator", "rk45"},
                {"reference.rtol", "1e-10"},
                {"reference.atol", "1e-12"},
                {"reference.geometry", "exact"}};
  t.label = "reference (rk45, rtol 1e-10, atol 1e-12, geometry exact)";
  t.note = why;
  return t;
}

TruthPlan truth_for(const Case& c) {
  switch (c.truth) {
    case TruthKind::analytic: {
      TruthPlan t;
      t.engine = "analytic";
      t.label = "analytic";
      t.note = "closed form valid over the whole run, SPEC §3";
      return t;
    }
    case TruthKind::analytic_until_first_contact:
      return reference_truth(
          "the closed form holds only until the first contact (its valid_until_s); through and "
          "after the impact the truth is the reference at exact geometry and tight tolerance "
          "(SPEC §3)");
    case TruthKind::converged:
    case TruthKind::none:
      break;
  }
  return reference_truth(
      "the case has no closed form (truth = none): the reference at exact geometry and tight "
      "tolerance (SPEC §3)");
}

double median(std::vector<double> values) {
  if (values.empty()) return std::nan("");
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double rung_cost(const SeriesPlan& s, double value, double duration_s) {
  if (s.knob == "rtol") {
    // ~1000 steps per simulated second at rtol 1e-10 on the shipped cases
    return duration_s * 1e3 * std::pow(1e-10 / value, 0.2) * 20.0;
  }
  // the reference's fixed RK4: 4 stages, each an outline contact search
  const double per_step = s.engine == "reference" ? 20.0 : 1.0;
  return duration_s / value * per_step;
}

bool ladder_is_flat(const std::vector<double>& errors) {
  if (errors.empty() || !std::isfinite(errors.back())) return false;
  std::vector<double> ok;
  for (auto it = errors.rbegin(); it != errors.rend() && ok.size() < 3; ++it) {
    if (std::isfinite(*it)) ok.push_back(*it);
  }
  if (ok.size() < 3) return false;
  auto close = [](double x, double y) {
    return std::abs(x - y) <= kFlatTolerance * std::min(x, y);
  };
  return close(ok[0], ok[1]) && close(ok[1], ok[2]);
}

const char* ladder_stop_rule() {
  return "each ladder runs coarse to fine and stops once its last three rungs that ran ok "
         "agree within 10 % (each change at most a tenth of the smaller error): a floor that "
         "finer rungs would only measure again; diverged rungs never stop a ladder";
}

}  // namespace pb::cli
