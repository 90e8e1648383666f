// The inside of a RunSpool (planarbench/run_spool.hpp), for the results writer.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "hdf5_chunks.hpp"
#include "hdf5_datasets.hpp"

namespace pb::internal {

// An unlinked temporary file that encoded chunks are appended to.
class SpoolFile {
 public:
  explicit SpoolFile(const std::filesystem::path& dir);
  ~SpoolFile();
  SpoolFile(const SpoolFile&) = delete;
  SpoolFile& operator=(const SpoolFile&) = delete;
  // appends bytes; returns their offset in the file
  std::uint64_t append(const EncodedChunk& bytes);
  // reads `size` bytes at `offset` into out
  void read(std::uint64_t offset, std::size_t size, EncodedChunk& out) const;

 private:
  int fd_ = -1;
  std::uint64_t end_ = 0;
};

// The rows of one dataset: whole chunks encoded in the spool file, the rest
// (at most kChunkRows rows) raw in memory. A chunk is encoded once a row past
// it arrives, so a dataset of at most kChunkRows rows (stored contiguous, not
// chunked: hdf5_datasets.hpp) is never encoded.
class DatasetSpool {
 public:
  DatasetSpool(SpoolFile* file, std::size_t row_bytes, std::size_t element_size);
  void append(const void* row);
  [[nodiscard]] hsize_t rows() const { return rows_; }
  // Writes every row into d, created for rows() rows by dataset_properties
  // with a file type whose bytes are the rows' (checked by the caller).
  void write(hid_t d, hid_t file_type, const std::string& object) const;

 private:
  SpoolFile* file_;
  std::size_t row_bytes_;
  std::size_t element_size_;
  hsize_t rows_ = 0;
  std::vector<unsigned char> pending_;  // raw rows not yet in a chunk
  std::vector<std::pair<std::uint64_t, std::uint32_t>> chunks_;  // offset, bytes
};

struct BodySpool {
  std::string name;
  std::vector<DatasetSpool> columns;  // kBodyColumns order
};

struct RunSpoolData {
  SpoolFile file;
  std::vector<std::string> body_names;
  std::vector<BodySpool> bodies;
  DatasetSpool contacts;
  explicit RunSpoolData(const std::filesystem::path& dir);
};

}  // namespace pb::internal
