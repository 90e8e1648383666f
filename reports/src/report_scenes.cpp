#include "report_scenes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <string>

#include "planarbench/reports/scene_metrics.hpp"
#include "report_campaign.hpp"
#include "report_svg.hpp"
#include "file_id.hpp"

namespace pb::internal {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// the family a scene belongs to: the kind of its first generator
std::string family_of(const Case& c) {
  return c.generated.empty() ? std::string() : scene_kind_name(c.generated.front().kind);
}

std::string cell(double v, const char* unit = "") {
  if (std::isnan(v)) return "";
  return fmt::format("{:.3g}{}", v, unit);
}

const char* family_title(const std::string& family) {
  if (family == "stack") return "Stacks";
  if (family == "pyramid") return "Pyramids";
  if (family == "row") return "Rows (cradles)";
  return "Piles";
}

struct Row {
  std::string scene;
  int bodies = 0;
  std::string engine;
  std::string status;
  std::map<std::string, double> value;  // scene metric -> value
  double cost = kNaN;                   // s per simulated s
};

}  // namespace

ScenesSection scenes_section(const std::vector<Case>& cases, const ResultsFile& results) {
  ScenesSection s;
  std::map<std::string, std::vector<Row>> by_family;
  for (std::size_t i = 0; i < cases.size() && i < results.cases.size(); ++i) {
    const Case& c = cases[i];
    if (c.generated.empty()) continue;
    const CaseRuns& cr = results.cases[i];
    const RunResult* truth = nullptr;
    for (const RunResult& r : cr.runs) {
      if (r.engine_name == "analytic" && r.status == RunStatus::ok) truth = &r;
    }
    int moving = 0;
    for (const Body& b : c.bodies) moving += b.fixed ? 0 : 1;
    for (const RunResult& r : cr.runs) {
      if (r.engine_name == "analytic" || r.status == RunStatus::unsupported) continue;
      Row row;
      row.scene = c.name;
      row.bodies = moving;
      row.engine = r.engine_name;
      row.status = run_status_name(r.status);
      // the signed sag as measured; the others as their error (desired 0 but
      // the support force's, against the weight)
      for (const MetricValue& m : scene_metrics(c, r, truth)) {
        row.value[m.metric] = m.metric == "sag_m" ? m.actual : m.error;
      }
      if (r.status == RunStatus::ok && c.duration_s > 0.0) row.cost = r.wall_time_s / c.duration_s;
      by_family[family_of(c)].push_back(row);
    }
  }
  if (by_family.empty()) return s;
  s.note =
      "Scenes of many bodies (SPEC §11): each engine with its own broad phase on every pair a "
      "contact group lets touch. Stacks start at rest pressed in at their static pose (truth: "
      "nothing moves, interface k from the top carries k m g); pyramids are released touching "
      "and settle (the support then carries the weight); rows are struck along their line "
      "without gravity (truth: binary closed-form impacts); piles fall from a grid into a box "
      "(no closed form: energy, penetration, engine against engine). Sag: the top body's sink "
      "at the end; drift: the largest sideways displacement; creep: the top's mean speed over "
      "the second half; energy ratio: max KE / (KE(0) + U_c(0) + work of gravity), <= 1 for "
      "passive contacts. Cost: wall seconds per simulated second, one run.";
  for (auto& entry : by_family) {
    // named, not bound: Clang 14 cannot capture a structured binding
    const std::string& family = entry.first;
    std::vector<Row>& rows = entry.second;
    std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) {
      return a.bodies < b.bodies || (a.bodies == b.bodies && a.scene < b.scene);
    });
    Table t;
    t.id = "scenes-" + family;
    t.title = family_title(family);
    const bool standing = family == "stack" || family == "pyramid";
    t.columns = {"scene", "bodies", "engine", "status"};
    if (standing) {
      for (const char* col : {"sag (m)", "sideways drift (m)", "settled creep (m/s)",
                              "support force / weight - 1", "interfaces vs k m g"}) {
        t.columns.push_back(col);
      }
    }
    t.columns.push_back("energy ratio");
    t.columns.push_back("deepest penetration (m)");
    t.columns.push_back("cost (s/s)");
    for (const Row& r : rows) {
      std::vector<std::string> cells = {r.scene, std::to_string(r.bodies), r.engine, r.status};
      auto v = [&](const char* name) {
        const auto it = r.value.find(name);
        return it == r.value.end() ? kNaN : it->second;
      };
      if (standing) {
        cells.push_back(cell(v("sag_m")));
        cells.push_back(cell(v("lateral_drift_m")));
        cells.push_back(cell(v("settled_creep_mps")));
        cells.push_back(cell(v("ground_force_error")));
        cells.push_back(cell(v("interface_force_error")));
      }
      cells.push_back(cell(v("energy_ratio")));
      cells.push_back(cell(v("deepest_penetration_m")));
      cells.push_back(cell(r.cost));
      t.rows.push_back(cells);
      t.row_status.push_back(r.status == "ok" ? "ok" : "fail");
    }
    s.tables.push_back(t);
    // against the number of bodies, where the family has several sizes
    std::map<std::string, std::map<int, Row>> per_engine;
    for (const Row& r : rows) {
      if (r.status == "ok") per_engine[r.engine][r.bodies] = r;
    }
    auto figure = [&](const std::string& what, const std::string& y_label,
                      const std::function<double(const Row&)>& y) {
      LinePlot p;
      p.title = fmt::format("{}: {} against bodies", family_title(family), what);
      p.x_label = "bodies";
      p.y_label = y_label;
      p.x_log = true;
      p.y_log = true;
      std::size_t k = 0;
      for (const auto& [engine, by_n] : per_engine) {
        LinePlot::Line line;
        line.name = engine;
        line.colour = engine_colour(engine, k++);
        for (const auto& [n, r] : by_n) {
          const double value = y(r);
          if (!(value > 0.0) || !std::isfinite(value)) continue;
          line.x.push_back(n);
          line.y.push_back(value);
        }
        if (line.x.size() >= 2) p.lines.push_back(line);
      }
      if (p.lines.empty()) return;
      s.figures.push_back({file_id("scenes_" + family + "_" + what), p.title, line_plot_svg(p)});
    };
    if (standing) {
      // a log axis: the sag's size (a stack that rose has a negative sag,
      // signed in the table)
      figure("sag", "|sag| (m)", [](const Row& r) {
        const auto it = r.value.find("sag_m");
        return it == r.value.end() ? kNaN : std::abs(it->second);
      });
    }
    figure("cost", "wall s per simulated s", [](const Row& r) { return r.cost; });
  }
  return s;
}

}  // namespace pb::internal
