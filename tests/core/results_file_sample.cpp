// Writes a small sample results file (argv[1]) through write_results_file, for
// tests/python/read_results.py to check with h5py alone: two cases, an ok run
// with contacts and two contact episodes, a diverged run with empty tables,
// unsupported runs without bodies, and a run above the compression threshold.
#include <cmath>
#include <cstdio>
#include <exception>

#include "planarbench/results_file.hpp"

namespace {

pb::BodyTrajectory falling(const char* name, int n, double dt_s) {
  // free fall from 1 m, g = 9.81 m/s^2: y = 1 - g t^2 / 2, v = -g t
  pb::BodyTrajectory b;
  b.name = name;
  for (int i = 0; i < n; ++i) {
    const double t = dt_s * i;
    b.time_s.push_back(t);
    b.position_m.emplace_back(0.0, 1.0 - 0.5 * 9.81 * t * t);
    b.angle_rad.push_back(0.0);
    b.velocity_mps.emplace_back(0.0, -9.81 * t);
    b.angular_velocity_radps.push_back(0.0);
  }
  return b;
}

pb::ResultsFile sample() {
  pb::ResultsFile f;
  f.provenance = {"results_file_sample", "2024-01-01T00:00:00Z", "sample-host"};

  pb::CaseRuns ball;
  ball.case_name = "falling_ball";
  ball.case_text = "# sample case — µ, δ\n[ball]\nradius = 0.1\n";
  ball.case_path = "cases/falling_ball.toml";
  ball.overrides = {{"dt", "1e-3"}};

  pb::RunResult ok;
  ok.case_name = "falling_ball";
  ok.engine_name = "reference";
  ok.engine_version = "sample";
  ok.body_names = {"ground", "ball"};
  ok.bodies.push_back(falling("ball", 100, 1e-3));
  ok.steps = 99;
  for (int i = 0; i < 3; ++i) {
    pb::ContactRow c;
    c.time_s = 0.45 + 1e-3 * i;
    c.sample = {0, 1, 100.0 * i, 1e-5 * i, pb::Vec2(0.0, 1.0), pb::Vec2(0.0, -5e-6 * i),
                -30.0 * i, 0.01 * i};
    ok.contacts.push_back(c);
  }
  ok.events.push_back({0, 1, 0.449, 0.4712, 1.98, 1.5, 1.5 / 1.98, 1234.5, 0.35, 1e-4});
  ok.events.push_back({0, 1, 0.9, std::nan(""), 1.1, 0.0, 0.0, 99.0, 0.01, 2e-5});

  pb::RunResult diverged = ok;
  diverged.engine_name = "mujoco";
  diverged.status = pb::RunStatus::diverged;
  diverged.reason = "sample divergence";
  diverged.diverged_at_s = 0.05;
  diverged.bodies = {falling("ball", 50, 1e-3)};
  diverged.contacts.clear();
  diverged.events.clear();

  pb::RunResult unsupported;
  unsupported.case_name = "falling_ball";
  unsupported.engine_name = "box2d";
  unsupported.status = pb::RunStatus::unsupported;
  unsupported.reason = "sample: not supported";
  unsupported.body_names = {"ground", "ball"};

  // an unsupported run that never learnt the bodies: a zero-length body_names
  pb::RunResult bare = unsupported;
  bare.engine_name = "ode";
  bare.body_names.clear();

  ball.runs = {ok, diverged, unsupported, bare};

  pb::CaseRuns second = ball;
  second.case_name = "falling_ball_long";
  second.overrides.clear();
  second.runs = {ok};
  second.runs[0].case_name = "falling_ball_long";
  second.runs[0].bodies = {falling("ball", 5000, 1e-4)};  // above the compression threshold

  f.cases = {ball, second};
  return f;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: results_file_sample OUT.h5\n");
    return 2;
  }
  try {
    pb::write_results_file(argv[1], sample());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "results_file_sample: %s\n", e.what());
    return 1;
  }
  return 0;
}
