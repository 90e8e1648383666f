#include "report_friction.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <variant>

#include "planarbench/case_loader.hpp"
#include "planarbench/reports/friction_metrics.hpp"
#include "report_campaign.hpp"
#include "report_svg.hpp"
#include "file_id.hpp"

namespace pb::internal {

namespace {

// a log plot needs a floor: drifts below it (Box2D's exact stick, the
// truth's 0) are drawn there; 1e-12 m is below anything an engine resolves
constexpr double kDriftFloor_m = 1e-12;
// points of the closed form's curve between 0.5 and 1.5
constexpr int kCurvePoints = 201;

const RunResult* run_of(const CaseRuns& cr, const std::string& engine) {
  for (const auto& r : cr.runs) {
    if (r.engine_name == engine) return &r;
  }
  return nullptr;
}

// the hold figure of one case, when its truth holds a body at rest
void add_hold_figure(const Case& c, const CaseRuns& cr, FrictionSection& s) {
  const RunResult* truth = run_of(cr, "analytic");
  if (truth == nullptr || truth->status != RunStatus::ok) return;
  LinePlot plot;
  plot.title = fmt::format("{}: drift of the contact point while friction should hold it", c.name);
  plot.x_label = "t (s)";
  plot.y_label = "|drift| along the incline (m)";
  plot.y_log = true;
  std::size_t index = 0;
  for (const auto& r : cr.runs) {
    if (r.engine_name == "analytic" || r.status != RunStatus::ok) continue;
    const auto series = hold_drift_series(c, r, *truth);
    if (series.empty()) return;  // the truth does not hold at rest: not a hold case
    LinePlot::Line line{r.engine_name, engine_colour(r.engine_name, index++), {}, {}, {}, {}};
    // every 10th output sample: 1000 points draw a second smoothly
    for (std::size_t i = 0; i < series.size(); i += 10) {
      line.x.push_back(series[i].first);
      line.y.push_back(std::max(series[i].second, kDriftFloor_m));
    }
    plot.lines.push_back(std::move(line));
  }
  if (plot.lines.empty()) return;
  s.figures.push_back({file_id(c.name + "_hold_drift"), plot.title, line_plot_svg(plot)});
}

// the curve's case: tan(theta) of its first half-plane pair's line against
// gravity, or NaN
double tan_theta(const Case& c) {
  for (const ContactPair& p : c.contacts) {
    const Body& line = c.bodies[static_cast<std::size_t>(p.body_a)];
    if (!std::holds_alternative<HalfPlane>(line.shape)) continue;
    const Vec2 t(std::cos(line.angle_rad), std::sin(line.angle_rad));
    const Vec2 n(-t.y(), t.x());
    const double along = std::abs(c.gravity_mps2.dot(t));
    const double into = -c.gravity_mps2.dot(n);
    return into > 0.0 ? along / into : std::nan("");
  }
  return std::nan("");
}

// the friction curve from a campaign: an axis on a pair's friction and the
// metric slide_acceleration_mps2
void add_curve(const CampaignTable& t, const std::string& file, FrictionSection& s) {
  std::size_t axis = t.axes.size();
  for (std::size_t a = 0; a < t.axes.size(); ++a) {
    const std::string& key = t.axes[a].key;
    if (key.size() >= 9 && key.compare(key.size() - 9, 9, ".friction") == 0) axis = a;
  }
  std::size_t metric = t.metrics.size();
  for (std::size_t m = 0; m < t.metrics.size(); ++m) {
    if (t.metrics[m].name == "slide_acceleration_mps2") metric = m;
  }
  if (axis == t.axes.size() || metric == t.metrics.size() || t.cases.empty()) return;
  const CampaignCase& cc = t.cases.front();
  SettingsOverrides keys;
  for (const auto& [k, v] : cc.overrides) {
    if (is_case_key(k)) keys.set(k, v, SettingSource{"campaign", 0});
  }
  const Case c = parse_case(cc.text, cc.path, cc.name, keys);
  const double tan_th = tan_theta(c);
  if (!std::isfinite(tan_th)) return;
  const double g = c.gravity_mps2.norm();
  const double theta = std::atan(tan_th);
  auto closed_form = [&](double mu) {
    // holds iff tan(theta) <= mu (SPEC §7)
    return tan_th <= mu ? 0.0 : g * (std::sin(theta) - mu * std::cos(theta));
  };

  LinePlot plot;
  plot.title = fmt::format("{}: steady acceleration against tan(theta) / mu (the friction curve)",
                           cc.name);
  plot.x_label = "tan(theta) / mu";
  plot.y_label = "a along the incline (m/s^2)";
  LinePlot::Line truth{"closed form", "#000000", {}, {}, {}, {}};
  double lo = 1e300, hi = -1e300;
  for (double v : t.axes[axis].values) {
    lo = std::min(lo, tan_th / v);
    hi = std::max(hi, tan_th / v);
  }
  for (int i = 0; i < kCurvePoints; ++i) {
    const double r = lo + (hi - lo) * i / (kCurvePoints - 1);
    truth.x.push_back(r);
    truth.y.push_back(closed_form(tan_th / r));
  }
  plot.lines.push_back(std::move(truth));
  // per engine its points, by ratio
  std::map<double, std::map<std::string, double>> table;
  for (std::size_t e = 0; e < t.engines.size(); ++e) {
    const std::string& engine = t.engines[e];
    LinePlot::Line line{engine, engine_colour(engine, e), {}, {}, {}, {}};
    std::vector<std::pair<double, double>> points;
    for (const auto& run : t.runs) {
      if (run.engine != engine || run.case_name != cc.name) continue;
      const double mu = run.axis_values[axis];
      const double r = tan_th / mu;
      const double a = run.status == RunStatus::ok ? run.metrics[metric] : std::nan("");
      points.emplace_back(r, a);
      table[r][engine] = a;
    }
    std::sort(points.begin(), points.end());
    for (const auto& [r, a] : points) {
      line.x.push_back(r);
      line.y.push_back(a);
    }
    if (!line.x.empty()) plot.lines.push_back(std::move(line));
  }
  s.curve_file = file;
  s.figures.push_back({file_id(cc.name + "_friction_curve"), plot.title, line_plot_svg(plot)});
  s.curve.id = "friction-curve";
  s.curve.title = "Friction curve: steady acceleration (m/s^2) per tan(theta) / mu";
  s.curve.note = fmt::format(
      "From {}: case {} (tan(theta) = {:.4g}), the pair's friction mu swept; each run's "
      "acceleration is the slope of its speed along the incline over the run's second half. "
      "Closed form: 0 while tan(theta) / mu <= 1 (it holds), g (sin(theta) - mu cos(theta)) "
      "beyond.",
      file, cc.name, tan_th);
  s.curve.columns = {"tan(theta) / mu", "mu", "closed form"};
  for (const auto& e : t.engines) s.curve.columns.push_back(e);
  for (const auto& [r, by_engine] : table) {
    std::vector<std::string> row = {fmt::format("{:.2f}", r), fmt::format("{:.4g}", tan_th / r),
                                     fmt::format("{:.5f}", closed_form(tan_th / r))};
    for (const auto& e : t.engines) {
      const auto it = by_engine.find(e);
      row.push_back(it == by_engine.end() || !std::isfinite(it->second)
                        ? "-"
                        : fmt::format("{:.5f}", it->second));
    }
    s.curve.rows.push_back(std::move(row));
    s.curve.row_status.emplace_back("");
  }
}

// the family's metrics: the errors a campaign records against the closed form
struct FamilyMetric {
  const char* name;     // campaign metric
  const char* kind;     // what the truth does
  const char* y_label;
  bool against_v0;      // x: the throw's speed, else tan(theta) / mu
};
constexpr FamilyMetric kFamilyMetrics[] = {
    {"hold_drift_m", "held", "|drift| of the contact point (m)", false},
    {"slide_acceleration_error", "sliding", "|a - a_closed| / a_closed", false},
    {"stop_time_error", "stopping", "|t_stop - v0 / (mu g)| / (v0 / (mu g))", true},
};

// the block family from a campaign recording its friction errors: per
// metric a log plot of each engine's error per member, and a table per
// engine of the members judged and the worst error
bool add_family(const CampaignTable& t, const std::string& file, FrictionSection& s) {
  std::vector<std::size_t> metric_index;
  for (const FamilyMetric& fm : kFamilyMetrics) {
    std::size_t k = t.metrics.size();
    for (std::size_t m = 0; m < t.metrics.size(); ++m) {
      if (t.metrics[m].name == fm.name) k = m;
    }
    metric_index.push_back(k);
  }
  if (std::all_of(metric_index.begin(), metric_index.end(),
                  [&](std::size_t k) { return k == t.metrics.size(); })) {
    return false;
  }
  // each member's x: tan(theta) / mu of its first pair, or its body's speed
  std::map<std::string, std::pair<double, double>> x_of;  // case -> (tan / mu, v0)
  for (const CampaignCase& cc : t.cases) {
    SettingsOverrides keys;
    for (const auto& [k, v] : cc.overrides) {
      if (is_case_key(k)) keys.set(k, v, SettingSource{"campaign", 0});
    }
    const Case c = parse_case(cc.text, cc.path, cc.name, keys);
    const ContactPair* p = c.first_pair_with_friction();
    double speed = 0.0;
    for (const Body& b : c.bodies) speed = std::max(speed, b.velocity_mps.norm());
    x_of[cc.name] = {p != nullptr ? tan_theta(c) / p->friction : std::nan(""), speed};
  }
  s.family.id = "block-family";
  s.family.title = "Block family: members and worst error against the closed form, per engine";
  s.family.note = fmt::format(
      "From {}: every block of the campaign's cases at rest in the static pose of its first "
      "phase; held: the drift of its contact point (m); sliding and stopping: the relative error "
      "of the steady acceleration and of the stop time. A member an engine does not support or "
      "a run that failed is counted apart.",
      file);
  s.family.columns = {"engine"};
  for (const FamilyMetric& fm : kFamilyMetrics) {
    s.family.columns.push_back(fmt::format("{}: members", fm.kind));
    s.family.columns.push_back(fmt::format("{}: worst", fm.kind));
  }
  s.family.columns.push_back("not run");
  std::vector<std::vector<std::string>> rows(t.engines.size());
  std::vector<std::size_t> not_run(t.engines.size(), 0);
  for (std::size_t e = 0; e < t.engines.size(); ++e) {
    for (const auto& run : t.runs) {
      if (run.engine == t.engines[e] && run.status != RunStatus::ok) ++not_run[e];
    }
    rows[e].push_back(t.engines[e]);
  }
  for (std::size_t f = 0; f < std::size(kFamilyMetrics); ++f) {
    const FamilyMetric& fm = kFamilyMetrics[f];
    const std::size_t k = metric_index[f];
    LinePlot plot;
    plot.title = fmt::format("Block family, {}: {} per member", fm.kind, fm.name);
    plot.x_label = fm.against_v0 ? "v0 (m/s)" : "tan(theta) / mu";
    plot.y_label = fm.y_label;
    plot.y_log = true;
    for (std::size_t e = 0; e < t.engines.size(); ++e) {
      LinePlot::Line line{t.engines[e], engine_colour(t.engines[e], e), {}, {}, {}, {}};
      line.scatter = true;
      std::size_t members = 0;
      double worst = 0.0;
      for (const auto& run : t.runs) {
        if (k == t.metrics.size() || run.engine != t.engines[e] || run.status != RunStatus::ok) {
          continue;
        }
        const double v = run.metrics[k];
        if (!std::isfinite(v)) continue;
        const auto& [ratio, v0] = x_of[run.case_name];
        ++members;
        worst = std::max(worst, std::abs(v));
        line.x.push_back(fm.against_v0 ? v0 : ratio);
        line.y.push_back(std::max(std::abs(v), kDriftFloor_m));
      }
      rows[e].push_back(std::to_string(members));
      rows[e].push_back(members > 0 ? fmt::format("{:.3g}", worst) : "-");
      if (!line.x.empty()) plot.lines.push_back(std::move(line));
    }
    if (!plot.lines.empty()) {
      s.figures.push_back({file_id(std::string("block_family_") + fm.name), plot.title,
                           line_plot_svg(plot)});
    }
  }
  for (std::size_t e = 0; e < t.engines.size(); ++e) {
    rows[e].push_back(std::to_string(not_run[e]));
    s.family.rows.push_back(std::move(rows[e]));
    s.family.row_status.emplace_back("");
  }
  return true;
}

}  // namespace

FrictionSection friction_section(const std::vector<Case>& cases, const ResultsFile& results,
                                 const std::vector<NamedCampaign>& campaigns) {
  FrictionSection s;
  for (std::size_t i = 0; i < cases.size() && i < results.cases.size(); ++i) {
    if (cases[i].first_pair_with_friction() != nullptr) add_hold_figure(cases[i], results.cases[i], s);
  }
  for (const NamedCampaign& c : campaigns) {
    if (!add_family(*c.table, c.file, s)) add_curve(*c.table, c.file, s);
  }
  if (!s.figures.empty()) {
    s.note =
        "Coulomb friction (SPEC §7): how far each engine lets a body that friction must hold "
        "drift (its contact point's displacement along the incline, log scale; values below "
        "1e-12 m drawn at 1e-12 m), and the friction curve: the steady acceleration of a block "
        "on an incline against tan(theta) / mu, where the closed form turns from holding (0) to "
        "sliding at 1.0; with the block family (campaigns/block_family.toml), each engine's "
        "error on every block of it against tan(theta) / mu or the throw's speed (values below "
        "1e-12 drawn at 1e-12). Every friction metric is in the metrics table (hold_drift_m, "
        "creep_speed_mps, slide_acceleration_mps2, ...); each engine's friction model and "
        "settings are in its mapping.";
  }
  return s;
}

}  // namespace pb::internal
