// The work-precision plot of a case as a static SVG: position error against
// wall time on log-log axes, one polyline per series with a circle at each
// rung and a ring at the engine's default setting, dashed lines at the error
// targets. Deterministic: the same case gives the same bytes.
#pragma once

#include <string>

#include "report_model.hpp"

namespace pb::internal {

// decades [floor(log10 lo), ceil(log10 hi)] covering lo..hi (lo, hi > 0),
// widened to one decade at least
struct Decades {
  int lo = 0;
  int hi = 1;
};
[[nodiscard]] Decades decades_of(double lo, double hi);

// "1e-3", "1", "10", "1e+4"... the label of the decade 10^k
[[nodiscard]] std::string decade_label(int k);

// A setting or error level as short as it reads: below 0.01 as "5e-4",
// "2.5e-5", "1e-10"; from 0.01 up as printf %g ("0.25", "1", "100").
[[nodiscard]] std::string compact_number(double v);

// The SVG document; a case without a plottable point gives a frame saying so.
[[nodiscard]] std::string work_precision_svg(const WorkPrecisionCase& c);

}  // namespace pb::internal
