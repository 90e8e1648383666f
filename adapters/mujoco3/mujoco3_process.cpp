#include "mujoco3_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include <array>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "planarbench/errors.hpp"

extern char** environ;

namespace pb::internal::mujoco3 {

namespace {

namespace fs = std::filesystem;

// what sets the project's npm packages up (README)
constexpr const char* kInstallCommand = "bash scripts/setup_web.sh";

std::string find_on_path(const std::string& exe) {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return "";
  std::string all = path;
  std::size_t start = 0;
  while (start <= all.size()) {
    const auto colon = all.find(':', start);
    const std::string dir = all.substr(start, colon == std::string::npos ? colon : colon - start);
    if (!dir.empty()) {
      const fs::path p = fs::path(dir) / exe;
      if (::access(p.c_str(), X_OK) == 0) return p.string();
    }
    if (colon == std::string::npos) break;
    start = colon + 1;
  }
  return "";
}

Mujoco3Install locate() {
  Mujoco3Install in;
  const char* node = std::getenv("PB_NODE");
  in.node = node != nullptr && *node != '\0' ? std::string(node) : find_on_path("node");
  const char* dir = std::getenv("PB_MUJOCO3_DIR");
  in.package_dir = dir != nullptr && *dir != '\0' ? std::string(dir) : std::string(PB_MUJOCO3_WASM_DIR);
  in.server = (fs::path(in.package_dir) / "server.mjs").string();
  const fs::path package = fs::path(in.package_dir) / "node_modules" / "mujoco-js" / "package.json";
  if (in.node.empty() || ::access(in.node.c_str(), X_OK) != 0) {
    in.reason = fmt::format("no Node.js executable ({}); install it with: {}",
                            node != nullptr ? "PB_NODE=" + std::string(node) : "none on PATH",
                            kInstallCommand);
  } else if (!fs::exists(in.server)) {
    in.reason = fmt::format("{} is missing (PB_MUJOCO3_DIR)", in.server);
  } else if (!fs::exists(package)) {
    in.reason = fmt::format("the mujoco-js package is not installed ({} missing); install it with: {}",
                            package.string(), kInstallCommand);
  } else {
    in.available = true;
  }
  return in;
}

// the last lines of what the process wrote to stderr
std::string tail_of(int fd) {
  if (fd < 0) return "";
  std::string text;
  std::array<char, 4096> buf{};
  ::lseek(fd, 0, SEEK_SET);
  for (;;) {
    const ssize_t r = ::read(fd, buf.data(), buf.size());
    if (r <= 0) break;
    text.append(buf.data(), static_cast<std::size_t>(r));
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  constexpr std::size_t kKeep = 1200;
  if (text.size() > kKeep) text = "..." + text.substr(text.size() - kKeep);
  return text;
}

// the other side's text (an ERROR frame, an INFO frame shown) as one line of
// a run's reason: control characters become spaces, at most `keep`
// characters (a 1 MB frame was a 1 MB reason)
std::string one_line(const std::vector<unsigned char>& bytes, std::size_t keep) {
  std::string text;
  for (const unsigned char ch : bytes) {
    if (text.size() == keep) break;
    text.push_back(ch < 32 || ch == 127 ? ' ' : static_cast<char>(ch));
  }
  if (bytes.size() > keep) text += fmt::format("... ({} bytes in all)", bytes.size());
  return text;
}

const char* json_type_name(JsonField type) {
  return type == JsonField::string ? "a string" : type == JsonField::integer ? "an integer" : "a number";
}

}  // namespace

const Mujoco3Install& mujoco3_install() {
  static const Mujoco3Install in = locate();
  return in;
}

double mujoco3_answer_timeout_s(double unset_s) {
  const char* v = std::getenv("PB_MUJOCO3_TIMEOUT_S");
  if (v == nullptr || *v == '\0') return unset_s;
  char* end = nullptr;
  const double s = std::strtod(v, &end);
  if (end == v || *end != '\0' || !(s >= 0.1 && s <= 86400.0)) {
    throw EngineError(fmt::format(
        "mujoco3: PB_MUJOCO3_TIMEOUT_S = '{}': must be a number of seconds in [0.1, 86400]", v));
  }
  return s;
}

Mujoco3Process::Mujoco3Process(const Mujoco3Install& install, double answer_timeout_s)
    : timeout_s_(answer_timeout_s) {
  if (!install.available) throw EngineError("mujoco3: unavailable: " + install.reason);
  int in_pipe[2];   // parent -> child stdin
  int out_pipe[2];  // child stdout -> parent
  if (::pipe2(in_pipe, O_CLOEXEC) != 0 || ::pipe2(out_pipe, O_CLOEXEC) != 0) {
    throw EngineError(fmt::format("mujoco3: pipe: {}", std::strerror(errno)));
  }
  char name[] = "/tmp/planarbench-mujoco3-XXXXXX";
  stderr_file_ = ::mkostemp(name, O_CLOEXEC);
  if (stderr_file_ >= 0) ::unlink(name);
  std::string node = install.node;
  std::string server = install.server;
  // Node's WebAssembly guards each memory with ~10 GB of reserved address
  // space (V8's trap handler); under an address-space cap (ulimit -v) that
  // reservation fails and so does every run. Without the trap handler V8
  // checks bounds in code instead (Node's --disable-wasm-trap-handler): the
  // same results, a little slower (issue 49).
  std::string no_trap = "--disable-wasm-trap-handler";
  std::vector<char*> argv = {node.data()};
  rlimit as{};
  if (::getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) argv.push_back(no_trap.data());
  argv.push_back(server.data());
  argv.push_back(nullptr);
  // a pipe that tells the parent whether exec failed (it closes on exec)
  int exec_pipe[2];
  if (::pipe2(exec_pipe, O_CLOEXEC) != 0) {
    throw EngineError(fmt::format("mujoco3: pipe: {}", std::strerror(errno)));
  }
  const pid_t parent = ::getpid();
  // fork, not posix_spawn: the child must die with this process (a run
  // past --run-timeout is SIGKILLed, and so must be the Node it started,
  // which would otherwise hold the run's pipes open for ever) and must not
  // inherit any descriptor but its three. Only async-signal-safe calls
  // follow in the child.
  pid_ = ::fork();
  if (pid_ == 0) {
    ::dup2(in_pipe[0], 0);
    ::dup2(out_pipe[1], 1);
    if (stderr_file_ >= 0) ::dup2(stderr_file_, 2);
    // every other descriptor closed, the exec-error pipe kept
    if (exec_pipe[1] > 3) ::close_range(3, static_cast<unsigned>(exec_pipe[1]) - 1, 0);
    ::close_range(static_cast<unsigned>(exec_pipe[1]) + 1, ~0U, 0);
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127);  // the parent went before prctl
    ::execve(node.c_str(), argv.data(), environ);
    const int e = errno;
    [[maybe_unused]] const ssize_t w = ::write(exec_pipe[1], &e, sizeof e);
    ::_exit(127);
  }
  const int fork_errno = errno;
  ::close(exec_pipe[1]);
  ::close(in_pipe[0]);
  ::close(out_pipe[1]);
  to_child_ = in_pipe[1];
  from_child_ = out_pipe[0];
  int exec_errno = 0;
  if (pid_ < 0) {
    exec_errno = fork_errno;
  } else {
    ssize_t r = 0;
    while ((r = ::read(exec_pipe[0], &exec_errno, sizeof exec_errno)) < 0 && errno == EINTR) {
    }
    if (r != static_cast<ssize_t>(sizeof exec_errno)) exec_errno = 0;
  }
  ::close(exec_pipe[0]);
  if (exec_errno != 0) {
    if (pid_ > 0) ::waitpid(pid_, nullptr, 0);
    pid_ = -1;
    fail(fmt::format("cannot start {} {}: {}", install.node, install.server, std::strerror(exec_errno)));
  }
}

Mujoco3Process::~Mujoco3Process() {
  if (pid_ > 0) {
    const std::uint32_t head[2] = {static_cast<std::uint32_t>(Kind::quit), 0};
    // best effort: a process that is gone already raises nothing here
    sigset_t pipe_set;
    sigset_t old;
    sigemptyset(&pipe_set);
    sigaddset(&pipe_set, SIGPIPE);
    pthread_sigmask(SIG_BLOCK, &pipe_set, &old);
    [[maybe_unused]] const ssize_t w = ::write(to_child_, head, sizeof head);
    const timespec zero{0, 0};
    while (sigtimedwait(&pipe_set, nullptr, &zero) > 0) {
    }
    pthread_sigmask(SIG_SETMASK, &old, nullptr);
  }
  if (to_child_ >= 0) ::close(to_child_);
  if (from_child_ >= 0) ::close(from_child_);
  if (pid_ > 0) {
    // the child exits on QUIT or on the closed pipe; 2 s, then it is killed
    int status = 0;
    for (int i = 0; i < 200; ++i) {
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        pid_ = -1;
        break;
      }
      ::usleep(10000);
    }
    if (pid_ > 0) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, &status, 0);
    }
  }
  if (stderr_file_ >= 0) ::close(stderr_file_);
}

void Mujoco3Process::fail(const std::string& what) {
  std::string status;
  if (pid_ > 0) {
    int st = 0;
    // a process that has closed its pipes may not be reaped yet: up to 1 s
    // for it to end by itself, then it is ended (a hang)
    pid_t done = 0;
    for (int i = 0; i < 100 && (done = ::waitpid(pid_, &st, WNOHANG)) == 0; ++i) ::usleep(10000);
    if (done == 0) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, &st, 0);
      status = "killed";
    } else if (WIFEXITED(st)) {
      status = fmt::format("exit status {}", WEXITSTATUS(st));
    } else if (WIFSIGNALED(st)) {
      status = fmt::format("signal {}", WTERMSIG(st));
    }
    pid_ = -1;
  }
  const std::string err = tail_of(stderr_file_);
  throw EngineError(fmt::format("mujoco3: the WebAssembly side (Node, MuJoCo 3): {}{}{}", what,
                                status.empty() ? "" : " (" + status + ")",
                                err.empty() ? "" : "; it said: " + err));
}

void Mujoco3Process::send(Kind kind, const void* data, std::size_t bytes) {
  const std::uint32_t head[2] = {static_cast<std::uint32_t>(kind), static_cast<std::uint32_t>(bytes)};
  scratch_.resize(sizeof head + bytes);
  std::memcpy(scratch_.data(), head, sizeof head);
  if (bytes > 0) std::memcpy(scratch_.data() + sizeof head, data, bytes);
  // a write to a process that is gone raises SIGPIPE: blocked here, taken
  // back below, and reported as the process's end
  sigset_t pipe_set;
  sigset_t old;
  sigemptyset(&pipe_set);
  sigaddset(&pipe_set, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipe_set, &old);
  std::size_t off = 0;
  int error = 0;
  while (off < scratch_.size()) {
    const ssize_t w = ::write(to_child_, scratch_.data() + off, scratch_.size() - off);
    if (w < 0) {
      if (errno == EINTR) continue;
      error = errno;
      break;
    }
    off += static_cast<std::size_t>(w);
  }
  const timespec zero{0, 0};
  while (sigtimedwait(&pipe_set, nullptr, &zero) > 0) {
  }
  pthread_sigmask(SIG_SETMASK, &old, nullptr);
  if (error != 0) fail(fmt::format("writing to it failed: {}", std::strerror(error)));
}

void Mujoco3Process::read_exactly(unsigned char* out, std::size_t n) {
  std::size_t got = 0;
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s_);
  while (got < n) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) fail(fmt::format("no answer within {} s (a hang)", timeout_s_));
    pollfd p{from_child_, POLLIN, 0};
    const int r = ::poll(&p, 1, static_cast<int>(left.count()));
    if (r < 0 && errno == EINTR) continue;
    if (r == 0) continue;  // the deadline check above ends it
    const ssize_t k = ::read(from_child_, out + got, n - got);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) fail("the process ended");
    got += static_cast<std::size_t>(k);
  }
}

void Mujoco3Process::receive(Kind expected, std::vector<unsigned char>& bytes) {
  std::uint32_t head[2] = {0, 0};
  read_exactly(reinterpret_cast<unsigned char*>(head), sizeof head);
  const bool known = head[0] == static_cast<std::uint32_t>(Kind::info) ||
                     head[0] == static_cast<std::uint32_t>(Kind::batch) ||
                     head[0] == static_cast<std::uint32_t>(Kind::error);
  // the protocol's own largest message is a BATCH of 1000 steps (a few MB)
  constexpr std::uint32_t kLargest = 1u << 30;
  if (!known || head[1] > kLargest) {
    std::string seen(reinterpret_cast<const char*>(head), sizeof head);
    for (char& ch : seen) {
      if (ch < 32 || ch > 126) ch = '?';
    }
    fail(fmt::format("wrote something that is not a frame on its stdout (\"{}...\")", seen));
  }
  bytes.resize(head[1]);
  if (head[1] > 0) read_exactly(bytes.data(), head[1]);
  if (head[0] == static_cast<std::uint32_t>(Kind::error)) {
    if (bytes.empty()) fail("sent an empty ERROR frame (no reason)");
    throw EngineError("mujoco3: " + one_line(bytes, 600));
  }
  if (head[0] != static_cast<std::uint32_t>(expected)) {
    fail(fmt::format("answered message kind {} where {} was expected", head[0],
                     static_cast<std::uint32_t>(expected)));
  }
}

void Mujoco3Process::receive_numbers(Kind expected, std::vector<double>& values) {
  receive(expected, scratch_);
  if (scratch_.size() % sizeof(double) != 0) fail("sent a message of a partial number");
  values.resize(scratch_.size() / sizeof(double));
  if (!values.empty()) std::memcpy(values.data(), scratch_.data(), scratch_.size());
}

std::string Mujoco3Process::stderr_tail() const {
  return tail_of(stderr_file_);
}

nlohmann::json Mujoco3Process::receive_info(const char* answer_to,
                                            std::initializer_list<std::pair<const char*, JsonField>> fields) {
  receive(Kind::info, scratch_);
  nlohmann::json j = nlohmann::json::parse(scratch_.begin(), scratch_.end(), nullptr, false);
  if (!j.is_object()) {
    fail(fmt::format("answered {} with an INFO frame that is not a JSON object (\"{}\")", answer_to,
                     one_line(scratch_, 80)));
  }
  for (const auto& [key, type] : fields) {
    const auto it = j.find(key);
    const bool ok = it != j.end() &&
                    (type == JsonField::string    ? it->is_string()
                     : type == JsonField::integer ? it->is_number_integer() || it->is_number_unsigned()
                                                  : it->is_number());
    if (!ok) {
      fail(fmt::format("answered {} with an INFO frame whose \"{}\" is {} (it must be {})", answer_to,
                       key, it == j.end() ? "missing" : std::string("a JSON ") + it->type_name(),
                       json_type_name(type)));
    }
  }
  return j;
}

}  // namespace pb::internal::mujoco3
