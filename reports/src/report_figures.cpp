#include "report_figures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

#include "file_id.hpp"

namespace pb::internal {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// SPEC §5 engine names in report order (the truth first)
constexpr std::array<const char*, 6> kEngineOrder = {"analytic", "reference", "mujoco",
                                                     "mujoco3",  "box2d",     "ode"};

// what one figure shows, before its series are extracted
struct FigureSpec {
  std::string id_suffix;  // appended to the case name
  std::string title;
  std::string paper_figure;  // "" for generic figures
  Quantity quantity = Quantity::x;
  int body = -1;  // for trajectories: index into Case::bodies
  int pair = -1;  // for forces: index into Case::contacts
};

const char* quantity_label(Quantity q) {
  switch (q) {
    case Quantity::force:
      return "contact force, N";
    case Quantity::x:
      return "x, m";
    case Quantity::y:
      return "y, m";
    case Quantity::vx:
      return "vx, m/s";
    case Quantity::vy:
      return "vy, m/s";
  }
  return "";
}

const char* quantity_name(Quantity q) {
  switch (q) {
    case Quantity::force:
      return "force";
    case Quantity::x:
      return "x";
    case Quantity::y:
      return "y";
    case Quantity::vx:
      return "vx";
    case Quantity::vy:
      return "vy";
  }
  return "";
}

int pair_index(const Case& c, const std::string& name) {
  for (std::size_t i = 0; i < c.contacts.size(); ++i) {
    if (c.contacts[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

FigureSpec body_spec(const Case& c, int body, Quantity q, std::string paper_figure = "",
                     std::string title = "") {
  const auto& name = c.bodies[static_cast<std::size_t>(body)].name;
  FigureSpec s;
  s.id_suffix = paper_figure.empty() ? fmt::format("{}_{}", name, quantity_name(q))
                                     : "fig" + paper_figure.substr(paper_figure.find(' ') + 1);
  s.title = title.empty() ? fmt::format("{} {} vs time", name, quantity_name(q)) : title;
  s.paper_figure = std::move(paper_figure);
  s.quantity = q;
  s.body = body;
  return s;
}

FigureSpec force_spec(const Case& c, int pair, std::string paper_figure = "",
                      std::string title = "") {
  const auto& p = c.contacts[static_cast<std::size_t>(pair)];
  FigureSpec s;
  s.id_suffix = paper_figure.empty() ? "force_" + p.name
                                     : "fig" + paper_figure.substr(paper_figure.find(' ') + 1);
  s.title = title.empty() ? fmt::format("Contact force {} ({} - {}) vs time", p.name,
                                        c.bodies[static_cast<std::size_t>(p.body_a)].name,
                                        c.bodies[static_cast<std::size_t>(p.body_b)].name)
                          : title;
  s.paper_figure = std::move(paper_figure);
  s.quantity = Quantity::force;
  s.pair = pair;
  return s;
}

// the paper's figures, with the paper's captions, for the three paper cases;
// nullopt when the case is another one (or lacks the bodies the paper plots)
std::optional<std::vector<FigureSpec>> paper_specs(const Case& c) {
  std::vector<FigureSpec> specs;
  if (c.name == "falling_ball") {
    const int ball = c.body_index("ball");
    const int pair = pair_index(c, "ground_ball");
    if (ball < 0 || pair < 0) return std::nullopt;
    specs.push_back(force_spec(c, pair, "Fig. 5", "Fig. 5 Contact force"));
    specs.push_back(
        body_spec(c, ball, Quantity::y, "Fig. 6", "Fig. 6 Displacement of ball on y-coordinate"));
  } else if (c.name == "dual_pendulum") {
    const int ellipse = c.body_index("ellipse");
    const int disk = c.body_index("disk");
    if (ellipse < 0 || disk < 0) return std::nullopt;
    specs.push_back(body_spec(c, ellipse, Quantity::x, "Fig. 8",
                              "Fig. 8 Displacement of ellipse pendulum on x-coordinate"));
    specs.push_back(body_spec(c, ellipse, Quantity::vx, "Fig. 9",
                              "Fig. 9 Velocity of ellipse pendulum on x-coordinate"));
    specs.push_back(body_spec(c, disk, Quantity::x, "Fig. 10",
                              "Fig. 10 Displacement of ball pendulum on x-coordinate"));
    specs.push_back(body_spec(c, disk, Quantity::vx, "Fig. 11",
                              "Fig. 11 Velocity of ball pendulum on x-coordinate"));
    // the paper shows no force here; the impact pulse is worth a plot
    for (std::size_t p = 0; p < c.contacts.size(); ++p) {
      specs.push_back(force_spec(c, static_cast<int>(p)));
    }
  } else if (c.name == "sliding") {
    const int ball = c.body_index("ball");
    const int pair = pair_index(c, "ground_ball");
    if (ball < 0 || pair < 0) return std::nullopt;
    specs.push_back(force_spec(c, pair, "Fig. 13", "Fig. 13 Contact force"));
    specs.push_back(
        body_spec(c, ball, Quantity::y, "Fig. 14", "Fig. 14 Displacement of ball on y-coordinate"));
    specs.push_back(
        body_spec(c, ball, Quantity::vy, "Fig. 15", "Fig. 15 Velocity of ball on y-coordinate"));
  } else {
    return std::nullopt;
  }
  return specs;
}

// every contact pair's force, then every moving body's x, y, vx, vy
std::vector<FigureSpec> generic_specs(const Case& c) {
  std::vector<FigureSpec> specs;
  for (std::size_t p = 0; p < c.contacts.size(); ++p) {
    specs.push_back(force_spec(c, static_cast<int>(p)));
  }
  for (std::size_t b = 0; b < c.bodies.size(); ++b) {
    if (c.bodies[b].fixed) continue;
    for (const Quantity q : {Quantity::x, Quantity::y, Quantity::vx, Quantity::vy}) {
      specs.push_back(body_spec(c, static_cast<int>(b), q));
    }
  }
  return specs;
}

const BodyTrajectory* find_body(const RunResult& r, const std::string& name) {
  for (const auto& b : r.bodies) {
    if (b.name == name) return &b;
  }
  return nullptr;
}

// the time up to which a run is valid: the analytic truth of dual_pendulum
// holds until the first contact only (extra attribute valid_until_s)
double valid_until(const RunResult& r) {
  if (r.extra.is_object() && r.extra.contains("valid_until_s") &&
      r.extra["valid_until_s"].is_number()) {
    return r.extra["valid_until_s"].get<double>();
  }
  return std::numeric_limits<double>::infinity();
}

// a full-resolution series before down-sampling
struct RawSeries {
  std::vector<double> time_s;
  std::vector<double> value;
};

RawSeries body_series(const BodyTrajectory& b, Quantity q, double until_s) {
  RawSeries s;
  const std::size_t n = b.time_s.size();
  s.time_s.reserve(n);
  s.value.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (b.time_s[i] > until_s) break;
    double v = kNaN;
    switch (q) {
      case Quantity::x:
        v = i < b.position_m.size() ? b.position_m[i].x() : kNaN;
        break;
      case Quantity::y:
        v = i < b.position_m.size() ? b.position_m[i].y() : kNaN;
        break;
      case Quantity::vx:
        v = i < b.velocity_mps.size() ? b.velocity_mps[i].x() : kNaN;
        break;
      case Quantity::vy:
        v = i < b.velocity_mps.size() ? b.velocity_mps[i].y() : kNaN;
        break;
      case Quantity::force:
        break;
    }
    s.time_s.push_back(b.time_s[i]);
    s.value.push_back(v);
  }
  return s;
}

// The normal force of one pair on the run's output grid: zero at every grid
// time without a contact row, the sum of the pair's rows at a grid time
// otherwise (rows off the grid are added as samples of their own).
RawSeries force_series(const RunResult& r, const ContactPair& pair, double until_s) {
  std::map<double, double> force;  // time s -> force N
  if (!r.bodies.empty()) {
    for (const double t : r.bodies.front().time_s) {
      if (t > until_s) break;
      force.emplace(t, 0.0);
    }
  }
  for (const auto& row : r.contacts) {
    const bool same = (row.sample.body_a == pair.body_a && row.sample.body_b == pair.body_b) ||
                      (row.sample.body_a == pair.body_b && row.sample.body_b == pair.body_a);
    if (!same || row.time_s > until_s) continue;
    // the grid time this row was sampled at, if any (1e-9 relative: a rounding)
    auto it = force.lower_bound(row.time_s - 1e-9 * std::max(1.0, std::abs(row.time_s)));
    if (it != force.end() &&
        std::abs(it->first - row.time_s) <= 1e-9 * std::max(1.0, std::abs(row.time_s))) {
      it->second += row.sample.force_n;
    } else {
      force[row.time_s] += row.sample.force_n;
    }
  }
  RawSeries s;
  s.time_s.reserve(force.size());
  s.value.reserve(force.size());
  for (const auto& [t, f] : force) {
    s.time_s.push_back(t);
    s.value.push_back(f);
  }
  return s;
}

// the end of an episode: its offset, or while still open the end of the run
// (or of the run's validity: the truth of dual_pendulum stops at the impact)
double episode_end(const Case& c, const RunResult& r, const ContactEpisode& e) {
  if (std::isfinite(e.offset_time_s)) return e.offset_time_s;
  return std::min(c.duration_s, valid_until(r));
}

// the run whose episodes a figure offers to zoom to: the truth when it covers
// the whole run, else the reference, else the first ok run that has episodes
const RunResult* episode_source(const std::vector<const RunResult*>& ordered) {
  for (const auto* r : ordered) {
    if (r->status == RunStatus::ok && !r->events.empty() && !std::isfinite(valid_until(*r))) {
      return r;
    }
  }
  for (const auto* r : ordered) {
    if (r->status == RunStatus::ok && !r->events.empty()) return r;
  }
  return nullptr;
}

std::vector<ZoomWindow> zoom_windows(const Case& c, const RunResult* source, int pair) {
  std::vector<ZoomWindow> out;
  if (source == nullptr) return out;
  constexpr std::size_t kMaxButtons = 12;  // a row of buttons, not a wall of them
  std::vector<ContactEpisode> episodes;
  for (const auto& e : source->events) {
    if (pair >= 0) {
      const auto& p = c.contacts[static_cast<std::size_t>(pair)];
      const bool same = (e.body_a == p.body_a && e.body_b == p.body_b) ||
                        (e.body_a == p.body_b && e.body_b == p.body_a);
      if (!same) continue;
    }
    episodes.push_back(e);
  }
  std::sort(episodes.begin(), episodes.end(),
            [](const auto& a, const auto& b) { return a.onset_time_s < b.onset_time_s; });
  for (std::size_t k = 0; k < episodes.size() && k < kMaxButtons; ++k) {
    const auto& e = episodes[k];
    const double t1 = episode_end(c, *source, e);
    // half the episode's length on each side, at least five output intervals
    const double pad = std::max(0.5 * (t1 - e.onset_time_s), 5.0 * c.output_interval_s);
    // counted from 0, as the metrics and the thresholds file count episodes
    out.push_back(ZoomWindow{fmt::format("episode {}", k), std::max(0.0, e.onset_time_s - pad),
                             std::min(c.duration_s, t1 + pad)});
  }
  return out;
}

PlotSeries downsample(const std::string& engine, const RawSeries& raw,
                      const std::vector<TimeWindow>& windows, const FigureLimits& limits) {
  PlotSeries s;
  s.engine = engine;
  s.full_points = raw.time_s.size();
  const auto keep =
      downsample_indices(raw.time_s, windows, limits.max_outside, limits.max_inside, &raw.value);
  s.time_s.reserve(keep.size());
  s.value.reserve(keep.size());
  for (const std::size_t i : keep) {
    s.time_s.push_back(raw.time_s[i]);
    s.value.push_back(raw.value[i]);
  }
  return s;
}

// An impulsive engine (Box2D: force = impulse / step) peaks orders of
// magnitude above a compliant law's pulse, which then drowns at the bottom of
// the axis. The default axis fits the other series; the off-scale ones say so.
void clip_off_scale(Figure& f) {
  if (f.quantity != Quantity::force || f.series.empty()) return;
  std::vector<double> peaks;
  for (auto& s : f.series) {
    s.peak = 0.0;
    for (const double v : s.value) {
      if (std::isfinite(v)) s.peak = std::max(s.peak, v);
    }
    if (s.peak > 0.0) peaks.push_back(s.peak);
  }
  if (peaks.empty()) return;
  // the scale to judge by: the truth's peak, else the median peak
  std::sort(peaks.begin(), peaks.end());
  double scale = peaks[(peaks.size() - 1) / 2];
  if (f.series.front().engine == "analytic" && f.series.front().peak > 0.0) {
    scale = f.series.front().peak;
  }
  // 4x: beyond any compliant engine's plausible peak error, far below an
  // impulse spread over one step (100x and more at dt = 1e-4 s)
  constexpr double kOffScaleFactor = 4.0;
  double fit = 0.0;
  bool any_off = false;
  for (auto& s : f.series) {
    s.off_scale = s.peak > kOffScaleFactor * scale;
    any_off = any_off || s.off_scale;
    if (!s.off_scale) fit = std::max(fit, s.peak);
  }
  if (!any_off || !(fit > 0.0)) {
    for (auto& s : f.series) s.off_scale = false;
    return;
  }
  f.y_clip = 1.1 * fit;  // 10 % headroom above the highest fitted peak
  for (auto& s : f.series) {
    if (!s.off_scale) continue;
    const std::string note = fmt::format("peak {:.4g} N, off the default scale", s.peak);
    s.note = s.note.empty() ? note : s.note + "; " + note;
  }
}

}  // namespace

std::vector<const RunResult*> runs_in_report_order(const CaseRuns& runs) {
  auto rank = [](const std::string& engine) -> std::size_t {
    for (std::size_t i = 0; i < kEngineOrder.size(); ++i) {
      if (engine == kEngineOrder[i]) return i;
    }
    return kEngineOrder.size();
  };
  std::vector<const RunResult*> out;
  for (const auto& r : runs.runs) out.push_back(&r);
  std::stable_sort(out.begin(), out.end(), [&](const RunResult* a, const RunResult* b) {
    const auto ra = rank(a->engine_name);
    const auto rb = rank(b->engine_name);
    return ra != rb ? ra < rb : a->engine_name < b->engine_name;
  });
  return out;
}

std::vector<TimeWindow> contact_windows(const Case& c, const CaseRuns& runs) {
  const double pad = 2.0 * c.output_interval_s;  // s: the samples either side of a pulse
  std::vector<TimeWindow> windows;
  for (const auto& r : runs.runs) {
    if (r.status != RunStatus::ok) continue;
    for (const auto& e : r.events) {
      windows.push_back(TimeWindow{e.onset_time_s - pad, episode_end(c, r, e) + pad});
    }
    // stretches of contact rows: a gap of more than 1.5 intervals ends one
    std::vector<double> times;
    times.reserve(r.contacts.size());
    for (const auto& row : r.contacts) times.push_back(row.time_s);
    std::sort(times.begin(), times.end());
    for (std::size_t i = 0; i < times.size();) {
      std::size_t j = i;
      while (j + 1 < times.size() && times[j + 1] - times[j] <= 1.5 * c.output_interval_s) ++j;
      windows.push_back(TimeWindow{times[i] - pad, times[j] + pad});
      i = j + 1;
    }
  }
  return merge_windows(std::move(windows));
}

std::string physics_label(const RunResult& r) {
  if (!r.mapping.is_object() || !r.mapping.contains("physics")) return "";
  const nlohmann::json& p = r.mapping["physics"];
  if (p.value("foreknowledge", false)) {
    return "oracle: parameters calibrated with the run's future (not how the engine's users run "
           "it)";
  }
  if (p.value("contact_force_by", "").rfind("adapter", 0) == 0) {
    return "inject: the case's law applied by the adapter, not the engine's contact model";
  }
  return "";
}

std::vector<Figure> case_figures(const Case& c, const CaseRuns& runs, const FigureLimits& limits) {
  const auto specs = paper_specs(c).value_or(generic_specs(c));
  const auto ordered = runs_in_report_order(runs);
  const auto windows = contact_windows(c, runs);
  const RunResult* episodes = episode_source(ordered);

  std::vector<Figure> figures;
  for (const auto& spec : specs) {
    Figure f;
    f.id = file_id(c.name + "_" + spec.id_suffix);
    f.case_name = c.name;
    f.title = spec.title;
    f.paper_figure = spec.paper_figure;
    f.y_label = quantity_label(spec.quantity);
    f.quantity = spec.quantity;
    f.t_end_s = c.duration_s;
    f.episodes = zoom_windows(c, episodes, spec.pair);
    for (const auto* r : ordered) {
      if (r->status != RunStatus::ok) continue;
      const double until = valid_until(*r);
      RawSeries raw;
      if (spec.quantity == Quantity::force) {
        raw = force_series(*r, c.contacts[static_cast<std::size_t>(spec.pair)], until);
      } else if (const auto* b =
                     find_body(*r, c.bodies[static_cast<std::size_t>(spec.body)].name)) {
        raw = body_series(*b, spec.quantity, until);
      }
      PlotSeries s = downsample(r->engine_name, raw, windows, limits);
      if (std::isfinite(until)) s.note = fmt::format("valid until t = {:.6g} s", until);
      // a run whose parameters saw the run's future is marked wherever it is shown
      if (const auto label = physics_label(*r); !label.empty()) {
        s.note += (s.note.empty() ? "" : "; ") + label;
      }
      f.series.push_back(std::move(s));
    }
    clip_off_scale(f);
    figures.push_back(std::move(f));
  }
  return figures;
}

}  // namespace pb::internal
