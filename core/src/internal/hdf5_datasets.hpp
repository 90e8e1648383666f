// Datasets of the results file: arrays of doubles ([n] or [n, cols]) and
// compound tables (one struct per row). Every dataset carries a `unit`
// attribute; tables carry `unit` and `fields` string arrays, one entry per
// field in field order. Small datasets are contiguous; above kChunkRows rows
// they are chunked, shuffled and deflated. No creation times are stored, so
// equal inputs give equal bytes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <cstring>
#include <string>
#include <vector>

#include "hdf5_attributes.hpp"
#include "hdf5_chunks.hpp"
#include "hdf5_handle.hpp"
#include "results_validation.hpp"

namespace pb::internal {

// rows per chunk, and the size above which datasets are compressed
inline constexpr hsize_t kChunkRows = 4096;
// zlib level 1, measured on the full matrix (`run --case all --engine all
// --jobs 1`, perf, one run each, this 2-core machine): zlib's samples fell by
// 36 % from level 4 (21.8 % -> 16.0 % of all, 13 % fewer samples in total)
// for a file 1.9 % larger (27.28 -> 27.78 MB): after shuffle the smooth
// trajectories compress nearly as well at the fastest level
inline constexpr unsigned kDeflateLevel = 1;
// bytes of a body name in a table (NUL-padded, h5py dtype S32)
inline constexpr std::size_t kNameBytes = 32;

// creation properties of a dataset of shape dims[0..rank): no times; above
// kChunkRows rows, chunks of kChunkRows rows, shuffled then deflated
inline Hid dataset_properties(int rank, const hsize_t* dims, const std::string& object) {
  Hid dcpl = owned_plist(H5Pcreate(H5P_DATASET_CREATE), object, "cannot create properties");
  check(H5Pset_obj_track_times(dcpl.get(), 0), object, "cannot switch off time tracking");
  if (dims[0] > kChunkRows) {
    hsize_t chunk[2] = {kChunkRows, rank > 1 ? dims[1] : 1};
    check(H5Pset_chunk(dcpl.get(), rank, chunk), object, "cannot set the chunk size");
    check(H5Pset_shuffle(dcpl.get()), object, "cannot set the shuffle filter");
    check(H5Pset_deflate(dcpl.get(), kDeflateLevel), object, "cannot set the deflate filter");
  }
  return dcpl;
}

// true when values of type t are plain bytes: no variable-length strings or
// sequences anywhere in it (those are pointers in memory)
inline bool fixed_size_type(hid_t t) {
  switch (H5Tget_class(t)) {
    case H5T_INTEGER:
    case H5T_FLOAT:
      return true;
    case H5T_STRING:
      return H5Tis_variable_str(t) == 0;
    case H5T_ARRAY: {
      const hid_t super = H5Tget_super(t);
      const bool fixed = super >= 0 && fixed_size_type(super);
      if (super >= 0) H5Tclose(super);
      return fixed;
    }
    case H5T_COMPOUND: {
      const int n = H5Tget_nmembers(t);
      if (n < 0) return false;
      for (int i = 0; i < n; ++i) {
        const hid_t member = H5Tget_member_type(t, static_cast<unsigned>(i));
        const bool fixed = member >= 0 && fixed_size_type(member);
        if (member >= 0) H5Tclose(member);
        if (!fixed) return false;
      }
      return true;
    }
    default:
      return false;
  }
}

// Hands the chunked dataset d, filled from buf, to `writer` (or writes it
// now when writer is null), when buf is already in the file's byte layout
// (H5Tequal: native little-endian doubles, rows without padding) and holds no
// pointers (no variable-length data); false when it is not, and the caller
// lets the library convert and filter.
inline bool write_encoded_chunks(const Hid& d, hid_t file_type, hid_t mem_type, int rank,
                                 const hsize_t* dims, const void* buf, ChunkWriter* writer,
                                 const std::string& object) {
  const htri_t same = H5Tequal(file_type, mem_type);
  if (same < 0) check(-1, object, "cannot compare the types");
  if (same == 0 || !fixed_size_type(file_type)) return false;
  const std::size_t type_size = H5Tget_size(file_type);
  const std::size_t row_bytes = type_size * (rank > 1 ? dims[1] : 1);
  const auto* first = static_cast<const unsigned char*>(buf);
  std::vector<unsigned char> bytes(first, first + row_bytes * dims[0]);
  // a handle of the writer's own: the caller may close d meanwhile
  check(H5Iinc_ref(d.get()), object, "cannot share the dataset handle");
  Hid own(d.get(), H5Dclose);
  if (writer != nullptr) {
    writer->submit(std::move(own), object, std::move(bytes), kChunkRows, row_bytes, type_size,
                   static_cast<int>(kDeflateLevel));
  } else {
    ChunkWriter now(1);
    now.submit(std::move(own), object, std::move(bytes), kChunkRows, row_bytes, type_size,
               static_cast<int>(kDeflateLevel));
    now.finish();
  }
  return true;
}

// creates dataset `name` in loc and writes buf (nothing to write for 0 rows);
// a chunked dataset goes through `writer` when given (compressed on its
// threads, written later: writer->finish() before the file is closed)
// creates dataset `name` in loc of shape dims[0..rank) (nothing written)
inline Hid create_dataset(hid_t loc, const char* name, hid_t file_type, int rank,
                          const hsize_t* dims) {
  const std::string object = object_path(loc) + "/" + name;
  Hid space = owned_space(H5Screate_simple(rank, dims, nullptr), object, "cannot create a space");
  Hid dcpl = dataset_properties(rank, dims, object);
  return owned_dataset(
      H5Dcreate2(loc, name, file_type, space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT), object,
      "cannot create the dataset");
}

inline Hid create_and_write(hid_t loc, const char* name, hid_t file_type, hid_t mem_type, int rank,
                            const hsize_t* dims, const void* buf, ChunkWriter* writer) {
  const std::string object = object_path(loc) + "/" + name;
  Hid d = create_dataset(loc, name, file_type, rank, dims);
  if (dims[0] > kChunkRows &&
      write_encoded_chunks(d, file_type, mem_type, rank, dims, buf, writer, object)) {
    return d;
  }
  if (dims[0] > 0) {
    check(H5Dwrite(d.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf), object,
          "cannot write the dataset");
  }
  return d;
}

// [rows] (cols == 0) or [rows, cols] doubles, row-major, with its unit
inline void write_double_dataset(hid_t loc, const char* name, const std::vector<double>& values,
                                 hsize_t cols, const std::string& unit,
                                 ChunkWriter* writer = nullptr) {
  const hsize_t rows = cols == 0 ? values.size() : values.size() / cols;
  const hsize_t dims[2] = {rows, cols};
  Hid d = create_and_write(loc, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, cols == 0 ? 1 : 2, dims,
                           values.data(), writer);
  write_string_attribute(d.get(), "unit", unit);
  d.close(object_path(loc) + "/" + name);
}

// opens dataset `name` of loc; Hdf5Error naming it when it is missing
inline Hid open_dataset(hid_t loc, const char* name) {
  const std::string parent = object_path(loc);
  const std::string object = (parent == "/" ? "" : parent) + "/" + name;
  const htri_t exists = H5Lexists(loc, name, H5P_DEFAULT);
  if (exists <= 0) {
    hdf5_last_error();
    throw Hdf5Error(object, "dataset is missing");
  }
  return owned_dataset(H5Dopen2(loc, name, H5P_DEFAULT), object, "cannot open the dataset");
}

// reads [n] (cols == 0) or [n, cols] doubles, row-major; the dataset must
// be float64 and store its rows (results_validation.hpp) before any is allocated
inline std::vector<double> read_double_dataset(hid_t loc, const char* name, hsize_t cols) {
  Hid d = open_dataset(loc, name);
  const std::string object = object_path(d.get());
  check_float64(d.get(), object);
  Hid space = owned_space(H5Dget_space(d.get()), object, "cannot read the dataset's space");
  const int rank = H5Sget_simple_extent_ndims(space.get());
  hsize_t dims[2] = {0, 0};
  const int want = cols == 0 ? 1 : 2;
  if (rank != want || H5Sget_simple_extent_dims(space.get(), dims, nullptr) < 0 ||
      (cols != 0 && dims[1] != cols)) {
    hdf5_last_error();
    throw Hdf5Error(object, cols == 0 ? "expected shape [n]"
                                      : "expected shape [n, " + std::to_string(cols) + "]");
  }
  check_rows_stored(d.get(), object);
  auto out = allocate_rows<double>(dims[0] * (cols == 0 ? 1 : cols), object);
  if (!out.empty()) {
    check(H5Dread(d.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), object,
          "cannot read the dataset");
  }
  return out;
}

// ---- compound tables --------------------------------------------------------

enum class FieldKind { f8, name, f8x2 };

// one field of a table row: its name, kind, offset in the C++ record, unit
struct TableField {
  const char* name;
  FieldKind kind;
  std::size_t offset;  // bytes, offsetof(Record, member)
  const char* unit;    // "1" dimensionless, "" for names
  // a column added after files were written (f8 only): a file without it is
  // read with NaN there ("not recorded", never 0)
  bool optional = false;
};

struct TableLayout {
  std::size_t record_size;  // bytes, sizeof(Record)
  std::vector<TableField> fields;
};

// the type of one field, in memory (native doubles) or in the file (little-endian)
inline Hid field_type(FieldKind kind, bool in_file, const std::string& object) {
  const hid_t f8 = in_file ? H5T_IEEE_F64LE : H5T_NATIVE_DOUBLE;
  switch (kind) {
    case FieldKind::f8:
      return owned_type(H5Tcopy(f8), object, "cannot copy a float type");
    case FieldKind::name: {
      Hid t = owned_type(H5Tcopy(H5T_C_S1), object, "cannot copy the string type");
      check(H5Tset_size(t.get(), kNameBytes), object, "cannot size the name type");
      check(H5Tset_strpad(t.get(), H5T_STR_NULLPAD), object, "cannot set padding");
      check(H5Tset_cset(t.get(), H5T_CSET_UTF8), object, "cannot set UTF-8");
      return t;
    }
    case FieldKind::f8x2: {
      const hsize_t two = 2;
      return owned_type(H5Tarray_create2(f8, 1, &two), object, "cannot create an array type");
    }
  }
  throw Hdf5Error(object, "unknown field kind");
}

// the row type: in memory at the record's offsets, in the file packed
inline Hid table_type(const TableLayout& layout, bool in_file, const std::string& object) {
  std::vector<Hid> types;
  std::size_t packed = 0;
  for (const auto& f : layout.fields) {
    types.push_back(field_type(f.kind, in_file, object));
    packed += H5Tget_size(types.back().get());
  }
  Hid t = owned_type(H5Tcreate(H5T_COMPOUND, in_file ? packed : layout.record_size), object,
                     "cannot create the row type");
  std::size_t offset = 0;
  for (std::size_t i = 0; i < layout.fields.size(); ++i) {
    const auto& f = layout.fields[i];
    check(H5Tinsert(t.get(), f.name, in_file ? offset : f.offset, types[i].get()), object,
          std::string("cannot add field ") + f.name);
    offset += H5Tget_size(types[i].get());
  }
  return t;
}

// a table's `unit` and `fields` attributes, one entry per field
inline void write_table_attributes(const Hid& d, const TableLayout& layout) {
  std::vector<std::string> units, fields;
  for (const auto& f : layout.fields) {
    units.emplace_back(f.unit);
    fields.emplace_back(f.name);
  }
  write_string_array_attribute(d.get(), "unit", units);
  write_string_array_attribute(d.get(), "fields", fields);
}

// writes rows (an array of n records laid out as `layout`) with unit and fields
inline void write_table(hid_t loc, const char* name, const TableLayout& layout, const void* rows,
                        hsize_t n, ChunkWriter* writer = nullptr) {
  const std::string object = object_path(loc) + "/" + name;
  Hid file_type = table_type(layout, true, object);
  Hid mem_type = table_type(layout, false, object);
  Hid d = create_and_write(loc, name, file_type.get(), mem_type.get(), 1, &n, rows, writer);
  write_table_attributes(d, layout);
  d.close(object);
}

// reads a table into records laid out as `layout`; every field must be
// present with its type, and the rows stored, before any is allocated
template <typename Record>
std::vector<Record> read_table(hid_t loc, const char* name, const TableLayout& layout) {
  Hid d = open_dataset(loc, name);
  const std::string object = object_path(d.get());
  Hid file_type = owned_type(H5Dget_type(d.get()), object, "cannot read the dataset's type");
  if (H5Tget_class(file_type.get()) != H5T_COMPOUND) {
    throw Hdf5Error(object, "is not a table (compound dataset)");
  }
  check_table_fields(file_type.get(), layout, object);
  Hid space = owned_space(H5Dget_space(d.get()), object, "cannot read the dataset's space");
  hsize_t n = 0;
  if (H5Sget_simple_extent_ndims(space.get()) != 1 ||
      H5Sget_simple_extent_dims(space.get(), &n, nullptr) < 0) {
    hdf5_last_error();
    throw Hdf5Error(object, "expected shape [n]");
  }
  check_rows_stored(d.get(), object);
  auto out = allocate_rows<Record>(n, object);
  // the columns this file has; an optional one it lacks reads as NaN
  TableLayout present{layout.record_size, {}};
  for (const auto& f : layout.fields) {
    if (H5Tget_member_index(file_type.get(), f.name) >= 0) {
      present.fields.push_back(f);
      continue;
    }
    hdf5_last_error();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (Record& row : out) std::memcpy(reinterpret_cast<char*>(&row) + f.offset, &nan, sizeof nan);
  }
  if (n > 0) {
    Hid mem_type = table_type(present, false, object);
    check(H5Dread(d.get(), mem_type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), object,
          "cannot read the table");
  }
  return out;
}

// ---- columns of strings and integers (the campaign table) ---------------------

// the length of a one-dimensional dataset
inline hsize_t dataset_length(hid_t d, const std::string& object) {
  Hid space = owned_space(H5Dget_space(d), object, "cannot read the dataset's space");
  hsize_t n = 0;
  if (H5Sget_simple_extent_ndims(space.get()) != 1 ||
      H5Sget_simple_extent_dims(space.get(), &n, nullptr) < 0) {
    hdf5_last_error();
    throw Hdf5Error(object, "expected shape [n]");
  }
  return n;
}

// [n] variable-length UTF-8 strings (h5py reads them as bytes; .asstr() gives str)
inline void write_string_dataset(hid_t loc, const char* name,
                                 const std::vector<std::string>& values, const std::string& unit) {
  const std::string object = object_path(loc) + "/" + name;
  Hid type = vlen_utf8_type(object);
  std::vector<const char*> ptrs;
  ptrs.reserve(values.size());
  for (const auto& v : values) ptrs.push_back(v.c_str());
  const hsize_t n = values.size();
  Hid d = create_and_write(loc, name, type.get(), type.get(), 1, &n, ptrs.data(), nullptr);
  write_string_attribute(d.get(), "unit", unit);
  d.close(object);
}

inline void write_int64_dataset(hid_t loc, const char* name,
                                const std::vector<std::int64_t>& values, const std::string& unit) {
  const std::string object = object_path(loc) + "/" + name;
  const hsize_t n = values.size();
  Hid d = create_and_write(loc, name, H5T_STD_I64LE, H5T_NATIVE_INT64, 1, &n, values.data(),
                           nullptr);
  write_string_attribute(d.get(), "unit", unit);
  d.close(object);
}

inline std::vector<std::string> read_string_dataset(hid_t loc, const char* name) {
  Hid d = open_dataset(loc, name);
  const std::string object = object_path(d.get());
  Hid file_type = owned_type(H5Dget_type(d.get()), object, "cannot read the type");
  if (H5Tget_class(file_type.get()) != H5T_STRING || H5Tis_variable_str(file_type.get()) <= 0) {
    throw Hdf5Error(object, "is not a variable-length string dataset");
  }
  const hsize_t n = dataset_length(d.get(), object);
  check_rows_stored(d.get(), object);
  auto ptrs = allocate_rows<char*>(n, object);
  std::vector<std::string> out;
  if (n == 0) return out;
  Hid mem = vlen_utf8_type(object);
  check(H5Dread(d.get(), mem.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, ptrs.data()), object,
        "cannot read the dataset");
  out.reserve(n);
  // HDF5 allocated each string; we free them
  for (char* p : ptrs) {
    out.emplace_back(p != nullptr ? p : "");
    if (p != nullptr) H5free_memory(p);
  }
  return out;
}

inline std::vector<std::int64_t> read_int64_dataset(hid_t loc, const char* name) {
  Hid d = open_dataset(loc, name);
  const std::string object = object_path(d.get());
  check_int64(d.get(), object);
  const hsize_t n = dataset_length(d.get(), object);
  check_rows_stored(d.get(), object);
  auto out = allocate_rows<std::int64_t>(n, object);
  if (!out.empty()) {
    check(H5Dread(d.get(), H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), object,
          "cannot read the dataset");
  }
  return out;
}

}  // namespace pb::internal
