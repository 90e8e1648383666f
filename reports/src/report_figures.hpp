// The figures of a case: the paper's figures for the paper's cases (falling_ball:
// Figs 5-6, dual_pendulum: Figs 8-11, sliding: Figs 13-15), and for any other
// case the same kinds of plots generically: every contact pair's force and
// every moving body's x, y, vx, vy. Truth and every engine whose run is ok are
// overlaid, one series per engine.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/run_result.hpp"
#include "report_downsample.hpp"
#include "report_model.hpp"

namespace pb::internal {

// how long series are thinned for embedding (report_downsample.hpp)
struct FigureLimits {
  std::size_t max_outside = 1500;  // samples per series outside contact windows
  std::size_t max_inside = 3000;   // samples per series inside them (extremes kept beyond)
};

// The runs of a case in report order: analytic, reference, mujoco, box2d, ode
// (SPEC §5), then any other engine by name.
[[nodiscard]] std::vector<const RunResult*> runs_in_report_order(const CaseRuns& runs);

// The contact windows of a case: every episode of every ok run (onset to
// offset, or while still open to the end of the run or of its validity) and
// every stretch of contact-table
// rows, each padded by two output intervals, merged.
[[nodiscard]] std::vector<TimeWindow> contact_windows(const Case& c, const CaseRuns& runs);

// Every figure of the case, its series down-sampled within `limits`.
[[nodiscard]] std::vector<Figure> case_figures(const Case& c, const CaseRuns& runs,
                                               const FigureLimits& limits);

// "oracle: ..." for a run calibrated with foreknowledge, "inject: ..." for one
// whose contact force is the case's law applied by the adapter, "" otherwise
// (SPEC §5b: marked wherever results are shown)
[[nodiscard]] std::string physics_label(const RunResult& r);

}  // namespace pb::internal
