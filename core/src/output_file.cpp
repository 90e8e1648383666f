#include "planarbench/output_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>

#include <fmt/format.h>

#include "planarbench/errors.hpp"

namespace pb {

namespace fs = std::filesystem;

namespace {

const char* const kAllowed = "give a regular file (or a new name) in an existing, writable folder";

// what a file of this type is, for the message
const char* type_name(fs::file_type t) {
  switch (t) {
    case fs::file_type::directory:
      return "a folder";
    case fs::file_type::block:
      return "a block device";
    case fs::file_type::character:
      return "a character device";
    case fs::file_type::fifo:
      return "a FIFO (named pipe)";
    case fs::file_type::socket:
      return "a socket";
    default:
      return "not a regular file";
  }
}

// The temporary a writer of `path` uses: `.<name>.tmp.<pid>` beside it.
std::string temporary_prefix(const fs::path& path) {
  return fmt::format(".{}.tmp.", path.filename().string());
}

// Removes the temporaries of earlier writers of the same target that were
// killed mid-write (SIGKILL, OOM, power loss run no clean-up): those whose pid
// names no process on this host (names_dead_process). A reused pid only
// delays the removal to a later run. Best effort: the write it follows has
// already succeeded.
void remove_stale_temporaries(const fs::path& dir, const fs::path& path) {
  const std::string prefix = temporary_prefix(path);
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string file = it->path().filename().string();
    if (file.rfind(prefix, 0) != 0 || !names_dead_process(file.substr(prefix.size()))) continue;
    std::error_code ignored;
    fs::remove(it->path(), ignored);
  }
}

// flushes a closed file's data (or a folder's entries) to the disk
void fsync_path(const fs::path& path, int flags) {
  const int fd = ::open(path.c_str(), flags | O_CLOEXEC);
  if (fd < 0) throw std::system_error(errno, std::generic_category(), "open " + path.string());
  const int rc = ::fsync(fd);
  const int err = errno;
  ::close(fd);
  if (rc != 0) throw std::system_error(err, std::generic_category(), "fsync " + path.string());
}

}  // namespace

fs::path output_target(const std::string& option, const fs::path& path) {
  const std::string given = path.string();
  if (path.empty()) throw InputError(option, 0, "", fmt::format("is empty; {}", kAllowed));
  if (!path.has_filename()) {
    throw InputError(option, 0, given, fmt::format("is a folder, not a file; {}", kAllowed));
  }
  fs::path target = path;
  std::error_code ec;
  const fs::file_status link = fs::symlink_status(path, ec);
  if (fs::is_symlink(link)) {
    const fs::file_status named = fs::status(path, ec);
    if (!fs::exists(named)) {
      throw InputError(option, 0, given,
                       fmt::format("is a symbolic link to '{}', which does not exist; {}",
                                   fs::read_symlink(path, ec).string(), kAllowed));
    }
    if (!fs::is_regular_file(named)) {
      throw InputError(option, 0, given,
                       fmt::format("is a symbolic link to {} ('{}'), which is not replaced; {}",
                                   type_name(named.type()), fs::canonical(path, ec).string(),
                                   kAllowed));
    }
    target = fs::canonical(path, ec);
    if (ec) {
      throw InputError(option, 0, given,
                       fmt::format("cannot resolve the symbolic link: {}", ec.message()));
    }
  } else if (fs::is_directory(link)) {
    throw InputError(option, 0, given, fmt::format("is a folder, not a file; {}", kAllowed));
  } else if (fs::exists(link) && !fs::is_regular_file(link)) {
    throw InputError(option, 0, given,
                     fmt::format("is {}, which is not replaced; {}", type_name(link.type()),
                                 kAllowed));
  }
  const fs::path dir = folder_of(target);
  if (!fs::exists(dir, ec)) {
    throw InputError(option, 0, given,
                     fmt::format("folder '{}' does not exist; {}", dir.string(), kAllowed));
  }
  if (!fs::is_directory(dir, ec)) {
    throw InputError(option, 0, given,
                     fmt::format("'{}' is not a folder; {}", dir.string(), kAllowed));
  }
  // a probe file is the only test that is right for every user and mount
  // (access(2) ignores read-only mounts and ACLs for root)
  const fs::path probe = dir / fmt::format(".planarbench-probe.{}", static_cast<long>(::getpid()));
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) {
    const int err = errno;
    throw InputError(option, 0, given,
                     fmt::format("folder '{}' is not writable ({}); {}", dir.string(),
                                 std::strerror(err), kAllowed));
  }
  ::close(fd);
  ::unlink(probe.c_str());
  return target;
}

AtomicOutput::AtomicOutput(const std::string& option, const fs::path& path)
    : option_(option), given_(path), target_(output_target(option, path)) {
  const fs::path dir = folder_of(target_);
  tmp_ = dir / fmt::format("{}{}", temporary_prefix(target_), static_cast<long>(::getpid()));
}

AtomicOutput::~AtomicOutput() {
  if (committed_) return;
  std::error_code ec;
  fs::remove(tmp_, ec);
}

void AtomicOutput::start_writeback() const {
#ifdef __linux__
  const int fd = ::open(tmp_.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return;
  (void)::sync_file_range(fd, 0, 0, SYNC_FILE_RANGE_WRITE);
  ::close(fd);
#endif
}

fs::path AtomicOutput::commit() {
  const fs::path dir = folder_of(target_);
  fsync_path(tmp_, O_RDONLY);
  // checked again just before the rename: a FIFO made meanwhile stays
  std::error_code ec;
  const fs::file_status now = fs::symlink_status(target_, ec);
  if (fs::exists(now) && !fs::is_regular_file(now)) {
    throw InputError(option_, 0, given_.string(),
                     fmt::format("became {} while it was written; not replaced",
                                 type_name(now.type())));
  }
  fs::rename(tmp_, target_);
  committed_ = true;
  remove_stale_temporaries(dir, target_);
  // make the rename and removals durable; the file is complete either way
  try {
    fsync_path(dir, O_RDONLY | O_DIRECTORY);
  } catch (const std::system_error&) {
  }
  return target_;
}

fs::path write_atomically(const std::string& option, const fs::path& path,
                          const std::function<void(const fs::path& temporary)>& fill) {
  AtomicOutput out(option, path);
  fill(out.temporary());
  return out.commit();
}

fs::path write_text_atomically(const std::string& option, const fs::path& path,
                               const std::string& text) {
  return write_atomically(option, path, [&](const fs::path& tmp) {
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) {
      throw InputError(path.string(), 0, "", fmt::format("cannot be written ({})",
                                                         std::strerror(errno)));
    }
    std::size_t done = 0;
    while (done < text.size()) {
      const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        const int err = n < 0 ? errno : ENOSPC;
        ::close(fd);
        throw InputError(path.string(), 0, "",
                         fmt::format("write failed ({})", std::strerror(err)));
      }
      done += static_cast<std::size_t>(n);
    }
    if (::close(fd) != 0) {
      throw InputError(path.string(), 0, "",
                       fmt::format("write failed ({})", std::strerror(errno)));
    }
  });
}

fs::path folder_of(const fs::path& path) {
  return path.parent_path().empty() ? fs::path(".") : path.parent_path();
}

bool names_dead_process(const std::string& digits) {
  // a pid: decimal, at most 7 digits (pid_max <= 2^22 on Linux)
  if (digits.empty() || digits.size() > 7 ||
      digits.find_first_not_of("0123456789") != std::string::npos) {
    return false;
  }
  const long pid = std::stol(digits);
  if (pid <= 0 || pid == static_cast<long>(::getpid())) return false;
  // kill(pid, 0) fails with ESRCH for no such process; EPERM means alive
  return ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

}  // namespace pb
