// A run's samples on disk as they are produced (issue 15: bounded memory).
//
// The runner appends each output sample of each body, and each contact row,
// to the spool instead of to vectors in RunResult. Every 4096 rows of a
// dataset (the results file's chunk) are encoded there and then, in the run's
// own thread, exactly as the results file stores them (shuffle + deflate,
// internal/hdf5_chunks.hpp), and appended to a temporary file that is
// unlinked as soon as it is made (nothing is left behind, whatever happens to
// the process). The results writer copies those chunks into the file as they
// are: a run written from a spool and the same run written from memory give
// the same datasets, and the compression happens in the workers while they
// run, not in a serial tail.
//
// Memory per run: one chunk of rows per dataset (5 datasets per moving body,
// 224 KiB per body; 480 KiB for the contacts table) plus 16 bytes per encoded
// chunk (4096 rows): about 40 KiB more per 10 million rows of a dataset.
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "planarbench/engine.hpp"

namespace pb {

namespace internal {
struct RunSpoolData;
}

class RunSpool {
 public:
  // `dir`: a writable folder (the results file's, so that the spool's disk is
  // the one the results go to); `body_names`: the case's bodies (contacts
  // name them by index); `moving`: the indices of the bodies with a
  // trajectory, in the order of RunResult::bodies. Throws InputError when the
  // folder cannot hold a temporary file.
  RunSpool(const std::filesystem::path& dir, std::vector<std::string> body_names,
           const std::vector<int>& moving);
  ~RunSpool();
  RunSpool(const RunSpool&) = delete;
  RunSpool& operator=(const RunSpool&) = delete;

  // one output sample of moving body j (index into `moving`); the angle
  // already made continuous
  void append_state(std::size_t j, double time_s, const BodyState& s, double angle_rad);
  // one row of the contacts table
  void append_contact(double time_s, const ContactSample& c);

  [[nodiscard]] std::size_t samples(std::size_t j) const;
  [[nodiscard]] std::size_t contact_rows() const;

  // for the results writer (results_file.cpp)
  [[nodiscard]] const internal::RunSpoolData& data() const { return *data_; }

 private:
  std::unique_ptr<internal::RunSpoolData> data_;
};

}  // namespace pb
