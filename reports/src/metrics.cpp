#include "planarbench/reports/metrics.hpp"

#include "planarbench/reports/contact_validity.hpp"
#include "planarbench/reports/friction_metrics.hpp"
#include "planarbench/reports/scene_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

namespace pb {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// the larger of a and b, NaN when either is: std::max(x, NaN) is x, and a
// maximum error taken over a run with NaN samples would skip them (issue 24)
double nan_max(double a, double b) {
  return std::isnan(a) || std::isnan(b) ? kNaN : std::max(a, b);
}
double nan_min(double a, double b) {
  return std::isnan(a) || std::isnan(b) ? kNaN : std::min(a, b);
}

// a run's body trajectory with repeated sample times removed (the last state
// at a time wins), ready for linear interpolation
struct Track {
  std::vector<double> t;
  std::vector<Vec2> p;
  std::vector<Vec2> v;
  std::vector<double> a;
};

Track make_track(const BodyTrajectory& b) {
  Track tr;
  for (std::size_t i = 0; i < b.time_s.size(); ++i) {
    if (!tr.t.empty() && b.time_s[i] <= tr.t.back()) {
      tr.p.back() = b.position_m[i];
      tr.v.back() = b.velocity_mps[i];
      tr.a.back() = b.angle_rad[i];
      continue;
    }
    tr.t.push_back(b.time_s[i]);
    tr.p.push_back(b.position_m[i]);
    tr.v.push_back(b.velocity_mps[i]);
    tr.a.push_back(b.angle_rad[i]);
  }
  return tr;
}

const BodyTrajectory* find_body(const RunResult& r, const std::string& name) {
  for (const auto& b : r.bodies) {
    if (b.name == name) return &b;
  }
  return nullptr;
}

MetricValue metric(const Case& c, const RunResult& run, const std::string& against,
                   const std::string& name, double actual, double desired, bool relative,
                   const std::string& unit) {
  return metric_value(c, run, against, name, actual, desired, relative, unit);
}

// trajectory metrics over every body the baseline has
// why `run` does not cover `base`'s trajectories (issue 25): a body the
// baseline has and the run lacks, or fewer rows of it than the baseline's
// (both are sampled on the case's output grid); "" when it covers them
std::string uncovered(const RunResult& run, const RunResult& base) {
  for (const auto& bb : base.bodies) {
    const BodyTrajectory* rb = find_body(run, bb.name);
    if (rb == nullptr || rb->time_s.empty()) {
      return "truncated: no samples of body '" + bb.name + "' in the run";
    }
    if (rb->time_s.size() < bb.time_s.size()) {
      return "truncated: " + std::to_string(rb->time_s.size()) + " rows of body '" + bb.name +
             "' (to t = " + std::to_string(rb->time_s.back()) + " s) against the baseline's " +
             std::to_string(bb.time_s.size()) + " (to t = " +
             std::to_string(bb.time_s.empty() ? 0.0 : bb.time_s.back()) + " s)";
    }
  }
  return "";
}

void trajectory_metrics(const Case& c, const RunResult& run, const RunResult& base,
                        const std::string& against, double valid_until_s,
                        std::vector<MetricValue>& out) {
  double pos_max = 0.0, pos_sq = 0.0, vel_max = 0.0, vel_sq = 0.0, ang_max = 0.0;
  long n = 0;
  double t_last = 0.0;
  // a run that stops early is not judged on its common prefix alone: an ok
  // run's errors are then NaN (the gate fails them); a diverged run (failed
  // by its status already) keeps its errors up to the divergence, noted
  const std::string gap = uncovered(run, base);
  for (const auto& bb : base.bodies) {
    const BodyTrajectory* rb = find_body(run, bb.name);
    if (rb == nullptr || rb->time_s.empty()) continue;
    const Track tr = make_track(*rb);
    std::size_t j = 0;
    for (std::size_t i = 0; i < bb.time_s.size(); ++i) {
      const double t = bb.time_s[i];
      if (t > valid_until_s || t < tr.t.front() || t > tr.t.back()) continue;
      while (j + 1 < tr.t.size() && tr.t[j + 1] < t) ++j;
      // linear interpolation between the run's samples j and j + 1
      const std::size_t k = std::min(j + 1, tr.t.size() - 1);
      const double w = (k == j || tr.t[k] == tr.t[j]) ? 0.0 : (t - tr.t[j]) / (tr.t[k] - tr.t[j]);
      const Vec2 p = (1 - w) * tr.p[j] + w * tr.p[k];
      const Vec2 v = (1 - w) * tr.v[j] + w * tr.v[k];
      const double a = (1 - w) * tr.a[j] + w * tr.a[k];
      const double dp = (p - bb.position_m[i]).norm();
      const double dv = (v - bb.velocity_mps[i]).norm();
      pos_max = nan_max(pos_max, dp);
      vel_max = nan_max(vel_max, dv);
      ang_max = nan_max(ang_max, std::abs(a - bb.angle_rad[i]));
      pos_sq += dp * dp;
      vel_sq += dv * dv;
      t_last = std::max(t_last, t);
      ++n;
    }
  }
  if (n == 0 && gap.empty()) return;
  std::string note =
      std::isfinite(valid_until_s) ? "compared up to t = " + std::to_string(t_last) + " s" : "";
  const bool unjudged = !gap.empty() && run.status == RunStatus::ok;
  if (!gap.empty()) note = gap + (note.empty() ? "" : "; " + note);
  auto add = [&](const char* name, double value, const char* unit) {
    auto m = metric(c, run, against, name, unjudged || n == 0 ? kNaN : value, 0.0, false, unit);
    m.note = note;
    out.push_back(m);
  };
  add("position_max", pos_max, "m");
  const double count = std::max(1.0, static_cast<double>(n));
  add("position_rms", std::sqrt(pos_sq / count), "m");
  add("angle_max", ang_max, "rad");
  add("velocity_max", vel_max, "m/s");
  add("velocity_rms", std::sqrt(vel_sq / count), "m/s");
}

using PairKey = std::pair<std::string, std::string>;

std::map<PairKey, std::vector<ContactEpisode>> episodes_by_pair(const RunResult& r,
                                                                double valid_until_s) {
  std::map<PairKey, std::vector<ContactEpisode>> out;
  auto name = [&](int i) {
    return i >= 0 && static_cast<std::size_t>(i) < r.body_names.size()
               ? r.body_names[static_cast<std::size_t>(i)]
               : std::to_string(i);
  };
  for (const auto& e : r.events) {
    if (e.onset_time_s > valid_until_s) continue;
    out[{name(e.body_a), name(e.body_b)}].push_back(e);
  }
  return out;
}

// per-episode metrics, episodes matched in order per body pair (k-th with
// k-th): a baseline episode the run lacks gets every metric its baseline
// value exists for, with the run's value NaN (the gate fails it); an extra
// episode of the run has no baseline value to compare with and shows in
// episode_count only (issue 25)
void episode_metrics(const Case& c, const RunResult& run, const RunResult& base,
                     const std::string& against, double valid_until_s,
                     std::vector<MetricValue>& out) {
  const auto run_eps = episodes_by_pair(run, valid_until_s);
  const auto base_eps = episodes_by_pair(base, valid_until_s);
  std::map<PairKey, int> pairs;
  for (const auto& [k, v] : run_eps) pairs[k] = 0;
  for (const auto& [k, v] : base_eps) pairs[k] = 0;
  for (const auto& [pair, unused] : pairs) {
    const auto ri = run_eps.find(pair);
    const auto bi = base_eps.find(pair);
    const std::vector<ContactEpisode> none;
    const auto& re = ri == run_eps.end() ? none : ri->second;
    const auto& be = bi == base_eps.end() ? none : bi->second;
    const std::string pair_name = pair.first + "-" + pair.second;
    auto count = metric(c, run, against, "episode_count", static_cast<double>(re.size()),
                        static_cast<double>(be.size()), false, "1");
    count.note = pair_name + (re.size() < be.size()   ? ": episodes missing in the run"
                              : re.size() > be.size() ? ": extra episodes in the run"
                                                      : "");
    out.push_back(count);
    ContactEpisode lost;  // stands in for a baseline episode the run lacks
    lost.onset_time_s = lost.offset_time_s = lost.restitution = lost.peak_force_n =
        lost.impulse_ns = lost.max_penetration_m = kNaN;
    for (std::size_t k = 0; k < be.size(); ++k) {
      const bool missing = k >= re.size();
      const ContactEpisode& a = missing ? lost : re[k];
      const ContactEpisode& d = be[k];
      // no baseline value (an episode still open at the end has no offset,
      // duration or restitution): nothing to compare; a run's NaN or inf
      // against a finite baseline value is kept, and fails its threshold
      auto add = [&](const char* name, double actual, double desired, bool relative,
                     const char* unit) {
        if (!std::isfinite(desired)) return;
        if (relative && desired == 0.0) return;
        auto m = metric(c, run, against, name, std::isfinite(actual) ? actual : kNaN, desired,
                        relative, unit);
        m.episode = static_cast<int>(k);
        m.note = pair_name + (missing ? ": episode missing in the run" : "");
        out.push_back(m);
      };
      add("impact_time", a.onset_time_s, d.onset_time_s, false, "s");
      // the unit given is the quantity's; a relative error's own is "1"
      add("contact_duration", a.offset_time_s - a.onset_time_s, d.offset_time_s - d.onset_time_s,
          true, "s");
      add("peak_force", a.peak_force_n, d.peak_force_n, true, "N");
      add("impulse", a.impulse_ns, d.impulse_ns, true, "N s");
      add("restitution", a.restitution, d.restitution, false, "1");
      add("max_penetration", a.max_penetration_m, d.max_penetration_m, false, "m");
    }
  }
}

}  // namespace

MetricValue metric_value(const Case& c, const RunResult& run, const std::string& against,
                         const std::string& name, double actual, double desired, bool relative,
                         const std::string& unit) {
  MetricValue m;
  m.case_name = c.name;
  m.engine = run.engine_name;
  m.against = against;
  m.metric = name;
  m.actual = actual;
  m.desired = desired;
  m.error = relative ? std::abs(actual - desired) / std::abs(desired) : std::abs(actual - desired);
  m.unit = relative ? "1" : unit;
  m.value_unit = unit;
  return m;
}

std::vector<MetricValue> compare_runs(const Case& c, const RunResult& run,
                                      const RunResult& baseline, const std::string& against,
                                      double valid_until_s) {
  std::vector<MetricValue> out;
  if (run.status == RunStatus::unsupported || baseline.status == RunStatus::unsupported) {
    return out;
  }
  trajectory_metrics(c, run, baseline, against, valid_until_s, out);
  episode_metrics(c, run, baseline, against, valid_until_s, out);
  return out;
}

std::vector<MetricValue> self_metrics(const Case& c, const RunResult& run) {
  std::vector<MetricValue> out;
  if (run.status == RunStatus::unsupported) return out;
  const double g = c.gravity_mps2.norm();
  const Vec2 up = g > 0.0 ? Vec2(-c.gravity_mps2 / g) : Vec2(0.0, 1.0);

  // energy over the shared sample index (every body is sampled at the same times)
  std::size_t n = 0;
  for (const auto& b : run.bodies) n = std::max(n, b.time_s.size());
  std::vector<double> energy(n, 0.0);
  double ke_max = 0.0;
  double pe_span = 0.0;
  std::vector<double> times;
  for (const auto& b : run.bodies) {
    const int bi = c.body_index(b.name);
    if (bi < 0 || b.time_s.size() != n) return out;
    const Body& body = c.bodies[static_cast<std::size_t>(bi)];
    double h_min = kInf, h_max = -kInf;
    for (std::size_t i = 0; i < n; ++i) {
      const double ke = 0.5 * body.mass_kg * b.velocity_mps[i].squaredNorm() +
                        0.5 * body.inertia_kgm2 * b.angular_velocity_radps[i] *
                            b.angular_velocity_radps[i];
      const double h = b.position_m[i].dot(up);
      energy[i] += ke + body.mass_kg * g * h;
      ke_max = nan_max(ke_max, ke);
      h_min = nan_min(h_min, h);
      h_max = nan_max(h_max, h);
    }
    if (n > 0) pe_span += body.mass_kg * g * (h_max - h_min);
    times = b.time_s;
  }
  const double scale = ke_max + pe_span;
  if (n > 1 && (scale > 0.0 || std::isnan(scale))) {
    // a sample is in contact within one grid interval of an episode
    const double dt = c.output_interval_s;
    auto in_contact = [&](double t) {
      for (const auto& e : run.events) {
        const double off = std::isfinite(e.offset_time_s) ? e.offset_time_s : kInf;
        if (t >= e.onset_time_s - dt && t <= off + dt) return true;
      }
      return false;
    };
    double drift = 0.0;
    bool any = false;
    double e0 = 0.0;
    bool open = false;
    for (std::size_t i = 0; i < n; ++i) {
      if (in_contact(times[i])) {
        open = false;
        continue;
      }
      if (!open) {
        e0 = energy[i];
        open = true;
      }
      any = true;
      drift = nan_max(drift, std::abs(energy[i] - e0) / scale);
    }
    if (any) {
      auto m = metric(c, run, "self", "energy_drift", drift, 0.0, false, "1");
      m.note = "relative to m g (y_max - y_min) + max kinetic energy";
      out.push_back(m);
    }
  }

  // free bodies that touch only each other (no joint, no fixed body in any
  // contact pair): their total momentum changes by gravity alone,
  // P(t) = P(0) + M g t; the drift is relative to |P(0)| (or, when that is 0,
  // to sum m |v(0)|)
  bool closed = c.joints.empty() && !run.bodies.empty();
  for (const auto& p : c.contacts) {
    closed = closed && !c.bodies[static_cast<std::size_t>(p.body_a)].fixed &&
             !c.bodies[static_cast<std::size_t>(p.body_b)].fixed;
  }
  for (const auto& group : c.contact_groups) {
    for (const int i : group.bodies) closed = closed && !c.bodies[static_cast<std::size_t>(i)].fixed;
  }
  if (closed && n > 1) {
    double total_mass = 0.0;
    Vec2 p0 = Vec2::Zero();
    double speed_scale = 0.0;
    // each trajectory's mass, looked up once (a scene has thousands of bodies)
    std::map<std::string, double> mass_of;
    for (const Body& body : c.bodies) mass_of.emplace(body.name, body.mass_kg);
    std::vector<double> masses;
    for (const auto& b : run.bodies) {
      masses.push_back(mass_of.at(b.name));
      total_mass += masses.back();
      p0 += masses.back() * b.velocity_mps.front();
      speed_scale += masses.back() * b.velocity_mps.front().norm();
    }
    const double p_scale = p0.norm() > 0.0 ? p0.norm() : speed_scale;  // kg m/s
    if (p_scale > 0.0 || std::isnan(p_scale)) {
      double worst = 0.0;
      const double t0 = run.bodies.front().time_s.front();
      for (std::size_t i = 0; i < n; ++i) {
        Vec2 p = Vec2::Zero();
        for (std::size_t j = 0; j < run.bodies.size(); ++j) {
          p += masses[j] * run.bodies[j].velocity_mps[i];
        }
        const double t = run.bodies.front().time_s[i] - t0;
        worst = nan_max(worst, (p - p0 - total_mass * t * c.gravity_mps2).norm() / p_scale);
      }
      auto m = metric(c, run, "self", "momentum_drift", worst, 0.0, false, "1");
      m.note = p0.norm() > 0.0 ? "max |P(t) - P(0) - M g t| / |P(0)|"
                               : "max |P(t) - P(0) - M g t| / sum m |v(0)|";
      out.push_back(m);
    }
  }

  // revolute joints: anchor on the body against its world pivot
  if (!c.joints.empty()) {
    double worst = 0.0;
    for (const auto& j : c.joints) {
      const Body& body = c.bodies[static_cast<std::size_t>(j.body)];
      const BodyTrajectory* b = find_body(run, body.name);
      if (b == nullptr) continue;
      for (std::size_t i = 0; i < b->time_s.size(); ++i) {
        const double th = b->angle_rad[i];
        const Vec2 r(std::cos(th) * j.anchor_local_m.x() - std::sin(th) * j.anchor_local_m.y(),
                     std::sin(th) * j.anchor_local_m.x() + std::cos(th) * j.anchor_local_m.y());
        worst = nan_max(worst, (b->position_m[i] + r - j.anchor_world_m).norm());
      }
    }
    out.push_back(metric(c, run, "self", "constraint_drift", worst, 0.0, false, "m"));
  }

  if (run.status == RunStatus::ok && c.duration_s > 0.0) {
    out.push_back(metric(c, run, "self", "wall_per_sim_s", run.wall_time_s / c.duration_s, 0.0,
                         false, "s/s"));
  }
  return out;
}

std::vector<MetricValue> case_metrics(const Case& c, const CaseRuns& runs) {
  std::vector<MetricValue> out;
  const RunResult* truth = nullptr;
  const RunResult* reference = nullptr;
  for (const auto& r : runs.runs) {
    if (r.engine_name == "analytic" && r.status == RunStatus::ok) truth = &r;
    if (r.engine_name == "reference" && r.status == RunStatus::ok) reference = &r;
  }
  double valid_until = kInf;
  if (truth != nullptr && truth->extra.contains("valid_until_s") &&
      truth->extra["valid_until_s"].is_number()) {
    valid_until = truth->extra["valid_until_s"].get<double>();
  }
  auto append = [&](std::vector<MetricValue> v) {
    out.insert(out.end(), v.begin(), v.end());
  };
  for (const auto& r : runs.runs) {
    if (r.engine_name == "analytic") continue;
    if (truth != nullptr) append(compare_runs(c, r, *truth, "truth", valid_until));
    if (truth != nullptr && r.status == RunStatus::ok) append(friction_metrics(c, r, *truth));
    if (reference != nullptr && &r != reference) {
      append(compare_runs(c, r, *reference, "reference", kInf));
    }
    append(self_metrics(c, r));
    append(validity_metrics(c, r));  // SPEC §9, against "self"
    append(scene_metrics(c, r, truth));  // SPEC §11
  }
  // engine against engine: the discrepancy matrix (upper triangle)
  for (std::size_t i = 0; i < runs.runs.size(); ++i) {
    for (std::size_t j = i + 1; j < runs.runs.size(); ++j) {
      const auto& a = runs.runs[i];
      const auto& b = runs.runs[j];
      if (a.engine_name == "analytic" || b.engine_name == "analytic") continue;
      if (a.engine_name == "reference" || b.engine_name == "reference") continue;
      append(compare_runs(c, a, b, b.engine_name, kInf));
    }
  }
  return out;
}

}  // namespace pb
