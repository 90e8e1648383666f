#include "report_versions.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

#include "report_tables.hpp"

namespace pb::internal {

namespace {

constexpr const char* kOld = "mujoco";
constexpr const char* kNew = "mujoco3";
// relative: two values this close are the same figure (MuJoCo's own rounding
// differences between two compilers stay at ~1e-15; a change of the library's
// method shows far above)
constexpr double kSame = 1e-9;
// absolute, in the metric's unit: a residual at double rounding (a cone
// violation of 2e-16, a drift of 1e-15 m) is the same figure whatever its
// relative change
constexpr double kRoundingFloor = 1e-12;

// the same figure: equal, within kSame relative, both at rounding, or both
// not a number (a metric neither version has, e.g. a missing episode)
bool same_figure(double a, double b) {
  if (std::isnan(a) && std::isnan(b)) return true;
  return std::abs(a - b) <= std::max(kSame * std::max(std::abs(a), std::abs(b)), kRoundingFloor);
}

// (case, against, metric, episode)
using Key = std::tuple<std::string, std::string, std::string, int>;

Key key_of(const MetricValue& m) { return {m.case_name, m.against, m.metric, m.episode}; }

std::string label(const Key& k) {
  const auto& [c, against, metric, episode] = k;
  return episode >= 0 ? fmt::format("{} vs {} [episode {}]", metric, against, episode)
                      : fmt::format("{} vs {}", metric, against);
}

// the gate's word for an outcome
std::string verdict(const CheckOutcome& o) {
  if (o.passed) return fails_gate(o) ? "unexpected pass" : "pass";
  return fails_gate(o) ? "fail" : "known breach";
}

struct CaseRow {
  int compared = 0;
  int same = 0;
  double largest = -1.0;
  std::string largest_text;
  std::vector<std::string> verdicts;
};

}  // namespace

Table mujoco_versions_table(const std::vector<MetricValue>& metrics,
                            const std::vector<CheckOutcome>& outcomes) {
  Table t;
  t.id = "mujoco_versions";
  t.title = "MuJoCo versions: 2.2.2 vs 3.3.8";
  t.note = fmt::format(
      "Engine mujoco is Debian's native MuJoCo 2.2.2, engine mujoco3 MuJoCo's own WebAssembly "
      "build of 3.3.8 (npm mujoco-js 0.0.7): the same plan, MJCF and per-step contact rule, "
      "each at MuJoCo's defaults, so what differs here is MuJoCo's change between the versions. "
      "Per case: the metrics both have, how many agree to {:g} (relative; values both within "
      "{:g} of 0 count as rounding), the largest change, and every metric whose verdict differs.",
      kSame, kRoundingFloor);
  t.columns = {"case", "metrics compared", "same to 1e-9", "largest change (2.2.2 -> 3.3.8)",
               "verdicts that differ"};
  std::map<Key, const MetricValue*> old_values;
  std::map<Key, const MetricValue*> new_values;
  for (const auto& m : metrics) {
    if (m.metric.rfind("wall", 0) == 0) continue;  // a cost, not physics: timings table
    if (m.engine == kOld) old_values[key_of(m)] = &m;
    if (m.engine == kNew) new_values[key_of(m)] = &m;
  }
  std::map<Key, std::string> old_verdict;
  std::map<Key, std::string> new_verdict;
  for (const auto& o : outcomes) {
    if (o.value.metric.empty()) continue;
    if (o.value.engine == kOld) old_verdict[key_of(o.value)] = verdict(o);
    if (o.value.engine == kNew) new_verdict[key_of(o.value)] = verdict(o);
  }
  std::map<std::string, CaseRow> rows;
  for (const auto& [k, a] : old_values) {
    const auto it = new_values.find(k);
    if (it == new_values.end()) continue;
    const MetricValue& b = *it->second;
    CaseRow& row = rows[std::get<0>(k)];
    ++row.compared;
    const double change = std::abs(b.actual - a->actual) /
                          std::max(std::abs(a->actual), std::numeric_limits<double>::min());
    const bool same = same_figure(a->actual, b.actual);
    row.same += same ? 1 : 0;
    if (!same && !(change <= row.largest)) {
      row.largest = std::isnan(change) ? std::numeric_limits<double>::infinity() : change;
      row.largest_text = fmt::format("{}: {} -> {} ({:.2g} relative)", label(k),
                                     format_number(a->actual), format_number(b.actual), change);
    }
    const auto vo = old_verdict.find(k);
    const auto vn = new_verdict.find(k);
    if (vo != old_verdict.end() && vn != new_verdict.end() && vo->second != vn->second) {
      row.verdicts.push_back(fmt::format("{}: {} -> {}", label(k), vo->second, vn->second));
    }
  }
  for (const auto& [name, row] : rows) {
    std::string verdicts;
    for (const auto& v : row.verdicts) verdicts += (verdicts.empty() ? "" : "; ") + v;
    t.rows.push_back({name, std::to_string(row.compared), std::to_string(row.same),
                      row.largest_text.empty() ? "none" : row.largest_text,
                      verdicts.empty() ? "none" : verdicts});
    t.row_status.push_back(row.verdicts.empty() ? "" : "fail");
  }
  return t;
}

}  // namespace pb::internal
