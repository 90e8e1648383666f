#include "report_svg.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "report_downsample.hpp"

namespace pb::internal {

namespace {

// page geometry, px
constexpr double kWidth = 760.0;
constexpr double kHeight = 380.0;
constexpr double kLeft = 78.0;
constexpr double kRight = 16.0;
constexpr double kTop = 58.0;
constexpr double kBottom = 46.0;

// decimals that show a tick step exactly (steps are 1, 2, 5 x 10^k)
int decimals_for(double step) {
  const int d = static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
  return std::clamp(d, 0, 12);
}

std::string tick_text(double v, int decimals) {
  if (std::abs(v) < 1e-12) v = 0.0;  // no "-0"
  return fmt::format("{:.{}f}", v, decimals);
}

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
};

// the value range of every series inside [t0, t1], padded by 5 %
Range value_range(const Figure& f, double t0, double t1) {
  Range r;
  for (const auto& s : f.series) {
    for (std::size_t i = 0; i < s.time_s.size() && i < s.value.size(); ++i) {
      if (s.time_s[i] < t0 || s.time_s[i] > t1 || !std::isfinite(s.value[i])) continue;
      r.lo = std::min(r.lo, s.value[i]);
      r.hi = std::max(r.hi, s.value[i]);
    }
  }
  if (!std::isfinite(r.lo)) return Range{-1.0, 1.0};
  // an off-scale series (report_figures.cpp) does not set the axis
  if (std::isfinite(f.y_clip) && r.hi > f.y_clip) r.hi = f.y_clip;
  if (r.hi - r.lo <= 1e-12 * std::max(1.0, std::abs(r.hi))) {
    const double half = std::max(1e-9, 0.1 * std::abs(r.hi));
    return Range{r.lo - half, r.hi + half};
  }
  const double pad = 0.05 * (r.hi - r.lo);
  return Range{r.lo - pad, r.hi + pad};
}

}  // namespace

std::string engine_colour(const std::string& engine, std::size_t index) {
  if (engine == "analytic") return "#000000";
  if (engine == "reference") return "#1f77b4";
  if (engine == "mujoco") return "#ff7f0e";
  if (engine == "mujoco3") return "#9467bd";
  if (engine == "box2d") return "#2ca02c";
  if (engine == "ode") return "#d62728";
  static constexpr std::array<const char*, 3> kOthers = {"#8c564b", "#e377c2", "#17becf"};
  return kOthers[index % kOthers.size()];
}

double tick_step(double range, int target) {
  if (!(range > 0.0) || target < 1) return 1.0;
  const double raw = range / target;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  const double m = raw / p;
  return (m < 1.5 ? 1.0 : m < 3.5 ? 2.0 : m < 7.5 ? 5.0 : 10.0) * p;
}

std::string figure_svg(const Figure& f, double t0_s, double t1_s, const std::string& title) {
  const double pw = kWidth - kLeft - kRight;   // plot width, px
  const double ph = kHeight - kTop - kBottom;  // plot height, px
  const Range yr = value_range(f, t0_s, t1_s);
  auto px = [&](double t) { return kLeft + (t - t0_s) / (t1_s - t0_s) * pw; };
  auto py = [&](double v) { return kTop + (yr.hi - v) / (yr.hi - yr.lo) * ph; };

  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0:.0f}\" height=\"{1:.0f}\" "
      "viewBox=\"0 0 {0:.0f} {1:.0f}\" font-family=\"sans-serif\" font-size=\"12\">\n"
      "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n"
      "<text x=\"{2:.1f}\" y=\"18\" font-size=\"14\" font-weight=\"bold\">{3}</text>\n",
      kWidth, kHeight, kLeft, xml_escape(title));

  // grid and ticks
  const double xs = tick_step(t1_s - t0_s, 8);
  const double ys = tick_step(yr.hi - yr.lo, 6);
  const int xd = decimals_for(xs);
  const int yd = decimals_for(ys);
  // ticks as integer multiples of the step: no accumulated rounding
  for (auto k = static_cast<long>(std::ceil(t0_s / xs - 1e-9));
       static_cast<double>(k) * xs <= t1_s + 1e-9 * xs; ++k) {
    const double t = static_cast<double>(k) * xs;
    svg += fmt::format(
        "<line x1=\"{0:.2f}\" y1=\"{1:.2f}\" x2=\"{0:.2f}\" y2=\"{2:.2f}\" stroke=\"#e0e0e0\"/>"
        "<text x=\"{0:.2f}\" y=\"{3:.2f}\" text-anchor=\"middle\">{4}</text>\n",
        px(t), kTop, kTop + ph, kTop + ph + 16, tick_text(t, xd));
  }
  for (auto k = static_cast<long>(std::ceil(yr.lo / ys - 1e-9));
       static_cast<double>(k) * ys <= yr.hi + 1e-9 * ys; ++k) {
    const double v = static_cast<double>(k) * ys;
    svg += fmt::format(
        "<line x1=\"{0:.2f}\" y1=\"{1:.2f}\" x2=\"{2:.2f}\" y2=\"{1:.2f}\" stroke=\"#e0e0e0\"/>"
        "<text x=\"{3:.2f}\" y=\"{4:.2f}\" text-anchor=\"end\">{5}</text>\n",
        kLeft, py(v), kLeft + pw, kLeft - 6, py(v) + 4, tick_text(v, yd));
  }
  svg += fmt::format(
      "<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"none\" "
      "stroke=\"#444444\"/>\n",
      kLeft, kTop, pw, ph);
  svg += fmt::format("<text x=\"{:.2f}\" y=\"{:.2f}\" text-anchor=\"middle\">time, s</text>\n",
                     kLeft + pw / 2, kHeight - 8);
  svg += fmt::format(
      "<text transform=\"translate(16 {:.2f}) rotate(-90)\" text-anchor=\"middle\">{}</text>\n",
      kTop + ph / 2, xml_escape(f.y_label));

  // the series, clipped to the plot; NaN breaks a line
  svg += fmt::format(
      "<clipPath id=\"plot\"><rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" "
      "height=\"{:.2f}\"/></clipPath>\n<g clip-path=\"url(#plot)\" fill=\"none\">\n",
      kLeft, kTop, pw, ph);
  // the truth last, dashed on top of the engines
  std::vector<std::size_t> order;
  for (std::size_t k = 0; k < f.series.size(); ++k) {
    if (f.series[k].engine != "analytic") order.push_back(k);
  }
  for (std::size_t k = 0; k < f.series.size(); ++k) {
    if (f.series[k].engine == "analytic") order.push_back(k);
  }
  for (const std::size_t k : order) {
    const auto& s = f.series[k];
    const bool truth = s.engine == "analytic";
    const std::string style =
        fmt::format("stroke=\"{}\" stroke-width=\"1.4\"{}", engine_colour(s.engine, k),
                    truth ? " stroke-dasharray=\"6 4\"" : "");
    const auto idx = minmax_indices(s.time_s, s.value, t0_s, t1_s, static_cast<std::size_t>(pw));
    std::string points;
    auto flush = [&] {
      if (!points.empty()) svg += "<polyline " + style + " points=\"" + points + "\"/>\n";
      points.clear();
    };
    for (const std::size_t i : idx) {
      if (!std::isfinite(s.value[i])) {
        flush();
        continue;
      }
      points += fmt::format("{}{:.2f},{:.2f}", points.empty() ? "" : " ", px(s.time_s[i]),
                            py(s.value[i]));
    }
    flush();
  }
  svg += "</g>\n";

  // legend: one entry per series in a row under the title
  double lx = kLeft;
  for (std::size_t k = 0; k < f.series.size(); ++k) {
    const auto& s = f.series[k];
    const std::string label = s.engine == "analytic" ? "analytic (truth)" : s.engine;
    svg += fmt::format(
        "<line x1=\"{0:.2f}\" y1=\"38\" x2=\"{1:.2f}\" y2=\"38\" stroke=\"{2}\" "
        "stroke-width=\"3\"{3}/><text x=\"{4:.2f}\" y=\"42\">{5}</text>\n",
        lx, lx + 22, engine_colour(s.engine, k),
        s.engine == "analytic" ? " stroke-dasharray=\"6 4\"" : "", lx + 27, xml_escape(label));
    lx += 40 + 7.0 * static_cast<double>(label.size());
  }
  // off-scale series: named under the legend with their peak
  std::string off;
  for (const auto& s : f.series) {
    if (s.off_scale && std::isfinite(f.y_clip)) {
      off += fmt::format("{}{} (peak {:.4g})", off.empty() ? "" : ", ", s.engine, s.peak);
    }
  }
  if (!off.empty()) {
    svg += fmt::format("<text x=\"{:.2f}\" y=\"{:.2f}\" fill=\"#5f6368\">off scale: {}</text>\n",
                       kLeft + 6, kTop + 14, xml_escape(off));
  }
  svg += "</svg>\n";
  return svg;
}

}  // namespace pb::internal
