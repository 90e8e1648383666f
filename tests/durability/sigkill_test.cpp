// Tests for core/src/results_file.cpp (write_results_file's atomic replace:
// a temporary `.<name>.tmp.<pid>` beside the target, fsync, rename), through
// the real planarbench binary killed with SIGKILL as a user's Ctrl-\ , an OOM
// killer or a CI timeout would.
//
// The promise (SPEC §5, results_file.hpp): the target path only ever holds
// what it held before the run or the complete new file, never a part. SIGKILL
// cannot be caught, so no clean-up code runs: this holds only if nothing is
// ever written at the target path except by the final rename.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <thread>

#include "child_process.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/results_file.hpp"

namespace {

namespace fs = std::filesystem;
using namespace pb::test;
using Clock = std::chrono::steady_clock;

// a run of seconds on the reference solver (sliding_paper: 1 s of sliding,
// ~1200 adaptive steps on 180-point outlines; 2.5 s in Release)
const std::vector<std::string> kLongRun = {"run", "--case", "sliding_paper", "--engine",
                                           "reference"};

// a quick complete file, standing for a user's earlier results
void write_earlier_file(const fs::path& out) {
  const auto r = run_planarbench(
      {"run", "--case", "falling_ball", "--engine", "analytic", "--quiet", "--out", out.string()});
  ASSERT_EQ(r.exit.code, 0) << r.err;
  ASSERT_FALSE(r.exit.signaled);
}

// starts the long run, waits for its first progress line on stderr (the
// simulation has started), kills it with SIGKILL and reaps it; its pid
pid_t kill_after_first_progress_line(const fs::path& out) {
  Pipe err;
  std::vector<std::string> args = kLongRun;
  args.insert(args.end(), {"--out", out.string()});
  const pid_t pid = spawn_planarbench(args, err.write_fd);
  err.close_write();
  std::string line;
  EXPECT_TRUE(err.read_line(line)) << "no progress line before the end of stderr";
  EXPECT_NE(line.find("[1/1] sliding_paper x reference"), std::string::npos) << line;
  EXPECT_EQ(::kill(pid, SIGKILL), 0);
  const ChildExit e = wait_child(pid);
  // a signaled exit proves the kill, not a normal end, stopped the run
  EXPECT_TRUE(e.signaled && e.code == SIGKILL) << "exit " << e.code;
  return pid;
}

// The folder of the run the killed command was waiting for, if it is there
// (apps/run_isolation.hpp: each run is a process of its own, working in
// `.results.h5.run.<pid>.<n>` beside the target; it ends with its parent,
// and SIGKILL runs no clean-up): removes it and says so.
bool remove_run_folder(const fs::path& dir, pid_t killed) {
  const fs::path folder = dir / (".results.h5.run." + std::to_string(killed) + ".0");
  const bool there = fs::exists(folder);
  fs::remove_all(folder);
  return there;
}

TEST(SigkillDuringSimulation, LeavesNoFileAtTheTarget) {
  const fs::path dir = fresh_dir("sigkill_no_target");
  const fs::path out = dir / "results.h5";
  const pid_t killed = kill_after_first_progress_line(out);
  EXPECT_FALSE(fs::exists(out));
  // nothing else: the temporary file is made only once the simulation is
  // done; the run's own folder, if its process had started, is all there is
  remove_run_folder(dir, killed);
  EXPECT_TRUE(dir_entries(dir).empty()) << dir_entries(dir).front();
}

// The next run to the same target removes a killed command's run folders
// (their pid names no live process), as it removes its stale temporaries.
TEST(SigkillDuringSimulation, TheNextRunRemovesTheKilledRunsFolder) {
  const fs::path dir = fresh_dir("sigkill_next_run");
  const fs::path out = dir / "results.h5";
  std::vector<std::string> args = kLongRun;
  args.insert(args.end(), {"--out", out.string()});
  const pid_t pid = spawn_planarbench(args);
  const fs::path folder = dir / (".results.h5.run." + std::to_string(pid) + ".0");
  // the run's process is started (its folder made) soon after the command;
  // polled, not timed: up to 2000 x 5 ms on a loaded machine
  for (int i = 0; i < 2000 && !fs::exists(folder); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_TRUE(fs::exists(folder)) << "the run's folder never appeared";
  ASSERT_EQ(::kill(pid, SIGKILL), 0);
  static_cast<void>(wait_child(pid));
  ASSERT_TRUE(fs::exists(folder));  // SIGKILL runs no clean-up
  write_earlier_file(out);          // a complete run to the same target
  EXPECT_EQ(dir_entries(dir), std::vector<std::string>{"results.h5"});
}

TEST(SigkillDuringSimulation, KeepsAnEarlierFileByteForByte) {
  const fs::path dir = fresh_dir("sigkill_keeps_earlier");
  const fs::path out = dir / "results.h5";
  write_earlier_file(out);
  const std::string before = file_bytes(out);
  ASSERT_GT(before.size(), 0u);
  const pid_t killed = kill_after_first_progress_line(out);
  ASSERT_TRUE(fs::exists(out));
  EXPECT_TRUE(file_bytes(out) == before) << "the earlier file changed";
  remove_run_folder(dir, killed);
  EXPECT_EQ(dir_entries(dir), std::vector<std::string>{"results.h5"});
}

// ---- kills spread over a whole run, writing included --------------------------

// A run whose HDF5 write is a large share of its time: four engines on two
// cases, each state sampled every 1e-4 s (25001 and 10001 rows a run), so the
// file is ~4 MB and writing it (deflate, fsync) takes a third or more of the
// run, a window no kill schedule can miss (measured figures are printed).
const std::vector<std::string> kMatrixRun = {
    "run",    "--case", "falling_ball,sliding", "--engine", "analytic,mujoco,box2d,ode",
    "--jobs", "1"};

// where a kill landed, judged from what it left behind
enum class Landing { simulating, writing, renamed, after_exit };

const char* landing_name(Landing l) {
  switch (l) {
    case Landing::simulating:
      return "while simulating (no temporary yet)";
    case Landing::writing:
      return "while writing (temporary left behind)";
    case Landing::renamed:
      return "after the rename";
    case Landing::after_exit:
      return "after the run had ended";
  }
  return "?";
}

class SigkillAnywhere : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fresh_dir("sigkill_anywhere");
    earlier_ = dir_ / "earlier.h5";
    write_earlier_file(earlier_);
    earlier_bytes_ = file_bytes(earlier_);

    // one uninterrupted run: the expected content and the phase times
    const fs::path complete = dir_ / "complete.h5";
    Pipe err;
    const auto t0 = Clock::now();
    const pid_t pid = spawn_planarbench(with_out(complete, false), err.write_fd);
    err.close_write();
    for (std::string line; err.read_line(line);) {
      const double t_s = seconds_since(t0);
      if (run_finished(line)) {
        last_run_done_s_ = t_s;
        ++runs_;
      }
    }
    const ChildExit e = wait_child(pid);
    run_s_ = seconds_since(t0);
    ASSERT_FALSE(e.signaled);
    ASSERT_EQ(e.code, 0);
    write_s_ = run_s_ - last_run_done_s_;
    complete_bytes_ = static_cast<double>(fs::file_size(complete));
    const auto h = dataset_hashes("runs " + complete.string());
    ASSERT_EQ(h.exit.code, 0) << h.err;
    expected_hashes_ = h.err;
    std::printf("uninterrupted run: %.3f s, of which writing the file (%.1f MB) %.3f s\n", run_s_,
                complete_bytes_ / 1e6, write_s_);
  }

  static std::vector<std::string> with_out(const fs::path& out, bool quiet) {
    std::vector<std::string> args = kMatrixRun;
    if (quiet) args.emplace_back("--quiet");
    args.insert(args.end(), {"--out", out.string()});
    return args;
  }

  // a progress line that ends a run: "[i/n] case x engine ok (0.08 s, 25000 steps)"
  static bool run_finished(const std::string& line) {
    return line.size() > 7 && line.compare(line.size() - 7, 7, " steps)") == 0;
  }

  static double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
  }

  // Kills one run at `delay_s` after its start (or, when `from_write` is set,
  // after its last run finished, i.e. once writing began) and checks what is
  // at the target. `keep_earlier`: the target holds the earlier file first.
  Landing kill_at(double delay_s, bool keep_earlier, bool from_write) {
    const fs::path out = dir_ / "results.h5";
    fs::remove(out);
    if (keep_earlier) fs::copy_file(earlier_, out);

    Pipe err;
    const pid_t pid = spawn_planarbench(with_out(out, !from_write), from_write ? err.write_fd : -1);
    err.close_write();
    if (from_write) {
      // the last run's end line comes just before the file is written
      int finished = 0;
      for (std::string line; finished < runs_ && err.read_line(line);)
        finished += run_finished(line);
    }
    std::this_thread::sleep_for(std::chrono::duration<double>(delay_s));
    ::kill(pid, SIGKILL);
    const ChildExit e = wait_child(pid);
    killed_pids_.insert(std::to_string(pid));
    const fs::path tmp = dir_ / (".results.h5.tmp." + std::to_string(pid));

    // the target: the earlier bytes, nothing (when there was nothing), or the
    // complete new file, read by planarbench's reader and hashed by h5py
    const bool exists = fs::exists(out);
    const bool unchanged = exists && keep_earlier && file_bytes(out) == earlier_bytes_;
    const bool renamed = exists && !unchanged;
    if (!exists) {
      EXPECT_FALSE(keep_earlier) << "the earlier file vanished";
    }
    if (renamed) {
      EXPECT_NO_THROW(static_cast<void>(pb::read_results_file(out)));
      const auto h = dataset_hashes("runs " + out.string());
      EXPECT_EQ(h.exit.code, 0) << h.err;
      EXPECT_EQ(h.err, expected_hashes_) << "the new file differs from the uninterrupted run's";
    }
    if (!e.signaled) return Landing::after_exit;
    if (fs::exists(tmp)) {
      EXPECT_FALSE(renamed) << "a temporary file beside a renamed target";
      writing_pids_.insert(std::to_string(pid));
      written_fraction_ = static_cast<double>(fs::file_size(tmp)) / complete_bytes_;
      return Landing::writing;
    }
    return renamed ? Landing::renamed : Landing::simulating;
  }

  // a landing, with how much of the file the temporary held
  std::string where(Landing l) const {
    std::string text = landing_name(l);
    if (l == Landing::writing) {
      text += " " + std::to_string(static_cast<int>(100.0 * written_fraction_)) + " % written";
    }
    return text;
  }

  fs::path dir_, earlier_;
  std::string earlier_bytes_, expected_hashes_;
  double run_s_ = 0, last_run_done_s_ = 0, write_s_ = 0;  // s
  int runs_ = 0;                                          // runs in the matrix
  std::set<std::string> writing_pids_;                    // of the kills that left a temporary
  std::set<std::string> killed_pids_;                     // of every kill
  double complete_bytes_ = 0;    // size of the uninterrupted run's file, bytes
  double written_fraction_ = 0;  // the last temporary's size / complete_bytes_
};

// 20 kills, one in each twentieth of 1.1 x the uninterrupted run's time, at a
// seeded random point within it, so they cover the simulation, the write and
// the moment after; then 10 kills at random points of the write phase alone.
TEST_F(SigkillAnywhere, TargetIsTheEarlierFileOrTheCompleteNewOne) {
  constexpr int kSpread = 20, kInWrite = 10;
  std::mt19937 rng(20240607);  // fixed seed: the same delays each time on one machine
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::map<Landing, int> landed;
  for (int k = 0; k < kSpread; ++k) {
    const double delay_s = 1.1 * run_s_ * (k + u(rng)) / kSpread;
    const Landing l = kill_at(delay_s, k % 2 == 0, false);
    ++landed[l];
    std::printf("kill %2d at %.3f s: %s\n", k, delay_s, where(l).c_str());
  }
  for (int k = 0; k < kInWrite; ++k) {
    const double delay_s = write_s_ * u(rng);
    const Landing l = kill_at(delay_s, k % 2 == 0, true);
    ++landed[l];
    std::printf("kill %2d at %.3f s after the last run ended: %s\n", kSpread + k, delay_s,
                where(l).c_str());
  }
  for (const auto& [l, n] : landed) std::printf("%2d kills %s\n", n, landing_name(l));

  // a kill during the write leaves its own temporary (until a later complete
  // run removes it, if results_file.cpp sweeps them), and nothing else is left
  // a kill also leaves the folder of the run it was waiting for, if any
  // (`.results.h5.run.<pid>.<n>`, apps/run_isolation.hpp), until the next run
  // to that target removes it: only the last kills' can be left
  const std::string prefix = ".results.h5.tmp.";
  const std::string run_prefix = ".results.h5.run.";
  int temps = 0;
  for (const auto& name : dir_entries(dir_)) {
    if (name.rfind(run_prefix, 0) == 0) {
      const std::string rest = name.substr(run_prefix.size());
      EXPECT_EQ(killed_pids_.count(rest.substr(0, rest.find('.'))), 1u) << name;
      fs::remove_all(dir_ / name);
    } else if (name.rfind(prefix, 0) == 0) {
      ++temps;
      EXPECT_EQ(writing_pids_.count(name.substr(prefix.size())), 1u) << name;
      fs::remove(dir_ / name);  // megabytes each
    } else {
      EXPECT_TRUE(name == "results.h5" || name == "earlier.h5" || name == "complete.h5") << name;
    }
  }
  std::printf("%d stale temporary files were left in %s\n", temps, dir_.c_str());
}

// ---- stale temporaries ----------------------------------------------------------

// A temporary of a writer that was killed stays behind: nothing can remove it
// at the time. The next complete write of the same target removes those whose
// pid is no live process, and nothing else: not a live writer's (this test
// process stands for one), not another target's, not a name that is no pid's.
TEST(StaleTemporaries, ACompleteRunRemovesThoseOfDeadWriters) {
  const fs::path dir = fresh_dir("stale_temporaries");
  // a pid that was just reaped names no process (reuse within the test is
  // possible in principle but needs the pid counter to wrap around)
  const pid_t dead = spawn_planarbench({"--help"});
  ASSERT_FALSE(wait_child(dead).signaled);
  const std::string dead_writer = ".results.h5.tmp." + std::to_string(dead);
  const std::string live_writer = ".results.h5.tmp." + std::to_string(::getpid());
  const std::string other_target = ".other.h5.tmp." + std::to_string(dead);
  const std::string not_a_pid = ".results.h5.tmp.x" + std::to_string(dead);
  for (const auto& name : {dead_writer, live_writer, other_target, not_a_pid}) {
    std::ofstream(dir / name) << "part of an HDF5 file";
  }
  write_earlier_file(dir / "results.h5");
  EXPECT_EQ(dir_entries(dir),
            (std::vector<std::string>{other_target, live_writer, not_a_pid, "results.h5"}));
}

}  // namespace
