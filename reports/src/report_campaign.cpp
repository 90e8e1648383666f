#include "report_campaign.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>

#include "planarbench/run_result.hpp"
#include "report_svg.hpp"
#include "report_work_precision_svg.hpp"
#include "file_id.hpp"

namespace pb::internal {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kWidth = 640.0;
constexpr double kHeight = 340.0;
constexpr double kLeft = 74.0;
constexpr double kRight = 150.0;  // the legend
constexpr double kTop = 40.0;
constexpr double kBottom = 46.0;
// the random axis' figures per case: one per point of the other axes, the first ones
constexpr std::size_t kMaxSpreadFigures = 8;

// an axis: its range, where a value lands, and its ticks
struct Axis {
  bool log = false;
  double lo = 0.0;
  double hi = 1.0;
  double px0 = 0.0;  // pixel of lo
  double px1 = 1.0;  // pixel of hi
  [[nodiscard]] double at(double v) const {
    const double f = log ? (std::log10(v) - lo) / (hi - lo) : (v - lo) / (hi - lo);
    return px0 + f * (px1 - px0);
  }
  [[nodiscard]] bool shows(double v) const { return std::isfinite(v) && (!log || v > 0.0); }
};

Axis make_axis(bool log, double lo, double hi, double px0, double px1) {
  Axis a;
  a.px0 = px0;
  a.px1 = px1;
  a.log = log;
  if (!std::isfinite(lo)) {
    lo = log ? 1e-3 : 0.0;
    hi = log ? 1.0 : 1.0;
  }
  if (log) {
    const Decades d = decades_of(lo, hi);
    a.lo = d.lo;
    a.hi = d.hi;
  } else {
    if (hi - lo <= 1e-12 * std::max(1.0, std::abs(hi))) {
      const double half = std::max(1e-9, 0.1 * std::abs(hi));
      lo -= half;
      hi += half;
    }
    const double step = tick_step(hi - lo, 5);
    a.lo = std::floor(lo / step) * step;
    a.hi = std::ceil(hi / step) * step;
  }
  return a;
}

std::vector<std::pair<double, std::string>> ticks(const Axis& a) {
  std::vector<std::pair<double, std::string>> out;
  if (a.log) {
    const int lo = static_cast<int>(a.lo);
    const int hi = static_cast<int>(a.hi);
    const int every = std::max(1, (hi - lo + 5) / 6);
    for (int k = lo; k <= hi; k += every) out.emplace_back(std::pow(10.0, k), decade_label(k));
    return out;
  }
  const double step = tick_step(a.hi - a.lo, 5);
  for (double v = a.lo; v <= a.hi + 1e-9 * step; v += step) {
    out.emplace_back(v, compact_number(std::abs(v) < 1e-12 * step ? 0.0 : v));
  }
  return out;
}

double median_of(std::vector<double> v) {
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct Stats {
  double median = std::nan("");
  double lo = std::nan("");
  double hi = std::nan("");
};

Stats stats_of(const std::vector<double>& v) {
  Stats s;
  s.median = median_of(v);
  for (const double x : v) {
    if (!std::isfinite(x)) continue;
    s.lo = std::isfinite(s.lo) ? std::min(s.lo, x) : x;
    s.hi = std::isfinite(s.hi) ? std::max(s.hi, x) : x;
  }
  return s;
}

std::string number_text(double v) {
  return std::isfinite(v) ? fmt::format("{:.4g}", v) : "-";
}

std::string stats_text(const Stats& s) {
  if (!std::isfinite(s.median)) return "-";
  if (s.lo == s.hi) return number_text(s.median);
  return fmt::format("{} ({}..{})", number_text(s.median), number_text(s.lo), number_text(s.hi));
}

bool all_positive_spanning(const std::vector<double>& v) {
  double lo = kInf;
  double hi = -kInf;
  for (const double x : v) {
    if (!(x > 0.0)) return false;
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  // log when the points span more than a factor 20
  return !v.empty() && hi / lo > 20.0;
}

// runs of one case grouped by a key of their axis points
using Rows = std::vector<const CampaignRun*>;

}  // namespace

double rms_spread(const std::vector<double>& x, const std::vector<double>& y) {
  double mx = 0.0;
  double my = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i])) continue;
    mx += x[i];
    my += y[i];
    ++n;
  }
  if (n == 0) return std::nan("");
  mx /= static_cast<double>(n);
  my /= static_cast<double>(n);
  double ss = 0.0;
  for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i])) continue;
    ss += (x[i] - mx) * (x[i] - mx) + (y[i] - my) * (y[i] - my);
  }
  return std::sqrt(ss / static_cast<double>(n));
}

std::string line_plot_svg(const LinePlot& p) {
  double xlo = kInf, xhi = -kInf, ylo = kInf, yhi = -kInf;
  const auto take = [](double v, bool log, double& lo, double& hi) {
    if (!std::isfinite(v) || (log && !(v > 0.0))) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  };
  for (const auto& l : p.lines) {
    for (std::size_t i = 0; i < l.x.size(); ++i) {
      if (!std::isfinite(l.y[i]) || (p.y_log && !(l.y[i] > 0.0))) continue;
      take(l.x[i], p.x_log, xlo, xhi);
      take(l.y[i], p.y_log, ylo, yhi);
      if (!l.lo.empty()) take(l.lo[i], p.y_log, ylo, yhi);
      if (!l.hi.empty()) take(l.hi[i], p.y_log, ylo, yhi);
    }
  }
  const double x0 = kLeft;
  const double x1 = kWidth - kRight;
  const double y0 = kHeight - kBottom;
  const double y1 = kTop;
  const Axis ax = make_axis(p.x_log, xlo, xhi, x0, x1);
  const Axis ay = make_axis(p.y_log, ylo, yhi, y0, y1);
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0:.0f}\" height=\"{1:.0f}\" "
      "viewBox=\"0 0 {0:.0f} {1:.0f}\" font-family=\"sans-serif\" font-size=\"11\">\n"
      "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n"
      "<text x=\"{2:.0f}\" y=\"22\" font-size=\"13\" font-weight=\"bold\">{3}</text>\n",
      kWidth, kHeight, kLeft, xml_escape(p.title));
  // frame, grid, ticks
  svg += fmt::format(
      "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" fill=\"none\" "
      "stroke=\"#888\"/>\n",
      x0, y1, x1 - x0, y0 - y1);
  for (const auto& [v, label] : ticks(ax)) {
    const double x = ax.at(v);
    svg += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\" stroke=\"#eee\"/>"
        "<text x=\"{0:.1f}\" y=\"{3:.1f}\" text-anchor=\"middle\">{4}</text>\n",
        x, y1, y0, y0 + 15, xml_escape(label));
  }
  for (const auto& [v, label] : ticks(ay)) {
    const double y = ay.at(v);
    svg += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"#eee\"/>"
        "<text x=\"{3:.1f}\" y=\"{4:.1f}\" text-anchor=\"end\">{5}</text>\n",
        x0, y, x1, x0 - 5, y + 4, xml_escape(label));
  }
  svg += fmt::format(
      "<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{}</text>\n"
      "<text transform=\"translate(16 {:.1f}) rotate(-90)\" text-anchor=\"middle\">{}</text>\n",
      0.5 * (x0 + x1), kHeight - 10, xml_escape(p.x_label + (p.x_log ? " (log)" : "")),
      0.5 * (y0 + y1), xml_escape(p.y_label + (p.y_log ? " (log)" : "")));
  // bands, then lines with their points, then the legend
  for (const auto& l : p.lines) {
    if (l.lo.empty() || l.hi.empty()) continue;
    std::string upper;
    std::string lower;
    for (std::size_t i = 0; i < l.x.size(); ++i) {
      if (!ax.shows(l.x[i]) || !ay.shows(l.lo[i]) || !ay.shows(l.hi[i])) continue;
      upper += fmt::format("{:.1f},{:.1f} ", ax.at(l.x[i]), ay.at(l.hi[i]));
      lower = fmt::format("{:.1f},{:.1f} ", ax.at(l.x[i]), ay.at(l.lo[i])) + lower;
    }
    if (!upper.empty()) {
      svg += fmt::format("<polygon points=\"{}{}\" fill=\"{}\" fill-opacity=\"0.15\" stroke=\"none\"/>\n",
                         upper, lower, l.colour);
    }
  }
  for (const auto& l : p.lines) {
    std::string path;
    std::string dots;
    bool pen = false;
    for (std::size_t i = 0; i < l.x.size(); ++i) {
      if (!ax.shows(l.x[i]) || !ay.shows(l.y[i])) {
        pen = false;  // a gap: the next point starts a new piece
        continue;
      }
      const double x = ax.at(l.x[i]);
      const double y = ay.at(l.y[i]);
      if (l.scatter) {
        dots += fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"1.6\"/>", x, y);
        continue;
      }
      path += fmt::format("{}{:.1f},{:.1f} ", pen ? "L" : "M", x, y);
      pen = true;
      if (l.x.size() <= 40) {
        dots += fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"2.5\" fill=\"{}\"/>", x, y,
                            l.colour);
      }
    }
    if (l.scatter && !dots.empty()) {
      svg += fmt::format("<g fill=\"{}\" fill-opacity=\"0.35\">{}</g>\n", l.colour, dots);
    } else if (!path.empty()) {
      svg += fmt::format("<path d=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"1.6\"/>{}\n",
                         path, l.colour, dots);
    }
  }
  double ly = y1 + 6;
  for (const auto& l : p.lines) {
    svg += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"{3}\" "
        "stroke-width=\"2\"/><text x=\"{4:.1f}\" y=\"{5:.1f}\">{6}</text>\n",
        x1 + 10, ly, x1 + 30, l.colour, x1 + 35, ly + 4, xml_escape(l.name));
    ly += 16;
  }
  if (p.lines.empty() || !std::isfinite(xlo)) {
    svg += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">no point to plot</text>\n",
                       0.5 * (x0 + x1), 0.5 * (y0 + y1));
  }
  return svg + "</svg>\n";
}

CampaignSection campaign_section(const CampaignTable& t, const std::string& file) {
  CampaignSection out;
  out.file = file;
  std::string axes_text;
  for (const auto& a : t.axes) {
    axes_text += fmt::format("{}{} ({}, key {}, {} points)", axes_text.empty() ? "" : "; ", a.name,
                             a.kind, a.key, a.values.size());
  }
  out.note = fmt::format(
      "{} of {} planned runs of the campaign {} ({} x {} engines{}{}). Each figure plots, per "
      "engine, the median over every run at that axis point (all points of the other axes) "
      "with a band from the smallest to the largest; wall time is per run, on the machine in "
      "the provenance. The spread of a random axis is, at each time, the largest over the "
      "moving bodies of the root-mean-square distance of the samples' positions from their "
      "mean.",
      t.runs.size(), t.planned_runs, t.source_path.empty() ? "(no file)" : t.source_path,
      fmt::format("{} cases", t.cases.size()), t.engines.size(), axes_text.empty() ? "" : "; axes: ",
      axes_text);
  const std::size_t primary = [&] {
    for (std::size_t m = 0; m < t.metrics.size(); ++m) {
      if (t.metrics[m].name == "position_error_m") return m;
    }
    return std::size_t{0};
  }();

  for (const auto& c : t.cases) {
    CampaignCaseSection sec;
    sec.name = c.name;
    sec.truth = c.truth;
    Rows rows;
    for (const auto& r : t.runs) {
      if (r.case_name == c.name) rows.push_back(&r);
    }
    // runs and status per engine
    Table runs_table;
    runs_table.id = file_id(c.name) + "_campaign_runs";
    runs_table.title = c.name + ": runs per engine";
    runs_table.note =
        "Whose physics: the mode, whose collision detection found the contacts and whose "
        "contact model made the force (the engine's own by default; a run with foreknowledge "
        "of its future, the opt-in oracle mode, is marked).";
    runs_table.columns = {"engine", "runs", "ok", "diverged", "unsupported", "median wall time per run, s",
                          "CPU time, s", "whose physics"};
    for (const auto& e : t.engines) {
      std::size_t n = 0, ok = 0, div = 0, uns = 0;
      std::vector<double> walls;
      double total = 0.0;
      std::vector<std::string> physics;  // the distinct attributions of the engine's runs
      bool foreknowledge = false;
      for (const auto* r : rows) {
        if (r->engine != e) continue;
        const auto p = nlohmann::json::parse(r->physics, nullptr, false);
        const bool future = p.is_object() && p.value("foreknowledge", false);
        foreknowledge = foreknowledge || future;
        const std::string text =
            p.is_object() && p.contains("mode")
                ? fmt::format("{}: collision by {}, force by {}{}", p.value("mode", ""),
                              p.value("collision_by", ""), p.value("contact_force_by", ""),
                              future ? ", WITH FOREKNOWLEDGE (oracle)" : "")
                : "not recorded";
        if (std::find(physics.begin(), physics.end(), text) == physics.end()) physics.push_back(text);
        ++n;
        ok += r->status == RunStatus::ok;
        div += r->status == RunStatus::diverged;
        uns += r->status == RunStatus::unsupported;
        walls.push_back(r->wall_time_s);
        total += r->wall_time_s;
      }
      if (n == 0) continue;
      std::string whose;
      for (const auto& x : physics) whose += (whose.empty() ? "" : "; ") + x;
      runs_table.rows.push_back({e, std::to_string(n), std::to_string(ok), std::to_string(div),
                                 std::to_string(uns), number_text(median_of(walls)),
                                 number_text(total), whose});
      runs_table.row_status.push_back(div + uns > 0 || foreknowledge ? "fail" : "");
    }
    sec.tables.push_back(std::move(runs_table));

    for (std::size_t k = 0; k < t.axes.size(); ++k) {
      const CampaignAxis& a = t.axes[k];
      if (a.kind == "perturb") continue;
      // per engine and point: the metric and the wall time of every run there
      std::vector<double> points;
      for (const auto* r : rows) {
        const double v = r->axis_values[k];
        if (std::isfinite(v) && std::find(points.begin(), points.end(), v) == points.end()) {
          points.push_back(v);
        }
      }
      std::sort(points.begin(), points.end());
      if (points.empty()) continue;
      const bool x_log = a.kind == "log" || all_positive_spanning(points);
      Table table;
      table.id = file_id(c.name + "_" + a.name) + "_campaign_axis";
      table.title = fmt::format("{}: median (min..max) against {}", c.name, a.name);
      table.columns = {"engine", a.name + (a.unit.empty() ? "" : ", " + a.unit), "runs"};
      for (const auto& m : t.metrics) table.columns.push_back(m.name + ", " + m.unit);
      table.columns.push_back("wall time, s");
      LinePlot metric_plot;
      LinePlot cost_plot;
      const std::string metric_name = t.metrics.empty() ? "" : t.metrics[primary].name;
      metric_plot.title = fmt::format("{}: {} against {}", c.name, metric_name, a.name);
      metric_plot.x_label = cost_plot.x_label = a.name + (a.unit.empty() ? "" : ", " + a.unit);
      metric_plot.y_label = t.metrics.empty() ? "" : metric_name + ", " + t.metrics[primary].unit;
      cost_plot.title = fmt::format("{}: wall time per run against {}", c.name, a.name);
      cost_plot.y_label = "wall time per run, s";
      metric_plot.x_log = cost_plot.x_log = x_log;
      cost_plot.y_log = true;
      std::vector<double> all_metric;
      for (std::size_t ei = 0; ei < t.engines.size(); ++ei) {
        const std::string& e = t.engines[ei];
        LinePlot::Line ml{e, engine_colour(e, ei), {}, {}, {}, {}};
        LinePlot::Line cl{e, engine_colour(e, ei), {}, {}, {}, {}};
        for (const double v : points) {
          std::vector<std::vector<double>> per_metric(t.metrics.size());
          std::vector<double> walls;
          std::size_t n = 0;
          for (const auto* r : rows) {
            if (r->engine != e || r->axis_values[k] != v) continue;
            ++n;
            walls.push_back(r->wall_time_s);
            for (std::size_t m = 0; m < t.metrics.size(); ++m) {
              per_metric[m].push_back(r->metrics[m]);
            }
          }
          if (n == 0) continue;
          std::vector<std::string> row = {e, compact_number(v), std::to_string(n)};
          for (const auto& pm : per_metric) row.push_back(stats_text(stats_of(pm)));
          const Stats w = stats_of(walls);
          row.push_back(stats_text(w));
          table.rows.push_back(std::move(row));
          table.row_status.emplace_back("");
          if (!t.metrics.empty()) {
            const Stats s = stats_of(per_metric[primary]);
            ml.x.push_back(v);
            ml.y.push_back(s.median);
            ml.lo.push_back(s.lo);
            ml.hi.push_back(s.hi);
            all_metric.insert(all_metric.end(), per_metric[primary].begin(),
                              per_metric[primary].end());
          }
          cl.x.push_back(v);
          cl.y.push_back(w.median);
          cl.lo.push_back(w.lo);
          cl.hi.push_back(w.hi);
        }
        if (!ml.x.empty()) metric_plot.lines.push_back(std::move(ml));
        if (!cl.x.empty()) cost_plot.lines.push_back(std::move(cl));
      }
      std::vector<double> finite;
      for (const double x : all_metric) {
        if (std::isfinite(x)) finite.push_back(x);
      }
      metric_plot.y_log = all_positive_spanning(finite);
      if (!t.metrics.empty()) {
        sec.figures.push_back({file_id(c.name + "_" + a.name + "_" + metric_name), metric_plot.title,
                               line_plot_svg(metric_plot)});
      }
      sec.figures.push_back(
          {file_id(c.name + "_" + a.name + "_wall_time"), cost_plot.title, line_plot_svg(cost_plot)});
      sec.tables.push_back(std::move(table));
    }

    // the spread over time of each random axis (needs the trace)
    const auto tp = static_cast<std::size_t>(t.trace_points);
    for (std::size_t k = 0; k < t.axes.size() && tp > 0; ++k) {
      if (t.axes[k].kind != "perturb") continue;
      // the runs grouped by their point on the other axes
      std::map<std::vector<double>, Rows> groups;
      for (const auto* r : rows) {
        std::vector<double> key = r->axis_values;
        key.erase(key.begin() + static_cast<std::ptrdiff_t>(k));
        groups[key].push_back(r);
      }
      Table table;
      table.id = file_id(c.name + "_" + t.axes[k].name) + "_campaign_spread";
      table.title = fmt::format("{}: spread of the trajectories over the {} samples of {}", c.name,
                                t.axes[k].values.size(), t.axes[k].name);
      table.columns = {"engine", "other axes", "ok samples", "spread at t = 0, m", "at the end, m",
                       "largest, m", "end / start"};
      std::size_t figures = 0;
      for (const auto& [key, group] : groups) {
        std::string where;
        for (std::size_t j = 0, a = 0; a < t.axes.size(); ++a) {
          if (a == k) continue;
          where += fmt::format("{}{}={}", where.empty() ? "" : ", ", t.axes[a].name,
                               compact_number(key[j++]));
        }
        LinePlot plot;
        plot.title = fmt::format("{}: spread over {} samples of {}{}{}", c.name,
                                 t.axes[k].values.size(), t.axes[k].name, where.empty() ? "" : " at ",
                                 where);
        plot.x_label = "time, s";
        plot.y_label = "spread, m";
        std::vector<double> all;
        for (std::size_t ei = 0; ei < t.engines.size(); ++ei) {
          const std::string& e = t.engines[ei];
          std::vector<const CampaignRun*> ok;
          for (const auto* r : group) {
            if (r->engine == e && r->status == RunStatus::ok) ok.push_back(r);
          }
          if (ok.empty()) continue;
          LinePlot::Line line{e, engine_colour(e, ei), {}, {}, {}, {}};
          for (std::size_t j = 0; j < tp; ++j) {
            double spread = std::nan("");
            for (std::size_t b = 0; b < c.moving_bodies.size(); ++b) {
              std::vector<double> xs;
              std::vector<double> ys;
              for (const auto* r : ok) {
                xs.push_back(r->trace_position_m[(b * tp + j) * 2]);
                ys.push_back(r->trace_position_m[(b * tp + j) * 2 + 1]);
              }
              const double s = rms_spread(xs, ys);
              if (std::isfinite(s)) spread = std::isfinite(spread) ? std::max(spread, s) : s;
            }
            line.x.push_back(ok.front()->trace_time_s[j]);
            line.y.push_back(spread);
          }
          const Stats s = stats_of(line.y);
          const double start = line.y.front();
          const double end = line.y.back();
          table.rows.push_back({e, where.empty() ? "-" : where, std::to_string(ok.size()),
                                number_text(start), number_text(end), number_text(s.hi),
                                start > 0.0 ? number_text(end / start) : "-"});
          table.row_status.emplace_back("");
          all.insert(all.end(), line.y.begin(), line.y.end());
          plot.lines.push_back(std::move(line));
        }
        std::vector<double> finite;
        for (const double x : all) {
          if (std::isfinite(x)) finite.push_back(x);
        }
        plot.y_log = all_positive_spanning(finite);
        if (figures < kMaxSpreadFigures) {
          sec.figures.push_back({file_id(fmt::format("{}_{}_spread_{}", c.name, t.axes[k].name, figures)),
                                 plot.title, line_plot_svg(plot)});
          ++figures;
        }
      }
      if (groups.size() > kMaxSpreadFigures) {
        table.note = fmt::format("The figures show the first {} of the {} points of the other axes; "
                                 "the table has every one.",
                                 kMaxSpreadFigures, groups.size());
      }
      sec.tables.push_back(std::move(table));
    }
    out.cases.push_back(std::move(sec));
  }
  return out;
}

}  // namespace pb::internal
