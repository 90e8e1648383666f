// Static SVG figures for the Markdown report: a polyline per series with axes,
// ticks, axis labels and a legend. Deterministic: the same figure gives the
// same bytes.
#pragma once

#include <string>

#include "report_model.hpp"
#include "xml_escape.hpp"  // the figures' text

namespace pb::internal {

// The colour of an engine's series, shared by the SVG and HTML figures:
// the truth black, reference blue, mujoco orange, box2d green, ode red.
[[nodiscard]] std::string engine_colour(const std::string& engine, std::size_t index);

// Nice tick spacing for a range: 1, 2 or 5 times a power of ten giving about
// `target` intervals.
[[nodiscard]] double tick_step(double range, int target);

// The figure over [t0_s, t1_s] as an SVG document, titled `title`. Each series
// is min-max decimated to the plot's pixel columns, so peaks survive.
[[nodiscard]] std::string figure_svg(const Figure& figure, double t0_s, double t1_s,
                                     const std::string& title);

}  // namespace pb::internal
