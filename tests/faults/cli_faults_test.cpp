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

  const auto c = run("check --thresholds " + std::string(PB_SOURCE_DIR) +
                     "/cases/thresholds.toml " + out.string());
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

}  // namespace
