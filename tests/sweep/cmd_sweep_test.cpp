// Tests for apps/cmd_sweep.cpp, run as a user runs it: the real binary, a
// quick sweep of the falling ball read back with h5py alone
// (tests/sweep/read_sweep.py), its errors, its bad input and its report.
//
// The falling ball has a closed form over the whole run (SPEC §3), so every
// error here is against the analytic truth. The reference runs at exact
// geometry (--set reference.geometry=exact) so that its errors are the
// integrator's alone.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>

#include "planarbench/sweep_file.hpp"

namespace {

namespace fs = std::filesystem;

struct Outcome {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

// runs a shell command, capturing both streams
Outcome shell(const std::string& cmd) {
  Outcome o;
  FILE* p = popen((cmd + " 2>&1").c_str(), "r");
  if (p == nullptr) return o;
  std::array<char, 4096> buf{};
  while (fgets(buf.data(), buf.size(), p) != nullptr) o.output += buf.data();
  const int status = pclose(p);
  o.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return o;
}

Outcome run(const std::string& args) {
  return shell(std::string(PB_EXE) + " " + args);
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
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

// the quick sweep of the falling ball on the reference and ODE, once per test binary
const fs::path& quick_sweep() {
  static const fs::path out = [] {
    // one file per process: ctest may run this binary's tests side by side
    const fs::path p = work_dir() / ("quick_" + std::to_string(::getpid()) + ".h5");
    fs::remove(p);
    const auto o =
        run("sweep --case falling_ball --engine reference,ode --quick --jobs 2 "
            "--set reference.geometry=exact --out " +
            p.string());
    EXPECT_EQ(o.exit_code, 0) << o.output;
    return p;
  }();
  return out;
}

// the file as h5py reads it (read_sweep.py checks the layout on the way)
nlohmann::json read_with_h5py(const fs::path& file) {
  const auto o = shell(std::string(PB_PYTHON) + " " + PB_SOURCE_DIR +
                       "/tests/sweep/read_sweep.py " + file.string());
  EXPECT_EQ(o.exit_code, 0) << o.output;
  return o.exit_code == 0 ? nlohmann::json::parse(o.output) : nlohmann::json::object();
}

// Each rung is a process of its own (apps/run_isolation.hpp, issue 24): a
// spin of 1e200 rad/s trips libode's dIASSERT (SIGABRT) at its first step,
// which ended the whole sweep before; now ODE's rungs are diverged naming
// the signal and the sweep file is written (exit 0: a sweep's diverged rungs
// are its data, README "planarbench sweep").
TEST(CmdSweep, AnAbortInsideOdeEndsItsRungsOnly) {
  const fs::path out = work_dir() / "abort.h5";
  fs::remove(out);
  const auto o = run("sweep --case falling_ball --engine ode --quick -q "
                     "--set bodies.ball.angular_velocity=1e200 --set duration=0.01 --out " +
                     out.string());
  EXPECT_EQ(o.exit_code, 0) << o.output;
  ASSERT_TRUE(fs::exists(out)) << o.output;
  const pb::SweepFile f = pb::read_sweep_file(out);
  ASSERT_EQ(f.cases.size(), 1u);
  ASSERT_FALSE(f.cases[0].series.empty());
  for (const auto& series : f.cases[0].series) {
    for (const auto& rung : series.rungs) {
      EXPECT_EQ(rung.status, pb::RunStatus::diverged);
      EXPECT_TRUE(contains(rung.reason, "SIGABRT")) << rung.reason;
    }
  }
}

TEST(CmdSweep, QuickSweepWritesAFileH5pyReads) {
  const auto j = read_with_h5py(quick_sweep());
  ASSERT_TRUE(j.contains("cases")) << j.dump();
  EXPECT_EQ(j["parameters"]["file_kind"], "sweep");
  EXPECT_EQ(j["parameters"]["dt_ladder"], nlohmann::json::array({1e-3, 1e-4}));
  const auto& c = j["cases"]["falling_ball"];
  EXPECT_EQ(c["truth"], "analytic");
  EXPECT_EQ(c["duration_s"], 2.5);
  for (const char* s : {"reference_rk45", "reference_fixed", "ode"}) {
    ASSERT_TRUE(c["series"].contains(s)) << s;
    const auto& series = c["series"][s];
    EXPECT_EQ(series["value"].size(), 2u) << s;  // --quick: two rungs
    EXPECT_EQ(series["status"], nlohmann::json::array({"ok", "ok"})) << s;
    for (const auto& e : series["position_error_m"]) EXPECT_TRUE(e.is_number()) << s;
  }
  EXPECT_EQ(c["series"]["reference_rk45"]["knob"], "rtol");
  EXPECT_EQ(c["series"]["ode"]["knob"], "dt");
  EXPECT_EQ(c["series"]["ode"]["default_value"], 1e-4);
  EXPECT_EQ(c["series"]["ode"]["steps"], nlohmann::json::array({2500.0, 25000.0}));
}

// Classic RK4 has global error O(h^4) (Hairer, Norsett & Wanner, Solving ODEs
// I, §II.3): a tenth of the step, 1e-3 s to 1e-4 s, divides the error by about
// 1e4, an observed order log10(e1 / e2) near 4. The band [3, 5] allows the
// coarse rung's pre-asymptotic error (h omega = 0.1 in the impact, omega =
// sqrt(k/m) = 100 rad/s) and the located contact events; measured 3.8.
TEST(CmdSweep, FixedStepRk4ErrorFallsAtFourthOrder) {
  const auto j = read_with_h5py(quick_sweep());
  const auto& e = j["cases"]["falling_ball"]["series"]["reference_fixed"]["position_error_m"];
  ASSERT_EQ(e.size(), 2u);
  const double order = std::log10(e[0].get<double>() / e[1].get<double>());
  EXPECT_GT(order, 3.0) << e.dump();
  EXPECT_LT(order, 5.0) << e.dump();
}

// No order is claimed for these: the error falls as the step or the tolerance does.
TEST(CmdSweep, ErrorFallsWithTheStepAndTheTolerance) {
  const auto j = read_with_h5py(quick_sweep());
  const auto& s = j["cases"]["falling_ball"]["series"];
  for (const char* name : {"reference_rk45", "ode"}) {
    const auto& e = s[name]["position_error_m"];
    ASSERT_EQ(e.size(), 2u);
    EXPECT_LT(e[1].get<double>(), e[0].get<double>()) << name << " " << e.dump();
  }
}

TEST(CmdSweep, JobsDoNotChangeTheErrors) {
  const auto one = work_dir() / "jobs1.h5";
  ASSERT_EQ(
      run("sweep --case falling_ball --engine ode --quick --quiet --jobs 1 --out " + one.string())
          .exit_code,
      0);
  const auto a = read_with_h5py(one);
  const auto b = read_with_h5py(quick_sweep());
  EXPECT_EQ(a["cases"]["falling_ball"]["series"]["ode"]["position_error_m"],
            b["cases"]["falling_ball"]["series"]["ode"]["position_error_m"]);
}

TEST(CmdSweep, ProgressLinesOnStderrUnlessQuiet) {
  const auto out = work_dir() / "progress.h5";
  const auto o = run("sweep --case sliding --engine ode --dt-ladder 1e-3 --out " + out.string());
  ASSERT_EQ(o.exit_code, 0) << o.output;
  EXPECT_TRUE(contains(o.output, "sliding truth: analytic ok")) << o.output;
  EXPECT_TRUE(contains(o.output, "[1/1] sliding x ode dt=0.001 ok")) << o.output;
  EXPECT_TRUE(contains(o.output, "wrote " + out.string())) << o.output;
  const auto q =
      run("sweep --case sliding --engine ode --dt-ladder 1e-3 --quiet --out " + out.string());
  EXPECT_EQ(q.exit_code, 0);
  EXPECT_EQ(q.output, "");
}

TEST(CmdSweep, BadInputExitsTwoNamingTheProblemAndWritesNothing) {
  const fs::path out = work_dir() / "bad.h5";
  const std::string base = "sweep --case falling_ball --engine ode --quick --out " + out.string();
  struct Bad {
    std::string args;
    std::string says;
  };
  for (const Bad& b :
       {Bad{base + " --repeat 0", "--repeat"}, Bad{base + " --jobs 0", "--jobs"},
        Bad{base + " --dt-ladder 1e-3,abc", "--dt-ladder"},
        Bad{base + " --dt-ladder 1e-3,-1e-4", "--dt-ladder"},
        Bad{base + " --dt-ladder 0.5", "ode.dt"},  // beyond ode's 1e-2 s
        Bad{base + " --set dt=1e-4", "dt"}, Bad{base + " --set ode.dtt=1e-4", "did you mean"},
        Bad{"sweep --case falling_ball --engine analytic --out " + out.string(), "truth"},
        Bad{"sweep --case falling_bal --engine ode --out " + out.string(), "falling_ball"},
        Bad{"sweep --case falling_ball --engine ode --out " +
                (work_dir() / "no_such_dir" / "s.h5").string(),
            "no_such_dir"}}) {
    fs::remove(out);
    const auto o = run(b.args);
    EXPECT_EQ(o.exit_code, 2) << b.args << "\n" << o.output;
    EXPECT_TRUE(contains(o.output, b.says)) << b.args << "\n" << o.output;
    EXPECT_FALSE(fs::exists(out)) << b.args;
  }
  EXPECT_FALSE(fs::exists(work_dir() / "no_such_dir"));
}

TEST(CmdSweep, ReportAddsTheWorkPrecisionSection) {
  const auto dir = work_dir() / "report";
  fs::remove_all(dir);
  const auto o = run("report --sweep " + quick_sweep().string() + " --out " + dir.string());
  ASSERT_EQ(o.exit_code, 0) << o.output;
  const std::string md = read_text(dir / "report.md");
  for (const char* part :
       {"## Work-precision", "### falling_ball", "figures/falling_ball_work_precision.svg",
        "time to 1e-3 m, s", "| reference_fixed | dt | 1e-5 |"}) {
    EXPECT_TRUE(contains(md, part)) << part << "\n" << md;
  }
  EXPECT_EQ(read_text(dir / "figures" / "falling_ball_work_precision.svg").rfind("<svg", 0), 0u);
  const std::string html = read_text(dir / "report.html");
  EXPECT_TRUE(contains(html, "\"work_precision\"")) << "page data lacks the section";
}

TEST(CmdSweep, ReportWithResultsAndSweepHasBoth) {
  const auto results = work_dir() / "results.h5";
  ASSERT_EQ(run("run --case falling_ball --engine analytic,ode --quiet --out " + results.string())
                .exit_code,
            0);
  const auto dir = work_dir() / "report_both";
  fs::remove_all(dir);
  const auto o = run("report " + results.string() + " --sweep " + quick_sweep().string() +
                     " --out " + dir.string());
  ASSERT_EQ(o.exit_code, 0) << o.output;
  const std::string md = read_text(dir / "report.md");
  EXPECT_TRUE(contains(md, "## Work-precision")) << md;
  EXPECT_TRUE(contains(md, "## Timings")) << md;
  EXPECT_TRUE(contains(md, "## Parameter mapping")) << md;
}

TEST(CmdSweep, ReportWithNeitherFileIsBadUsage) {
  const auto o = run("report --out " + (work_dir() / "neither").string());
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_TRUE(contains(o.output, "--sweep")) << o.output;
}

}  // namespace
