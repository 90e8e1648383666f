#include "planarbench/impacts/impact_fit.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <exception>
#include <limits>
#include <mutex>
#include <nlopt.hpp>
#include <thread>

namespace pb {

std::vector<ImpactOutcome> predict_impacts(const ImpactModel& model, const ImpactTable& table,
                                           const std::vector<std::size_t>& indices,
                                           const std::vector<double>& parameters, int jobs) {
  std::vector<ImpactOutcome> out(indices.size());
  std::atomic<std::size_t> next{0};
  // an exception in a worker (a bad build, memory) is rethrown here, the
  // first one, once every worker has stopped
  std::mutex failed_mutex;
  std::exception_ptr failed;
  auto work = [&] {
    try {
      auto predictor = model.predictor();
      for (std::size_t k = next++; k < indices.size(); k = next++) {
        out[k] = predictor->predict(table, indices[k], parameters);
      }
    } catch (...) {
      const std::lock_guard<std::mutex> lock(failed_mutex);
      if (!failed) failed = std::current_exception();
      next = indices.size();  // the others stop at their next impact
    }
  };
  const int threads = std::max(1, std::min<int>(jobs, static_cast<int>(indices.size())));
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  if (failed) std::rethrow_exception(failed);
  return out;
}

std::vector<ImpactScore> impact_scores(const ImpactTable& table,
                                       const std::vector<std::size_t>& indices,
                                       const std::vector<ImpactOutcome>& outcomes) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<ImpactScore> scores(indices.size(), ImpactScore{nan, nan, nan});
  for (std::size_t k = 0; k < indices.size(); ++k) {
    const std::size_t i = indices[k];
    if (!outcomes[k].ok()) continue;
    scores[k] = impact_score(table.object, outcomes[k].after.velocities(),
                             table.before[i].velocities(), table.after[i].velocities());
  }
  return scores;
}

std::vector<double> impact_errors(const ImpactTable& table, const std::vector<std::size_t>& indices,
                                  const std::vector<ImpactOutcome>& outcomes) {
  const std::vector<ImpactScore> scores = impact_scores(table, indices, outcomes);
  std::vector<double> eps(scores.size());
  for (std::size_t k = 0; k < scores.size(); ++k) eps[k] = scores[k].eps;
  return eps;
}

namespace {

double from_unit(const ImpactParameter& p, double u) {
  u = std::clamp(u, 0.0, 1.0);
  if (p.log_scale) return p.lower * std::pow(p.upper / p.lower, u);
  return p.lower + u * (p.upper - p.lower);
}

double to_unit(const ImpactParameter& p, double v) {
  if (p.upper == p.lower) return 0.0;
  if (p.log_scale) return std::log(v / p.lower) / std::log(p.upper / p.lower);
  return (v - p.lower) / (p.upper - p.lower);
}

const char* stop_reason(nlopt::result r) {
  switch (r) {
    case nlopt::SUCCESS: return "success";
    case nlopt::STOPVAL_REACHED: return "stopval reached";
    case nlopt::FTOL_REACHED: return "ftol reached";
    case nlopt::XTOL_REACHED: return "xtol reached";
    case nlopt::MAXEVAL_REACHED: return "maxeval reached";
    case nlopt::MAXTIME_REACHED: return "maxtime reached";
    default: return "stopped";
  }
}

}  // namespace

FitResult fit_impacts(const ImpactModel& model, const ImpactTable& table,
                      const std::vector<std::size_t>& indices, const FitOptions& options) {
  const std::vector<ImpactParameter> specs = model.parameters();
  // the free ones: a parameter with lower == upper is held at its start
  std::vector<std::size_t> free;
  for (std::size_t j = 0; j < specs.size(); ++j) {
    if (specs[j].upper > specs[j].lower) free.push_back(j);
  }
  std::vector<double> values(specs.size());
  for (std::size_t j = 0; j < specs.size(); ++j) values[j] = specs[j].start;

  FitResult result;
  auto evaluate = [&](const std::vector<double>& v) {
    const std::vector<double> eps = impact_errors(table, indices,
                                                  predict_impacts(model, table, indices, v, options.jobs));
    ++result.evaluations;
    const double objective = fit_objective(eps, options.objective);
    if (options.progress) options.progress(result.evaluations, objective);
    return objective;
  };
  if (free.empty()) {
    result.parameters = values;
    result.objective = evaluate(values);
    result.stop = "no parameters";
    return result;
  }

  nlopt::opt opt(nlopt::LN_NELDERMEAD, static_cast<unsigned>(free.size()));
  opt.set_lower_bounds(std::vector<double>(free.size(), 0.0));
  opt.set_upper_bounds(std::vector<double>(free.size(), 1.0));
  opt.set_initial_step(options.initial_step);
  const int budget = std::max(options.max_evaluations, model.evaluations_hint());
  opt.set_maxeval(budget);
  opt.set_xtol_abs(1e-4);  // 1e-4 of a parameter's range: far below what the median resolves
  // the objective on the unit cube of the free parameters
  // (an exception inside it is kept and rethrown after NLopt has stopped:
  // NLopt's wrapper would turn it into a bare "nlopt failure")
  std::exception_ptr failed;
  std::function<double(const std::vector<double>&)> objective = [&](const std::vector<double>& u) {
    try {
      std::vector<double> v = values;
      for (std::size_t f = 0; f < free.size(); ++f) v[free[f]] = from_unit(specs[free[f]], u[f]);
      const double value = evaluate(v);
      // a median of failures is +inf: NLopt needs a finite number
      return std::isfinite(value) ? value : 1e6;
    } catch (...) {
      failed = std::current_exception();
      throw nlopt::forced_stop();
    }
  };
  opt.set_min_objective(
      [](const std::vector<double>& u, std::vector<double>& /*grad*/, void* data) {
        return (*static_cast<std::function<double(const std::vector<double>&)>*>(data))(u);
      },
      &objective);
  std::vector<double> u(free.size());
  for (std::size_t f = 0; f < free.size(); ++f) u[f] = to_unit(specs[free[f]], specs[free[f]].start);
  double best = 0.0;
  nlopt::result r = nlopt::FAILURE;
  // A simplex that collapsed (xtol) with evaluations left starts again at its
  // best point with a fresh simplex, while that still improves the objective
  // by more than 1e-6: Nelder-Mead's collapse on a rough objective is not a
  // minimum (the remedy of Nelder-Mead with restarts; a model that runs out of
  // evaluations, every engine at 40, is not restarted)
  for (double previous = std::numeric_limits<double>::infinity();;) {
    try {
      r = opt.optimize(u, best);
    } catch (const nlopt::roundoff_limited&) {
      r = nlopt::SUCCESS;  // the best point so far is in u
    } catch (...) {
      if (failed) std::rethrow_exception(failed);
      throw;
    }
    // a fresh simplex spends n + 1 evaluations being built: with fewer than
    // 4 n left (a heuristic: a few of its moves past that) no restart
    const int left = budget - result.evaluations;
    if (r != nlopt::XTOL_REACHED || left < static_cast<int>(4 * free.size()) ||
        !(best < previous - 1e-6)) {
      break;
    }
    previous = best;
    opt.set_maxeval(left);
  }
  for (std::size_t f = 0; f < free.size(); ++f) values[free[f]] = from_unit(specs[free[f]], u[f]);
  result.parameters = values;
  result.objective = best;
  result.stop = stop_reason(r);
  return result;
}

std::vector<std::vector<std::size_t>> impact_folds(std::size_t n, int k, std::uint64_t seed) {
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::uint64_t state = seed;
  auto next = [&state] {  // splitmix64 (Steele, Lea & Flood 2014)
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  };
  for (std::size_t i = n; i > 1; --i) std::swap(order[i - 1], order[next() % i]);
  std::vector<std::vector<std::size_t>> folds(static_cast<std::size_t>(k));
  for (std::size_t i = 0; i < n; ++i) folds[i % folds.size()].push_back(order[i]);
  for (auto& f : folds) std::sort(f.begin(), f.end());
  return folds;
}

std::vector<std::size_t> complement(std::size_t n, const std::vector<std::size_t>& held_out) {
  std::vector<bool> out(n, false);
  for (std::size_t i : held_out) out[i] = true;
  std::vector<std::size_t> rest;
  for (std::size_t i = 0; i < n; ++i) {
    if (!out[i]) rest.push_back(i);
  }
  return rest;
}

}  // namespace pb
