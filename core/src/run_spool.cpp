#include "planarbench/run_spool.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include <fmt/format.h>

#include "internal/results_layout.hpp"
#include "internal/run_spool_data.hpp"
#include "planarbench/errors.hpp"

namespace pb {

namespace internal {

namespace {

// the spool's file, unlinked at once: O_TMPFILE where the file system has it,
// else a named file removed as soon as it is open
int open_unlinked(const std::filesystem::path& dir) {
#ifdef O_TMPFILE
  const int fd = ::open(dir.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
  if (fd >= 0) return fd;
#endif
  std::string name = (dir / ".planarbench-spool.XXXXXX").string();
  const int named = ::mkostemp(name.data(), O_CLOEXEC);
  if (named >= 0) ::unlink(name.c_str());
  return named;
}

}  // namespace

SpoolFile::SpoolFile(const std::filesystem::path& dir) : fd_(open_unlinked(dir)) {
  if (fd_ < 0) {
    throw InputError("--out", 0, dir.string(),
                     fmt::format("cannot hold the run's temporary samples ({})",
                                 std::strerror(errno)));
  }
}

SpoolFile::~SpoolFile() {
  if (fd_ >= 0) ::close(fd_);
}

std::uint64_t SpoolFile::append(const EncodedChunk& bytes) {
  const std::uint64_t at = end_;
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::pwrite(fd_, bytes.data() + done, bytes.size() - done,
                               static_cast<off_t>(end_ + done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      throw std::runtime_error(fmt::format("cannot write the run's temporary samples ({})",
                                           std::strerror(n < 0 ? errno : ENOSPC)));
    }
    done += static_cast<std::size_t>(n);
  }
  end_ += bytes.size();
  return at;
}

void SpoolFile::read(std::uint64_t offset, std::size_t size, EncodedChunk& out) const {
  out.resize(size);
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::pread(fd_, out.data() + done, size - done,
                              static_cast<off_t>(offset + done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      throw std::runtime_error(fmt::format("cannot read the run's temporary samples ({})",
                                           n < 0 ? std::strerror(errno) : "end of file"));
    }
    done += static_cast<std::size_t>(n);
  }
}

DatasetSpool::DatasetSpool(SpoolFile* file, std::size_t row_bytes, std::size_t element_size)
    : file_(file), row_bytes_(row_bytes), element_size_(element_size) {
  pending_.reserve((kChunkRows + 1) * row_bytes);
}

void DatasetSpool::append(const void* row) {
  const auto* bytes = static_cast<const unsigned char*>(row);
  pending_.insert(pending_.end(), bytes, bytes + row_bytes_);
  ++rows_;
  const std::size_t chunk_bytes = kChunkRows * row_bytes_;
  if (pending_.size() <= chunk_bytes) return;
  // a row past a whole chunk: the dataset will be chunked, encode the chunk
  const EncodedChunk chunk = encode_chunk(pending_.data(), chunk_bytes, 0, chunk_bytes,
                                          element_size_, static_cast<int>(kDeflateLevel));
  chunks_.emplace_back(file_->append(chunk), static_cast<std::uint32_t>(chunk.size()));
  pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(chunk_bytes));
}

void DatasetSpool::write(hid_t d, hid_t file_type, const std::string& object) const {
  if (rows_ == 0) return;
  if (chunks_.empty()) {
    // at most kChunkRows rows: a contiguous dataset, the bytes as they are
    check(H5Dwrite(d, file_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, pending_.data()), object,
          "cannot write the dataset");
    return;
  }
  EncodedChunk chunk;
  auto put = [&](std::size_t i) {
    const hsize_t offset[2] = {static_cast<hsize_t>(i) * kChunkRows, 0};
    // filter mask 0: every filter of the pipeline was applied
    check(H5Dwrite_chunk(d, H5P_DEFAULT, 0, offset, chunk.size(), chunk.data()), object,
          "cannot write a chunk of the dataset");
  };
  for (std::size_t i = 0; i < chunks_.size(); ++i) {
    file_->read(chunks_[i].first, chunks_[i].second, chunk);
    put(i);
  }
  // the last, partial chunk: zero past the end, as encode_chunk pads it
  chunk = encode_chunk(pending_.data(), pending_.size(), 0, kChunkRows * row_bytes_, element_size_,
                       static_cast<int>(kDeflateLevel));
  put(chunks_.size());
}

RunSpoolData::RunSpoolData(const std::filesystem::path& dir)
    : file(dir), contacts(&file, sizeof(ContactRecord), sizeof(ContactRecord)) {}

}  // namespace internal

RunSpool::RunSpool(const std::filesystem::path& dir, std::vector<std::string> body_names,
                   const std::vector<int>& moving)
    : data_(std::make_unique<internal::RunSpoolData>(dir)) {
  // the table's rows are packed records: the file's compound type is the
  // record byte for byte (no padding), which results_file.cpp checks
  static_assert(sizeof(internal::ContactRecord) == 8 + 2 * internal::kNameBytes + 8 * 8);
  data_->body_names = std::move(body_names);
  for (const int i : moving) {
    internal::BodySpool b;
    b.name = data_->body_names.at(static_cast<std::size_t>(i));
    for (const auto& c : internal::kBodyColumns) {
      const std::size_t values = c.cols == 0 ? 1 : static_cast<std::size_t>(c.cols);
      b.columns.emplace_back(&data_->file, values * sizeof(double), sizeof(double));
    }
    data_->bodies.push_back(std::move(b));
  }
}

RunSpool::~RunSpool() = default;

void RunSpool::append_state(std::size_t j, double time_s, const BodyState& s, double angle_rad) {
  auto& columns = data_->bodies.at(j).columns;
  const double position[2] = {s.position_m.x(), s.position_m.y()};
  const double velocity[2] = {s.velocity_mps.x(), s.velocity_mps.y()};
  columns[0].append(&time_s);
  columns[1].append(position);
  columns[2].append(&angle_rad);
  columns[3].append(velocity);
  columns[4].append(&s.angular_velocity_radps);
}

void RunSpool::append_contact(double time_s, const ContactSample& c) {
  const internal::ContactRecord row =
      internal::contact_record(time_s, c, data_->body_names, "contacts");
  data_->contacts.append(&row);
}

std::size_t RunSpool::samples(std::size_t j) const {
  return static_cast<std::size_t>(data_->bodies.at(j).columns[0].rows());
}

std::size_t RunSpool::contact_rows() const {
  return static_cast<std::size_t>(data_->contacts.rows());
}

}  // namespace pb
