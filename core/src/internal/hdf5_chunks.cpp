#include "hdf5_chunks.hpp"

#include <zlib.h>

#include <algorithm>
#include <atomic>
#include <cstring>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

namespace pb::internal {

namespace {

// element i's byte j to out[j * n + i], reading the input once, in order
template <std::size_t Size>
void shuffle_fixed(const unsigned char* in, std::size_t n, unsigned char* out) {
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned char* e = in + i * Size;
    for (std::size_t j = 0; j < Size; ++j) out[j * n + i] = e[j];
  }
}

}  // namespace

void shuffle_bytes(const unsigned char* in, std::size_t bytes, std::size_t element_size,
                   unsigned char* out) {
  const std::size_t n = element_size == 0 ? 0 : bytes / element_size;
  if (element_size <= 1 || n <= 1) {
    std::memcpy(out, in, bytes);
    return;
  }
  if (element_size == 8) {
    shuffle_fixed<8>(in, n, out);  // doubles: the common case, unrolled
  } else {
    for (std::size_t j = 0; j < element_size; ++j) {
      unsigned char* dst = out + j * n;
      const unsigned char* src = in + j;
      for (std::size_t i = 0; i < n; ++i) dst[i] = src[i * element_size];
    }
  }
  const std::size_t tail = bytes - n * element_size;
  if (tail != 0) std::memcpy(out + n * element_size, in + n * element_size, tail);
}

EncodedChunk encode_chunk(const unsigned char* data, std::size_t data_bytes, std::size_t begin,
                          std::size_t chunk_bytes, std::size_t element_size, int level) {
  // the chunk's raw bytes, zero past the end of the data (a copy only for
  // the last chunk); buffers reused by the thread from chunk to chunk
  thread_local std::vector<unsigned char> raw, shuffled;
  const unsigned char* chunk = data + begin;
  if (data_bytes - begin < chunk_bytes) {
    raw.assign(chunk_bytes, 0);
    std::memcpy(raw.data(), chunk, data_bytes - begin);
    chunk = raw.data();
  }
  shuffled.resize(chunk_bytes);
  shuffle_bytes(chunk, chunk_bytes, element_size, shuffled.data());
  EncodedChunk out(compressBound(static_cast<uLong>(chunk_bytes)));
  uLongf size = static_cast<uLongf>(out.size());
  const int rc = compress2(out.data(), &size, shuffled.data(), static_cast<uLong>(chunk_bytes), level);
  if (rc != Z_OK) throw std::runtime_error("zlib compress2 failed (code " + std::to_string(rc) + ")");
  out.resize(size);
  return out;
}

// ---- ChunkWriter --------------------------------------------------------------

struct ChunkWriter::Entry {
  Hid dataset;
  std::string object;
  std::vector<unsigned char> bytes;
  hsize_t rows_per_chunk = 0;
  std::size_t chunk_bytes = 0;
  std::size_t element_size = 0;
  int level = 0;
  std::vector<EncodedChunk> chunks;
  std::size_t remaining = 0;  // chunks not encoded yet (guarded by mutex_)
  std::exception_ptr error;   // the first encoding failure (guarded by mutex_)
};

ChunkWriter::ChunkWriter(int threads) {
  for (int i = 0; threads > 1 && i < threads; ++i) workers_.emplace_back([this] { work(); });
}

ChunkWriter::~ChunkWriter() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  jobs_ready_.notify_all();
  for (auto& t : workers_) t.join();
}

void ChunkWriter::work() {
  for (;;) {
    std::pair<Entry*, std::size_t> job;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      jobs_ready_.wait(lock, [&] { return stopping_ || !jobs_.empty(); });
      if (stopping_) return;  // what is left is not going to be written
      job = jobs_.front();
      jobs_.pop_front();
    }
    Entry& e = *job.first;
    EncodedChunk chunk;
    std::exception_ptr error;
    try {
      chunk = encode_chunk(e.bytes.data(), e.bytes.size(), job.second * e.chunk_bytes,
                           e.chunk_bytes, e.element_size, e.level);
    } catch (...) {
      error = std::current_exception();
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      e.chunks[job.second] = std::move(chunk);
      if (error && !e.error) e.error = error;
      --e.remaining;
    }
    chunk_done_.notify_all();
  }
}

void ChunkWriter::submit(Hid dataset, std::string object, std::vector<unsigned char> bytes,
                         hsize_t rows_per_chunk, std::size_t row_bytes, std::size_t element_size,
                         int level) {
  const std::size_t chunk_bytes = static_cast<std::size_t>(rows_per_chunk) * row_bytes;
  if (chunk_bytes == 0) throw Hdf5Error(object, "chunk size is 0");
  auto e = std::make_unique<Entry>();
  e->dataset = std::move(dataset);
  e->object = std::move(object);
  e->bytes = std::move(bytes);
  e->rows_per_chunk = rows_per_chunk;
  e->chunk_bytes = chunk_bytes;
  e->element_size = element_size;
  e->level = level;
  const std::size_t n = (e->bytes.size() + chunk_bytes - 1) / chunk_bytes;
  e->chunks.resize(n);
  if (workers_.empty()) {
    for (std::size_t i = 0; i < n; ++i) {
      try {
        e->chunks[i] = encode_chunk(e->bytes.data(), e->bytes.size(), i * chunk_bytes, chunk_bytes,
                                    element_size, level);
      } catch (const std::exception& x) {
        throw Hdf5Error(e->object, std::string("cannot compress the dataset: ") + x.what());
      }
    }
    write_entry(*e);
    return;
  }
  Entry* raw = e.get();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    e->remaining = n;
    entries_.push_back(std::move(e));
    for (std::size_t i = 0; i < n; ++i) jobs_.emplace_back(raw, i);
  }
  jobs_ready_.notify_all();
  write_ready(false);
}

void ChunkWriter::finish() { write_ready(true); }

void ChunkWriter::write_ready(bool wait) {
  for (;;) {
    std::unique_ptr<Entry> e;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      if (entries_.empty()) return;
      Entry* front = entries_.front().get();
      if (front->remaining > 0) {
        if (!wait) return;
        chunk_done_.wait(lock, [&] { return front->remaining == 0; });
      }
      e = std::move(entries_.front());
      entries_.pop_front();
    }
    write_entry(*e);
  }
}

void ChunkWriter::write_entry(Entry& e) {
  if (e.error) {
    try {
      std::rethrow_exception(e.error);
    } catch (const std::exception& x) {
      throw Hdf5Error(e.object, std::string("cannot compress the dataset: ") + x.what());
    }
  }
  for (std::size_t i = 0; i < e.chunks.size(); ++i) {
    // chunk i starts at row i * rows_per_chunk (and column 0)
    const hsize_t offset[2] = {static_cast<hsize_t>(i) * e.rows_per_chunk, 0};
    // filter mask 0: every filter of the pipeline was applied
    check(H5Dwrite_chunk(e.dataset.get(), H5P_DEFAULT, 0, offset, e.chunks[i].size(),
                         e.chunks[i].data()),
          e.object, "cannot write a chunk of the dataset");
  }
  e.dataset.close(e.object);
}

}  // namespace pb::internal
