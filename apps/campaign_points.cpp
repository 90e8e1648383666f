#include "campaign_points.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "campaign_size.hpp"
#include "cli_common.hpp"
#include "planarbench/case_loader.hpp"
#include "planarbench/did_you_mean.hpp"
#include "planarbench/engines.hpp"
#include "planarbench/errors.hpp"

namespace pb::cli {

namespace {

// the case and engines at one point of `sub` (a plan of one case and some of
// the axes); the loader's or an engine's refusal, or "" when both accept it
std::string problem_at(const CampaignPlan& sub, const CampaignPlan::RunRef& r,
                       const std::vector<std::string>& set_assignments) {
  std::vector<std::string> assignments = set_assignments;
  for (const auto& [key, value] : sub.assignments(r)) assignments.push_back(key + "=" + value);
  try {
    const Overrides o = parse_overrides(assignments);
    // the text the plan read once (load_case would read the file again per point)
    const Case& planned = sub.cases.front().c;
    const Case loaded =
        parse_case(planned.source_text, planned.source_path, planned.name, o.case_keys);
    check_engine_settings(o.engine_keys, sub.engines);
    const SettingsOverrides settings = engine_settings_for(loaded, o.engine_keys);
    for (const auto& e : sub.engines) make_engine(e)->settings().apply(settings);
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

// the value indices of an axis that a combination check visits: all of them,
// or (corners) its first, last, smallest and largest
std::vector<std::size_t> visited(const CampaignAxisPlan& a, bool corners) {
  const auto& v = a.axis.values;
  std::vector<std::size_t> out;
  if (!corners) {
    for (std::size_t i = 0; i < v.size(); ++i) out.push_back(i);
    return out;
  }
  const auto lo = static_cast<std::size_t>(std::min_element(v.begin(), v.end()) - v.begin());
  const auto hi = static_cast<std::size_t>(std::max_element(v.begin(), v.end()) - v.begin());
  out = {0, v.size() - 1, lo, hi};
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace

void check_axis_points(const CampaignPlan& plan, bool quiet) {
  std::vector<std::string> set_assignments;
  for (const auto& [k, v] : plan.set) set_assignments.push_back(k + "=" + v);
  auto fail = [&](std::size_t axis, const std::string& field, const std::string& what) {
    throw InputError(plan.file, axis < plan.axis_lines.size() ? plan.axis_lines[axis] : 0, field,
                     what);
  };
  // ---- each axis alone ----
  std::int64_t to_check = 0;
  for (const auto& a : plan.axes) {
    to_check += static_cast<std::int64_t>(plan.cases.size()) *
                (a.axis.kind == "perturb" ? 1 : static_cast<std::int64_t>(a.axis.values.size()));
  }
  PlanProgress checking("checking every axis point against every case and engine", to_check, quiet);
  std::int64_t checked = 0;
  for (std::size_t k = 0; k < plan.axes.size(); ++k) {
    const CampaignAxisPlan& a = plan.axes[k];
    const std::string where = fmt::format("axis[{}]", k);
    CampaignPlan single;
    single.engines = plan.engines;
    single.axes = {a};
    for (const CampaignCasePlan& cp : plan.cases) {
      single.cases = {cp};
      if (a.axis.kind == "perturb" && a.body != "*" &&
          std::none_of(cp.c.bodies.begin(), cp.c.bodies.end(),
                       [&](const Body& b) { return !b.fixed && b.name == a.body; })) {
        fail(k, where + ".key",
             fmt::format("case '{}' has no moving body '{}' (its moving bodies: {}); use "
                         "bodies.*.{} for every moving body of each case",
                         cp.c.name, a.body, join_words(cp.moving_bodies), a.field));
      }
      // a random axis: its first sample stands for the rest (same keys and types)
      const std::size_t points = a.axis.kind == "perturb" ? 1 : a.axis.values.size();
      for (std::size_t p = 0; p < points; ++p) {
        checking.tick(++checked);
        CampaignPlan::RunRef r;
        r.point = {p};
        if (const std::string why = problem_at(single, r, set_assignments); !why.empty()) {
          fail(k, where,
               fmt::format("at {} on case '{}': {}", a.axis.values[p], cp.c.name, why));
        }
      }
    }
  }

  // ---- the axes that change the case, together ----
  std::vector<std::size_t> joint;
  for (std::size_t k = 0; k < plan.axes.size(); ++k) {
    if (plan.axes[k].case_key && plan.axes[k].axis.kind != "perturb") joint.push_back(k);
  }
  if (joint.size() < 2) return;
  std::int64_t combinations = 1;
  for (const std::size_t k : joint) {
    combinations = std::min<std::int64_t>(
        combinations * static_cast<std::int64_t>(plan.axes[k].axis.values.size()),
        kMaxCheckedCombinations + 1);
  }
  const bool corners = combinations > kMaxCheckedCombinations;
  CampaignPlan sub;
  sub.engines = plan.engines;
  std::vector<std::vector<std::size_t>> values;
  std::string fields;
  for (const std::size_t k : joint) {
    sub.axes.push_back(plan.axes[k]);
    values.push_back(visited(plan.axes[k], corners));
    fields += (fields.empty() ? "" : ", ") + fmt::format("axis[{}]", k);
  }
  for (const CampaignCasePlan& cp : plan.cases) {
    sub.cases = {cp};
    std::vector<std::size_t> digit(joint.size(), 0);  // a mixed-radix counter over `values`
    while (true) {
      CampaignPlan::RunRef r;
      for (std::size_t j = 0; j < joint.size(); ++j) r.point.push_back(values[j][digit[j]]);
      if (const std::string why = problem_at(sub, r, set_assignments); !why.empty()) {
        std::string point;
        for (std::size_t j = 0; j < joint.size(); ++j) {
          point += (point.empty() ? "" : ", ") +
                   fmt::format("{} = {}", sub.axes[j].axis.key, sub.axes[j].axis.values[r.point[j]]);
        }
        fail(joint.front(), fields,
             fmt::format("the axes together: at {} on case '{}': {}", point, cp.c.name, why));
      }
      std::size_t j = 0;
      while (j < digit.size() && ++digit[j] == values[j].size()) digit[j++] = 0;
      if (j == digit.size()) break;
    }
  }
}

}  // namespace pb::cli
