#include "planarbench/reports/thresholds.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <set>
#include <toml++/toml.h>

#include "planarbench/did_you_mean.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/reports/contact_validity.hpp"
#include "planarbench/reports/friction_metrics.hpp"
#include "planarbench/reports/scene_metrics.hpp"
#include "markdown_text.hpp"
#include "xml_escape.hpp"

namespace pb {

namespace {

const std::set<std::string>& metric_names() {
  static const std::set<std::string> names = [] {
    std::set<std::string> n = {
      "position_max", "position_rms",    "angle_max",       "velocity_max",    "velocity_rms",
      "impact_time",  "contact_duration", "peak_force",     "impulse",         "restitution",
      "max_penetration", "energy_drift", "constraint_drift", "momentum_drift", "wall_per_sim_s",
      "episode_count"};
    for (const char* f : friction_metric_names()) n.insert(f);  // SPEC §7
    for (const char* f : validity_metric_names()) n.insert(f);  // SPEC §9
    for (const char* f : scene_metric_names()) n.insert(f);     // SPEC §11
    return n;
  }();
  return names;
}

int line_of(const toml::node& n) { return static_cast<int>(n.source().begin.line); }

// a value as quoted in messages: 1e-06, "abc", true, an array of 2, a table
std::string describe(const toml::node& n) {
  if (const auto* v = n.as_integer()) return fmt::format("{}", v->get());
  if (const auto* v = n.as_floating_point()) return fmt::format("{}", v->get());
  if (const auto* v = n.as_boolean()) return v->get() ? "true" : "false";
  if (const auto* v = n.as_string()) return fmt::format("\"{}\"", v->get());
  if (const auto* v = n.as_array()) return fmt::format("an array of {}", v->size());
  if (n.is_table()) return "a table";
  return "a date/time";
}

std::string test_name(const CheckOutcome& o) {
  const Threshold& t = o.threshold;
  std::string name = fmt::format("{} vs {}", t.metric, t.against);
  const int ep = o.value.episode >= 0 ? o.value.episode : t.episode;
  if (ep >= 0) name += fmt::format(" [episode {}]", ep);
  return name;
}

// A known breach's expected range: `expected = [min, max]` (finite numbers,
// min <= max), required with known_breach (a known breach without one could
// never fail) and refused without it; `expected_bound` (two expressions, the
// derivation) and `expected_why` (its words) go with it.
void read_expected_range(const std::string& file, const std::string& where,
                         const toml::table& t, Threshold& th) {
  const toml::node* e = t.get("expected");
  const bool known = t.get("known_breach") != nullptr;
  if (!known) {
    for (const char* key : {"expected", "expected_bound", "expected_why"}) {
      if (const toml::node* n = t.get(key)) {
        throw InputError(file, line_of(*n), where + "." + key,
                         "belongs to a known breach only (its expected range); this threshold "
                         "has no known_breach");
      }
    }
    return;
  }
  if (e == nullptr) {
    throw InputError(file, th.line, where + ".expected",
                     "missing: a known breach states the range its mechanism gives, expected = "
                     "[min, max] in the metric's units (with expected_bound and expected_why); "
                     "without one it could never fail");
  }
  const toml::array* a = e->as_array();
  std::optional<double> lo;
  std::optional<double> hi;
  if (a != nullptr && a->size() == 2) {
    lo = (*a)[0].is_number() ? (*a)[0].value<double>() : std::nullopt;
    hi = (*a)[1].is_number() ? (*a)[1].value<double>() : std::nullopt;
  }
  if (!lo || !hi || !std::isfinite(*lo) || !std::isfinite(*hi) || *lo > *hi) {
    throw InputError(file, line_of(*e), where + ".expected",
                     fmt::format("must be [min, max], two finite numbers with min <= max (got {})",
                                 describe(*e)));
  }
  th.expected_min = *lo;
  th.expected_max = *hi;
  if (const toml::node* b = t.get("expected_bound")) {
    const toml::array* ba = b->as_array();
    const bool ok = ba != nullptr && ba->size() == 2 && (*ba)[0].is_string() &&
                    (*ba)[1].is_string();
    if (!ok) {
      throw InputError(file, line_of(*b), where + ".expected_bound",
                       fmt::format("must be two expressions as strings, [\"min\", \"max\"] "
                                   "(got {})",
                                   describe(*b)));
    }
  }
  const toml::node* w = t.get("expected_why");
  if (w == nullptr || !w->is_string() || w->as_string()->get().empty()) {
    throw InputError(file, w != nullptr ? line_of(*w) : th.line, where + ".expected_why",
                     "must be a non-empty string: the mechanism the expected range comes from");
  }
  th.expected_why = w->as_string()->get();
}

}  // namespace

std::vector<Threshold> load_thresholds(const std::filesystem::path& path) {
  return load_thresholds_file(path).thresholds;
}

ThresholdsFile load_thresholds_file(const std::filesystem::path& path) {
  const std::string file = path.string();
  // a thresholds file is a few hundred lines; anything past this is not one
  constexpr std::uintmax_t kMaxBytes = 1u << 20;  // 1 MiB
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(file, 0, "", "no such thresholds file");
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw InputError(file, 0, "", "is not a regular file; give a thresholds file (TOML)");
  }
  if (const auto bytes = std::filesystem::file_size(path, ec); !ec && bytes > kMaxBytes) {
    throw InputError(file, 0, "",
                     fmt::format("is {} bytes; a thresholds file has at most {} bytes (1 MiB)",
                                 bytes, kMaxBytes));
  }
  toml::table doc;
  try {
    doc = toml::parse_file(file);
  } catch (const toml::parse_error& e) {
    throw InputError(file, static_cast<int>(e.source().begin.line), "",
                     std::string(e.description()));
  }
  for (const auto& [key, node] : doc) {
    if (key.str() != "threshold" && key.str() != "constants" && key.str() != "covers" &&
        key.str() != "truths") {
      throw InputError(
          file, line_of(node), std::string(key.str()),
          fmt::format("unknown key{}; a thresholds file holds `covers`, a [constants] table, a "
                      "[truths] table and [[threshold]] entries only",
                      did_you_mean(key.str(), {"threshold", "constants", "covers", "truths"})));
    }
  }
  ThresholdsFile loaded;
  // covers: what the bands also hold for besides each engine's defaults, the
  // case's outline and no foreknowledge (apps/check_scope.hpp)
  if (const toml::node* c = doc.get("covers")) {
    const toml::array* list = c->as_array();
    const auto bad = [&](const toml::node& n) {
      return fmt::format("must be a list of setting keys (\"dt\", \"mujoco.mode\"), "
                         "\"foreknowledge\" or \"outline_points\" (got {})",
                         describe(n));
    };
    if (list == nullptr) throw InputError(file, line_of(*c), "covers", bad(*c));
    for (const auto& n : *list) {
      if (!n.is_string() || n.as_string()->get().empty()) {
        throw InputError(file, line_of(n), "covers", bad(n));
      }
      loaded.covers.push_back(n.as_string()->get());
      loaded.covers_lines.push_back(line_of(n));
    }
  }
  // [truths]: the kind of truth each case's bands were derived with
  if (const toml::node* tr = doc.get("truths")) {
    const toml::table* tab = tr->as_table();
    if (tab == nullptr) {
      throw InputError(file, line_of(*tr), "truths",
                       fmt::format("must be a table of case = \"kind\" (got {})", describe(*tr)));
    }
    for (const auto& [key, node] : *tab) {
      const auto& kinds = truth_kinds();
      const std::string* kind = node.is_string() ? &node.as_string()->get() : nullptr;
      if (kind == nullptr || std::find(kinds.begin(), kinds.end(), *kind) == kinds.end()) {
        throw InputError(file, line_of(node), "truths." + std::string(key.str()),
                         fmt::format("must be one of {} (got {})", join_words(kinds),
                                     describe(node)));
      }
      loaded.truths[std::string(key.str())] = *kind;
    }
  }
  // [constants]: named figures the bounds use, each an expression as a string;
  // evaluated by tests/python/threshold_derivations.py, not by the gate
  if (const toml::node* c = doc.get("constants")) {
    const toml::table* tab = c->as_table();
    if (tab == nullptr) {
      throw InputError(file, line_of(*c), "constants",
                       fmt::format("must be a table of name = \"expression\" (got {})",
                                   describe(*c)));
    }
    for (const auto& [key, node] : *tab) {
      if (!node.is_string() || node.as_string()->get().empty()) {
        throw InputError(file, line_of(node), "constants." + std::string(key.str()),
                         fmt::format("must be a non-empty string holding an expression (got {})",
                                     describe(node)));
      }
    }
  }
  const toml::node* entries = doc.get("threshold");
  const toml::array* arr = entries != nullptr ? entries->as_array() : nullptr;
  if (arr == nullptr) {
    throw InputError(file, entries != nullptr ? line_of(*entries) : 0, "threshold",
                     entries != nullptr
                         ? fmt::format("must be [[threshold]] entries (got {})", describe(*entries))
                         : std::string("no [[threshold]] entries: give at least one"));
  }
  static const std::vector<std::string> allowed = {
      "case", "engine", "against", "metric", "episode", "atol", "rtol", "why", "known_breach",
      "by_construction", "bound", "expected", "expected_bound", "expected_why", "steps_at_most",
      "depth_error_at_most"};
  const std::vector<std::string> metrics(metric_names().begin(), metric_names().end());
  std::vector<Threshold> out;
  for (std::size_t i = 0; i < arr->size(); ++i) {
    const toml::table* t = (*arr)[i].as_table();
    const std::string where = fmt::format("threshold[{}]", i);
    if (t == nullptr) {
      throw InputError(file, line_of((*arr)[i]), where,
                       fmt::format("must be a table (got {})", describe((*arr)[i])));
    }
    Threshold th;
    th.line = line_of(*t);
    for (const auto& [key, node] : *t) {
      const std::string k(key.str());
      if (std::find(allowed.begin(), allowed.end(), k) == allowed.end()) {
        throw InputError(file, line_of(node), where + "." + k,
                         fmt::format("unknown key{}; allowed: {}", did_you_mean(k, allowed),
                                     join_words(allowed)));
      }
    }
    auto text = [&](const char* key, std::string& dst) {
      const auto* n = t->get(key);
      if (n == nullptr) {
        throw InputError(file, th.line, where + "." + key, "missing; give a non-empty string");
      }
      if (!n->is_string() || n->as_string()->get().empty()) {
        throw InputError(file, line_of(*n), where + "." + key,
                         fmt::format("must be a non-empty string (got {})", describe(*n)));
      }
      dst = n->as_string()->get();
    };
    auto number = [&](const char* key, double& dst) {
      const auto* n = t->get(key);
      if (n == nullptr) return;
      const auto v = n->is_number() ? n->value<double>() : std::nullopt;
      if (!v || !std::isfinite(*v) || *v < 0.0) {
        throw InputError(file, line_of(*n), where + "." + key,
                         fmt::format("must be a finite number >= 0 (got {})", describe(*n)));
      }
      dst = *v;
    };
    text("case", th.case_name);
    text("engine", th.engine);
    text("against", th.against);
    text("metric", th.metric);
    text("why", th.why);
    number("atol", th.atol);
    number("rtol", th.rtol);
    if (t->get("known_breach") != nullptr) text("known_breach", th.known_breach);
    if (t->get("bound") != nullptr) text("bound", th.bound);
    if (const auto* n = t->get("by_construction")) {
      if (!n->is_boolean()) {
        throw InputError(file, line_of(*n), where + ".by_construction",
                         fmt::format("must be true or false (got {})", describe(*n)));
      }
      th.by_construction = n->as_boolean()->get();
    }
    read_expected_range(file, where, *t, th);
    if (const auto* n = t->get("steps_at_most")) {
      constexpr std::int64_t kMaxSteps = 1000000000;
      const auto* v = n->as_integer();
      if (v == nullptr || v->get() < 1 || v->get() > kMaxSteps) {
        throw InputError(file, line_of(*n), where + ".steps_at_most",
                         fmt::format("must be an integer in [1, {}]: the accepted steps the band "
                                     "assumes at most (got {})",
                                     kMaxSteps, describe(*n)));
      }
      th.steps_at_most = static_cast<long>(v->get());
    }
    if (const auto* n = t->get("depth_error_at_most")) {
      const auto v = n->is_number() ? n->value<double>() : std::nullopt;
      if (!v || !std::isfinite(*v) || *v <= 0.0) {
        throw InputError(file, line_of(*n), where + ".depth_error_at_most",
                         fmt::format("must be a finite number > 0 in m: the collider's depth "
                                     "error the band assumes at most (got {})",
                                     describe(*n)));
      }
      th.depth_error_at_most_m = *v;
    }
    if (metric_names().count(th.metric) == 0) {
      throw InputError(file, line_of(*t->get("metric")), where + ".metric",
                       fmt::format("unknown metric '{}'{}; allowed (SPEC §4): {}", th.metric,
                                   did_you_mean(th.metric, metrics), join_words(metrics)));
    }
    if (t->get("atol") == nullptr && t->get("rtol") == nullptr) {
      throw InputError(file, th.line, where, "has no tolerance; give atol, rtol or both (>= 0)");
    }
    if (const auto* n = t->get("episode")) {
      constexpr std::int64_t kMaxEpisode = 1000000;
      const auto* v = n->as_integer();
      if (v == nullptr || v->get() < 0 || v->get() > kMaxEpisode) {
        throw InputError(file, line_of(*n), where + ".episode",
                         fmt::format("must be an integer in [0, {}] (got {})", kMaxEpisode,
                                     describe(*n)));
      }
      th.episode = static_cast<int>(v->get());
    }
    // the same check twice is a copy-paste slip, and the two could disagree
    for (std::size_t j = 0; j < out.size(); ++j) {
      const Threshold& o = out[j];
      if (o.case_name == th.case_name && o.engine == th.engine && o.against == th.against &&
          o.metric == th.metric && o.episode == th.episode) {
        throw InputError(file, th.line, where,
                         fmt::format("repeats threshold[{}] (line {}): the same case, engine, "
                                     "against, metric and episode; keep one",
                                     j, o.line));
      }
    }
    out.push_back(th);
  }
  // a [truths] key is a case some band of this file judges (issue 49: a
  // misspelled key, or one naming no case, passed while the case it meant
  // went without its kind)
  if (const toml::node* tr = doc.get("truths")) {
    std::vector<std::string> judged;
    for (const Threshold& th : out) {
      if (std::find(judged.begin(), judged.end(), th.case_name) == judged.end()) {
        judged.push_back(th.case_name);
      }
    }
    for (const auto& [key, node] : *tr->as_table()) {
      const std::string name(key.str());
      if (std::find(judged.begin(), judged.end(), name) != judged.end()) continue;
      throw InputError(file, line_of(node), "truths." + name,
                       fmt::format("names no case of this file's [[threshold]] entries{}; a truth's "
                                   "kind is stated for a case its bands judge",
                                   did_you_mean(name, judged)));
    }
  }
  loaded.thresholds = std::move(out);
  return loaded;
}

const std::vector<std::string>& truth_kinds() {
  static const std::vector<std::string> kinds = {"closed form", "independent",
                                                 "closed form, then independent", "converged",
                                                 "closed form, then converged"};
  return kinds;
}

std::string truth_kind_of_mode(const std::string& mode) {
  // the analytic engine's physics.mode (core/analytic/analytic_engine.cpp)
  if (mode == "closed form") return "closed form";
  if (mode == "independent integration") return "independent";
  if (mode == "closed form, then independent integration") return "closed form, then independent";
  if (mode == "converged reference") return "converged";
  if (mode == "closed form, then converged reference") return "closed form, then converged";
  return "";
}

bool fails_gate(const CheckOutcome& o) {
  // a metric that was not computed, or computed from NaN, fails whatever the
  // threshold expects: a known breach is a value outside the band, not a
  // missing run or invalid data
  if (o.value.metric.empty() || !o.invalid_data.empty() || !o.assumption.empty()) return true;
  // nor is a value that is not a number (a lost episode, a friction figure
  // never reached): it fails a known breach's check too (issue 31)
  if (!std::isfinite(o.value.actual) || !std::isfinite(o.value.desired)) return true;
  return o.threshold.known_breach.empty() ? !o.passed : o.passed || o.beyond_range;
}

const char* outcome_label(const CheckOutcome& o) {
  if (!o.invalid_data.empty()) return "invalid data";
  if (!o.assumption.empty()) return "assumption broken";
  if (o.threshold.known_breach.empty() || o.value.metric.empty()) return o.passed ? "pass" : "fail";
  if (!std::isfinite(o.value.actual) || !std::isfinite(o.value.desired)) return "fail";
  if (o.passed) return "unexpected pass";
  return o.beyond_range ? "beyond its known breach" : "known breach";
}

std::vector<CheckOutcome> check_thresholds(const std::vector<Threshold>& thresholds,
                                           const std::vector<MetricValue>& metrics,
                                           const std::vector<InvalidRun>& invalid) {
  std::vector<CheckOutcome> out;
  // the run of a threshold, or its baseline, with invalid data: the outcome fails naming it
  auto invalid_data = [&](const Threshold& th) -> std::string {
    const std::string baseline = th.against == "truth"  ? std::string("analytic")
                                 : th.against == "self" ? th.engine
                                                        : th.against;
    for (const std::string& engine : {th.engine, baseline}) {
      if (const InvalidRun* f = find_invalid(invalid, th.case_name, engine)) {
        return fmt::format("invalid data: {}{}; its metrics mean nothing",
                           engine == th.engine ? "" : "the baseline ", f->describe());
      }
    }
    return "";
  };
  auto mark_invalid = [&](CheckOutcome& o) {
    o.invalid_data = invalid_data(o.threshold);
    if (o.invalid_data.empty()) return;
    o.passed = false;
    o.message = o.invalid_data + (o.message.empty() ? "" : "; " + o.message);
  };
  for (const auto& th : thresholds) {
    bool matched = false;
    for (const auto& m : metrics) {
      if (m.case_name != th.case_name || m.engine != th.engine || m.against != th.against ||
          m.metric != th.metric || (th.episode >= 0 && m.episode != th.episode)) {
        continue;
      }
      matched = true;
      CheckOutcome o;
      o.threshold = th;
      o.value = m;
      o.limit = th.atol + th.rtol * std::abs(m.desired);
      const double deviation = std::abs(m.actual - m.desired);
      o.passed = deviation <= o.limit;  // NaN fails
      if (!std::isfinite(m.actual) || !std::isfinite(m.desired)) {
        // not a value: a lost episode, a figure never reached, NaN or inf; it
        // fails whatever the threshold expects (a known breach included)
        o.message = fmt::format(
            "not a number: actual {} against {} (a lost or extra episode, a friction figure "
            "never reached, NaN or inf): fails whatever the threshold expects",
            m.actual, m.desired);
      } else if (!o.passed) {
        o.message = fmt::format("|{:.6g} - {:.6g}| = {:.4g} > {:.4g} (atol {:g} + rtol {:g})",
                                m.actual, m.desired, deviation, o.limit, th.atol, th.rtol);
        if (!th.known_breach.empty()) {
          o.beyond_range = std::isfinite(m.actual) &&
                           !(m.actual >= th.expected_min && m.actual <= th.expected_max);
          if (o.beyond_range) {
            o.message = fmt::format(
                "beyond its known breach: {:.6g} is outside the expected range [{:.6g}, {:.6g}] "
                "({}); {}; known breach: {}",
                m.actual, th.expected_min, th.expected_max, th.expected_why, o.message,
                th.known_breach);
          } else {
            o.message += fmt::format("; known breach: {} (within its expected range [{:.6g}, {:.6g}])",
                                     th.known_breach, th.expected_min, th.expected_max);
          }
        }
      } else if (!th.known_breach.empty()) {
        o.message = fmt::format(
            "unexpected pass: |{:.6g} - {:.6g}| = {:.4g} <= {:.4g}, but the threshold says the "
            "engine cannot meet it ({}); remove known_breach",
            m.actual, m.desired, deviation, o.limit, th.known_breach);
      }
      mark_invalid(o);
      out.push_back(o);
    }
    if (!matched) {
      CheckOutcome o;
      o.threshold = th;
      o.limit = th.atol;
      o.message = "not computed: the run is missing, unsupported or diverged, or has no such "
                  "metric";
      mark_invalid(o);
      out.push_back(o);
    }
  }
  return out;
}

void check_run_assumptions(
    std::vector<CheckOutcome>& outcomes,
    const std::function<RunFigures(const std::string&, const std::string&)>& figures_of) {
  for (auto& o : outcomes) {
    const Threshold& th = o.threshold;
    if ((th.steps_at_most <= 0 && th.depth_error_at_most_m <= 0.0) || o.value.metric.empty()) {
      continue;
    }
    const RunFigures f = figures_of(th.case_name, th.engine);
    if (f.steps < 0) continue;
    std::string broken;
    if (th.steps_at_most > 0 && f.steps > th.steps_at_most) {
      broken = fmt::format("the band assumes at most {} accepted steps (steps_at_most), the run "
                           "took {}",
                           th.steps_at_most, f.steps);
    } else if (th.depth_error_at_most_m > 0.0 && !(f.depth_error_m >= 0.0)) {
      broken = "the band assumes the collider's depth error recorded and at most " +
               fmt::format("{:g} m (depth_error_at_most); the run records none", th.depth_error_at_most_m);
    } else if (th.depth_error_at_most_m > 0.0 && f.depth_error_m > th.depth_error_at_most_m) {
      broken = fmt::format("the band assumes the collider's depth error at most {:g} m "
                           "(depth_error_at_most), the run's is {:.3g} m",
                           th.depth_error_at_most_m, f.depth_error_m);
    }
    if (broken.empty()) continue;
    o.assumption = "assumption broken: " + broken;
    o.passed = false;
    o.message = o.assumption + (o.message.empty() ? "" : "; " + o.message);
  }
}

std::string junit_xml(const std::vector<CheckOutcome>& outcomes,
                      const std::vector<std::string>& diverged_runs,
                      const std::vector<InvalidRun>& invalid) {
  std::size_t failures = diverged_runs.size() + invalid.size();
  for (const auto& o : outcomes) failures += fails_gate(o) ? 1 : 0;
  std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  const std::size_t tests = outcomes.size() + diverged_runs.size() + invalid.size();
  x += fmt::format("<testsuites name=\"planarbench check\" tests=\"{}\" failures=\"{}\">\n",
                   tests, failures);
  x += fmt::format("  <testsuite name=\"planarbench\" tests=\"{}\" failures=\"{}\">\n", tests,
                   failures);
  for (const auto& run : diverged_runs) {
    x += fmt::format("    <testcase classname=\"{}\" name=\"status\">\n", internal::xml_escape(run));
    x += fmt::format("      <failure message=\"run diverged\"/>\n    </testcase>\n");
  }
  for (const auto& f : invalid) {
    x += fmt::format("    <testcase classname=\"{}\" name=\"data\">\n", internal::xml_escape(f.run()));
    x += fmt::format("      <failure message=\"invalid data: {}\"/>\n    </testcase>\n",
                     internal::xml_escape(f.what()));
  }
  for (const auto& o : outcomes) {
    x += fmt::format("    <testcase classname=\"{}.{}\" name=\"{}\">\n",
                     internal::xml_escape(o.threshold.case_name), internal::xml_escape(o.threshold.engine),
                     internal::xml_escape(test_name(o)));
    x += "      <properties>\n";
    x += fmt::format("        <property name=\"value\" value=\"{:.9g}\"/>\n", o.value.actual);
    x += fmt::format("        <property name=\"desired\" value=\"{:.9g}\"/>\n", o.value.desired);
    x += fmt::format("        <property name=\"error\" value=\"{:.9g}\"/>\n", o.value.error);
    x += fmt::format("        <property name=\"limit\" value=\"{:.9g}\"/>\n", o.limit);
    x += fmt::format("        <property name=\"why\" value=\"{}\"/>\n", internal::xml_escape(o.threshold.why));
    if (!o.threshold.bound.empty()) {
      x += fmt::format("        <property name=\"bound\" value=\"{}\"/>\n",
                       internal::xml_escape(o.threshold.bound));
    }
    x += fmt::format("        <property name=\"outcome\" value=\"{}\"/>\n", outcome_label(o));
    if (!o.threshold.known_breach.empty()) {
      x += fmt::format("        <property name=\"known_breach\" value=\"{}\"/>\n",
                       internal::xml_escape(o.threshold.known_breach));
      x += fmt::format("        <property name=\"expected_min\" value=\"{:.9g}\"/>\n",
                       o.threshold.expected_min);
      x += fmt::format("        <property name=\"expected_max\" value=\"{:.9g}\"/>\n",
                       o.threshold.expected_max);
    }
    x += "      </properties>\n";
    if (fails_gate(o)) {
      x += fmt::format("      <failure message=\"{}\"/>\n", internal::xml_escape(o.message));
    } else if (!o.passed) {
      // a known breach: shown, not failing (JUnit's skipped, with the reason)
      x += fmt::format("      <skipped message=\"{}\"/>\n", internal::xml_escape(o.message));
    }
    x += "    </testcase>\n";
  }
  x += "  </testsuite>\n</testsuites>\n";
  return x;
}

std::string markdown_summary(const std::vector<CheckOutcome>& outcomes,
                             const std::vector<std::string>& diverged_runs,
                             const std::vector<InvalidRun>& invalid) {
  std::size_t failed = 0;
  std::size_t known = 0;
  for (const auto& o : outcomes) {
    failed += fails_gate(o) ? 1 : 0;
    known += !o.passed && !fails_gate(o) ? 1 : 0;
  }
  std::string md = "## planarbench check\n\n";
  md += fmt::format("{} of {} checks passed{}{}.\n\n", outcomes.size() - failed - known,
                    outcomes.size(),
                    known == 0 ? ""
                               : fmt::format("; {} known breach(es) of engines that cannot meet "
                                             "their band (listed, not failing the gate)",
                                             known),
                    diverged_runs.empty() ? ""
                                          : fmt::format("; {} run(s) diverged", diverged_runs.size()));
  // every text here can hold what a user or an engine wrote (a reason, a
  // why, a case name): shown as Markdown text, never as markup
  using internal::md_text;
  for (const auto& r : diverged_runs) md += fmt::format("- **diverged**: {}\n", md_text(r));
  for (const auto& f : invalid) md += fmt::format("- **invalid data**: {}\n", md_text(f.describe()));
  if (failed + known == 0) return md;
  md += "| case | engine | metric | outcome | deviation | limit | known breach: value in its expected "
        "range | why |\n|---|---|---|---|---|---|---|---|\n";
  // every failure and every known breach (issue 31: a CI reader sees them all)
  for (const auto& o : outcomes) {
    if (o.passed && !fails_gate(o)) continue;
    const std::string range =
        o.threshold.known_breach.empty()
            ? std::string("-")
            : fmt::format("{:.4g} in [{:.4g}, {:.4g}]", o.value.actual, o.threshold.expected_min,
                          o.threshold.expected_max);
    md += fmt::format("| {} | {} | {} | {} | {:.4g} | {:.4g} | {} | {} |\n",
                      md_text(o.threshold.case_name), md_text(o.threshold.engine),
                      md_text(test_name(o)), outcome_label(o),
                      std::abs(o.value.actual - o.value.desired), o.limit, range,
                      md_text(o.threshold.known_breach.empty() ? o.threshold.why
                                                               : o.threshold.known_breach));
  }
  return md;
}

}  // namespace pb
