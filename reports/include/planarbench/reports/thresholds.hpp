// The CI gate (SPEC §6): a thresholds file per (case, engine, against,
// metric) with absolute and relative tolerance, numpy assert_allclose
// semantics (|actual - desired| <= atol + rtol |desired|, desired = baseline).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "planarbench/reports/metrics.hpp"

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
  int line = 0;          // in the thresholds file
};

// Loads and validates a thresholds file (InputError naming file, line, field).
[[nodiscard]] std::vector<Threshold> load_thresholds(const std::filesystem::path& path);

// One checked (threshold, metric value) pair.
struct CheckOutcome {
  Threshold threshold;
  MetricValue value;     // value.metric empty when no such metric was computed
  double limit = 0.0;    // atol + rtol |desired|
  bool passed = false;
  std::string message;   // why it failed
};

// Every threshold against the metrics; a threshold that matches no metric
// fails ("not computed": a gate never passes silently).
[[nodiscard]] std::vector<CheckOutcome> check_thresholds(const std::vector<Threshold>& thresholds,
                                                         const std::vector<MetricValue>& metrics);

// JUnit XML: one test case per checked metric, value and limit as properties.
[[nodiscard]] std::string junit_xml(const std::vector<CheckOutcome>& outcomes,
                                    const std::vector<std::string>& diverged_runs);
// A Markdown summary small enough for a CI job summary.
[[nodiscard]] std::string markdown_summary(const std::vector<CheckOutcome>& outcomes,
                                           const std::vector<std::string>& diverged_runs);

}  // namespace pb
