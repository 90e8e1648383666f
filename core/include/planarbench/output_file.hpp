// The files a command writes (results, sweep, JUnit, summary, report pages):
// one way to check and replace them. Every file is written to a temporary
// beside its target, flushed to disk and renamed over the target, so a reader
// sees the old file or the complete new one, never a part (SPEC §5).
//
// Renaming is right for a regular file and wrong for anything else: renamed
// over a device node, a FIFO or a socket, the temporary silently replaces it
// with a regular file, and renamed over a symbolic link it replaces the link.
// So an existing target that is not a regular file is refused before any
// work, and a symbolic link to a regular file is followed: the file it names
// is the one replaced, the link stays.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

namespace pb {

// The file to replace for output `path`, given by command-line option or
// field `option`. Throws InputError (exit 2) naming the option and the path
// when the folder is missing, not a folder or not writable, when the path is
// a folder, or when it exists and is not a regular file (a device, FIFO,
// socket, or a symbolic link to one, or a dangling link). Creates nothing.
[[nodiscard]] std::filesystem::path output_target(const std::string& option,
                                                  const std::filesystem::path& path);

// One output being written: the temporary beside the target, named
// `.<name>.tmp.<pid>`, renamed over the target by commit(). Destroyed without
// commit (an exception, a failed run), it removes the temporary and leaves the
// target as it was.
class AtomicOutput {
 public:
  // checks `path` (output_target); creates nothing
  AtomicOutput(const std::string& option, const std::filesystem::path& path);
  ~AtomicOutput();
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;
  // the temporary to write (closed by the caller before commit)
  [[nodiscard]] const std::filesystem::path& temporary() const { return tmp_; }
  // Starts the disk writes of what the temporary holds so far, without
  // waiting for them (best effort: Linux's sync_file_range; elsewhere
  // nothing), so that commit's flush has little left to wait for.
  void start_writeback() const;
  // Flushes the temporary, renames it over the target (re-checked: a FIFO
  // made meanwhile stays) and removes temporaries of killed writers. Returns
  // the path written (the link's target for a symbolic link).
  std::filesystem::path commit();

 private:
  std::string option_;
  std::filesystem::path given_, target_, tmp_;
  bool committed_ = false;
};

// Writes `path` (checked by output_target) through a temporary in its folder:
// fill(temporary) writes the temporary, which is then flushed and renamed
// over the target. On any failure the temporary is removed, the target is
// left as it was and the exception propagates. Temporaries of earlier writers
// of the same target that were killed (their pid is gone) are removed after a
// success. Returns the path written (the link's target for a symbolic link).
std::filesystem::path write_atomically(
    const std::string& option, const std::filesystem::path& path,
    const std::function<void(const std::filesystem::path& temporary)>& fill);

// write_atomically of a text (or any bytes)
std::filesystem::path write_text_atomically(const std::string& option,
                                            const std::filesystem::path& path,
                                            const std::string& text);

// the folder a file `path` is in: its parent, or "." for a bare name
[[nodiscard]] std::filesystem::path folder_of(const std::filesystem::path& path);

// `digits` is the decimal pid of no live process on this host, other than
// this one (a killed writer's temporary or folder may go)
[[nodiscard]] bool names_dead_process(const std::string& digits);

}  // namespace pb
