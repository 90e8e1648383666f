#include "planarbench/reports/run_validity.hpp"

#include <fmt/format.h>

#include <cmath>
#include <functional>

namespace pb {

namespace {

// the non-finite rows of a dataset of n rows, value(i) giving row i's first
// non-finite value (or a finite one when there is none)
void scan(const std::string& case_name, const RunResult& r, const std::string& dataset,
          const std::string& field, std::size_t n, const std::function<double(std::size_t)>& value,
          std::vector<InvalidRun>& out) {
  InvalidRun bad;
  for (std::size_t i = 0; i < n; ++i) {
    const double v = value(i);
    if (std::isfinite(v)) continue;
    if (bad.rows == 0) {
      bad.first_row = i;
      bad.first_value = v;
    }
    ++bad.rows;
  }
  if (bad.rows == 0) return;
  bad.case_name = case_name;
  bad.engine = r.engine_name;
  bad.dataset = dataset;
  bad.field = field;
  bad.total_rows = n;
  out.push_back(std::move(bad));
}

// the first non-finite coordinate of v, or v's x
double first_bad(const Vec2& v) {
  return std::isfinite(v.x()) ? v.y() : v.x();
}

// a field where NaN means "not given": only an infinity is invalid
double not_inf(double v) {
  return std::isinf(v) ? v : 0.0;
}

}  // namespace

std::string InvalidRun::run() const {
  return case_name + "." + engine;
}

std::string InvalidRun::what() const {
  return fmt::format("{}{}: {} of {} rows hold NaN or inf (the first: row {}, {})", dataset,
                     field.empty() ? "" : ", field " + field, rows, total_rows, first_row,
                     first_value);
}

std::string InvalidRun::describe() const {
  return run() + ": " + what();
}

std::vector<InvalidRun> invalid_runs(const CaseRuns& cr) {
  std::vector<InvalidRun> out;
  for (const auto& r : cr.runs) {
    if (r.status == RunStatus::unsupported) continue;
    const std::string run = "/runs/" + cr.case_name + "/" + r.engine_name;
    for (const auto& b : r.bodies) {
      const std::string body = run + "/bodies/" + b.name + "/";
      scan(
          cr.case_name, r, body + "time", "", b.time_s.size(),
          [&](std::size_t i) { return b.time_s[i]; }, out);
      scan(
          cr.case_name, r, body + "position", "", b.position_m.size(),
          [&](std::size_t i) { return first_bad(b.position_m[i]); }, out);
      scan(
          cr.case_name, r, body + "angle", "", b.angle_rad.size(),
          [&](std::size_t i) { return b.angle_rad[i]; }, out);
      scan(
          cr.case_name, r, body + "velocity", "", b.velocity_mps.size(),
          [&](std::size_t i) { return first_bad(b.velocity_mps[i]); }, out);
      scan(
          cr.case_name, r, body + "angular_velocity", "", b.angular_velocity_radps.size(),
          [&](std::size_t i) { return b.angular_velocity_radps[i]; }, out);
    }
    scan(
        cr.case_name, r, run + "/contacts", "time", r.contacts.size(),
        [&](std::size_t i) { return r.contacts[i].time_s; }, out);
    const auto& cs = r.contacts;
    const std::string contacts = run + "/contacts";
    scan(
        cr.case_name, r, contacts, "force_n", cs.size(),
        [&](std::size_t i) { return cs[i].sample.force_n; }, out);
    scan(
        cr.case_name, r, contacts, "normal", cs.size(),
        [&](std::size_t i) { return first_bad(cs[i].sample.normal); }, out);
    scan(
        cr.case_name, r, contacts, "point_m", cs.size(),
        [&](std::size_t i) { return first_bad(cs[i].sample.point_m); }, out);
    scan(
        cr.case_name, r, contacts, "penetration_m", cs.size(),
        [&](std::size_t i) { return not_inf(cs[i].sample.penetration_m); }, out);
    scan(
        cr.case_name, r, contacts, "tangential_force_n", cs.size(),
        [&](std::size_t i) { return not_inf(cs[i].sample.tangential_force_n); }, out);
    scan(
        cr.case_name, r, contacts, "slip_mps", cs.size(),
        [&](std::size_t i) { return not_inf(cs[i].sample.slip_mps); }, out);
    // the episodes (issue 49: every float of a reference run's events set to
    // NaN passed the gate): an episode has begun, so its onset, approach,
    // peak and impulse are numbers; the rest may be NaN as the layout says
    const auto& es = r.events;
    const std::string events = run + "/events";
    struct EventField {
      const char* name;
      double ContactEpisode::*member;
      bool may_be_nan;
    };
    constexpr EventField fields[] = {
        {"onset_time_s", &ContactEpisode::onset_time_s, false},
        {"approach_speed_mps", &ContactEpisode::approach_speed_mps, false},
        {"peak_force_n", &ContactEpisode::peak_force_n, false},
        {"impulse_ns", &ContactEpisode::impulse_ns, false},
        {"offset_time_s", &ContactEpisode::offset_time_s, true},
        {"separation_speed_mps", &ContactEpisode::separation_speed_mps, true},
        {"restitution", &ContactEpisode::restitution, true},
        {"max_penetration_m", &ContactEpisode::max_penetration_m, true}};
    for (const EventField& f : fields) {
      scan(
          cr.case_name, r, events, f.name, es.size(),
          [&](std::size_t i) {
            const double v = es[i].*f.member;
            return f.may_be_nan ? not_inf(v) : v;
          },
          out);
    }
  }
  return out;
}

const InvalidRun* find_invalid(const std::vector<InvalidRun>& invalid, const std::string& case_name,
                               const std::string& engine) {
  for (const auto& f : invalid) {
    if (f.case_name == case_name && f.engine == engine) return &f;
  }
  return nullptr;
}

}  // namespace pb
