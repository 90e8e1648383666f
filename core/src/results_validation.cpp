// Checks of a results file's datasets against its layout (issue 24):
// internal/results_validation.hpp says what each one checks and why.
#include "internal/results_validation.hpp"

#include <cmath>
#include <cstdint>
#include <iterator>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "internal/hdf5_datasets.hpp"
#include "internal/results_layout.hpp"

namespace pb::internal {

namespace {

// what the layout gives for a field kind, as dtype_name names it
const char* kind_name(FieldKind kind) {
  switch (kind) {
    case FieldKind::f8:
      return "float64";
    case FieldKind::name:
      return "S32 (a NUL-padded name of 32 bytes)";
    case FieldKind::f8x2:
      return "array of float64 [2]";
  }
  return "?";
}

bool is_float64(hid_t t) {
  return H5Tget_class(t) == H5T_FLOAT && H5Tget_size(t) == 8;
}

bool has_kind(hid_t t, FieldKind kind) {
  switch (kind) {
    case FieldKind::f8:
      return is_float64(t);
    case FieldKind::name:
      return H5Tget_class(t) == H5T_STRING && H5Tis_variable_str(t) == 0;
    case FieldKind::f8x2: {
      if (H5Tget_class(t) != H5T_ARRAY || H5Tget_array_ndims(t) != 1) return false;
      hsize_t n = 0;
      if (H5Tget_array_dims2(t, &n) < 0 || n != 2) return false;
      const hid_t super = H5Tget_super(t);
      if (super < 0) return false;
      const bool ok = is_float64(super);
      H5Tclose(super);
      return ok;
    }
  }
  return false;
}

Hid type_of(hid_t d, const std::string& object) {
  return owned_type(H5Dget_type(d), object, "cannot read the dataset's type");
}

// the dimensions of dataset d (rank 0: a scalar)
std::vector<hsize_t> dims_of(hid_t d, const std::string& object) {
  Hid space = owned_space(H5Dget_space(d), object, "cannot read the dataset's space");
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 0) check(-1, object, "cannot read the dataset's shape");
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank), 0);
  if (rank > 0 && H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr) < 0) {
    check(-1, object, "cannot read the dataset's shape");
  }
  return dims;
}

std::string shape_text(const std::vector<hsize_t>& dims) {
  std::string s = "[";
  for (std::size_t i = 0; i < dims.size(); ++i) s += (i ? ", " : "") + std::to_string(dims[i]);
  return s + "]";
}

}  // namespace

std::string dtype_name(hid_t type) {
  const std::size_t size = H5Tget_size(type);
  switch (H5Tget_class(type)) {
    case H5T_INTEGER:
      return fmt::format("{}int{}", H5Tget_sign(type) == H5T_SGN_NONE ? "u" : "", 8 * size);
    case H5T_FLOAT:
      return fmt::format("float{}", 8 * size);
    case H5T_STRING:
      return H5Tis_variable_str(type) > 0 ? "variable-length string" : fmt::format("S{}", size);
    case H5T_COMPOUND:
      return "compound";
    case H5T_ARRAY: {
      const int rank = H5Tget_array_ndims(type);
      std::vector<hsize_t> dims(rank > 0 ? static_cast<std::size_t>(rank) : 0, 0);
      if (rank > 0) H5Tget_array_dims2(type, dims.data());
      const hid_t super = H5Tget_super(type);
      const std::string inner = super >= 0 ? dtype_name(super) : "?";
      if (super >= 0) H5Tclose(super);
      return "array of " + inner + " " + shape_text(dims);
    }
    case H5T_ENUM:
      return "enum";
    case H5T_BITFIELD:
      return "bitfield";
    case H5T_OPAQUE:
      return "opaque";
    case H5T_REFERENCE:
      return "reference";
    case H5T_VLEN:
      return "variable-length sequence";
    default:
      break;
  }
  hdf5_last_error();
  return "an unknown type";
}

void check_float64(hid_t d, const std::string& object) {
  Hid t = type_of(d, object);
  if (is_float64(t.get())) return;
  throw Hdf5Error(object, fmt::format("has dtype {}; the results layout (SPEC §5) stores float64 "
                                      "(IEEE doubles) here",
                                      dtype_name(t.get())));
}

void check_int64(hid_t d, const std::string& object) {
  Hid t = type_of(d, object);
  if (H5Tget_class(t.get()) == H5T_INTEGER && H5Tget_size(t.get()) == 8) return;
  throw Hdf5Error(object, fmt::format("has dtype {}; the results layout stores int64 here",
                                      dtype_name(t.get())));
}

void check_table_fields(hid_t file_type, const TableLayout& layout, const std::string& object) {
  for (const auto& f : layout.fields) {
    const int index = H5Tget_member_index(file_type, f.name);
    if (index < 0) {
      hdf5_last_error();
      if (f.optional) continue;  // a file written before the column: NaN (read_table)
      throw Hdf5Error(object, std::string("field '") + f.name + "' is missing");
    }
    Hid member = owned_type(H5Tget_member_type(file_type, static_cast<unsigned>(index)), object,
                            std::string("cannot read the type of field ") + f.name);
    if (has_kind(member.get(), f.kind)) continue;
    throw Hdf5Error(object, fmt::format("field '{}' has dtype {}; the results layout (SPEC §5) "
                                        "gives {}",
                                        f.name, dtype_name(member.get()), kind_name(f.kind)));
  }
}

void check_rows_stored(hid_t d, const std::string& object) {
  Hid dcpl = owned_plist(H5Dget_create_plist(d), object, "cannot read the dataset's properties");
  const H5D_layout_t layout = H5Pget_layout(dcpl.get());
  if (layout == H5D_VIRTUAL || H5Pget_external_count(dcpl.get()) > 0) {
    throw Hdf5Error(object,
                    "keeps its rows outside this file (external or virtual storage); a "
                    "results file holds its own data");
  }
  const std::vector<hsize_t> dims = dims_of(d, object);
  Hid type = type_of(d, object);
  // in double: a hostile shape's product may not fit in 64 bits
  double claimed = static_cast<double>(H5Tget_size(type.get()));
  for (const hsize_t n : dims) claimed *= static_cast<double>(n);
  if (claimed == 0.0) return;
  const auto stored = static_cast<double>(H5Dget_storage_size(d));
  hdf5_last_error();  // a size of 0 may leave an error behind
  const bool filtered = H5Pget_nfilters(dcpl.get()) > 0;
  const double most = filtered ? stored * kMaxDeflateRatio : stored;
  if (claimed <= most) return;
  const std::string rows = dims.empty() ? "1 value" : fmt::format("{} rows", dims.front());
  throw Hdf5Error(
      object,
      fmt::format("claims {} ({:.0f} bytes) but the file stores {:.0f} bytes of them{}; every row "
                  "of a results dataset is written{}",
                  rows, claimed, stored, filtered ? " (compressed)" : "",
                  filtered ? fmt::format(" (and deflate packs at most {:.0f} bytes into one)",
                                         kMaxDeflateRatio)
                           : ""));
}

void check_body_columns(hid_t body) {
  const std::string group = object_path(body);
  hsize_t time_rows = 0;
  for (std::size_t k = 0; k < std::size(kBodyColumns); ++k) {
    const BodyColumn& c = kBodyColumns[k];
    Hid d = open_dataset(body, c.name);
    const std::string object = group + "/" + c.name;
    check_float64(d.get(), object);
    const std::vector<hsize_t> dims = dims_of(d.get(), object);
    const std::size_t rank = c.cols == 0 ? 1 : 2;
    if (dims.size() != rank || (c.cols != 0 && dims[1] != c.cols)) {
      throw Hdf5Error(
          object, fmt::format("has shape {}; the results layout gives {}", shape_text(dims),
                              c.cols == 0 ? std::string("[n]") : fmt::format("[n, {}]", c.cols)));
    }
    if (k == 0) {
      time_rows = dims[0];
      if (time_rows > kMaxBodyRows) {
        throw Hdf5Error(object,
                        fmt::format("claims {} rows; a body has at most {} samples (a case's "
                                    "duration / output_interval is at most 1e7, plus the sample "
                                    "at t = 0)",
                                    time_rows, kMaxBodyRows));
      }
    } else if (dims[0] != time_rows) {
      throw Hdf5Error(object, fmt::format("has {} rows but time has {}; a body's datasets have one "
                                          "row per sample time",
                                          dims[0], time_rows));
    }
  }
}

void check_sample_times(const std::vector<double>& t, const std::string& object) {
  static constexpr const char* kRule =
      "sample times are finite and never decrease (an engine whose step is coarser than the "
      "output interval repeats one, none goes back)";
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!std::isfinite(t[i])) {
      throw Hdf5Error(object, fmt::format("row {} is {}; {}", i, t[i], kRule));
    }
    if (i > 0 && t[i] < t[i - 1]) {
      throw Hdf5Error(object, fmt::format("row {} ({:.9g} s) is earlier than row {} ({:.9g} s); {}",
                                          i, t[i], i - 1, t[i - 1], kRule));
    }
  }
}

void throw_cannot_allocate(std::size_t n, std::size_t bytes_per_value, const std::string& object) {
  throw Hdf5Error(object,
                  fmt::format("claims {} values ({:.0f} bytes), more than this machine can "
                              "allocate; a results file this large cannot be read here",
                              n, static_cast<double>(n) * static_cast<double>(bytes_per_value)));
}

}  // namespace pb::internal
