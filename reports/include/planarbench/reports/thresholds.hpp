// The CI gate (SPEC §6): a thresholds file per (case, engine, against,
// metric) with absolute and relative tolerance, numpy assert_allclose
// semantics (|actual - desired| <= atol + rtol |desired|, desired = baseline).
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "planarbench/reports/metrics.hpp"
#include "planarbench/reports/run_validity.hpp"

namespace pb {

struct Threshold {
  std::string case_name;
  std::string engine;
  std::string against;   // truth | reference | <engine> | self
  std::string metric;    // SPEC §4 name (or episode_count)
  int episode = -1;      // -1: every episode
  double atol = 0.0;
  double rtol = 0.0;
  std::string why;       // the bound the tolerance comes from
  // non-empty: the engine's own model cannot meet this band, for the stated
  // reason (its mapping says so before the run); the check expects a breach,
  // shows it as a failure, and does not fail the gate on it; a pass then
  // fails the gate ("unexpected pass": the reason no longer holds)
  std::string known_breach;
  // a known breach's expected range (issue 31): the metric's value its
  // mechanism gives, [expected_min, expected_max] in the metric's own units
  // (the error itself for an error metric); a value outside it fails the gate
  // ("beyond its known breach"), so a known breach can fail like any band.
  // Required with known_breach, refused without it; the derivation is
  // `expected_bound` (two expressions, checked by
  // tests/python/threshold_derivations.py) and `expected_why`
  double expected_min = 0.0;
  double expected_max = 0.0;
  std::string expected_why;
  // an assumption of the band on the run's own figures (issue 31): it holds
  // for a run of at most this many accepted steps (the reference's rk45 error
  // grows with them); 0: none. `check` fails the threshold, naming the
  // assumption, when the run took more (check_run_assumptions)
  long steps_at_most = 0;
  // the same for the depth error of an engine's collider the band assumes
  // (MuJoCo's MPR on circle-ellipse, which the run records against the exact
  // depth: mapping pairs[].mpr_depth_check.max_abs_error_m); 0: none
  double depth_error_at_most_m = 0.0;
  // the tolerance holds by construction (e.g. a joint that is a generalized
  // coordinate), not by a numerical bound; the report labels it so
  bool by_construction = false;
  // the bound the tolerance is derived from, as an arithmetic expression over
  // numbers and the file's [constants] (tests/python/threshold_derivations.py
  // evaluates it and checks the tolerance against it); empty: none given
  std::string bound;
  int line = 0;          // in the thresholds file
};

// A thresholds file: its thresholds, and what its bands also hold for besides
// each engine's default settings, the case's outline and no foreknowledge
// (`covers`: setting keys, "foreknowledge", "outline_points"; the gate
// refuses runs made otherwise, apps/check_scope.hpp).
struct ThresholdsFile {
  std::vector<Threshold> thresholds;
  std::vector<std::string> covers;
  std::vector<int> covers_lines;  // covers[i]'s line in the file
  // [truths]: case -> the kind of truth its bands against "truth" were derived
  // with (truth_kinds()); `check` refuses a run whose truth was another kind
  // (the independent truth failed at run time and the converged reference
  // stood in, say). A case not listed is not checked.
  std::map<std::string, std::string> truths;
};

// The kinds a [truths] entry names, as the analytic engine's mapping states
// them (physics.mode): "closed form", "independent", "closed form, then
// independent", "converged", "closed form, then converged".
[[nodiscard]] const std::vector<std::string>& truth_kinds();
// The kind of a truth run from its physics.mode ("" when not one of them).
[[nodiscard]] std::string truth_kind_of_mode(const std::string& mode);

// Loads and validates a thresholds file (InputError naming file, line, field).
[[nodiscard]] ThresholdsFile load_thresholds_file(const std::filesystem::path& path);
// Its thresholds only.
[[nodiscard]] std::vector<Threshold> load_thresholds(const std::filesystem::path& path);

// One checked (threshold, metric value) pair.
struct CheckOutcome {
  Threshold threshold;
  MetricValue value;     // value.metric empty when no such metric was computed
  double limit = 0.0;    // atol + rtol |desired|
  bool passed = false;   // the band holds
  std::string message;   // why it failed
  // non-empty: the run or its baseline holds NaN or inf (run_validity.hpp),
  // what and where; the check fails whatever its value
  std::string invalid_data;
  // a known breach whose finite value lies outside its expected range
  bool beyond_range = false;
  // non-empty: the run breaks an assumption of the band (steps_at_most): it
  // fails whatever its value
  std::string assumption;
};

// whether an outcome fails the gate: a breach that is not a known one, a
// known breach that passed or left its expected range, a metric that was not
// computed or is not a number, or a run or baseline with invalid data
[[nodiscard]] bool fails_gate(const CheckOutcome& o);
// "pass", "fail", "known breach", "beyond its known breach", "unexpected
// pass", "assumption broken" or "invalid data"
[[nodiscard]] const char* outcome_label(const CheckOutcome& o);

// Every threshold against the metrics; a threshold that matches no metric
// fails ("not computed": a gate never passes silently). A threshold of a run
// in `invalid` (invalid_runs of its case), or against one (its baseline:
// "truth" is the analytic run, "self" the run itself, else the engine named),
// fails with the invalid data named, whatever its value.
[[nodiscard]] std::vector<CheckOutcome> check_thresholds(const std::vector<Threshold>& thresholds,
                                                         const std::vector<MetricValue>& metrics,
                                                         const std::vector<InvalidRun>& invalid);

// A run's own figures that bands may assume a bound on.
struct RunFigures {
  long steps = -1;                    // accepted steps; -1: no such run
  double depth_error_m = -1.0;        // the collider's recorded depth error; < 0: not recorded
};
// The bands' assumptions on a run's own figures: an outcome whose threshold
// has steps_at_most (depth_error_at_most_m) fails (assumption set, passed
// false) when the run's figure is larger, or, for the depth error, not
// recorded; no such run leaves it as it is.
void check_run_assumptions(
    std::vector<CheckOutcome>& outcomes,
    const std::function<RunFigures(const std::string&, const std::string&)>& figures_of);

// JUnit XML: one test case per checked metric, value and limit as properties;
// one failed test case per diverged run and per dataset of invalid data
// (classname CASE.ENGINE, name "data").
[[nodiscard]] std::string junit_xml(const std::vector<CheckOutcome>& outcomes,
                                    const std::vector<std::string>& diverged_runs,
                                    const std::vector<InvalidRun>& invalid);
// A Markdown summary small enough for a CI job summary.
[[nodiscard]] std::string markdown_summary(const std::vector<CheckOutcome>& outcomes,
                                           const std::vector<std::string>& diverged_runs,
                                           const std::vector<InvalidRun>& invalid);

}  // namespace pb
