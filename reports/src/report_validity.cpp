#include "report_validity.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "planarbench/reports/contact_validity.hpp"
#include "report_campaign.hpp"
#include "report_svg.hpp"
#include "file_id.hpp"

namespace pb::internal {

namespace {

// a log plot needs a floor: a sample below it (an exact 0: the reference's
// Coulomb friction, a rigid engine's stick) is drawn on it; 1e-17 is below
// the unit roundoff of doubles (1.1e-16), so a rounding-level value stands above it
constexpr double kPlotFloor = 1e-17;
// time buckets of a per-step plot: each keeps its largest value
constexpr int kBuckets = 400;

std::string number(double x) { return std::isnan(x) ? std::string("-") : fmt::format("{:.2g}", x); }

std::string max_p99(const ValiditySeries& s) {
  if (s.samples == 0) return "-";
  return fmt::format("{} ({})", number(s.max), number(s.p99));
}

// the worst of one series over the runs of an engine, and where
struct Worst {
  double value = -1.0;  // < 0: no sample anywhere
  std::string where;
  void take(const ValiditySeries& s, const std::string& case_name) {
    if (s.samples == 0) return;
    if (value < 0.0 || std::isnan(s.max) || s.max > value) {
      value = s.max;
      where = case_name;
    }
  }
};

struct EngineWorst {
  Worst cone, dissipation, creep, distance, law, complementarity;
};

std::string reading(const std::string& engine, const EngineWorst& w) {
  std::vector<std::string> parts;
  if (w.cone.value >= 0.0) {
    parts.push_back(w.cone.value == 0.0
                        ? std::string("Coulomb cone respected exactly")
                        : fmt::format("Coulomb cone respected to {} of mu F_n ({})",
                                      number(w.cone.value), w.cone.where));
  }
  // 1 + sign(v) F_t / (mu F_n): 0 at Coulomb's maximum dissipation, 1 with no
  // friction force, above 1 when the friction pushes along the slip
  if (w.dissipation.value == 0.0) {
    parts.push_back("dissipates at Coulomb's maximum rate while sliding");
  } else if (w.dissipation.value > 1.0) {
    parts.push_back(fmt::format("while sliding its friction at times pushes along the slip "
                                "(1 + sign(v_t) F_t / (mu F_n) up to {}, {})",
                                number(w.dissipation.value), w.dissipation.where));
  } else if (w.dissipation.value > 0.0 || std::isnan(w.dissipation.value)) {
    parts.push_back(fmt::format("short of the maximum dissipation by up to {} of mu F_n while "
                                "sliding ({})",
                                number(w.dissipation.value), w.dissipation.where));
  }
  if (w.creep.value >= 0.0) {
    parts.push_back(fmt::format("creeps up to {} m/s inside the cone ({})", number(w.creep.value),
                                w.creep.where));
  }
  parts.push_back(w.distance.value > 0.0 ? fmt::format("pushes up to {} N across an open gap ({})",
                                                       number(w.distance.value), w.distance.where)
                                         : std::string("no force at a distance"));
  if (w.law.value >= 0.0) {
    parts.push_back(fmt::format("normal force off the case's law by up to {} of its peak ({})",
                                number(w.law.value), w.law.where));
  }
  if (w.complementarity.value > 0.0) {
    parts.push_back(fmt::format("up to {} W of normal force on a separating contact ({})",
                                number(w.complementarity.value), w.complementarity.where));
  }
  std::string out = engine + ": ";
  for (std::size_t i = 0; i < parts.size(); ++i) out += (i == 0 ? "" : "; ") + parts[i];
  return out + ".";
}

// per-step values bucketed into their largest over kBuckets time spans
LinePlot::Line bucketed(const std::string& engine, std::size_t index, double t_end,
                        const std::vector<std::pair<double, double>>& points) {
  LinePlot::Line line{engine, engine_colour(engine, index), {}, {}, {}, {}};
  const double span = t_end > 0.0 ? t_end / kBuckets : 1.0;
  std::map<long, std::pair<double, double>> best;  // bucket -> (t, value)
  for (const auto& [t, v] : points) {
    if (std::isnan(v)) continue;
    const auto b = static_cast<long>(std::floor(t / span));
    const double y = std::max(v, kPlotFloor);
    auto it = best.find(b);
    if (it == best.end() || y > it->second.second) best[b] = {t, y};
  }
  for (const auto& [b, tv] : best) {
    line.x.push_back(tv.first);
    line.y.push_back(tv.second);
  }
  return line;
}

// one run's samples of each pair of its case, computed once for the table and
// the figures
struct RunSamples {
  const RunResult* run = nullptr;
  std::vector<std::vector<ValiditySample>> pairs;  // index = Case::contacts index
};

// a case's per-step figure of one quantity, or none (false) when no run has a
// value; scatter: points alone
bool add_figure(const Case& c, const std::vector<RunSamples>& runs, const char* suffix,
                const std::string& title, const std::string& y_label,
                double (*value)(const ValiditySample&), bool (*wanted)(const Case&, std::size_t),
                bool scatter, std::vector<CampaignFigure>& out) {
  LinePlot plot;
  plot.title = title;
  plot.x_label = "t (s)";
  plot.y_label = y_label;
  plot.y_log = true;
  std::size_t index = 0;
  for (const RunSamples& r : runs) {
    std::vector<std::pair<double, double>> points;
    for (std::size_t k = 0; k < r.pairs.size(); ++k) {
      if (!wanted(c, k)) continue;
      for (const ValiditySample& s : r.pairs[k]) points.emplace_back(s.time_s, value(s));
    }
    LinePlot::Line line = bucketed(r.run->engine_name, index++, c.duration_s, points);
    line.scatter = scatter;
    if (!line.x.empty()) plot.lines.push_back(std::move(line));
  }
  if (plot.lines.empty()) return false;
  out.push_back({file_id(c.name + suffix), plot.title, line_plot_svg(plot)});
  return true;
}

bool friction_pair(const Case& c, std::size_t k) { return c.contacts[k].has_friction(); }
bool frictionless_pair(const Case& c, std::size_t k) { return !c.contacts[k].has_friction(); }

// the friction's distance from Coulomb: the cone violation while it holds,
// |1 + sign(v) F_t / (mu F_n)| while it slides (beyond the cone it is negative)
double coulomb_distance(const ValiditySample& s) {
  return s.sliding ? std::abs(s.dissipation) : s.cone;
}
double law_residual(const ValiditySample& s) { return s.law_residual; }
double stick_creep(const ValiditySample& s) { return s.stick_creep_mps; }

}  // namespace

ValiditySection validity_section(const std::vector<Case>& cases, const ResultsFile& results) {
  ValiditySection s;
  s.table.id = "validity";
  s.table.title = "Per-step violations, max (p99) over each pair's samples";
  s.table.note =
      "cone: max(0, |F_t| - mu F_n) / (mu F_n); dissipation: 1 + sign(v_t) F_t / (mu F_n) while "
      "|v_t| > 1e-3 m/s (0: Coulomb's maximum dissipation); creep: |v_t| while |F_t| < (1 - 1e-3) "
      "mu F_n (m/s); at a distance: F_n with the gap open by more than 1e-9 m (N); law: |F_n - "
      "F_law(delta, delta_dot)| / the pair's peak F_n, smooth pairs only; complementarity: F_n "
      "max(0, -delta_dot) after the step (W; 0 for a rigid contact but its restitution). "
      "'-': no sample of that kind (no friction, never sliding, a faced pair).";
  s.table.columns = {"case", "engine", "pair", "mu", "cone", "dissipation", "creep (m/s)",
                     "at a distance (N)", "law", "complementarity (W)"};
  std::map<std::string, EngineWorst> worst;
  std::vector<std::string> engines;  // in order of first appearance
  int coulomb_figures = 0;           // the cases with friction drawn
  for (std::size_t i = 0; i < cases.size() && i < results.cases.size(); ++i) {
    const Case& c = cases[i];
    std::vector<RunSamples> runs;
    for (const auto& r : results.cases[i].runs) {
      if (r.engine_name == "analytic" || r.status == RunStatus::unsupported) continue;
      RunSamples rs{&r, {}};
      for (std::size_t k = 0; k < c.contacts.size(); ++k) {
        rs.pairs.push_back(validity_samples(c, r, k));
      }
      for (std::size_t k = 0; k < c.contacts.size(); ++k) {
        const PairValidity v = pair_validity(c, k, rs.pairs[k]);
        if (v.samples == 0) continue;
        if (worst.find(r.engine_name) == worst.end()) engines.push_back(r.engine_name);
        EngineWorst& w = worst[r.engine_name];
        w.cone.take(v.cone, c.name);
        w.dissipation.take(v.dissipation, c.name);
        w.creep.take(v.stick_creep_mps, c.name);
        w.distance.take(v.force_at_distance_n, c.name);
        w.law.take(v.law_residual, c.name);
        w.complementarity.take(v.complementarity_w, c.name);
        s.table.rows.push_back({c.name, r.engine_name, v.pair, fmt::format("{:g}", v.mu),
                                max_p99(v.mu > 0.0 ? v.cone : v.frictionless_tangent),
                                max_p99(v.dissipation), max_p99(v.stick_creep_mps),
                                v.force_at_distance_n.samples == 0 ? "0" : number(v.force_at_distance_n.max),
                                max_p99(v.law_residual), max_p99(v.complementarity_w)});
        s.table.row_status.emplace_back();
      }
      runs.push_back(std::move(rs));
    }
    coulomb_figures +=
        add_figure(c, runs, "_coulomb", c.name + ": friction's distance from Coulomb per sample",
                   "fraction of mu F_n", coulomb_distance, friction_pair, false, s.figures) ? 1 : 0;
    add_figure(c, runs, "_creep", c.name + ": slip while the load is inside the cone, per sample",
               "|v_t| (m/s)", stick_creep, friction_pair, false, s.figures);
    add_figure(c, runs, "_law", c.name + ": normal-law residual per sample",
               "|F_n - F_law| / peak F_n", law_residual, frictionless_pair,
               true,  // impacts: points, no line across the flights between them
               s.figures);
  }
  for (const auto& e : engines) s.readings.push_back(reading(e, worst[e]));
  if (!s.table.rows.empty()) {
    s.note = fmt::format(
        "Each engine's contact forces judged per output sample (SPEC §9; Le Lidec et al., "
        "T-RO 2024, judge contact solvers by the same violations): the Coulomb cone, the "
        "maximum dissipation while sliding, the creep of a stick, a force across an open gap, "
        "the normal force against the case's law, and a normal force on a separating contact. "
        "Computed from the results file's contacts columns by the same code for every engine. "
        "Plots: friction's distance from Coulomb per sample on the {} cases with friction (the "
        "cone violation while it holds, |dissipation deficit| while it slides) and the slip "
        "while the load is inside the cone (a stick's creep), the normal-law residual on the "
        "cases without friction; each line is the largest value per "
        "1/{} of the run, values below {:g} drawn at it.",
        coulomb_figures, kBuckets, kPlotFloor);
  }
  return s;
}

}  // namespace pb::internal
