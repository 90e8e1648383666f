#include "planarbench/reference/convergence_study.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <variant>

#include "planarbench/reference/reference_engine.hpp"

namespace pb {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

SettingsOverrides overrides(std::initializer_list<std::pair<std::string, std::string>> kv) {
  SettingsOverrides o;
  for (const auto& [k, v] : kv) o.set(k, v, SettingSource{"convergence study", 0});
  return o;
}

std::string number(double x) { return fmt::format("{:.17g}", x); }

// errors of `f` against `truth`, in the order of the table's quantities
std::vector<double> figure_errors(const RunFigures& f, const RunFigures& truth) {
  return {(f.position_m - truth.position_m).norm(), std::abs(f.onset_s - truth.onset_s),
          std::abs(f.peak_force_n - truth.peak_force_n) / std::abs(truth.peak_force_n),
          std::abs(f.max_penetration_m - truth.max_penetration_m),
          std::abs(f.restitution - truth.restitution)};
}

const std::vector<std::string>& figure_quantities() {
  static const std::vector<std::string> q = {"position [m]", "onset [s]", "peak force [rel]",
                                             "max penetration [m]", "restitution [-]"};
  return q;
}

// observed order of each quantity against the previous row
void fill_orders(ConvergenceTable& t, bool parameter_is_count) {
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    ConvergenceRow& r = t.rows[i];
    r.orders.assign(r.errors.size(), kNaN);
    if (i == 0) continue;
    const ConvergenceRow& p = t.rows[i - 1];
    const double ratio = parameter_is_count ? r.parameter / p.parameter : p.parameter / r.parameter;
    for (std::size_t q = 0; q < r.errors.size(); ++q) {
      if (p.errors[q] > 0.0 && r.errors[q] > 0.0) {
        r.orders[q] = std::log(p.errors[q] / r.errors[q]) / std::log(ratio);
      }
    }
  }
}

}  // namespace

RunFigures run_reference(const Case& c, const SettingsOverrides& settings, double t_probe,
                         int body) {
  auto engine = make_reference_engine();
  engine->settings().apply(settings);
  engine->build(c, settings);
  engine->advance_to(t_probe);
  std::vector<BodyState> states;
  engine->body_states(states);
  RunFigures f;
  f.position_m = states.at(static_cast<std::size_t>(body)).position_m;
  f.angle_rad = states.at(static_cast<std::size_t>(body)).angle_rad;
  f.steps = engine->steps();
  const auto eps = engine->episodes();
  if (eps.empty()) {
    f.onset_s = f.peak_force_n = f.max_penetration_m = f.restitution = f.impulse_ns = kNaN;
  } else {
    f.onset_s = eps[0].onset_time_s;
    f.peak_force_n = eps[0].peak_force_n;
    f.max_penetration_m = eps[0].max_penetration_m;
    f.restitution = eps[0].restitution;
    f.impulse_ns = eps[0].impulse_ns;
  }
  return f;
}

ConvergenceTable step_size_convergence(const Case& c, int body, double t_probe,
                                       const std::vector<double>& dts) {
  ConvergenceTable t;
  t.title = fmt::format("{}: fixed RK4 against rk45 rtol 1e-12, geometry exact, t = {} s", c.name,
                        t_probe);
  t.parameter_name = "dt [s]";
  t.quantities = figure_quantities();
  const RunFigures truth = run_reference(
      c, overrides({{"geometry", "exact"}, {"integrator", "rk45"}, {"rtol", "1e-12"}, {"atol", "1e-14"}}),
      t_probe, body);
  for (const double dt : dts) {
    const RunFigures f = run_reference(
        c, overrides({{"geometry", "exact"}, {"integrator", "fixed"}, {"dt", number(dt)}}), t_probe,
        body);
    t.rows.push_back(ConvergenceRow{dt, figure_errors(f, truth), {}, f.steps});
  }
  fill_orders(t, false);
  return t;
}

ConvergenceTable outline_convergence(const Case& c, int body, double t_probe,
                                     const std::vector<int>& points, double rtol) {
  ConvergenceTable t;
  t.title = fmt::format("{}: outline points N against geometry exact, rk45 rtol {:g}, t = {} s",
                        c.name, rtol, t_probe);
  t.parameter_name = "points N";
  t.quantities = figure_quantities();
  const auto tight = [&](const char* geometry) {
    return overrides({{"geometry", geometry},
                      {"integrator", "rk45"},
                      {"rtol", number(rtol)},
                      {"atol", number(rtol * 1e-2)}});
  };
  const RunFigures truth = run_reference(c, tight("exact"), t_probe, body);
  for (const int n : points) {
    // every curved moving body gets N points; the straight ground is exact anyway
    Case cn = c;
    for (auto& b : cn.bodies) {
      if (!b.fixed && !std::holds_alternative<Polygon>(b.shape)) b.outline_points = n;
    }
    const RunFigures f = run_reference(cn, tight("outline"), t_probe, body);
    t.rows.push_back(ConvergenceRow{static_cast<double>(n), figure_errors(f, truth), {}, f.steps});
  }
  fill_orders(t, true);
  return t;
}

ConvergenceTable tolerance_convergence(const Case& c, int body, double t_probe,
                                       const std::vector<double>& rtols) {
  ConvergenceTable t;
  t.title = fmt::format("{}: rk45 tolerance sweep, geometry exact, t = {} s", c.name, t_probe);
  t.parameter_name = "rtol";
  t.quantities = {"|dpos| to next [m]", "|dpeak| to next [rel]", "Richardson pos err [m]"};
  std::vector<RunFigures> runs;
  for (const double r : rtols) {
    runs.push_back(run_reference(c,
                                 overrides({{"geometry", "exact"},
                                            {"integrator", "rk45"},
                                            {"rtol", number(r)},
                                            {"atol", number(r * 1e-2)}}),
                                 t_probe, body));
  }
  for (std::size_t i = 0; i < runs.size(); ++i) {
    ConvergenceRow row;
    row.parameter = rtols[i];
    row.steps = runs[i].steps;
    if (i + 1 < runs.size()) {
      row.errors = {(runs[i].position_m - runs[i + 1].position_m).norm(),
                    std::abs(runs[i].peak_force_n - runs[i + 1].peak_force_n) /
                        std::abs(runs[i + 1].peak_force_n),
                    kNaN};
    } else {
      row.errors = {kNaN, kNaN, kNaN};
    }
    t.rows.push_back(row);
  }
  fill_orders(t, false);
  // Richardson: with error C rtol^p, the solution at rtol_i is off by
  // d_i 10^p / (10^p - 1), d_i its difference to the next tighter one
  for (std::size_t i = 0; i + 1 < t.rows.size(); ++i) {
    // the order observed at this row, or 1 (error proportional to rtol) when
    // the differences do not shrink yet
    const double p_obs = t.rows[i].orders[0];
    const double p = std::isfinite(p_obs) && p_obs > 0.3 ? p_obs : 1.0;
    const double rp = std::pow(rtols[i] / rtols[i + 1], p);
    t.rows[i].errors[2] = t.rows[i].errors[0] * rp / (rp - 1.0);
  }
  return t;
}

std::string format_table(const ConvergenceTable& t) {
  std::string s = t.title + "\n";
  s += fmt::format("{:>10} {:>9}", t.parameter_name, "steps");
  for (const auto& q : t.quantities) s += fmt::format(" | {:>22} {:>6}", q, "order");
  s += "\n";
  for (const auto& r : t.rows) {
    s += fmt::format("{:>10.4g} {:>9}", r.parameter, r.steps);
    for (std::size_t q = 0; q < r.errors.size(); ++q) {
      const double o = q < r.orders.size() ? r.orders[q] : kNaN;
      s += fmt::format(" | {:>22.3e} {:>6}", r.errors[q],
                       std::isfinite(o) ? fmt::format("{:.2f}", o) : std::string("-"));
    }
    s += "\n";
  }
  return s;
}

}  // namespace pb
