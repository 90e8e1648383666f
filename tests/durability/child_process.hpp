// The real planarbench binary as a child process the durability tests can
// start, read, kill and reap: posix_spawn without a shell, so a pid is the
// binary's own (its temporary results file is named after it).
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

extern char** environ;

namespace pb::test {

namespace fs = std::filesystem;

// how a child ended
struct ChildExit {
  bool signaled = false;  // killed by a signal (then `code` is the signal)
  int code = -1;          // exit code, or the signal number
};

// the words of a command line split at spaces (the tests' commands quote nothing)
inline std::vector<std::string> words(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

// Starts PB_EXE with `args`; stdout goes to /dev/null, stderr to `stderr_fd`
// (or /dev/null when it is -1). The built-in cases folder (the source tree's
// cases/) is used whatever the caller's environment says.
inline pid_t spawn_planarbench(const std::vector<std::string>& args, int stderr_fd = -1) {
  ::unsetenv("PLANARBENCH_CASES_DIR");
  std::vector<std::string> all{PB_EXE};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  if (stderr_fd >= 0) {
    posix_spawn_file_actions_adddup2(&actions, stderr_fd, STDERR_FILENO);
  } else {
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  }
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw std::system_error(rc, std::generic_category(), "posix_spawn planarbench");
  return pid;
}

// reaps the child, retrying on EINTR
inline ChildExit wait_child(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw std::system_error(errno, std::generic_category(), "waitpid");
  }
  if (WIFSIGNALED(status)) return {true, WTERMSIG(status)};
  return {false, WIFEXITED(status) ? WEXITSTATUS(status) : -1};
}

// a pipe whose write end the child gets as stderr
struct Pipe {
  int read_fd = -1;
  int write_fd = -1;
  Pipe() {
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0)
      throw std::system_error(errno, std::generic_category(), "pipe");
    read_fd = fds[0];
    write_fd = fds[1];
  }
  ~Pipe() {
    close_write();
    if (read_fd >= 0) ::close(read_fd);
  }
  Pipe(const Pipe&) = delete;
  Pipe& operator=(const Pipe&) = delete;
  // the parent closes its copy of the write end once the child has it, so
  // reading ends at the child's exit
  void close_write() {
    if (write_fd >= 0) ::close(write_fd);
    write_fd = -1;
  }
  // the next line without its newline; false at end of stream
  bool read_line(std::string& line) {
    line.clear();
    char c = 0;
    for (;;) {
      const ssize_t n = ::read(read_fd, &c, 1);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return !line.empty();
      if (c == '\n') return true;
      line.push_back(c);
    }
  }
};

// a child run to its end: exit and stderr
struct Finished {
  ChildExit exit;
  std::string err;
};

inline Finished run_planarbench(const std::vector<std::string>& args) {
  Pipe p;
  const pid_t pid = spawn_planarbench(args, p.write_fd);
  p.close_write();
  Finished f;
  for (std::string line; p.read_line(line);) f.err += line + "\n";
  f.exit = wait_child(pid);
  return f;
}

// a shell command's exit code and its stdout and stderr together
inline Finished run_shell(const std::string& command) {
  Finished f;
  FILE* p = ::popen((command + " 2>&1").c_str(), "r");
  if (p == nullptr) return f;
  std::array<char, 4096> buf{};
  while (std::fgets(buf.data(), buf.size(), p) != nullptr) f.err += buf.data();
  const int status = ::pclose(p);
  f.exit = {false, WIFEXITED(status) ? WEXITSTATUS(status) : -1};
  return f;
}

// /usr/bin/python3 tests/python/dataset_hashes.py with `args`
inline Finished dataset_hashes(const std::string& args) {
  // appended piece by piece: GCC 12 -O3 warns falsely (-Warray-bounds) on the
  // temporaries of a longer sum of string literals and strings here
  std::string command = PB_PYTHON;
  command += ' ';
  command += (fs::path(PB_SOURCE_DIR) / "tests" / "python" / "dataset_hashes.py").string();
  command += ' ';
  command += args;
  return run_shell(command);
}

inline std::string file_bytes(const fs::path& path) {
  std::ifstream f(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

// an empty folder of this test's own under the build tree
inline fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(PB_WORK_DIR) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// names of the files in `dir`, sorted
inline std::vector<std::string> dir_entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace pb::test
