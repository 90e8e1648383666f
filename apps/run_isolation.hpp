// One run in a process of its own (issue 24): an abort, an assertion or a
// segmentation fault inside an engine's library, an allocation failure or a
// run past its time limit ends that process only, and the run is reported
// `diverged` with what ended it, while the command goes on with the others.
//
// Why a process, not validation: libode keeps its dIASSERTs in Debian's build
// (abort), MuJoCo's mju_error ends the process, libbox2d keeps its b2Asserts;
// knowing every input each library would assert on is not something one can
// show complete, a process boundary is. The child is this same executable,
// `planarbench run` on the one (case, engine) with --isolation none, so it
// runs exactly the code an in-process run would: the same bits (tested).
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "planarbench/case.hpp"
#include "planarbench/run_result.hpp"
#include "planarbench/settings.hpp"

namespace CLI {
class App;
}  // namespace CLI

namespace pb::cli {

struct IsolatedRun {
  std::filesystem::path case_path;  // the case file, as `run` resolved it
  std::string case_name;            // for the messages
  std::string engine;
  std::vector<std::string> set;     // --set KEY=VALUE, as given
  int repeat = 1;
  double duration_s = 0.0;          // s, the case's, to say how far a failed run got
  double timeout_s = 0.0;           // s of wall time, 0: none
  std::filesystem::path work_dir;   // where the child's folder is made
  std::filesystem::path target;     // the command's results file (names the folder)
};

// What a child left: its run's attributes (no samples) and its results file
// to copy into the command's (ResultsFileWriter::copy_run, chunk by chunk:
// the parent never holds a run's samples), or, when it ended without its
// results, a `diverged` run made here and no file. The file lives as long as
// this object.
struct IsolatedResult {
  RunResult run;
  std::filesystem::path file;  // empty: no file, write `run`
  std::shared_ptr<void> folder;
};

// Runs `spec` in a child process. A run that ended without its results is
// `diverged`, its reason naming the case, the engine and what ended the
// process (the signal, the exit status, the child's last line on stderr).
// `progress` is called with the fraction done, as in RunOptions. An
// InputError the child reports (exit 2) is thrown as one.
[[nodiscard]] IsolatedResult run_isolated(const IsolatedRun& spec,
                                          const std::function<void(double)>& progress);

// The same, the run read whole into memory (campaigns, whose runs are
// reduced to metrics in memory anyway); a lost run is completed by
// describe_lost_run.
[[nodiscard]] RunResult run_isolated_whole(const IsolatedRun& spec, const Case& c,
                                           const SettingsOverrides& engine_settings);

// a run whose process ended without its results: what the parent knows of it
// (the engine's version and settings, the case's bodies), as an unsupported
// run has them
void describe_lost_run(RunResult& r, const Case& c, const SettingsOverrides& engine_settings);

// --isolation process|none and --run-timeout SECONDS on a command that runs
// engines; check_run_timeout validates the latter (0, none, or (0, 30 days])
inline constexpr double kDefaultRunTimeout_s = 3600.0;
void add_isolation_options(CLI::App& cmd, std::string& isolation, double& run_timeout_s);
void check_run_timeout(double seconds);

// A parent killed with SIGKILL leaves its children's folders
// (`.<target>.run.<pid>.<n>` beside the target, as a killed writer leaves its
// `.<target>.tmp.<pid>`): removes those of `target` whose pid names no live
// process. Called before a command's runs start.
void remove_stale_child_folders(const std::filesystem::path& work_dir,
                                const std::filesystem::path& target);

// In a child: end with the parent (PR_SET_PDEATHSIG, SIGKILL), so that a
// killed command leaves no run going on behind it.
void die_with_parent();

}  // namespace pb::cli
