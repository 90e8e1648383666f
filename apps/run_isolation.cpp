#include "run_isolation.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <atomic>
#include <cmath>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <fmt/format.h>
#include <stdexcept>

#include "planarbench/engines.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/output_file.hpp"
#include "planarbench/results_file.hpp"

extern char** environ;

namespace pb::cli {

namespace {

namespace fs = std::filesystem;

// the child's stderr kept for the reason: its last lines are what a library
// printed before it aborted (libode: "ODE INTERNAL ERROR 1: assertion ...")
constexpr std::size_t kStderrTail = 8192;
// the reason quotes at most this much of the child's last line
constexpr std::size_t kQuoted = 240;
// the fd the child writes its progress to (--progress-fd)
constexpr int kProgressFd = 3;

// a file descriptor closed on scope exit
class Fd {
 public:
  explicit Fd(int fd = -1) : fd_(fd) {}
  ~Fd() { reset(); }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  [[nodiscard]] int get() const { return fd_; }
  void reset(int fd = -1) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = fd;
  }

 private:
  int fd_;
};

// a pipe whose ends are close-on-exec and above the fds the child is given
// (0-3), so that adddup2 onto 2 or 3 always copies and clears close-on-exec
void make_pipe(Fd& read_end, Fd& write_end) {
  int p[2];
  if (::pipe2(p, O_CLOEXEC) != 0) {
    throw std::runtime_error(fmt::format("run isolation: pipe: {}", std::strerror(errno)));
  }
  auto lift = [](int fd) {
    const int high = ::fcntl(fd, F_DUPFD_CLOEXEC, 10);
    ::close(fd);
    if (high < 0) throw std::runtime_error(fmt::format("run isolation: fcntl: {}", std::strerror(errno)));
    return high;
  };
  read_end.reset(lift(p[0]));
  write_end.reset(lift(p[1]));
}

std::string signal_name(int sig) {
  const char* abbrev = ::sigabbrev_np(sig);
  const char* desc = ::sigdescr_np(sig);
  return fmt::format("SIG{} ({})", abbrev ? abbrev : std::to_string(sig).c_str(),
                     desc ? desc : "unknown signal");
}

// the last non-empty line of the child's stderr, printable (errors.hpp), cut
std::string last_line(const std::string& text) {
  const std::size_t end = text.find_last_not_of("\r\n ");
  if (end == std::string::npos) return {};
  const std::size_t nl = text.rfind('\n', end);
  const std::size_t begin = nl == std::string::npos ? 0 : nl + 1;
  std::string line = printable(std::string_view(text).substr(begin, end + 1 - begin));
  if (line.size() > kQuoted) line = line.substr(0, kQuoted) + "...";
  return line;
}

std::vector<std::string> child_arguments(const IsolatedRun& spec, const fs::path& out) {
  std::vector<std::string> args = {"planarbench", "run",   "--case",         spec.case_path.string(),
                                   "--engine",    spec.engine, "--out",      out.string(),
                                   "--quiet",     "--isolation", "none",     "--progress-fd",
                                   std::to_string(kProgressFd), "--repeat", std::to_string(spec.repeat)};
  if (!spec.set.empty()) {
    args.emplace_back("--set");
    for (const auto& s : spec.set) args.push_back(s);
  }
  return args;
}

struct ChildEnd {
  int wait_status = 0;
  bool timed_out = false;
  double fraction = -1.0;  // the last fraction done it reported, -1: none
  std::string stderr_tail;
};

// spawns the child, relays its progress, enforces the time limit, reaps it
ChildEnd run_child(const IsolatedRun& spec, const fs::path& out,
                   const std::function<void(double)>& progress) {
  static const fs::path self = fs::read_symlink("/proc/self/exe");
  const std::vector<std::string> args = child_arguments(spec, out);
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);

  Fd prog_r, prog_w, err_r, err_w;
  make_pipe(prog_r, prog_w);
  make_pipe(err_r, err_w);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&fa, err_w.get(), STDERR_FILENO);
  posix_spawn_file_actions_adddup2(&fa, prog_w.get(), kProgressFd);
  pid_t pid = 0;
  const int rc = ::posix_spawn(&pid, self.c_str(), &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) {
    throw std::runtime_error(
        fmt::format("run isolation: cannot start {}: {}", self.string(), std::strerror(rc)));
  }
  prog_w.reset();
  err_w.reset();

  ChildEnd end;
  const auto start = std::chrono::steady_clock::now();
  std::string prog_buf;
  bool prog_open = true, err_open = true;
  bool reaped = false;
  char buf[4096];
  while (prog_open || err_open) {
    pollfd fds[2] = {{prog_open ? prog_r.get() : -1, POLLIN, 0}, {err_open ? err_r.get() : -1, POLLIN, 0}};
    // once the child is reaped, only what its pipes hold already is read: a
    // process it started that outlived it (it should not: engine processes
    // die with their parent) may hold the pipes open for ever (issue 49)
    const int n = ::poll(fds, 2, reaped ? 0 : 200);
    if (n < 0 && errno != EINTR) break;
    if (reaped && n == 0) break;
    if (fds[0].revents != 0) {
      const ssize_t k = ::read(prog_r.get(), buf, sizeof buf);
      if (k <= 0) {
        prog_open = false;
      } else {
        prog_buf.append(buf, static_cast<std::size_t>(k));
        for (std::size_t nl; (nl = prog_buf.find('\n')) != std::string::npos;) {
          const std::string line = prog_buf.substr(0, nl);
          prog_buf.erase(0, nl + 1);
          try {
            end.fraction = std::stod(line);
          } catch (const std::exception&) {
            continue;  // not ours; the child writes only fractions here
          }
          if (progress) progress(end.fraction);
        }
      }
    }
    if (fds[1].revents != 0) {
      const ssize_t k = ::read(err_r.get(), buf, sizeof buf);
      if (k <= 0) {
        err_open = false;
      } else {
        end.stderr_tail.append(buf, static_cast<std::size_t>(k));
        if (end.stderr_tail.size() > kStderrTail) {
          end.stderr_tail.erase(0, end.stderr_tail.size() - kStderrTail);
        }
      }
    }
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (spec.timeout_s > 0.0 && elapsed > spec.timeout_s && !end.timed_out) {
      end.timed_out = true;
      ::kill(pid, SIGKILL);
    }
    if (!reaped && ::waitpid(pid, &end.wait_status, WNOHANG) == pid) reaped = true;
  }
  while (!reaped && ::waitpid(pid, &end.wait_status, 0) < 0 && errno == EINTR) {
  }
  return end;
}

// `.<target name>.run.`: a child's folder beside the target, named like the
// target's temporary (output_file.cpp), then the parent's pid and a count
std::string child_folder_prefix(const fs::path& target) {
  return fmt::format(".{}.run.", target.filename().string());
}

// the child's own folder: its results file and the spool of its samples;
// removed with whatever a killed child left in it
class ChildFolder {
 public:
  ChildFolder(const fs::path& work_dir, const fs::path& target) {
    static std::atomic<unsigned> counter{0};
    path_ = work_dir / fmt::format("{}{}.{}", child_folder_prefix(target), ::getpid(), counter++);
    fs::create_directory(path_);
  }
  ~ChildFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  ChildFolder(const ChildFolder&) = delete;
  ChildFolder& operator=(const ChildFolder&) = delete;
  [[nodiscard]] const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

}  // namespace

IsolatedResult run_isolated(const IsolatedRun& spec, const std::function<void(double)>& progress) {
  auto folder = std::make_shared<ChildFolder>(spec.work_dir, spec.target);
  const fs::path out = folder->path() / "run.h5";
  const auto start = std::chrono::steady_clock::now();
  const ChildEnd end = run_child(spec, out, progress);
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const bool exited = WIFEXITED(end.wait_status);
  const int code = exited ? WEXITSTATUS(end.wait_status) : -1;
  std::error_code ec;
  if (!end.timed_out && exited && (code == kExitOk || code == kExitEngineFailed) &&
      fs::exists(out, ec)) {
    IsolatedResult kept;
    kept.run = read_run_header(out);
    kept.file = out;
    kept.folder = folder;
    return kept;
  }
  const std::string line = last_line(end.stderr_tail);
  const std::string prefix = "planarbench: error: ";
  if (exited && code == kExitBadInput && line.rfind(prefix, 0) == 0) {
    throw InputError(line.substr(prefix.size()));
  }
  std::string cause;
  if (end.timed_out) {
    cause = fmt::format("stopped at the --run-timeout of {:g} s of wall time (killed)", spec.timeout_s);
  } else if (WIFSIGNALED(end.wait_status)) {
    cause = fmt::format("killed by {}", signal_name(WTERMSIG(end.wait_status)));
  } else {
    cause = fmt::format("exit status {} without its results", code);
  }
  RunResult r;
  r.wall_time_s = wall_s;
  r.case_name = spec.case_name;
  r.engine_name = spec.engine;
  r.status = RunStatus::diverged;
  r.diverged_at_s = end.fraction >= 0.0 ? end.fraction * spec.duration_s : -1.0;
  const std::string when =
      end.fraction >= 0.0 ? fmt::format(" after t = {:.6g} s of {:.6g} s", r.diverged_at_s, spec.duration_s)
                          : " before its first sample";
  r.reason = fmt::format("the {} run of case '{}' ended its process{}: {}{}{}", spec.engine,
                         spec.case_name, when, cause, line.empty() ? "" : "; its last words: ", line);
  IsolatedResult lost;
  lost.run = std::move(r);
  return lost;
}

void remove_stale_child_folders(const fs::path& work_dir, const fs::path& target) {
  const std::string prefix = child_folder_prefix(target);
  std::error_code ec;
  for (fs::directory_iterator it(work_dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    const std::string rest = name.substr(prefix.size());
    if (!names_dead_process(rest.substr(0, rest.find('.')))) continue;
    std::error_code ignored;
    fs::remove_all(it->path(), ignored);
  }
}

RunResult run_isolated_whole(const IsolatedRun& spec, const Case& c,
                             const SettingsOverrides& engine_settings) {
  IsolatedResult got = run_isolated(spec, nullptr);
  if (got.file.empty()) {
    describe_lost_run(got.run, c, engine_settings);
    return std::move(got.run);
  }
  ResultsFile f = read_results_file(got.file);
  return std::move(f.cases.at(0).runs.at(0));
}

void describe_lost_run(RunResult& r, const Case& c, const SettingsOverrides& engine_settings) {
  auto engine = make_engine(r.engine_name);
  engine->settings().apply(engine_settings);
  r.engine_version = engine->version();
  r.settings = engine->settings().to_json();
  r.mapping = {{"physics", physics_json(engine->physics())}};
  r.body_names.clear();
  for (const auto& b : c.bodies) r.body_names.push_back(b.name);
}

void add_isolation_options(CLI::App& cmd, std::string& isolation, double& run_timeout_s) {
  cmd.add_option("--isolation", isolation,
                 "process: each run in a process of its own, so that an engine library's abort, "
                 "assertion, crash or allocation failure, or a run past --run-timeout, ends that "
                 "run only (marked diverged with what ended it); none: every run in this process "
                 "(profilers, debuggers; one library's abort then ends the command)")
      ->check(CLI::IsMember({"process", "none"}))
      ->default_val("process");
  cmd.add_option("--run-timeout", run_timeout_s,
                 "Wall-clock seconds one run (with its repeats) may take before it is stopped "
                 "and marked diverged; 0: no limit (with --isolation process only)")
      ->default_val(kDefaultRunTimeout_s);
}

void check_run_timeout(double s) {
  if (!std::isfinite(s) || s < 0.0 || s > 30.0 * 86400.0) {
    throw InputError("--run-timeout", 0, "",
                     fmt::format("must be 0 (no limit) or seconds in (0, 2592000] (got {})", s));
  }
}

void die_with_parent() {
  const pid_t parent = ::getppid();
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  // the parent may have gone before prctl: then this one was re-parented
  if (::getppid() != parent) ::_exit(kExitEngineFailed);
}

}  // namespace pb::cli
