// planarbench check: the CI gate (SPEC §6).
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <memory>
#include <set>
#include <toml++/toml.h>

#include "check_scope.hpp"
#include "cli_common.hpp"
#include "threshold_names.hpp"
#include "commands.hpp"
#include "planarbench/case_loader.hpp"
#include "planarbench/did_you_mean.hpp"
#include "planarbench/engines.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/output_file.hpp"
#include "planarbench/reports/run_validity.hpp"
#include "planarbench/reports/thresholds.hpp"
#include "planarbench/results_file.hpp"

namespace pb::cli {

namespace {

struct CheckOptions {
  std::string thresholds;
  std::string results;
  std::string junit;
  std::string summary;
  bool quiet = false;
  // thresholds of cases the results file does not hold are skipped, counted
  bool cases_in_results_only = false;
};

// runs the bands were not derived for: exit 2 naming them (a few, then a count)
void refuse_runs_out_of_scope(const std::string& results, const std::vector<RunOutOfScope>& out) {
  if (out.empty()) return;
  constexpr std::size_t kNamed = 4;  // one line stays readable
  std::string runs;
  for (std::size_t i = 0; i < out.size() && i < kNamed; ++i) {
    std::string what;
    for (const auto& d : out[i].differences) what += (what.empty() ? "" : ", ") + d;
    runs += fmt::format("{}{} ({})", i == 0 ? "" : "; ", out[i].run, what);
  }
  if (out.size() > kNamed) runs += fmt::format("; and {} more run(s)", out.size() - kNamed);
  throw InputError(results, 0, "/runs",
                   fmt::format("{} run(s) made outside what the thresholds were derived for (each "
                               "engine's default settings, the case's outline, no "
                               "foreknowledge): {}; run them at the defaults, or state what the "
                               "bands also hold for in the thresholds file's `covers`",
                               out.size(), runs));
}

// what bands may assume of a run: its accepted steps, and the largest depth
// error its collider recorded against the exact depth (MuJoCo's MPR check)
RunFigures run_figures(const RunResult& r) {
  RunFigures f;
  f.steps = r.steps;
  const auto pairs = r.mapping.find("pairs");
  if (pairs == r.mapping.end() || !pairs->is_array()) return f;
  for (const auto& p : *pairs) {
    const auto check = p.find("mpr_depth_check");
    if (check == p.end() || !check->is_object()) continue;
    const auto e = check->find("max_abs_error_m");
    if (e != check->end() && e->is_number()) f.depth_error_m = std::max(f.depth_error_m, e->get<double>());
  }
  return f;
}

int run_check(const CheckOptions& opt) {
  // everything that can be checked before the (large) results file is read
  const ThresholdsFile file = load_thresholds_file(opt.thresholds);
  check_covers(opt.thresholds, file.covers, file.covers_lines);
  std::vector<Threshold> thresholds = file.thresholds;
  const std::filesystem::path res(opt.results);
  const auto stem = res.parent_path() / res.stem();
  const std::string junit = opt.junit.empty() ? stem.string() + ".junit.xml" : opt.junit;
  const std::string summary = opt.summary.empty() ? stem.string() + ".summary.md" : opt.summary;
  check_output_file("--junit", junit);
  check_output_file("--summary", summary);
  check_not_an_input("--junit", junit, {opt.results, opt.thresholds});
  check_not_an_input("--summary", summary, {opt.results, opt.thresholds, junit});
  const ResultsFile results = read_results_file(opt.results);
  if (results.cases.empty() && results.campaign) {
    throw InputError(opt.results, 0, "/campaign",
                     fmt::format("is the file of a {} (a table of runs, no /runs): `check` gates the "
                                 "runs of `planarbench run`; `planarbench report` shows a {}",
                                 results.campaign->kind, results.campaign->kind));
  }
  check_threshold_names(opt.thresholds, thresholds, results);
  // a run's group names its engine: one this build does not have is the
  // file's fault (issue 49: it was blamed on --engine, which check lacks)
  const auto& engines = engine_names();
  for (const auto& cr : results.cases) {
    for (const auto& r : cr.runs) {
      if (std::find(engines.begin(), engines.end(), r.engine_name) != engines.end()) continue;
      throw InputError(opt.results, 0, fmt::format("/runs/{}/{}", cr.case_name, r.engine_name),
                       fmt::format("names no engine of this build (engines: {}){}",
                                   join_words(engines), did_you_mean(r.engine_name, engines)));
    }
  }
  // each case as it was run: its text under the --set case keys stored with it
  std::vector<Case> cases;
  for (const auto& cr : results.cases) cases.push_back(case_as_run(cr));
  refuse_runs_out_of_scope(opt.results,
                           runs_out_of_scope(results, cases, opt.thresholds, file.covers,
                                                             file.truths));

  std::vector<MetricValue> metrics;
  std::vector<std::string> diverged;
  std::vector<InvalidRun> invalid;  // NaN or inf in a run's samples: its checks fail
  for (std::size_t i = 0; i < results.cases.size(); ++i) {
    const CaseRuns& cr = results.cases[i];
    auto m = case_metrics(cases[i], cr);
    metrics.insert(metrics.end(), m.begin(), m.end());
    const auto bad = invalid_runs(cr);
    invalid.insert(invalid.end(), bad.begin(), bad.end());
    for (const auto& r : cr.runs) {
      if (r.status == RunStatus::diverged) {
        diverged.push_back(fmt::format("{}.{}: {}", cr.case_name, r.engine_name, r.reason));
      }
    }
  }
  // a results file of some of the cases (CI's subset of the scenes): the
  // bands of the others are not judged, and the count says so
  std::size_t skipped = 0;
  if (opt.cases_in_results_only) {
    std::set<std::string> held;
    for (const auto& cr : results.cases) held.insert(cr.case_name);
    const auto absent = [&](const Threshold& t) { return held.count(t.case_name) == 0; };
    skipped = static_cast<std::size_t>(std::count_if(thresholds.begin(), thresholds.end(), absent));
    thresholds.erase(std::remove_if(thresholds.begin(), thresholds.end(), absent), thresholds.end());
  }
  auto outcomes = check_thresholds(thresholds, metrics, invalid);
  check_run_assumptions(outcomes, [&](const std::string& case_name, const std::string& engine) {
    for (const auto& cr : results.cases) {
      if (cr.case_name != case_name) continue;
      for (const auto& r : cr.runs) {
        if (r.engine_name == engine) return run_figures(r);
      }
    }
    return RunFigures{};
  });

  (void)write_text_atomically("--junit", junit, junit_xml(outcomes, diverged, invalid));
  (void)write_text_atomically("--summary", summary, markdown_summary(outcomes, diverged, invalid));

  std::size_t failed = 0;
  std::size_t known = 0;
  for (const auto& o : outcomes) {
    const bool fails = fails_gate(o);
    if (o.passed && !fails) continue;
    if (fails) {
      ++failed;
    } else {
      ++known;
    }
    const char* label = !fails           ? "KNOWN BREACH"
                        : !o.assumption.empty() ? "ASSUMPTION BROKEN"
                        : o.passed       ? "UNEXPECTED PASS"
                        : o.beyond_range ? "BEYOND KNOWN BREACH"
                                         : "BREACH";
    std::printf("%s %s.%s %s vs %s%s: %s  [why: %s]\n", label, o.threshold.case_name.c_str(),
                o.threshold.engine.c_str(), o.threshold.metric.c_str(),
                o.threshold.against.c_str(),
                o.value.episode >= 0 ? fmt::format(" [episode {}]", o.value.episode).c_str() : "",
                o.message.c_str(), o.threshold.why.c_str());
  }
  for (const auto& d : diverged) std::printf("DIVERGED %s\n", d.c_str());
  if (skipped > 0) {
    std::printf("%zu checks of cases not in the results file skipped (--cases-in-results-only)\n",
                skipped);
  }
  for (const auto& f : invalid) std::printf("INVALID %s\n", f.describe().c_str());
  std::printf(
      "%zu of %zu checks passed, %zu breached, %zu known breach(es) (engines that cannot meet "
      "their band, not failing the gate), %zu run(s) diverged, %zu dataset(s) of invalid data "
      "(NaN or inf)\n",
      outcomes.size() - failed - known, outcomes.size(), failed, known, diverged.size(),
      invalid.size());
  if (!diverged.empty()) return kExitEngineFailed;
  return failed > 0 || !invalid.empty() ? kExitToleranceBreached : kExitOk;
}

}  // namespace

Action add_check_command(CLI::App& app) {
  auto opt = std::make_shared<CheckOptions>();
  auto* cmd = app.add_subcommand(
      "check",
      "Check a results file against a thresholds file (the CI gate); exit 1 on a breach, 2 on "
      "bad input, including runs made outside what the thresholds were derived for (an "
      "engine's non-default settings, foreknowledge, another outline resolution) unless the "
      "thresholds file's `covers` states them");
  cmd->add_option("--thresholds", opt->thresholds, "Thresholds file (TOML), e.g. cases/thresholds.toml")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("results", opt->results, "Results file written by `planarbench run`")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--junit", opt->junit, "JUnit XML output (default: RESULTS stem + .junit.xml)");
  cmd->add_option("--summary", opt->summary,
                  "Markdown summary output (default: RESULTS stem + .summary.md)");
  cmd->add_flag("--cases-in-results-only", opt->cases_in_results_only,
                "Judge only the thresholds of cases the results file holds (a subset run, e.g. "
                "CI's scenes); the others are skipped and counted, where they would fail as not "
                "computed");
  return [opt] { return run_check(*opt); };
}

}  // namespace pb::cli
