// Synthetic runs of the falling_ball case for the report tests: simple
// closed-form signals with known values, so a test can tell what a figure or
// table must show without running an engine.
#pragma once

#include <cmath>
#include <string>

#include "planarbench/case.hpp"
#include "planarbench/case_loader.hpp"
#include "planarbench/run_result.hpp"

namespace pb::test {

// the falling_ball case file of the source tree
inline Case falling_ball_case() {
  return load_case(std::string(PB_CASES_DIR) + "/falling_ball.toml");
}

// A run of `c` on the case's output grid: the ball's y = y0 - offset_m - t,
// x = 2 t, vx = 2, vy = -1 (m, m/s); one contact row of force `force_n` at
// every grid time in [0.7250, 0.7560] s (the first impact's window) and one
// episode over that window.
inline RunResult synthetic_run(const Case& c, const std::string& engine, double offset_m,
                               double force_n) {
  RunResult r;
  r.case_name = c.name;
  r.engine_name = engine;
  r.engine_version = engine + " 1.0";
  r.wall_time_s = 0.5;
  r.steps = 25000;
  r.body_names = {"ground", "ball"};
  BodyTrajectory b;
  b.name = "ball";
  const int ground = c.body_index("ground");
  const int ball = c.body_index("ball");
  for (int k = 0; k < c.output_samples(); ++k) {
    const double t = c.output_time(k);
    b.time_s.push_back(t);
    b.position_m.emplace_back(2.0 * t, 2.0 - offset_m - t);
    b.angle_rad.push_back(0.0);
    b.velocity_mps.emplace_back(2.0, -1.0);
    b.angular_velocity_radps.push_back(0.0);
    if (t >= 0.7250 - 1e-12 && t <= 0.7560 + 1e-12) {
      ContactRow row;
      row.time_s = t;
      row.sample.body_a = ground;
      row.sample.body_b = ball;
      row.sample.force_n = force_n;
      row.sample.penetration_m = 0.01;
      row.sample.normal = Vec2(0.5, std::sqrt(3.0) / 2.0);
      r.contacts.push_back(row);
    }
  }
  r.bodies.push_back(b);
  ContactEpisode e;
  e.body_a = ground;
  e.body_b = ball;
  e.onset_time_s = 0.7250;
  e.offset_time_s = 0.7560;
  e.approach_speed_mps = 6.0;
  e.separation_speed_mps = 5.0;
  e.restitution = 5.0 / 6.0;
  e.peak_force_n = force_n;
  e.impulse_ns = force_n * 0.031;
  e.max_penetration_m = 0.01;
  r.events.push_back(e);
  r.mapping = {{"engine", engine}, {"not_expressed", {engine + " cannot do X"}}};
  return r;
}

inline RunResult unsupported_run(const Case& c, const std::string& engine) {
  RunResult r;
  r.case_name = c.name;
  r.engine_name = engine;
  r.status = RunStatus::unsupported;
  r.reason = "cannot run this case";
  r.body_names = {"ground", "ball"};
  return r;
}

// falling_ball runs stored in a shuffled order: box2d (ok, force 1e5 N:
// impulsive), reference (unsupported), analytic (ok, force 580 N), mujoco (ok,
// force 590 N, y offset 1 mm)
inline CaseRuns falling_ball_runs(const Case& c) {
  CaseRuns cr;
  cr.case_name = c.name;
  cr.case_text = c.source_text;
  cr.case_path = c.source_path;
  cr.runs.push_back(synthetic_run(c, "box2d", 0.0, 1e5));
  cr.runs.push_back(unsupported_run(c, "reference"));
  cr.runs.push_back(synthetic_run(c, "analytic", 0.0, 580.0));
  cr.runs.push_back(synthetic_run(c, "mujoco", 1e-3, 590.0));
  return cr;
}

}  // namespace pb::test
