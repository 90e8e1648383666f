// Tests for the command line's handling of engine faults (apps/cmd_run.cpp,
// apps/cmd_check.cpp, apps/cmd_report.cpp), run as a user runs it: the real
// planarbench binary. One run of a matrix diverges; the others complete,
// `run` and `check` exit 3 (SPEC §5) naming it, the results file keeps its
// status, time and reason, and the report shows it.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "planarbench/results_file.hpp"

namespace {

namespace fs = std::filesystem;

struct Outcome {
  int exit_code = -1;  // -1: killed by a signal (an abort is not an exit code)
  std::string output;  // stdout and stderr together
};

Outcome run(const std::string& args) {
  const std::string cmd = std::string(PB_EXE) + " " + args + " 2>&1";
  Outcome o;
  FILE* p = popen(cmd.c_str(), "r");
  if (p == nullptr) return o;
  std::array<char, 4096> buf{};
  while (fgets(buf.data(), buf.size(), p) != nullptr) o.output += buf.data();
  const int status = pclose(p);
  o.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return o;
}

fs::path work_dir() {
  fs::create_directories(PB_WORK_DIR);
  return PB_WORK_DIR;
}

bool contains(const std::string& haystack, const std::string& needle) {
  return haystack.find(needle) != std::string::npos;
}

std::string read_text(const fs::path& p) {
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

const pb::RunResult* find_run(const pb::ResultsFile& f, const std::string& engine) {
  for (const auto& cr : f.cases) {
    for (const auto& r : cr.runs) {
      if (r.engine_name == engine) return &r;
    }
  }
  return nullptr;
}

// falling_ball for 0.8 s with contact.stiffness = 1e16 N/m on four engines:
// MuJoCo's soft contact maps it to a reference acceleration of ~7e12 m/s^2 at
// the first contact (t = 0.725 s), beyond mjMAXVAL: mjWARN_BADQACC, diverged.
// The analytic truth has the closed form at any stiffness, Box2D only uses
// the restitution the law produces, ODE's implicit soft contact (one step
// per dt, ode.substeps=1, so that the stiffness does not ask for 1e5
// substeps) stays bounded: those three complete ok.
TEST(CliFaults, OneDivergedRunInAMatrix) {
  const auto out = work_dir() / "one_diverged.h5";
  const auto r =
      run("run --case falling_ball --engine analytic,mujoco,box2d,ode --quiet "
          "--set contact.stiffness=1e16 --set ode.substeps=1 --set duration=0.8 "
          "--out " +
          out.string());
  ASSERT_EQ(r.exit_code, 3) << r.output;
  ASSERT_TRUE(fs::exists(out)) << r.output;

  const pb::ResultsFile f = pb::read_results_file(out);
  for (const char* engine : {"analytic", "box2d", "ode"}) {
    const pb::RunResult* ok = find_run(f, engine);
    ASSERT_NE(ok, nullptr) << engine;
    EXPECT_EQ(ok->status, pb::RunStatus::ok) << engine << ": " << ok->reason;
    EXPECT_FALSE(ok->bodies.at(0).time_s.empty()) << engine;
  }
  const pb::RunResult* bad = find_run(f, "mujoco");
  ASSERT_NE(bad, nullptr);
  EXPECT_EQ(bad->status, pb::RunStatus::diverged);
  EXPECT_TRUE(contains(bad->reason, "mjWARN_BADQACC")) << bad->reason;
  // 2e-4 s: the first contact (0.72501 s) resolved to a step, plus Euler's lead
  EXPECT_NEAR(bad->diverged_at_s, 0.72501, 2e-4);

  // judged by a copy of the committed thresholds that states it covers the
  // two case keys this run was given (check refuses them otherwise, issue 31)
  const auto covering = work_dir() / "covers_stiffness_duration.toml";
  {
    std::ifstream in(std::string(PB_SOURCE_DIR) + "/cases/thresholds.toml");
    std::ofstream copy(covering);
    copy << "covers = [\"contact.stiffness\", \"duration\"]\n" << in.rdbuf();
  }
  const auto c = run("check --thresholds " + covering.string() + " " + out.string());
  EXPECT_EQ(c.exit_code, 3) << c.output;
  EXPECT_TRUE(contains(c.output, "DIVERGED falling_ball.mujoco: mujoco: mjWARN_BADQACC"))
      << c.output;
  EXPECT_TRUE(contains(c.output, "1 run(s) diverged")) << c.output;

  const auto dir = work_dir() / "one_diverged_report";
  fs::remove_all(dir);
  const auto rep = run("report " + out.string() + " --out " + dir.string());
  ASSERT_EQ(rep.exit_code, 0) << rep.output;
  const std::string md = read_text(dir / "report.md");
  EXPECT_TRUE(contains(md, "diverged at t = 0.725 s: mujoco: mjWARN_BADQACC")) << md;
}

// A Box2D input that tripped an assert in libbox2d (the process aborted, no
// file) is now a refused run: exit 3, a results file, the reason.
TEST(CliFaults, Box2dInputThatWouldAssertIsARefusedRunNotACrash) {
  const auto out = work_dir() / "box2d_refused.h5";
  const auto r =
      run("run --case falling_ball --engine box2d --quiet "
          "--set bodies.ball.mass=1e39 --set duration=0.1 --out " +
          out.string());
  ASSERT_EQ(r.exit_code, 3) << r.output;
  const pb::ResultsFile f = pb::read_results_file(out);
  const pb::RunResult* b = find_run(f, "box2d");
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(b->status, pb::RunStatus::diverged);
  EXPECT_TRUE(contains(b->reason, "box2d: refused")) << b->reason;
}

// An energy runaway with no engine warning (Box2D with the case's
// Lankarani-Nikravesh law applied explicitly at dt = 1e-3 s, a quarter of a
// step per impact) is diverged too, named by the runner's energy check.
TEST(CliFaults, EnergyRunawayIsDivergedAndNamed) {
  const auto out = work_dir() / "runaway.h5";
  const auto r =
      run("run --case dual_pendulum --engine box2d --quiet --set box2d.mode=inject "
          "--set dt=1e-3 --set duration=0.6 --out " +
          out.string());
  ASSERT_EQ(r.exit_code, 3) << r.output;
  const pb::ResultsFile f = pb::read_results_file(out);
  const pb::RunResult* b = find_run(f, "box2d");
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(b->status, pb::RunStatus::diverged);
  EXPECT_TRUE(contains(b->reason, "energy runaway at t =")) << b->reason;
  // right after the first impact (t = 0.4965 s, SPEC §2), within 5 steps of it
  EXPECT_GT(b->diverged_at_s, 0.4965 - 1e-3);
  EXPECT_LT(b->diverged_at_s, 0.4965 + 5e-3);
}


// ---- run isolation (apps/run_isolation.cpp, issue 24) ----------------------------
// Each run of `planarbench run` is a process of its own, so that an abort
// inside an engine's library or a run past --run-timeout ends that run only:
// it is written `diverged` with what ended it, the other runs are written
// whole, the command exits 3.

// a fresh folder of its own for a test that checks what is left in it
fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::path(PB_WORK_DIR) / "isolation" / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// only the results file is left in the folder: no child's folder, no spool
void expect_only(const fs::path& dir, const fs::path& file) {
  for (const auto& e : fs::directory_iterator(dir)) {
    EXPECT_EQ(e.path(), file) << "left behind: " << e.path();
  }
}

// A spin of 1e200 rad/s, which the case format allows, trips libode's
// dIASSERT in dxNormalize4 at its first step: SIGABRT. It ended the whole
// command before (every engine's results lost). Now ODE's run is diverged,
// naming the signal and what ODE printed, and the other five are written.
TEST(Isolation, AnAbortInsideOdeLosesOnlyOdesRun) {
  const fs::path dir = fresh_dir("abort");
  const fs::path out = dir / "spin.h5";
  const auto r = run("run --case falling_ball --engine all --quiet --jobs 2 "
                     "--set bodies.ball.angular_velocity=1e200 --set duration=0.01 --out " +
                     out.string());
  ASSERT_EQ(r.exit_code, 3) << r.output;  // SPEC §5: a run failed, the file is written
  ASSERT_TRUE(fs::exists(out)) << r.output;
  expect_only(dir, out);

  const pb::ResultsFile f = pb::read_results_file(out);
  ASSERT_EQ(f.cases.size(), 1u);
  EXPECT_EQ(f.cases[0].runs.size(), 6u);  // every engine of the registry, mujoco3 included
  const pb::RunResult* ode = find_run(f, "ode");
  ASSERT_NE(ode, nullptr);
  EXPECT_EQ(ode->status, pb::RunStatus::diverged);
  EXPECT_TRUE(contains(ode->reason, "the ode run of case 'falling_ball' ended its process"))
      << ode->reason;
  EXPECT_TRUE(contains(ode->reason, "SIGABRT")) << ode->reason;
  EXPECT_TRUE(contains(ode->reason, "dxNormalize4")) << ode->reason;  // ODE's own words
  EXPECT_FALSE(ode->settings.empty());  // the parent still says how it was set up
  // the closed form does not care about the spin of a frictionless disk
  const pb::RunResult* analytic = find_run(f, "analytic");
  ASSERT_NE(analytic, nullptr);
  EXPECT_EQ(analytic->status, pb::RunStatus::ok) << analytic->reason;
  EXPECT_FALSE(analytic->bodies.at(0).time_s.empty());
  for (const char* engine : {"reference", "mujoco", "mujoco3", "box2d"}) {
    const pb::RunResult* e = find_run(f, engine);
    ASSERT_NE(e, nullptr) << engine;
    // whatever each makes of the spin, it is its own verdict, with a reason
    if (e->status != pb::RunStatus::ok) {
      EXPECT_FALSE(e->reason.empty()) << engine;
      EXPECT_FALSE(contains(e->reason, "ended its process")) << engine << ": " << e->reason;
    }
  }
}

// The same bits whether a run is made in a process of its own or in this
// one: the child is the same code, and its results cross through the
// results file's own reader (the datasets are compared exactly).
TEST(Isolation, IsolatedAndInProcessRunsAreTheSameBits) {
  const fs::path dir = fresh_dir("bits");
  const fs::path a = dir / "process.h5";
  const fs::path b = dir / "none.h5";
  const std::string common =
      "run --case falling_ball,dual_pendulum --engine all --quiet --jobs 2 --set duration=0.8 ";
  ASSERT_EQ(run(common + "--isolation process --out " + a.string()).exit_code, 0);
  ASSERT_EQ(run(common + "--isolation none --out " + b.string()).exit_code, 0);
  const pb::ResultsFile fa = pb::read_results_file(a);
  const pb::ResultsFile fb = pb::read_results_file(b);
  ASSERT_EQ(fa.cases.size(), fb.cases.size());
  for (std::size_t c = 0; c < fa.cases.size(); ++c) {
    ASSERT_EQ(fa.cases[c].runs.size(), fb.cases[c].runs.size());
    for (std::size_t k = 0; k < fa.cases[c].runs.size(); ++k) {
      const pb::RunResult& x = fa.cases[c].runs[k];
      const pb::RunResult& y = fb.cases[c].runs[k];
      SCOPED_TRACE(fa.cases[c].case_name + " x " + x.engine_name);
      EXPECT_EQ(x.status, y.status);
      EXPECT_EQ(x.steps, y.steps);
      EXPECT_EQ(x.settings, y.settings);
      EXPECT_EQ(x.mapping, y.mapping);
      ASSERT_EQ(x.bodies.size(), y.bodies.size());
      for (std::size_t i = 0; i < x.bodies.size(); ++i) {
        EXPECT_EQ(x.bodies[i].time_s, y.bodies[i].time_s);
        EXPECT_EQ(x.bodies[i].position_m, y.bodies[i].position_m);
        EXPECT_EQ(x.bodies[i].angle_rad, y.bodies[i].angle_rad);
        EXPECT_EQ(x.bodies[i].velocity_mps, y.bodies[i].velocity_mps);
        EXPECT_EQ(x.bodies[i].angular_velocity_radps, y.bodies[i].angular_velocity_radps);
      }
      ASSERT_EQ(x.contacts.size(), y.contacts.size());
      for (std::size_t i = 0; i < x.contacts.size(); ++i) {
        EXPECT_EQ(x.contacts[i].time_s, y.contacts[i].time_s);
        EXPECT_EQ(x.contacts[i].sample.force_n, y.contacts[i].sample.force_n);
      }
      ASSERT_EQ(x.events.size(), y.events.size());
    }
  }
}

// A run past --run-timeout is stopped (SIGKILL) and marked diverged naming
// the option; the others are kept. head_on on MuJoCo at dt = 1e-7 s over
// 1000 s is 1e10 steps (hours); its closed form takes milliseconds.
TEST(Isolation, ARunPastItsTimeoutIsStoppedAndTheOthersKept) {
  const fs::path dir = fresh_dir("timeout");
  const fs::path out = dir / "slow.h5";
  const auto r = run("run --case head_on --engine analytic,mujoco --quiet --run-timeout 1 "
                     "--set mujoco.dt=1e-7 --set duration=1000 --set output_interval=1 --out " +
                     out.string());
  ASSERT_EQ(r.exit_code, 3) << r.output;
  expect_only(dir, out);
  const pb::ResultsFile f = pb::read_results_file(out);
  const pb::RunResult* mj = find_run(f, "mujoco");
  ASSERT_NE(mj, nullptr);
  EXPECT_EQ(mj->status, pb::RunStatus::diverged);
  EXPECT_TRUE(contains(mj->reason, "--run-timeout of 1 s")) << mj->reason;
  const pb::RunResult* an = find_run(f, "analytic");
  ASSERT_NE(an, nullptr);
  EXPECT_EQ(an->status, pb::RunStatus::ok) << an->reason;
}

}  // namespace
