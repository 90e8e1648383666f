// Checks of a results file's datasets against its layout (SPEC §5;
// tests/python/README.md), made by the reader before and after it reads them
// (issue 24): the dtype of every dataset and table field, the rows a dataset
// claims against the bytes the file stores for it (before anything is
// allocated), the lengths of a body's datasets, and its sample times. Each
// failure is an Hdf5Error naming the object; read_results_file reports it as
// bad input (exit 2) naming the file too.
#pragma once

#include <cstddef>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "hdf5_handle.hpp"

namespace pb::internal {

struct TableLayout;  // hdf5_datasets.hpp

// Rows of a body's datasets: a case has at most 1e7 output intervals
// (duration / output_interval, the case loader's limit: kMaxOutputSamples in
// core/src/case_loader.cpp), plus the sample at t = 0.
inline constexpr hsize_t kMaxBodyRows = 10'000'001;

// At most this many bytes of data per byte a filtered (deflated) dataset
// stores: deflate's largest compression ratio (zlib's technical details:
// 258 bytes in 2 bits of a repeated match, about 1032:1). Shuffle keeps sizes.
inline constexpr double kMaxDeflateRatio = 1032.0;

// a type as numpy would name it: float64, int64, uint8, S32, variable-length
// string, compound, array of float64 [2] ...
[[nodiscard]] std::string dtype_name(hid_t type);

// dataset d holds IEEE floats of 8 bytes (H5T_IEEE_F64LE as written)
void check_float64(hid_t d, const std::string& object);
// dataset d holds integers of 8 bytes (H5T_STD_I64LE as written)
void check_int64(hid_t d, const std::string& object);
// every field of `layout` in the compound type of a table has the field's type
void check_table_fields(hid_t file_type, const TableLayout& layout, const std::string& object);

// Dataset d keeps its rows in this file (no external or virtual storage), and
// stores enough bytes for the rows it claims: all of them unfiltered, at least
// 1 / kMaxDeflateRatio of them filtered. A dataset whose chunks were never
// written claims rows it does not have (and would make the reader allocate
// them): refused before anything is allocated.
void check_rows_stored(hid_t d, const std::string& object);

// The datasets of a body group (kBodyColumns) before any is read: each is
// float64 of its shape, time has at most kMaxBodyRows rows, and every other
// has as many rows as time.
void check_body_columns(hid_t body);

// Sample times are finite and never decrease. Equal times are allowed: an
// engine whose step is coarser than the output interval repeats its time on
// the grid (core/src/runner.cpp records engine.time() at every sample).
void check_sample_times(const std::vector<double>& t, const std::string& object);

// a vector of n values, or an Hdf5Error naming the object when the memory
// cannot be had (a huge dataset that passed check_rows_stored: a deflate bomb)
template <typename T>
std::vector<T> allocate_rows(std::size_t n, const std::string& object);

// ---- implementation of the template ------------------------------------------------

[[noreturn]] void throw_cannot_allocate(std::size_t n, std::size_t bytes_per_value,
                                        const std::string& object);

template <typename T>
std::vector<T> allocate_rows(std::size_t n, const std::string& object) {
  try {
    return std::vector<T>(n);
  } catch (const std::bad_alloc&) {
    throw_cannot_allocate(n, sizeof(T), object);
  } catch (const std::length_error&) {
    throw_cannot_allocate(n, sizeof(T), object);
  }
}

}  // namespace pb::internal
