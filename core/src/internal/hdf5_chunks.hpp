// Chunked datasets written chunk by chunk, the filters applied by us.
//
// HDF5 applies a dataset's filters (here shuffle, then deflate) inside
// H5Dwrite, and a thread-safe build of the library holds one global lock: the
// compression of a results file, most of its cost, would run on one core
// whatever --jobs says. So the chunks are encoded here, on several threads,
// exactly as the library's filters encode them, and handed to H5Dwrite_chunk
// (HDF5 >= 1.10.3), which only places the bytes in the file:
//   - shuffle (H5Zshuffle.c): byte j of element i goes to j * n + i, where n
//     is the number of elements of the chunk and the element is the dataset's
//     type (8 bytes for doubles, the whole row of a compound);
//   - deflate (H5Zdeflate.c): zlib's compress2 at the dataset's level, a zlib
//     stream (RFC 1950).
// Any HDF5 reader (h5py, h5dump) decodes them with the dataset's own filter
// pipeline; the values read back are the values given, which the tests check.
// Edge chunks are whole chunks: the rows past the end are zero (the default
// fill value), as the library itself stores them.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "hdf5_handle.hpp"

namespace pb::internal {

// one encoded chunk: shuffled, then a zlib stream
using EncodedChunk = std::vector<unsigned char>;

// shuffles `bytes` bytes of elements `element_size` bytes long into out (the
// same size); a trailing partial element is copied as is, as H5Zshuffle.c does
void shuffle_bytes(const unsigned char* in, std::size_t bytes, std::size_t element_size,
                   unsigned char* out);

// Encodes one chunk: bytes [begin, begin + chunk_bytes) of `data`
// (`data_bytes` bytes in the file's byte layout, zero past its end), shuffled
// by elements of `element_size` bytes, then deflated at `level`. Throws
// std::runtime_error when zlib fails.
[[nodiscard]] EncodedChunk encode_chunk(const unsigned char* data, std::size_t data_bytes,
                                        std::size_t begin, std::size_t chunk_bytes,
                                        std::size_t element_size, int level);

// Writes chunked datasets while their chunks are encoded on `threads` worker
// threads: the caller goes on creating groups, attributes and datasets (HDF5
// calls, one thread) while the workers compress (no HDF5 calls), and the
// chunks of each dataset are written, in submission order, as soon as they
// are ready. With threads <= 1 everything happens in the caller's thread, at
// submit. The bytes written do not depend on the thread count.
class ChunkWriter {
 public:
  explicit ChunkWriter(int threads);
  ~ChunkWriter();
  ChunkWriter(const ChunkWriter&) = delete;
  ChunkWriter& operator=(const ChunkWriter&) = delete;

  // Queues the chunked dataset `dataset` (a handle of its own, closed once
  // written): `bytes` are its rows in the file's byte layout, `row_bytes` each,
  // `rows_per_chunk` to a chunk; elements (the shuffle's unit) of
  // `element_size` bytes; deflate `level`. Writes the datasets whose chunks
  // are ready. Throws Hdf5Error naming the object on failure.
  void submit(Hid dataset, std::string object, std::vector<unsigned char> bytes,
              hsize_t rows_per_chunk, std::size_t row_bytes, std::size_t element_size, int level);
  // Writes everything queued; rethrows the first failure.
  void finish();

 private:
  struct Entry;
  void work();
  void write_ready(bool wait);
  void write_entry(Entry& e);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable jobs_ready_;
  std::condition_variable chunk_done_;
  std::deque<std::unique_ptr<Entry>> entries_;  // submission order, not yet written
  std::deque<std::pair<Entry*, std::size_t>> jobs_;  // (entry, chunk) to encode
  bool stopping_ = false;
};

}  // namespace pb::internal
