#include "report_work_precision_svg.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "report_svg.hpp"

namespace pb::internal {

namespace {

// page geometry, px (as report_svg.cpp, a little taller for the legend)
constexpr double kWidth = 760.0;
constexpr double kHeight = 420.0;
constexpr double kLeft = 78.0;
constexpr double kRight = 16.0;
constexpr double kTop = 62.0;
constexpr double kBottom = 46.0;

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

Decades decades_of(double lo, double hi) {
  Decades d;
  d.lo = static_cast<int>(std::floor(std::log10(lo) + 1e-9));
  d.hi = static_cast<int>(std::ceil(std::log10(hi) - 1e-9));
  if (d.hi <= d.lo) d.hi = d.lo + 1;
  return d;
}

std::string decade_label(int k) {
  if (k == 0) return "1";
  if (k == 1) return "10";
  if (k == 2) return "100";
  return fmt::format("1e{}", k);
}

std::string compact_number(double v) {
  if (!(std::isfinite(v) && v > 0.0 && v < 1e-2)) return fmt::format("{:g}", v);
  // below 0.01 in scientific notation: mantissa without trailing zeros, exponent
  // without '+' or leading zeros ("5.000000e-04" -> "5e-4")
  const std::string text = fmt::format("{:e}", v);
  const auto e = text.find('e');
  std::string mantissa = text.substr(0, e);
  while (!mantissa.empty() && mantissa.back() == '0') mantissa.pop_back();
  if (!mantissa.empty() && mantissa.back() == '.') mantissa.pop_back();
  return mantissa + "e" + std::to_string(std::stoi(text.substr(e + 1)));
}

std::string work_precision_svg(const WorkPrecisionCase& c) {
  const double pw = kWidth - kLeft - kRight;   // plot width, px
  const double ph = kHeight - kTop - kBottom;  // plot height, px

  // the ranges: every plotted point, and the targets on the error axis
  double t_lo = kInf, t_hi = -kInf, e_lo = kInf, e_hi = -kInf;
  for (const auto& s : c.series) {
    for (std::size_t i = 0; i < s.wall_s.size(); ++i) {
      t_lo = std::min(t_lo, s.wall_s[i]);
      t_hi = std::max(t_hi, s.wall_s[i]);
      e_lo = std::min(e_lo, s.error_m[i]);
      e_hi = std::max(e_hi, s.error_m[i]);
    }
  }
  const bool empty = !std::isfinite(t_lo);
  if (empty) {
    t_lo = 1e-3;
    t_hi = 1.0;
  }
  for (const double target : c.targets_m) {
    e_lo = std::min(e_lo, target);
    e_hi = std::max(e_hi, target);
  }
  if (!std::isfinite(e_lo)) {
    e_lo = 1e-6;
    e_hi = 1.0;
  }
  const Decades xd = decades_of(t_lo, t_hi);
  const Decades yd = decades_of(e_lo, e_hi);
  auto px = [&](double t) { return kLeft + (std::log10(t) - xd.lo) / (xd.hi - xd.lo) * pw; };
  auto py = [&](double e) { return kTop + (yd.hi - std::log10(e)) / (yd.hi - yd.lo) * ph; };

  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0:.0f}\" height=\"{1:.0f}\" "
      "viewBox=\"0 0 {0:.0f} {1:.0f}\" font-family=\"sans-serif\" font-size=\"12\">\n"
      "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n"
      "<text x=\"{2:.1f}\" y=\"18\" font-size=\"14\" font-weight=\"bold\">{3}</text>\n",
      kWidth, kHeight, kLeft, xml_escape(c.name + ": position error vs wall time"));

  // decade grid; with many decades only every second one is labelled
  const int x_every = xd.hi - xd.lo > 10 ? 2 : 1;
  const int y_every = yd.hi - yd.lo > 10 ? 2 : 1;
  for (int k = xd.lo; k <= xd.hi; ++k) {
    const double x = px(std::pow(10.0, k));
    svg += fmt::format(
        "<line x1=\"{0:.2f}\" y1=\"{1:.2f}\" x2=\"{0:.2f}\" y2=\"{2:.2f}\" stroke=\"#e0e0e0\"/>", x,
        kTop, kTop + ph);
    if ((k - xd.lo) % x_every == 0) {
      svg += fmt::format("<text x=\"{:.2f}\" y=\"{:.2f}\" text-anchor=\"middle\">{}</text>", x,
                         kTop + ph + 16, decade_label(k));
    }
    svg += "\n";
  }
  for (int k = yd.lo; k <= yd.hi; ++k) {
    const double y = py(std::pow(10.0, k));
    svg += fmt::format(
        "<line x1=\"{0:.2f}\" y1=\"{1:.2f}\" x2=\"{2:.2f}\" y2=\"{1:.2f}\" stroke=\"#e0e0e0\"/>",
        kLeft, y, kLeft + pw);
    if ((k - yd.lo) % y_every == 0) {
      svg += fmt::format("<text x=\"{:.2f}\" y=\"{:.2f}\" text-anchor=\"end\">{}</text>", kLeft - 6,
                         y + 4, decade_label(k));
    }
    svg += "\n";
  }
  svg += fmt::format(
      "<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"none\" "
      "stroke=\"#444444\"/>\n",
      kLeft, kTop, pw, ph);
  svg += fmt::format(
      "<text x=\"{:.2f}\" y=\"{:.2f}\" text-anchor=\"middle\">wall time, s (log)</text>\n",
      kLeft + pw / 2, kHeight - 8);
  svg += fmt::format(
      "<text transform=\"translate(16 {:.2f}) rotate(-90)\" text-anchor=\"middle\">max position "
      "error, m (log)</text>\n",
      kTop + ph / 2);

  // the error targets of the table, dashed grey
  for (const double target : c.targets_m) {
    svg += fmt::format(
        "<line x1=\"{0:.2f}\" y1=\"{1:.2f}\" x2=\"{2:.2f}\" y2=\"{1:.2f}\" stroke=\"#888888\" "
        "stroke-dasharray=\"3 3\"/><text x=\"{3:.2f}\" y=\"{4:.2f}\" text-anchor=\"end\" "
        "fill=\"#5f6368\">{5} m</text>\n",
        kLeft, py(target), kLeft + pw, kLeft + pw - 4, py(target) - 4, compact_number(target));
  }

  // the series: a polyline through the rungs, a circle at each, a ring at the default
  svg += "<g fill=\"none\">\n";
  for (std::size_t k = 0; k < c.series.size(); ++k) {
    const auto& s = c.series[k];
    if (s.wall_s.empty()) continue;
    const std::string colour = engine_colour(s.engine, k);
    std::string points;
    for (std::size_t i = 0; i < s.wall_s.size(); ++i) {
      points += fmt::format("{}{:.2f},{:.2f}", i ? " " : "", px(s.wall_s[i]), py(s.error_m[i]));
    }
    svg += fmt::format("<polyline stroke=\"{}\" stroke-width=\"1.6\"{} points=\"{}\"/>\n", colour,
                       s.dashed ? " stroke-dasharray=\"6 4\"" : "", points);
    for (std::size_t i = 0; i < s.wall_s.size(); ++i) {
      svg += fmt::format(
          "<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"3\" fill=\"{}\"><title>{}</title></circle>\n",
          px(s.wall_s[i]), py(s.error_m[i]), colour,
          xml_escape(fmt::format("{} {}: {:.4g} s, {:.4g} m", s.name, s.labels[i], s.wall_s[i],
                                 s.error_m[i])));
      if (static_cast<int>(i) == s.default_index) {
        svg += fmt::format(
            "<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"6.5\" stroke=\"{}\" stroke-width=\"1.5\"/>\n",
            px(s.wall_s[i]), py(s.error_m[i]), colour);
      }
    }
  }
  svg += "</g>\n";
  if (empty) {
    svg += fmt::format(
        "<text x=\"{:.2f}\" y=\"{:.2f}\" text-anchor=\"middle\" fill=\"#5f6368\">no rung has an "
        "error to plot</text>\n",
        kLeft + pw / 2, kTop + ph / 2);
  }

  // legend: one entry per series in a row under the title
  double lx = kLeft;
  for (std::size_t k = 0; k < c.series.size(); ++k) {
    const auto& s = c.series[k];
    svg += fmt::format(
        "<line x1=\"{0:.2f}\" y1=\"40\" x2=\"{1:.2f}\" y2=\"40\" stroke=\"{2}\" "
        "stroke-width=\"3\"{3}/><text x=\"{4:.2f}\" y=\"44\">{5}</text>\n",
        lx, lx + 22, engine_colour(s.engine, k), s.dashed ? " stroke-dasharray=\"6 4\"" : "",
        lx + 27, xml_escape(s.name));
    lx += 40 + 7.0 * static_cast<double>(s.name.size());
  }
  svg += "</svg>\n";
  return svg;
}

}  // namespace pb::internal
