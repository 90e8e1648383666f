// Observed orders of accuracy of the reference solver, for the pb_convergence
// tool and its tests:
//   in the step size  fixed RK4 at dt, dt/2, ... against rk45 at rtol 1e-12
//                     (same geometry), expected order 4 (events located);
//   in the outlines   outline points N, 2N, ... against geometry=exact (both
//                     rk45, rtol 1e-12 by default), expected order 2: the outline is an
//                     inscribed polygon whose sag is R (1 - cos(pi/N)) ~ 1/N^2;
//   in the tolerance  rk45 at rtol 1e-8 .. 1e-12: successive differences and
//                     the Richardson estimate of each solution's error.
// Observed order between rows i-1 and i: log(e_{i-1}/e_i) / log(p_{i-1}/p_i)
// for dt and rtol, log(e_{i-1}/e_i) / log(N_i/N_{i-1}) for N.
#pragma once

#include <string>
#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/settings.hpp"

namespace pb {

// figures of one reference run up to t_probe
struct RunFigures {
  Vec2 position_m = Vec2::Zero();     // m, centre of `body` at t_probe
  double angle_rad = 0.0;             // rad, of `body` at t_probe
  double onset_s = 0.0;               // s, first contact onset (NaN if none)
  double peak_force_n = 0.0;          // N, first episode
  double max_penetration_m = 0.0;     // m, first episode
  double restitution = 0.0;           // -, first episode
  double impulse_ns = 0.0;            // N s, first episode
  long steps = 0;
};

// runs engine "reference" on `c` with `settings` (keys as for --set) to t_probe
[[nodiscard]] RunFigures run_reference(const Case& c, const SettingsOverrides& settings,
                                       double t_probe, int body);

struct ConvergenceRow {
  double parameter = 0.0;           // dt (s), N, or rtol
  std::vector<double> errors;       // per quantity (see ConvergenceTable::quantities)
  std::vector<double> orders;       // observed order against the previous row (NaN first)
  long steps = 0;
};

struct ConvergenceTable {
  std::string title;
  std::string parameter_name;
  std::vector<std::string> quantities;  // with units, e.g. "position [m]"
  std::vector<ConvergenceRow> rows;
};

// quantities of the step-size and outline tables: |position error| (m), onset
// error (s), peak force relative error, max penetration error (m),
// restitution error
[[nodiscard]] ConvergenceTable step_size_convergence(const Case& c, int body, double t_probe,
                                                     const std::vector<double>& dts);
// (rtol: of both the outline and the exact runs; far below the outline error)
[[nodiscard]] ConvergenceTable outline_convergence(const Case& c, int body, double t_probe,
                                                   const std::vector<int>& points,
                                                   double rtol = 1e-12);
// rows: rtol; errors: |difference to the next tighter rtol| of the position at
// t_probe (m) and of the first episode's peak force (relative), and the
// Richardson estimate of the position error of this row's solution (m)
[[nodiscard]] ConvergenceTable tolerance_convergence(const Case& c, int body, double t_probe,
                                                     const std::vector<double>& rtols);

[[nodiscard]] std::string format_table(const ConvergenceTable& t);

}  // namespace pb
