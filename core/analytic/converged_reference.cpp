#include "converged_reference.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "planarbench/errors.hpp"
#include "planarbench/reference/reference_solver.hpp"

namespace pb::internal {

namespace {

// tight: the truth, two decades tighter than the reference's default rtol
// 1e-10 (so the reference at its defaults is never judged against its own
// bits: issue 25); the two looser ones only for the Richardson estimate
constexpr double kTruthRtol = 1e-12;
constexpr double kAtol = 1e-14;  // m, rad, m/s, rad/s, N s per state component

ReferenceSettings exact_settings(double rtol) {
  ReferenceSettings s;
  s.geometry = "exact";
  s.integrator = "rk45";
  s.rtol = rtol;
  s.atol = kAtol;
  return s;
}

std::unique_ptr<ReferenceSolver> make_solver(const Case& c, double rtol) {
  try {
    return std::make_unique<ReferenceSolver>(c, exact_settings(rtol));
  } catch (const std::invalid_argument& e) {
    throw EngineError(
        fmt::format("analytic: the converged truth of case '{}' needs the reference at exact "
                    "geometry: {}",
                    c.name, e.what()));
  }
}

// every moving body's position at the end of the case, at one tolerance
std::vector<Vec2> end_positions(const Case& c, double rtol) {
  auto solver = make_solver(c, rtol);
  solver->advance_to(c.duration_s);
  std::vector<Vec2> out;
  for (std::size_t i = 0; i < c.bodies.size(); ++i) {
    if (!c.bodies[i].fixed) out.push_back(solver->body_state(static_cast<int>(i)).position_m);
  }
  return out;
}

double largest_difference(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  double d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, (a[i] - b[i]).norm());
  return d;
}

}  // namespace

ConvergedReference::ConvergedReference(const Case& c) : case_(c) {
  solver_ = make_solver(case_, kTruthRtol);
  const auto y10 = end_positions(case_, 1e-10);
  const auto y11 = end_positions(case_, 1e-11);
  const auto y12 = end_positions(case_, kTruthRtol);
  const double d1 = largest_difference(y11, y10);  // m
  const double d2 = largest_difference(y12, y11);  // m
  const double q = d2 > 0.0 ? d1 / d2 : std::nan("");
  convergence_ = {
      {"what",
       "Richardson estimate of the truth's error: every moving body's position at t = duration "
       "at rtol 1e-10, 1e-11, 1e-12; d1 = max |y(1e-11) - y(1e-10)|, d2 = max |y(1e-12) - "
       "y(1e-11)|, "
       "q = d1 / d2, error of the truth ~ d2 / (q - 1)"},
      {"d1_m", d1},
      {"d2_m", d2},
      {"ratio_q", q},
      {"estimated_error_m", q > 1.0 ? d2 / (q - 1.0) : d2}};
}

ConvergedReference::~ConvergedReference() = default;

void ConvergedReference::advance_to(double t_s) { solver_->advance_to(t_s); }

double ConvergedReference::time() const { return solver_->time(); }

void ConvergedReference::body_states(std::vector<BodyState>& out) const {
  out.resize(case_.bodies.size());
  for (std::size_t i = 0; i < case_.bodies.size(); ++i) {
    out[i] = solver_->body_state(static_cast<int>(i));
  }
}

void ConvergedReference::contacts(std::vector<ContactSample>& out) const {
  solver_->contacts(out);
}

std::vector<ContactEpisode> ConvergedReference::episodes() const { return solver_->episodes(); }

long ConvergedReference::steps() const { return solver_->stats().steps; }

nlohmann::json ConvergedReference::description() const {
  return {{"solver",
           fmt::format("the reference solver at exact geometry, rk45 (Dormand-Prince 5(4)) at "
                       "rtol {:g}, atol {:g}, contact events located",
                       kTruthRtol, kAtol)},
          {"convergence", convergence_}};
}

}  // namespace pb::internal
