#include "planarbench/reports/scene_metrics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <unordered_map>

#include "planarbench/energy_budget.hpp"
#include "planarbench/contact_pairs.hpp"

namespace pb {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double nan_max(double a, double b) { return std::isnan(a) || std::isnan(b) ? kNaN : std::max(a, b); }

// body name -> its trajectory in the run
std::unordered_map<std::string, const BodyTrajectory*> trajectories(const RunResult& r) {
  std::unordered_map<std::string, const BodyTrajectory*> out;
  for (const auto& b : r.bodies) out.emplace(b.name, &b);
  return out;
}

std::uint64_t pair_key(int a, int b) {
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint64_t>(std::max(a, b));
}

// the support force of a run at each sample time: sum of the normal forces
// of the rows joining the support to a body of the generator
std::map<double, double> support_forces(const RunResult& r, const GeneratedBodies& g) {
  std::map<double, double> out;
  for (const ContactRow& row : r.contacts) {
    const ContactSample& s = row.sample;
    const int other = s.body_a == g.support ? s.body_b : s.body_b == g.support ? s.body_a : -1;
    if (other < g.first_body || other >= g.first_body + g.count) continue;
    out[row.time_s] += s.force_n;
  }
  return out;
}

void standing_metrics(const Case& c, const RunResult& run, const RunResult* truth,
                      const GeneratedBodies& g, std::vector<MetricValue>& out) {
  const auto tracks = trajectories(run);
  const Body& plane = c.bodies[static_cast<std::size_t>(g.support)];
  const Vec2 n(-std::sin(plane.angle_rad), std::cos(plane.angle_rad));
  const Vec2 t(n.y(), -n.x());
  // sideways, any body, any sample
  double lateral = 0.0;
  bool any = false;
  for (int k = 0; k < g.count; ++k) {
    const auto it = tracks.find(c.bodies[static_cast<std::size_t>(g.body(k))].name);
    if (it == tracks.end() || it->second->position_m.empty()) continue;
    const BodyTrajectory& b = *it->second;
    for (const Vec2& p : b.position_m) lateral = nan_max(lateral, std::abs((p - b.position_m.front()).dot(t)));
    any = true;
  }
  if (!any) return;
  auto lat = metric_value(c, run, "self", "lateral_drift_m", lateral, 0.0, false, "m");
  lat.note = fmt::format("{} '{}': along the surface of '{}'", scene_kind_name(g.kind), g.name, plane.name);
  out.push_back(lat);
  // the top body: the last of the generator
  const auto top = tracks.find(c.bodies[static_cast<std::size_t>(g.body(g.count - 1))].name);
  if (top != tracks.end() && top->second->position_m.size() > 1) {
    const BodyTrajectory& b = *top->second;
    const double sag = (b.position_m.front() - b.position_m.back()).dot(n);
    auto m = metric_value(c, run, "self", "sag_m", sag, 0.0, false, "m");
    m.note = fmt::format("body '{}' at t = {:.6g} s", b.name, b.time_s.back());
    out.push_back(m);
    const std::size_t half = b.time_s.size() / 2;
    const double span = b.time_s.back() - b.time_s[half];
    if (span > 0.0) {
      const double creep = (b.position_m.back() - b.position_m[half]).norm() / span;
      auto cr = metric_value(c, run, "self", "settled_creep_mps", creep, 0.0, false, "m/s");
      cr.note = fmt::format("body '{}' from t = {:.6g} s", b.name, b.time_s[half]);
      out.push_back(cr);
    }
  }
  // the support carries the weight once settled
  double weight = 0.0;
  const double g_n = -c.gravity_mps2.dot(n);
  for (int k = 0; k < g.count; ++k) weight += c.bodies[static_cast<std::size_t>(g.body(k))].mass_kg * g_n;
  const auto forces = support_forces(run, g);
  if (weight > 0.0 && !forces.empty() && top != tracks.end() && !top->second->time_s.empty()) {
    const double from = 0.5 * top->second->time_s.back();
    double sum = 0.0;
    int samples = 0;
    for (const auto& [time, f] : forces) {
      if (time < from) continue;
      sum += f;
      ++samples;
    }
    if (samples > 0) {
      auto m = metric_value(c, run, "self", "ground_force_error", sum / samples, weight, true, "N");
      m.note = fmt::format("mean over {} samples from t = {:.6g} s against the weight {:.6g} N",
                           samples, from, weight);
      out.push_back(m);
    }
  }
  // interfaces against the truth's: each body pair's summed force per sample
  if (truth == nullptr) return;
  std::unordered_map<std::uint64_t, double> expected;
  for (const ContactRow& row : truth->contacts) {
    expected[pair_key(row.sample.body_a, row.sample.body_b)] = row.sample.force_n;
  }
  // from the first sample after the start: a stepping engine's force is that
  // of a step (Box2D's impulse over dt, ODE's joint feedback), so its row at
  // t = 0, before any step, holds 0 whatever the pose presses
  std::map<std::pair<double, std::uint64_t>, double> got;
  for (const ContactRow& row : run.contacts) {
    if (!(row.time_s > 0.0)) continue;
    const std::uint64_t key = pair_key(row.sample.body_a, row.sample.body_b);
    if (expected.count(key)) got[{row.time_s, key}] += row.sample.force_n;
  }
  double worst = 0.0;
  int rows = 0;
  for (const auto& [at, f] : got) {
    const double want = expected[at.second];
    if (!(want > 0.0)) continue;
    worst = nan_max(worst, std::abs(f - want) / want);
    ++rows;
  }
  // an interface with no row at a sample carries nothing: an error of 1
  std::map<double, int> per_time;
  for (const auto& [at, f] : got) ++per_time[at.first];
  for (const auto& [time, count] : per_time) {
    if (count < static_cast<int>(expected.size())) worst = std::max(worst, 1.0);
  }
  if (rows > 0) {
    auto m = metric_value(c, run, "truth", "interface_force_error", worst, 0.0, false, "1");
    m.note = fmt::format("{} interfaces, {} samples after t = 0; an interface without a row counts 1",
                         expected.size(), per_time.size());
    out.push_back(m);
  }
}

// J, the case law's elastic energy at penetration delta (the budget's U_c)
double stored_j(const ContactLaw& law, double delta) { return elastic_energy_j(law, delta); }

void energy_metrics(const Case& c, const RunResult& run, std::vector<MetricValue>& out) {
  if (run.bodies.empty()) return;
  const auto tracks = trajectories(run);
  std::vector<std::pair<const Body*, const BodyTrajectory*>> moving;
  for (const Body& b : c.bodies) {
    if (b.fixed) continue;
    const auto it = tracks.find(b.name);
    if (it == tracks.end()) return;
    moving.emplace_back(&b, it->second);
  }
  std::size_t n = moving.front().second->time_s.size();
  for (const auto& [b, tr] : moving) n = std::min(n, tr->time_s.size());
  if (n == 0) return;
  // U_c(0) from the first sample's rows
  const ContactPairs rules(c);
  double stored = 0.0;
  const double t0 = moving.front().second->time_s.front();
  for (const ContactRow& row : run.contacts) {
    if (row.time_s > t0) break;
    if (const ContactLaw* law = rules.law_between(row.sample.body_a, row.sample.body_b)) {
      if (std::isfinite(row.sample.penetration_m)) stored += stored_j(*law, row.sample.penetration_m);
    }
  }
  double ke0 = 0.0;
  double worst = 0.0;
  double most_work = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    double ke = 0.0, work = 0.0;
    for (const auto& [b, tr] : moving) {
      ke += 0.5 * b->mass_kg * tr->velocity_mps[i].squaredNorm() +
            0.5 * b->inertia_kgm2 * tr->angular_velocity_radps[i] * tr->angular_velocity_radps[i];
      work += b->mass_kg * c.gravity_mps2.dot(tr->position_m[i] - tr->position_m.front());
    }
    if (i == 0) ke0 = ke;
    most_work = std::max(most_work, work);
    const double available = ke0 + stored + most_work;
    if (available > 0.0) worst = nan_max(worst, ke / available);
  }
  auto m = metric_value(c, run, "self", "energy_ratio", worst, 0.0, false, "1");
  m.note = "max KE / (KE(0) + U_c(0) + max W_g so far); passive contacts keep it <= 1";
  out.push_back(m);
  double deepest = 0.0;
  for (const ContactRow& row : run.contacts) deepest = nan_max(deepest, row.sample.penetration_m);
  out.push_back(metric_value(c, run, "self", "deepest_penetration_m", deepest, 0.0, false, "m"));
}

}  // namespace

const std::vector<const char*>& scene_metric_names() {
  static const std::vector<const char*> names = {
      "lateral_drift_m",      "sag_m",        "settled_creep_mps",     "ground_force_error",
      "interface_force_error", "energy_ratio", "deepest_penetration_m"};
  return names;
}

std::vector<MetricValue> scene_metrics(const Case& c, const RunResult& run, const RunResult* truth) {
  std::vector<MetricValue> out;
  if (c.generated.empty() || run.status == RunStatus::unsupported) return out;
  for (const GeneratedBodies& g : c.generated) {
    if (g.support >= 0 && (g.kind == SceneKind::stack || g.kind == SceneKind::pyramid)) {
      standing_metrics(c, run, truth, g, out);
    }
  }
  energy_metrics(c, run, out);
  return out;
}

}  // namespace pb
