#include "planarbench/reports/thresholds.hpp"

#include <fmt/format.h>

#include <cmath>
#include <set>
#include <toml++/toml.h>

#include "planarbench/errors.hpp"

namespace pb {

namespace {

const std::set<std::string>& metric_names() {
  static const std::set<std::string> names = {
      "position_max", "position_rms",    "angle_max",       "velocity_max",    "velocity_rms",
      "impact_time",  "contact_duration", "peak_force",     "impulse",         "restitution",
      "max_penetration", "energy_drift", "constraint_drift", "wall_per_sim_s", "episode_count"};
  return names;
}

int line_of(const toml::node& n) { return static_cast<int>(n.source().begin.line); }

std::string xml_escaped(const std::string& s) {
  std::string out;
  for (char ch : s) {
    switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += ch;
    }
  }
  return out;
}

std::string test_name(const CheckOutcome& o) {
  const Threshold& t = o.threshold;
  std::string name = fmt::format("{} vs {}", t.metric, t.against);
  const int ep = o.value.episode >= 0 ? o.value.episode : t.episode;
  if (ep >= 0) name += fmt::format(" [episode {}]", ep);
  return name;
}

}  // namespace

std::vector<Threshold> load_thresholds(const std::filesystem::path& path) {
  const std::string file = path.string();
  toml::table doc;
  try {
    doc = toml::parse_file(file);
  } catch (const toml::parse_error& e) {
    throw InputError(file, static_cast<int>(e.source().begin.line), "",
                     std::string(e.description()));
  }
  for (const auto& [key, node] : doc) {
    if (key.str() != "threshold") {
      throw InputError(file, line_of(node), std::string(key.str()),
                       "unknown key; a thresholds file holds [[threshold]] entries only");
    }
  }
  const toml::array* arr = doc["threshold"].as_array();
  if (arr == nullptr) {
    throw InputError(file, 0, "threshold", "expected [[threshold]] entries");
  }
  std::vector<Threshold> out;
  for (std::size_t i = 0; i < arr->size(); ++i) {
    const toml::table* t = (*arr)[i].as_table();
    const std::string where = fmt::format("threshold[{}]", i);
    if (t == nullptr) throw InputError(file, line_of((*arr)[i]), where, "must be a table");
    Threshold th;
    th.line = line_of(*t);
    static const std::set<std::string> allowed = {"case", "engine", "against", "metric",
                                                  "episode", "atol", "rtol", "why"};
    for (const auto& [key, node] : *t) {
      if (allowed.count(std::string(key.str())) == 0) {
        throw InputError(file, line_of(node), where + "." + std::string(key.str()),
                         "unknown key; allowed: case, engine, against, metric, episode, atol, "
                         "rtol, why");
      }
    }
    auto text = [&](const char* key, std::string& dst) {
      const auto* n = t->get(key);
      if (n == nullptr || !n->is_string() || n->as_string()->get().empty()) {
        throw InputError(file, n ? line_of(*n) : th.line, where + "." + key,
                         "required: a non-empty string");
      }
      dst = n->as_string()->get();
    };
    auto number = [&](const char* key, double& dst) {
      const auto* n = t->get(key);
      if (n == nullptr) return;
      const auto v = n->value<double>();
      if (!v || !std::isfinite(*v) || *v < 0.0) {
        throw InputError(file, line_of(*n), where + "." + key, "must be a finite number >= 0");
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
    if (metric_names().count(th.metric) == 0) {
      throw InputError(file, line_of(*t->get("metric")), where + ".metric",
                       fmt::format("unknown metric '{}' (SPEC §4 names)", th.metric));
    }
    if (t->get("atol") == nullptr && t->get("rtol") == nullptr) {
      throw InputError(file, th.line, where, "needs atol, rtol or both");
    }
    if (const auto* n = t->get("episode")) {
      const auto v = n->value<int64_t>();
      if (!n->is_integer() || !v || *v < 0 || *v > 1000000) {
        throw InputError(file, line_of(*n), where + ".episode", "must be an integer >= 0");
      }
      th.episode = static_cast<int>(*v);
    }
    out.push_back(th);
  }
  return out;
}

std::vector<CheckOutcome> check_thresholds(const std::vector<Threshold>& thresholds,
                                           const std::vector<MetricValue>& metrics) {
  std::vector<CheckOutcome> out;
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
      if (!o.passed) {
        o.message = fmt::format("|{:.6g} - {:.6g}| = {:.4g} > {:.4g} (atol {:g} + rtol {:g})",
                                m.actual, m.desired, deviation, o.limit, th.atol, th.rtol);
      }
      out.push_back(o);
    }
    if (!matched) {
      CheckOutcome o;
      o.threshold = th;
      o.limit = th.atol;
      o.message = "not computed: the run is missing, unsupported or diverged, or has no such "
                  "metric";
      out.push_back(o);
    }
  }
  return out;
}

std::string junit_xml(const std::vector<CheckOutcome>& outcomes,
                      const std::vector<std::string>& diverged_runs) {
  std::size_t failures = diverged_runs.size();
  for (const auto& o : outcomes) failures += o.passed ? 0 : 1;
  std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  x += fmt::format("<testsuites name=\"planarbench check\" tests=\"{}\" failures=\"{}\">\n",
                   outcomes.size() + diverged_runs.size(), failures);
  x += fmt::format("  <testsuite name=\"planarbench\" tests=\"{}\" failures=\"{}\">\n",
                   outcomes.size() + diverged_runs.size(), failures);
  for (const auto& run : diverged_runs) {
    x += fmt::format("    <testcase classname=\"{}\" name=\"status\">\n", xml_escaped(run));
    x += fmt::format("      <failure message=\"run diverged\"/>\n    </testcase>\n");
  }
  for (const auto& o : outcomes) {
    x += fmt::format("    <testcase classname=\"{}.{}\" name=\"{}\">\n",
                     xml_escaped(o.threshold.case_name), xml_escaped(o.threshold.engine),
                     xml_escaped(test_name(o)));
    x += "      <properties>\n";
    x += fmt::format("        <property name=\"value\" value=\"{:.9g}\"/>\n", o.value.actual);
    x += fmt::format("        <property name=\"desired\" value=\"{:.9g}\"/>\n", o.value.desired);
    x += fmt::format("        <property name=\"error\" value=\"{:.9g}\"/>\n", o.value.error);
    x += fmt::format("        <property name=\"limit\" value=\"{:.9g}\"/>\n", o.limit);
    x += fmt::format("        <property name=\"why\" value=\"{}\"/>\n", xml_escaped(o.threshold.why));
    x += "      </properties>\n";
    if (!o.passed) {
      x += fmt::format("      <failure message=\"{}\"/>\n", xml_escaped(o.message));
    }
    x += "    </testcase>\n";
  }
  x += "  </testsuite>\n</testsuites>\n";
  return x;
}

std::string markdown_summary(const std::vector<CheckOutcome>& outcomes,
                             const std::vector<std::string>& diverged_runs) {
  std::size_t failed = 0;
  for (const auto& o : outcomes) failed += o.passed ? 0 : 1;
  std::string md = "## planarbench check\n\n";
  md += fmt::format("{} of {} checks passed{}.\n\n", outcomes.size() - failed, outcomes.size(),
                    diverged_runs.empty() ? ""
                                          : fmt::format("; {} run(s) diverged", diverged_runs.size()));
  for (const auto& r : diverged_runs) md += fmt::format("- **diverged**: {}\n", r);
  if (failed == 0) return md;
  md += "| case | engine | metric | value | limit | why |\n|---|---|---|---|---|---|\n";
  std::size_t shown = 0;
  for (const auto& o : outcomes) {
    if (o.passed) continue;
    if (++shown > 50) {
      md += fmt::format("\n… and {} more breaches (see the JUnit XML).\n", failed - 50);
      break;
    }
    md += fmt::format("| {} | {} | {} | {:.4g} | {:.4g} | {} |\n", o.threshold.case_name,
                      o.threshold.engine, test_name(o),
                      std::abs(o.value.actual - o.value.desired), o.limit, o.threshold.why);
  }
  return md;
}

}  // namespace pb
