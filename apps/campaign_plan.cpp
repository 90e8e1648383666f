// A campaign's plan (campaign_plan.hpp): its runs numbered and decoded, their
// assignments (a random axis's samples drawn here), cost and header. Reading
// the campaign file into a plan is campaign_file.cpp.
#include "campaign_plan.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "planarbench/case_loader.hpp"
#include "sweep_plan.hpp"
#include "task_scheduler.hpp"

namespace pb::cli {

namespace {

// splitmix64's finaliser (Steele, Lea & Flood, "Fast splittable pseudorandom
// number generators", OOPSLA 2014): a counter-based generator, so a sample's
// value depends on (seed, sample, body, component) only, not on the order or
// the shard that draws it
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

std::uint64_t hash_text(const std::string& s) {
  std::uint64_t h = 1469598103934665603ULL;  // FNV-1a
  for (const unsigned char ch : s) h = (h ^ ch) * 1099511628211ULL;
  return h;
}

// a standard normal deviate by Box-Muller from two uniforms in (0, 1)
double normal(std::uint64_t seed, std::uint64_t sample, const std::string& what, int component) {
  const std::uint64_t base = mix(mix(mix(seed) ^ sample) ^ hash_text(what)) ^
                             static_cast<std::uint64_t>(component);
  const double u1 = (static_cast<double>(mix(base) >> 11) + 0.5) * 0x1.0p-53;
  const double u2 = (static_cast<double>(mix(base ^ 0x5bd1e995ULL) >> 11) + 0.5) * 0x1.0p-53;
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * 3.14159265358979323846 * u2);
}

// the nominal value of a body's state field (1 or 2 numbers)
std::vector<double> nominal(const Body& b, const std::string& field) {
  if (field == "position") return {b.position_m.x(), b.position_m.y()};
  if (field == "velocity") return {b.velocity_mps.x(), b.velocity_mps.y()};
  if (field == "angle") return {b.angle_rad};
  return {b.angular_velocity_radps};
}

}  // namespace


const std::vector<CampaignMetric>& campaign_metrics() {
  static const std::vector<CampaignMetric> m = {
      {"position_error_m", "m",
       "max over the output samples and bodies of |p - p_truth|, the truth of the case at the "
       "run's own initial state (sweep_error.hpp)"},
      {"events", "1", "number of contact episodes"},
      {"first_onset_time_s", "s", "onset of the first contact episode"},
      {"first_restitution", "1", "restitution of the first contact episode"},
      {"first_peak_force_n", "N", "peak normal force of the first contact episode"},
      {"first_impulse_ns", "N s", "normal impulse of the first contact episode"},
      {"max_penetration_m", "m", "largest penetration over every episode"},
      {"slide_acceleration_mps2", "m/s^2",
       "steady acceleration along the line of the body on the case's first half-plane pair: "
       "least-squares slope of its speed over the run's second half (0 while friction holds "
       "it; the friction curve, SPEC §7)"},
      {"hold_drift_m", "m",
       "SPEC §7's hold_drift_m of the run against its truth (the drift of the material contact "
       "point while the truth holds the body at rest), where the truth holds: the block family "
       "(campaigns/block_family.toml)"},
      {"creep_speed_mps", "m/s",
       "SPEC §7's creep_speed_mps of the run against its truth (the drift's mean rate over the "
       "hold's second half), where the truth holds"},
      {"slide_acceleration_error", "1",
       "relative error of slide_acceleration_mps2 against the truth's closed form, where the "
       "truth slides at a constant acceleration"},
      {"stop_time_error", "1",
       "relative error of stop_time_s against the truth's closed form, where the truth slides "
       "and stops"},
      {"trace", "m",
       "positions of every moving body at trace_points times evenly over the run (not a "
       "column: trace_time_s and trace_position_m)"},
  };
  return m;
}

std::int64_t CampaignPlan::size() const {
  std::int64_t n = static_cast<std::int64_t>(cases.size() * engines.size());
  for (const auto& a : axes) n *= static_cast<std::int64_t>(a.axis.values.size());
  return n;
}

bool CampaignPlan::needs_truth() const {
  return std::any_of(metrics.begin(), metrics.end(),
                     [](const CampaignMetric& m) {
                       return m.name == "position_error_m" || m.name == "hold_drift_m" ||
                              m.name == "creep_speed_mps" ||
                              m.name == "slide_acceleration_error" ||
                              m.name == "stop_time_error";
                     });
}

CampaignPlan::RunRef decode_run(std::int64_t id, std::size_t engines,
                                const std::vector<std::size_t>& axis_sizes) {
  CampaignPlan::RunRef r;
  r.point.resize(axis_sizes.size());
  for (std::size_t k = axis_sizes.size(); k-- > 0;) {
    const auto n = static_cast<std::int64_t>(axis_sizes[k]);
    r.point[k] = static_cast<std::size_t>(id % n);
    id /= n;
  }
  const auto e = static_cast<std::int64_t>(engines);
  r.engine_index = static_cast<std::size_t>(id % e);
  r.case_index = static_cast<std::size_t>(id / e);
  return r;
}

namespace {
// "run 7: falling_ball x ode, dt=0.001, state=1"
std::string run_text(std::int64_t id, const std::string& case_name, const std::string& engine,
                     const std::vector<const CampaignAxis*>& axes,
                     const std::vector<std::size_t>& point) {
  std::string out = fmt::format("run {}: {} x {}", id, case_name, engine);
  for (std::size_t k = 0; k < axes.size(); ++k) {
    out += fmt::format(", {}={}", axes[k]->name, number_text(axes[k]->values[point[k]]));
  }
  return out;
}
}  // namespace

std::string describe_run(const CampaignTable& t, std::int64_t id) {
  std::vector<std::size_t> sizes;
  std::vector<const CampaignAxis*> axes;
  for (const auto& a : t.axes) {
    sizes.push_back(a.values.size());
    axes.push_back(&a);
  }
  const auto r = decode_run(id, t.engines.size(), sizes);
  return run_text(id, r.case_index < t.cases.size() ? t.cases[r.case_index].name : "?",
                  t.engines.at(r.engine_index), axes, r.point);
}

CampaignPlan::RunRef CampaignPlan::decode(std::int64_t id) const {
  std::vector<std::size_t> sizes;
  for (const auto& a : axes) sizes.push_back(a.axis.values.size());
  return decode_run(id, engines.size(), sizes);
}

std::vector<std::pair<std::string, std::string>> CampaignPlan::assignments(const RunRef& r) const {
  std::vector<std::pair<std::string, std::string>> out;
  const CampaignCasePlan& cp = cases[r.case_index];
  for (std::size_t k = 0; k < axes.size(); ++k) {
    const CampaignAxisPlan& a = axes[k];
    if (a.axis.kind != "perturb") {
      out.emplace_back(a.axis.key, number_text(a.axis.values[r.point[k]]));
      continue;
    }
    for (const Body& b : cp.c.bodies) {
      if (b.fixed || (a.body != "*" && a.body != b.name)) continue;
      const std::vector<double> v0 = nominal(b, a.field);
      std::vector<double> v = v0;
      for (std::size_t j = 0; j < v.size(); ++j) {
        v[j] += a.sigma * normal(a.seed, r.point[k], b.name + "." + a.field, static_cast<int>(j));
      }
      const std::string key = "bodies." + b.name + "." + a.field;
      out.emplace_back(key, v.size() == 1 ? number_text(v[0])
                                          : fmt::format("[{},{}]", number_text(v[0]), number_text(v[1])));
    }
  }
  return out;
}

std::vector<std::pair<std::string, std::string>> CampaignPlan::case_assignments(
    const RunRef& r) const {
  std::vector<std::pair<std::string, std::string>> out;
  for (auto& kv : assignments(r)) {
    if (is_case_key(kv.first)) out.push_back(std::move(kv));
  }
  return out;
}

std::vector<double> CampaignPlan::axis_values(const RunRef& r) const {
  std::vector<double> out;
  for (std::size_t k = 0; k < axes.size(); ++k) out.push_back(axes[k].axis.values[r.point[k]]);
  return out;
}

namespace {

// an axis of `key` sets `engine`'s step (cost() and cost_by_engine() scale by it)
bool sets_step(const std::string& key, const std::string& engine) {
  return key == "dt" || key == engine + ".dt";
}

}  // namespace

double CampaignPlan::cost(std::int64_t id) const {
  const RunRef r = decode(id);
  const CampaignCasePlan& cp = cases[r.case_index];
  const std::string& engine = engines[r.engine_index];
  double c = expected_cost(cp.c.name, engine, cp.c.duration_s);
  const double dt0 = cp.default_dt[r.engine_index];
  for (std::size_t k = 0; k < axes.size(); ++k) {
    if (sets_step(axes[k].axis.key, engine) && std::isfinite(dt0)) {
      c *= dt0 / axes[k].axis.values[r.point[k]];
    }
  }
  return c;
}

std::vector<double> CampaignPlan::cost_by_engine() const {
  std::vector<double> out(engines.size(), 0.0);
  for (const CampaignCasePlan& cp : cases) {
    for (std::size_t e = 0; e < engines.size(); ++e) {
      double c = expected_cost(cp.c.name, engines[e], cp.c.duration_s);
      const double dt0 = cp.default_dt[e];
      for (const CampaignAxisPlan& a : axes) {
        if (sets_step(a.axis.key, engines[e]) && std::isfinite(dt0)) {
          double f = 0.0;  // cost() scales by dt0 / dt at each point
          for (const double v : a.axis.values) f += dt0 / v;
          c *= f;
        } else {
          c *= static_cast<double>(a.axis.values.size());
        }
      }
      out[e] += c;
    }
  }
  return out;
}

std::string CampaignPlan::describe(std::int64_t id) const {
  const RunRef r = decode(id);
  std::vector<const CampaignAxis*> a;
  for (const auto& x : axes) a.push_back(&x.axis);
  return run_text(id, cases[r.case_index].c.name, engines[r.engine_index], a, r.point);
}

CampaignTable campaign_header(const CampaignPlan& plan) {
  CampaignTable t;
  t.kind = "campaign";
  t.source_text = plan.text;
  t.source_path = plan.file;
  t.planned_runs = plan.size();
  t.engines = plan.engines;
  t.metrics = plan.metrics;
  t.trace_points = plan.trace_points;
  for (const auto& cp : plan.cases) {
    CampaignCase c;
    c.name = cp.c.name;
    c.text = cp.c.source_text;
    c.path = cp.c.source_path;
    c.overrides = plan.set;
    c.duration_s = cp.c.duration_s;
    const TruthPlan truth = truth_for(cp.c);
    c.truth = plan.needs_truth() ? truth.label : "none";
    c.truth_note = plan.needs_truth() ? truth.note : "no metric against the truth recorded";
    c.moving_bodies = cp.moving_bodies;
    t.trace_bodies = std::max(t.trace_bodies, static_cast<int>(cp.moving_bodies.size()));
    t.cases.push_back(std::move(c));
  }
  if (t.trace_points == 0) t.trace_bodies = 0;
  for (const auto& a : plan.axes) t.axes.push_back(a.axis);
  return t;
}

}  // namespace pb::cli
