// The HDF5 results file (SPEC §5), readable with h5py alone. Written to a
// temporary name in the target directory and renamed when complete.
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>

#include "planarbench/run_result.hpp"

namespace pb {

// The results file written run by run, as the runs end (`planarbench run`).
// The constructor checks the target (output_target: exit 2 for a FIFO,
// a device, a missing folder), and makes the file's header, every case's
// group and one empty group per run of `layout` (only their engine names are
// read), in that order: the file lists its runs in that order whatever order
// they end in, and its datasets do not depend on it. write_run may be called
// from any thread, one call at a time (it serialises its callers: the HDF5
// library is not thread-safe; nothing else may call HDF5 meanwhile);
// commit() checks every run was written and renames the complete file over
// the target. Destroyed without commit, it leaves nothing behind. HDF5
// failures are std::runtime_error naming the file and the object.
class ResultsFileWriter {
 public:
  ResultsFileWriter(const std::filesystem::path& path, const ResultsFile& layout, int threads = 1);
  ~ResultsFileWriter();
  ResultsFileWriter(const ResultsFileWriter&) = delete;
  ResultsFileWriter& operator=(const ResultsFileWriter&) = delete;
  void write_run(std::size_t case_index, std::size_t run_index, const RunResult& r);
  // the same, the run taken whole from `source`, a file this writer's kind
  // wrote with that case and engine (a child process's run, run_isolation):
  // its group's datasets are copied chunk by chunk as stored (H5Ocopy; no
  // sample is held in memory) and its attributes one by one
  void copy_run(std::size_t case_index, std::size_t run_index, const std::filesystem::path& source);
  void commit();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Writes the whole file atomically. Throws InputError when the target
// directory is missing or not writable (nothing is left behind), and
// std::runtime_error on an HDF5 failure (the temporary file is removed).
// `threads` threads compress the chunked datasets (the file's largest cost);
// the datasets do not depend on it.
void write_results_file(const std::filesystem::path& path, const ResultsFile& results,
                        int threads = 1);

// Reads a results file written by write_results_file. Throws InputError naming
// the file and the missing or malformed object for a truncated or foreign file.
[[nodiscard]] ResultsFile read_results_file(const std::filesystem::path& path);

// The one run of a file that holds one (a child process's): its attributes
// (status, reason, steps, times, settings, mapping), without its samples.
[[nodiscard]] RunResult read_run_header(const std::filesystem::path& path);

}  // namespace pb
