// Scalar and one-dimensional attributes of the results file. Strings are
// written as variable-length UTF-8 (h5py reads them as `str`); on reading,
// fixed-length strings are accepted too, so files touched by other tools
// still load. Numbers are stored little-endian whatever the host.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "hdf5_handle.hpp"

namespace pb::internal {

// ---- writing ----------------------------------------------------------------

// variable-length UTF-8 string type, the one every string attribute uses
inline Hid vlen_utf8_type(const std::string& object) {
  Hid t = owned_type(H5Tcopy(H5T_C_S1), object, "cannot copy the string type");
  check(H5Tset_size(t.get(), H5T_VARIABLE), object, "cannot make a variable-length string");
  check(H5Tset_cset(t.get(), H5T_CSET_UTF8), object, "cannot set UTF-8");
  return t;
}

// creates attribute `name` of loc with the given file type and space, writes buf
inline void write_attribute(hid_t loc, const char* name, hid_t file_type, hid_t mem_type,
                            hid_t space, const void* buf) {
  const std::string object = object_path(loc) + "@" + name;
  Hid a = owned_attribute(H5Acreate2(loc, name, file_type, space, H5P_DEFAULT, H5P_DEFAULT), object,
                          "cannot create the attribute");
  // an empty array has nothing to write (and HDF5 refuses a null buffer)
  if (H5Sget_simple_extent_npoints(space) > 0) {
    check(H5Awrite(a.get(), mem_type, buf), object, "cannot write the attribute");
  }
  a.close(object);
}

inline void write_string_attribute(hid_t loc, const char* name, const std::string& value) {
  const std::string object = object_path(loc) + "@" + name;
  Hid type = vlen_utf8_type(object);
  Hid space = owned_space(H5Screate(H5S_SCALAR), object, "cannot create a scalar space");
  const char* p = value.c_str();
  write_attribute(loc, name, type.get(), type.get(), space.get(), &p);
}

inline void write_string_array_attribute(hid_t loc, const char* name,
                                         const std::vector<std::string>& values) {
  const std::string object = object_path(loc) + "@" + name;
  Hid type = vlen_utf8_type(object);
  const hsize_t n = values.size();
  Hid space = owned_space(H5Screate_simple(1, &n, nullptr), object, "cannot create a space");
  std::vector<const char*> ptrs;
  ptrs.reserve(values.size());
  for (const auto& v : values) ptrs.push_back(v.c_str());
  write_attribute(loc, name, type.get(), type.get(), space.get(), ptrs.data());
}

inline void write_double_attribute(hid_t loc, const char* name, double value) {
  const std::string object = object_path(loc) + "@" + name;
  Hid space = owned_space(H5Screate(H5S_SCALAR), object, "cannot create a scalar space");
  write_attribute(loc, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, space.get(), &value);
}

inline void write_int64_attribute(hid_t loc, const char* name, std::int64_t value) {
  const std::string object = object_path(loc) + "@" + name;
  Hid space = owned_space(H5Screate(H5S_SCALAR), object, "cannot create a scalar space");
  write_attribute(loc, name, H5T_STD_I64LE, H5T_NATIVE_INT64, space.get(), &value);
}

inline void write_double_array_attribute(hid_t loc, const char* name,
                                         const std::vector<double>& values) {
  const std::string object = object_path(loc) + "@" + name;
  const hsize_t n = values.size();
  Hid space = owned_space(H5Screate_simple(1, &n, nullptr), object, "cannot create a space");
  write_attribute(loc, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, space.get(), values.data());
}

inline void write_int32_array_attribute(hid_t loc, const char* name,
                                        const std::vector<std::int32_t>& values) {
  const std::string object = object_path(loc) + "@" + name;
  const hsize_t n = values.size();
  Hid space = owned_space(H5Screate_simple(1, &n, nullptr), object, "cannot create a space");
  write_attribute(loc, name, H5T_STD_I32LE, H5T_NATIVE_INT32, space.get(), values.data());
}

// ---- reading ----------------------------------------------------------------

// opens attribute `name` of loc; Hdf5Error "attribute 'name' is missing" if absent
inline Hid open_attribute(hid_t loc, const char* name) {
  const std::string object = object_path(loc);
  const htri_t exists = H5Aexists(loc, name);
  if (exists <= 0) {
    hdf5_last_error();
    throw Hdf5Error(object, std::string("attribute '") + name + "' is missing");
  }
  return owned_attribute(H5Aopen(loc, name, H5P_DEFAULT), object,
                         std::string("cannot open attribute '") + name + "'");
}

// number of elements of an attribute's space (1 for a scalar)
inline hsize_t attribute_size(hid_t attr, const std::string& object) {
  Hid space = owned_space(H5Aget_space(attr), object, "cannot read the attribute's space");
  const hssize_t n = H5Sget_simple_extent_npoints(space.get());
  if (n < 0) check(-1, object, "cannot read the attribute's size");
  return static_cast<hsize_t>(n);
}

// all strings of a string attribute (scalar or 1-D, variable or fixed length)
inline std::vector<std::string> read_strings(hid_t loc, const char* name) {
  const std::string object = object_path(loc) + "@" + name;
  Hid a = open_attribute(loc, name);
  Hid file_type = owned_type(H5Aget_type(a.get()), object, "cannot read the attribute's type");
  if (H5Tget_class(file_type.get()) != H5T_STRING) {
    throw Hdf5Error(object_path(loc), std::string("attribute '") + name + "' is not a string");
  }
  const hsize_t n = attribute_size(a.get(), object);
  std::vector<std::string> out;
  if (n == 0) return out;
  out.reserve(n);
  if (H5Tis_variable_str(file_type.get()) > 0) {
    // variable length: HDF5 allocates each string; we free them
    Hid mem = vlen_utf8_type(object);
    std::vector<char*> ptrs(n, nullptr);
    check(H5Aread(a.get(), mem.get(), ptrs.data()), object, "cannot read the attribute");
    for (char* p : ptrs) {
      out.emplace_back(p != nullptr ? p : "");
      if (p != nullptr) H5free_memory(p);
    }
  } else {
    // fixed length: n blocks of `size` bytes, padded with NUL or spaces
    const std::size_t size = H5Tget_size(file_type.get());
    Hid mem = owned_type(H5Tcopy(H5T_C_S1), object, "cannot copy the string type");
    check(H5Tset_size(mem.get(), size), object, "cannot size the string type");
    check(H5Tset_strpad(mem.get(), H5T_STR_NULLPAD), object, "cannot set padding");
    std::vector<char> buf(n * size + 1, '\0');
    check(H5Aread(a.get(), mem.get(), buf.data()), object, "cannot read the attribute");
    for (hsize_t i = 0; i < n; ++i) {
      const char* p = buf.data() + i * size;
      std::size_t len = 0;
      while (len < size && p[len] != '\0') ++len;
      out.emplace_back(p, len);
    }
  }
  return out;
}

// one string attribute; Hdf5Error unless it holds exactly one string
inline std::string read_string_attribute(hid_t loc, const char* name) {
  std::vector<std::string> v = read_strings(loc, name);
  if (v.size() != 1) {
    throw Hdf5Error(object_path(loc), std::string("attribute '") + name + "' is not one string");
  }
  return v.front();
}

// numeric attribute converted by HDF5 into `mem_type`; n elements expected
inline void read_numbers(hid_t loc, const char* name, hid_t mem_type, void* buf, hsize_t n) {
  const std::string object = object_path(loc) + "@" + name;
  Hid a = open_attribute(loc, name);
  Hid file_type = owned_type(H5Aget_type(a.get()), object, "cannot read the attribute's type");
  const H5T_class_t cls = H5Tget_class(file_type.get());
  if (cls != H5T_INTEGER && cls != H5T_FLOAT) {
    throw Hdf5Error(object_path(loc), std::string("attribute '") + name + "' is not a number");
  }
  if (attribute_size(a.get(), object) != n) {
    throw Hdf5Error(object_path(loc), std::string("attribute '") + name + "' has " +
                                          std::to_string(attribute_size(a.get(), object)) +
                                          " elements, expected " + std::to_string(n));
  }
  check(H5Aread(a.get(), mem_type, buf), object, "cannot read the attribute");
}

inline double read_double_attribute(hid_t loc, const char* name) {
  double v = 0.0;
  read_numbers(loc, name, H5T_NATIVE_DOUBLE, &v, 1);
  return v;
}

// a 1-D numeric attribute of any length, as doubles
inline std::vector<double> read_double_array_attribute(hid_t loc, const char* name) {
  const std::string object = object_path(loc) + "@" + name;
  hsize_t n = 0;
  {
    Hid a = open_attribute(loc, name);
    n = attribute_size(a.get(), object);
  }
  std::vector<double> v(n);
  if (n > 0) read_numbers(loc, name, H5T_NATIVE_DOUBLE, v.data(), n);
  return v;
}

inline std::int64_t read_int64_attribute(hid_t loc, const char* name) {
  std::int64_t v = 0;
  read_numbers(loc, name, H5T_NATIVE_INT64, &v, 1);
  return v;
}

}  // namespace pb::internal
