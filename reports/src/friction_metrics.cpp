#include "planarbench/reports/friction_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <variant>

namespace pb {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// a speed has "fallen to zero" at this fraction of its starting value: far
// below what the metrics resolve, far above the creep of a held body
constexpr double kZeroFraction = 1e-3;
// s: the impact window reaches this far before the truth's onset and after
// its offset, so that an engine's own onset or offset a few steps away
// (1e-4 s each) stays inside it; nothing but gravity acts in flight
constexpr double kImpactMargin_s = 2e-3;
// s: a constant-acceleration phase shorter than this gives no fit
constexpr double kMinFitWindow_s = 0.2;
// the fit leaves out this fraction of the phase at its start
constexpr double kFitSkip = 0.1;

struct Phase {
  std::string kind;  // flight, slip, stick
  double start_s = 0.0;
  double end_s = kInf;
  double along_rate0_mps = 0.0;
};

// the truth's closed-form phases and constants (body_on_line with friction)
struct TruthFriction {
  std::vector<Phase> phases;
  double stick_acceleration_mps2 = 0.0;
  double tangential_gravity_mps2 = 0.0;
  bool normal_at_rest = false;  // pressed in at its static penetration from t = 0
  double support_m = 0.0;       // m, centre to contact point along the normal
};

bool read_truth(const RunResult& truth, TruthFriction& out) {
  const nlohmann::json& m = truth.mapping;
  if (!m.is_object() || !m.contains("friction") || !m["friction"].is_object()) return false;
  const nlohmann::json& f = m["friction"];
  if (!f.contains("phases") || !f["phases"].is_array()) return false;
  for (const auto& p : f["phases"]) {
    Phase ph;
    ph.kind = p.value("kind", "");
    ph.start_s = p.value("start_s", 0.0);
    ph.end_s = p.contains("end_s") && p["end_s"].is_number() ? p["end_s"].get<double>() : kInf;
    ph.along_rate0_mps = p.value("along_rate0_mps", 0.0);
    out.phases.push_back(ph);
  }
  out.stick_acceleration_mps2 = f.value("stick_acceleration_mps2", 0.0);
  out.support_m = m.value("support_m", 0.0);
  out.tangential_gravity_mps2 = f.value("tangential_gravity_mps2", 0.0);
  const double gap0 = m.value("initial_gap_m", kNaN);
  const double rest = m.value("static_penetration_m", kNaN);
  // the closed form's own rounding of the stated position: 1e-9 of it
  out.normal_at_rest = rest > 0.0 && std::abs(gap0 + rest) <= 1e-9 * rest;
  return !out.phases.empty();
}

// the case's body on a line: its first pair whose body_a is a fixed
// half-plane and body_b a moving body
struct LineCase {
  const Body* body = nullptr;
  Vec2 tangent = Vec2(1.0, 0.0);  // the half-plane's surface direction (its body x)
  double radius_m = 0.0;          // a disk's radius (its contact point turns with it), else 0
  bool disk = false;
};

std::optional<LineCase> line_case(const Case& c) {
  for (const ContactPair& p : c.contacts) {
    const Body& line = c.bodies[static_cast<std::size_t>(p.body_a)];
    const Body& body = c.bodies[static_cast<std::size_t>(p.body_b)];
    if (!std::holds_alternative<HalfPlane>(line.shape) || body.fixed) continue;
    LineCase lc;
    lc.body = &body;
    lc.tangent = Vec2(std::cos(line.angle_rad), std::sin(line.angle_rad));
    if (const auto* circle = std::get_if<Circle>(&body.shape)) {
      lc.radius_m = circle->radius_m;
      lc.disk = true;
    }
    return lc;
  }
  return std::nullopt;
}

const BodyTrajectory* trajectory(const RunResult& r, const std::string& body) {
  for (const auto& b : r.bodies) {
    if (b.name == body) return &b;
  }
  return nullptr;
}

// the truth holds the body at rest from t = 0
bool holds_at_rest(const TruthFriction& tf) {
  const Phase& p = tf.phases.front();
  return p.kind == "stick" && p.start_s == 0.0 && p.along_rate0_mps == 0.0 &&
         tf.stick_acceleration_mps2 == 0.0;
}

// the body's motion along the line, deduplicated by time; `point` is the
// displacement along the line of the material point that was the contact
// point at t = 0
struct LineTrack {
  std::vector<double> t, s, w, slip, spin, energy, point;
};

Vec2 rotated(const Vec2& v, double angle) {
  const double c = std::cos(angle);
  const double sn = std::sin(angle);
  return {c * v.x() - sn * v.y(), sn * v.x() + c * v.y()};
}

// support_m: the centre's height above the contact point along the line's
// normal n (the truth's support distance)
LineTrack line_track(const BodyTrajectory& b, const Body& body, const Vec2& tangent, double radius_m,
                     const Vec2& gravity, double support_m) {
  LineTrack tr;
  const Vec2 normal(-tangent.y(), tangent.x());
  // the contact point in the body frame at t = 0
  const Vec2 contact_local =
      b.angle_rad.empty() ? Vec2::Zero() : rotated(-support_m * normal, -b.angle_rad.front());
  const Vec2 contact0 =
      b.position_m.empty() ? Vec2::Zero() : Vec2(b.position_m.front() - support_m * normal);
  for (std::size_t i = 0; i < b.time_s.size(); ++i) {
    const Vec2& v = b.velocity_mps[i];
    const double omega = b.angular_velocity_radps[i];
    const double w = v.dot(tangent);
    const double e = 0.5 * body.mass_kg * v.squaredNorm() +
                     0.5 * body.inertia_kgm2 * omega * omega -
                     body.mass_kg * gravity.dot(b.position_m[i]);
    const double s = (b.position_m[i] - b.position_m.front()).dot(tangent);
    if (!tr.t.empty() && b.time_s[i] <= tr.t.back()) {
      // a repeated time (a step coarser than the grid): the last state wins
      for (auto* column : {&tr.t, &tr.s, &tr.w, &tr.slip, &tr.spin, &tr.energy, &tr.point}) {
        column->pop_back();
      }
    }
    const Vec2 contact = b.position_m[i] + rotated(contact_local, b.angle_rad[i]);
    tr.point.push_back((contact - contact0).dot(tangent));
    tr.t.push_back(b.time_s[i]);
    tr.s.push_back(s);
    tr.w.push_back(w);
    tr.slip.push_back(w + omega * radius_m);
    tr.spin.push_back(omega);
    tr.energy.push_back(e);
  }
  return tr;
}

// y at time t by linear interpolation (clamped to the ends)
double at(const std::vector<double>& t, const std::vector<double>& y, double when) {
  if (t.empty()) return kNaN;
  if (when <= t.front()) return y.front();
  if (when >= t.back()) return y.back();
  const auto it = std::upper_bound(t.begin(), t.end(), when);
  const std::size_t j = static_cast<std::size_t>(it - t.begin());
  const double u = (when - t[j - 1]) / (t[j] - t[j - 1]);
  return (1.0 - u) * y[j - 1] + u * y[j];
}

// first time after t0 at which |y| falls to `level` (linear between samples), or NaN
double first_fall(const std::vector<double>& t, const std::vector<double>& y, double t0,
                  double level) {
  for (std::size_t i = 1; i < t.size(); ++i) {
    if (t[i] < t0) continue;
    if (std::abs(y[i]) <= level) {
      const double a = std::abs(y[i - 1]);
      const double b = std::abs(y[i]);
      if (!(a > level) || a == b) return t[i];
      return t[i - 1] + (t[i] - t[i - 1]) * (a - level) / (a - b);
    }
  }
  return kNaN;
}

// least-squares slope of y over t in [a, b], or NaN with fewer than 3 samples
double slope(const std::vector<double>& t, const std::vector<double>& y, double a, double b) {
  double n = 0.0, st = 0.0, sy = 0.0, stt = 0.0, sty = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] < a || t[i] > b) continue;
    const double x = t[i] - a;
    n += 1.0;
    st += x;
    sy += y[i];
    stt += x * x;
    sty += x * y[i];
  }
  const double den = n * stt - st * st;
  return n >= 3.0 && den > 0.0 ? (n * sty - st * sy) / den : kNaN;
}

// every friction figure of one run (NaN where it does not apply or is not reached)
struct Figures {
  double hold_drift = kNaN, creep = kNaN, accel = kNaN, stop_time = kNaN, stop_distance = kNaN,
         slip_end = kNaN, roll_speed = kNaN, dissipation = kNaN;
  std::vector<double> impulse, spin;  // per truth episode
};

Figures figures(const LineTrack& tr, const TruthFriction& tf, const RunResult& truth, double mass_kg,
                bool disk) {
  Figures f;
  if (tr.t.size() < 2) return f;
  const double t_end = tr.t.back();
  const auto& ph = tf.phases;

  // held at rest from t = 0
  if (holds_at_rest(tf)) {
    const double b = std::min(ph[0].end_s, t_end);
    double worst = 0.0;
    for (std::size_t i = 0; i < tr.t.size() && tr.t[i] <= b; ++i) {
      worst = std::max(worst, std::abs(tr.point[i]));
    }
    f.hold_drift = worst;
    // the steady rate: over the second half, past the start's transients
    const double mid = ph[0].start_s + 0.5 * (b - ph[0].start_s);
    f.creep = b > mid ? std::abs(at(tr.t, tr.point, b) - at(tr.t, tr.point, mid)) / (b - mid) : kNaN;
  }

  // a constant acceleration over the last phase
  const Phase& last = ph.back();
  const double last_end = std::min(last.end_s, t_end);
  if (last.kind != "flight" && last_end - last.start_s >= kMinFitWindow_s) {
    const double a = last.start_s + kFitSkip * (last_end - last.start_s);
    f.accel = slope(tr.t, tr.w, a, last_end);
  }

  // slides from t = 0, then holds at rest
  const std::size_t np = ph.size();
  if (np >= 2 && ph[np - 2].kind == "slip" && ph[np - 2].start_s == 0.0 && last.kind == "stick" &&
      tf.stick_acceleration_mps2 == 0.0 && !disk) {
    f.stop_time = first_fall(tr.t, tr.w, 0.0, kZeroFraction * std::abs(tr.w.front()));
    f.stop_distance = at(tr.t, tr.s, f.stop_time);
  }

  // a disk slips from t = 0, then rolls
  if (disk && np == 2 && ph[0].kind == "slip" && ph[0].start_s == 0.0 && last.kind == "stick") {
    f.slip_end = first_fall(tr.t, tr.slip, 0.0, kZeroFraction * std::abs(tr.slip.front()));
    f.roll_speed = std::abs(at(tr.t, tr.w, f.slip_end));
  }

  // impacts: the body starts apart
  if (ph[0].kind == "flight") {
    for (const ContactEpisode& e : truth.events) {
      if (!std::isfinite(e.offset_time_s)) continue;
      const double a = std::max(tr.t.front(), e.onset_time_s - kImpactMargin_s);
      const double b = std::min(t_end, e.offset_time_s + kImpactMargin_s);
      const double jt = mass_kg * (at(tr.t, tr.w, b) - at(tr.t, tr.w, a)) -
                        mass_kg * tf.tangential_gravity_mps2 * (b - a);
      f.impulse.push_back(jt);
      f.spin.push_back(at(tr.t, tr.spin, b));
    }
  }

  // friction alone dissipates while the normal motion rests
  if (tf.normal_at_rest) f.dissipation = tr.energy.front() - tr.energy.back();
  return f;
}

}  // namespace

const std::vector<const char*>& friction_metric_names() {
  static const std::vector<const char*> names = {
      "hold_drift_m",    "creep_speed_mps",       "slide_acceleration_mps2",
      "stop_time_s",     "stop_distance_m",       "slip_end_time_s",
      "roll_speed_mps",  "tangential_impulse_ns", "post_impact_spin_radps",
      "friction_dissipation_j"};
  return names;
}

std::vector<MetricValue> friction_metrics(const Case& c, const RunResult& run,
                                          const RunResult& truth) {
  std::vector<MetricValue> out;
  if (c.contacts.size() != 1 || !c.contacts[0].has_friction()) return out;
  TruthFriction tf;
  const auto lc = line_case(c);
  if (!lc || !read_truth(truth, tf)) return out;
  const BodyTrajectory* rb = trajectory(run, lc->body->name);
  const BodyTrajectory* tb = trajectory(truth, lc->body->name);
  if (rb == nullptr || tb == nullptr) return out;
  auto figures_of = [&](const BodyTrajectory& b) {
    return figures(line_track(b, *lc->body, lc->tangent, lc->radius_m, c.gravity_mps2, tf.support_m),
                   tf, truth, lc->body->mass_kg, lc->disk);
  };
  const Figures fr = figures_of(*rb);
  const Figures ft = figures_of(*tb);
  auto add = [&](const char* name, double actual, double desired, bool relative, const char* unit,
                 int episode = -1) {
    if (std::isnan(desired)) return;  // the truth does not have it: not this case's metric
    const bool rel = relative && desired != 0.0;
    MetricValue m = metric_value(c, run, "truth", name, actual, desired, rel, unit);
    m.episode = episode;
    if (std::isnan(actual)) m.note = "not reached in the run";
    out.push_back(m);
  };
  add("hold_drift_m", fr.hold_drift, ft.hold_drift, false, "m");
  add("creep_speed_mps", fr.creep, ft.creep, false, "m/s");
  if (std::abs(ft.accel) > 1e-9) add("slide_acceleration_mps2", fr.accel, ft.accel, true, "m/s^2");
  add("stop_time_s", fr.stop_time, ft.stop_time, true, "s");
  add("stop_distance_m", fr.stop_distance, ft.stop_distance, true, "m");
  add("slip_end_time_s", fr.slip_end, ft.slip_end, true, "s");
  add("roll_speed_mps", fr.roll_speed, ft.roll_speed, true, "m/s");
  for (std::size_t k = 0; k < ft.impulse.size(); ++k) {
    const double ai = k < fr.impulse.size() ? fr.impulse[k] : kNaN;
    const double as = k < fr.spin.size() ? fr.spin[k] : kNaN;
    add("tangential_impulse_ns", ai, ft.impulse[k], true, "N s", static_cast<int>(k));
    add("post_impact_spin_radps", as, ft.spin[k], true, "rad/s", static_cast<int>(k));
  }
  add("friction_dissipation_j", fr.dissipation, ft.dissipation, ft.dissipation > 1e-9, "J");
  return out;
}

double steady_slide_acceleration_mps2(const Case& c, const RunResult& run) {
  const auto lc = line_case(c);
  if (!lc || run.status != RunStatus::ok) return kNaN;
  const BodyTrajectory* b = trajectory(run, lc->body->name);
  if (b == nullptr || b->time_s.size() < 3) return kNaN;
  const LineTrack tr = line_track(*b, *lc->body, lc->tangent, lc->radius_m, c.gravity_mps2, 0.0);
  const double t_end = tr.t.back();
  return slope(tr.t, tr.w, 0.5 * t_end, t_end);
}

std::vector<std::pair<double, double>> hold_drift_series(const Case& c, const RunResult& run,
                                                         const RunResult& truth) {
  std::vector<std::pair<double, double>> out;
  TruthFriction tf;
  const auto lc = line_case(c);
  if (!lc || !read_truth(truth, tf) || !holds_at_rest(tf)) return out;
  const BodyTrajectory* b = trajectory(run, lc->body->name);
  if (b == nullptr) return out;
  const LineTrack tr =
      line_track(*b, *lc->body, lc->tangent, lc->radius_m, c.gravity_mps2, tf.support_m);
  for (std::size_t i = 0; i < tr.t.size(); ++i) out.emplace_back(tr.t[i], std::abs(tr.point[i]));
  return out;
}

}  // namespace pb
