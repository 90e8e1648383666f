// The friction metrics of SPEC §7: what a run's trajectory says about its
// Coulomb friction, read the same way from every engine's run and from the
// truth's, so that a metric is the run's figure against the truth's.
//
// A case qualifies when one moving body touches one fixed half-plane through
// one pair with friction and the truth (engine analytic) is the body on a
// line with friction: its mapping lists the closed form's stick / slip
// phases (tangential_motion.hpp), which choose the metrics and their windows.
// Along the line (tangent t, the half-plane's body x axis) s is the centre's
// displacement from t = 0, w its speed, and a disk's contact point slips at
// v = w + omega R (R its radius; a block's v is w). Each metric is computed
// for the run and for the truth by the same code (below), so a bias of the
// reading (a speed threshold, a fit window) is common to both:
//   hold_drift_m            the truth holds at rest from t = 0 over a stick
//                           phase: max |s(t)| over it, m;
//   creep_speed_mps         |s(end)| / its length, m/s;
//   slide_acceleration_mps2 the truth's last phase moves at a constant
//                           acceleration a != 0 for >= 0.2 s: least-squares
//                           slope of w(t) over it, its first tenth left out
//                           (an engine's start transient), m/s^2;
//   stop_time_s,            the truth slides, then holds at rest: the time w
//   stop_distance_m         first falls to 1e-3 of its starting value
//                           (linear between samples), and s then;
//   slip_end_time_s,        a disk's truth slips from t = 0 and then rolls:
//   roll_speed_mps          the time v first falls to 1e-3 of v(0), and |w| then;
//   tangential_impulse_ns,  per contact episode of the truth that starts
//   post_impact_spin_radps  apart (an impact): m (w(b) - w(a)) - m g_t (b - a)
//                           and omega(b), a and b 2 ms before the truth's
//                           onset and after its offset;
//   friction_dissipation_j  the truth's normal motion rests at its static
//                           penetration all along: the mechanical energy lost
//                           over the run (friction is then all that dissipates), J.
#pragma once

#include <utility>
#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/reports/metrics.hpp"
#include "planarbench/run_result.hpp"

namespace pb {

// metrics of `run` against `truth` (the analytic run) for case c; none when
// the case or the truth does not qualify (above)
[[nodiscard]] std::vector<MetricValue> friction_metrics(const Case& c, const RunResult& run,
                                                        const RunResult& truth);

// the names above, for the thresholds file
[[nodiscard]] const std::vector<const char*>& friction_metric_names();

// The steady acceleration of a run's slide, m/s^2, without a truth (the
// campaign metric of the same name, for the friction curve): the
// least-squares slope of the speed along the line of the body of the case's
// first pair with a half-plane, over the run's second half (0 while it
// holds); NaN when the case has no such pair or the run is not ok.
[[nodiscard]] double steady_slide_acceleration_mps2(const Case& c, const RunResult& run);

// The drift of a body held by friction: (t, |p(t)|) with p the displacement
// along the line of its material contact point (as hold_drift_m reads it),
// or empty when the truth does not hold at rest from t = 0.
[[nodiscard]] std::vector<std::pair<double, double>> hold_drift_series(const Case& c,
                                                                       const RunResult& run,
                                                                       const RunResult& truth);

}  // namespace pb
