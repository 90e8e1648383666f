#include "planarbench/sweep_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <system_error>
#include <vector>

#include "internal/hdf5_attributes.hpp"
#include "internal/hdf5_datasets.hpp"
#include "internal/hdf5_handle.hpp"
#include "internal/hdf5_sha256.hpp"
#include "planarbench/build_info.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/output_file.hpp"

namespace pb {

namespace fs = std::filesystem;
using internal::Hdf5Error;
using internal::Hid;

namespace {

std::string child_path(hid_t loc, const std::string& name) {
  const std::string parent = internal::object_path(loc);
  return (parent == "/" ? "" : parent) + "/" + name;
}

// ---- writing ----------------------------------------------------------------

// a group that records no times and keeps its children in creation order (the
// results file's groups are made the same way, results_file.cpp)
Hid create_group(hid_t loc, const std::string& name) {
  const std::string object = child_path(loc, name);
  if (name.empty() || name == "." || name.find('/') != std::string::npos) {
    throw Hdf5Error(object, fmt::format("'{}' cannot be a group name", name));
  }
  Hid gcpl = internal::owned_plist(H5Pcreate(H5P_GROUP_CREATE), object, "cannot create properties");
  internal::check(H5Pset_obj_track_times(gcpl.get(), 0), object, "cannot switch off times");
  internal::check(
      H5Pset_link_creation_order(gcpl.get(), H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED), object,
      "cannot track creation order");
  return internal::owned_group(H5Gcreate2(loc, name.c_str(), H5P_DEFAULT, gcpl.get(), H5P_DEFAULT),
                               object, "cannot create the group");
}

// [n] variable-length UTF-8 strings (h5py reads them as bytes objects; .asstr() gives str)
void write_string_dataset(hid_t loc, const char* name, const std::vector<std::string>& values,
                          const std::string& unit) {
  const std::string object = child_path(loc, name);
  Hid type = internal::vlen_utf8_type(object);
  std::vector<const char*> ptrs;
  ptrs.reserve(values.size());
  for (const auto& v : values) ptrs.push_back(v.c_str());
  const hsize_t n = values.size();
  Hid d = internal::create_and_write(loc, name, type.get(), type.get(), 1, &n, ptrs.data(), nullptr);
  internal::write_string_attribute(d.get(), "unit", unit);
  d.close(object);
}

void write_int64_dataset(hid_t loc, const char* name, const std::vector<std::int64_t>& values,
                         const std::string& unit) {
  const std::string object = child_path(loc, name);
  const hsize_t n = values.size();
  Hid d =
      internal::create_and_write(loc, name, H5T_STD_I64LE, H5T_NATIVE_INT64, 1, &n,
                                 values.data(), nullptr);
  internal::write_string_attribute(d.get(), "unit", unit);
  d.close(object);
}

void write_double_array_attribute(hid_t loc, const char* name, const std::vector<double>& values) {
  const std::string object = internal::object_path(loc) + "@" + name;
  const hsize_t n = values.size();
  Hid space =
      internal::owned_space(H5Screate_simple(1, &n, nullptr), object, "cannot create a space");
  internal::write_attribute(loc, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, space.get(),
                            values.data());
}

void write_parameters(hid_t file, const SweepFile& s) {
  Hid g = create_group(file, "parameters");
  const ResultsProvenance& p = s.provenance;
  internal::write_string_attribute(g.get(), "build_revision", build_info::kRevision);
  internal::write_string_attribute(g.get(), "compiler", build_info::kCompiler);
  internal::write_string_attribute(g.get(), "compiler_flags", build_info::kFlags);
  internal::write_string_attribute(g.get(), "build_type", build_info::kBuildType);
  internal::write_string_attribute(g.get(), "host", p.host);
  internal::write_string_attribute(g.get(), "utc_time", p.utc_time);
  internal::write_string_attribute(g.get(), "planarbench_version", build_info::kVersion);
  internal::write_string_attribute(g.get(), "command_line", p.command_line);
  internal::write_string_attribute(g.get(), "file_kind", "sweep");
  internal::write_int64_attribute(g.get(), "repeat", s.repeat);
  internal::write_int64_attribute(g.get(), "quick", s.quick ? 1 : 0);
  write_double_array_attribute(g.get(), "dt_ladder", s.dt_ladder);
  write_double_array_attribute(g.get(), "rtol_ladder", s.rtol_ladder);
  internal::write_string_attribute(g.get(), "ladder_stop_rule", s.ladder_stop_rule);
}

void write_series(hid_t case_group, const SweepSeries& s, const std::string& truth) {
  Hid g = create_group(case_group, s.name);
  internal::write_string_attribute(g.get(), "engine", s.engine);
  internal::write_string_attribute(g.get(), "knob", s.knob);
  internal::write_string_attribute(g.get(), "knob_key", s.knob_key);
  internal::write_double_attribute(g.get(), "default_value", s.default_value);
  internal::write_string_attribute(g.get(), "fixed_settings", s.fixed_settings);
  internal::write_string_attribute(g.get(), "truth", truth);
  std::vector<double> value, wall, error;
  std::vector<std::int64_t> steps;
  std::vector<std::string> status, reason;
  for (const auto& r : s.rungs) {
    value.push_back(r.value);
    wall.push_back(r.wall_time_s);
    error.push_back(r.position_error_m);
    steps.push_back(r.steps);
    status.emplace_back(run_status_name(r.status));
    reason.push_back(r.reason);
  }
  internal::write_double_dataset(g.get(), "value", value, 0, s.knob_unit);
  internal::write_double_dataset(g.get(), "wall_time_s", wall, 0, "s");
  write_int64_dataset(g.get(), "steps", steps, "1");
  internal::write_double_dataset(g.get(), "position_error_m", error, 0, "m");
  write_string_dataset(g.get(), "status", status, "");
  write_string_dataset(g.get(), "reason", reason, "");
}

void write_case(hid_t sweep, const SweepCase& c) {
  Hid g = create_group(sweep, c.case_name);
  internal::write_string_attribute(g.get(), "case_text", c.case_text);
  internal::write_string_attribute(g.get(), "case_sha256", internal::sha256_hex(c.case_text));
  internal::write_string_attribute(g.get(), "case_path", c.case_path);
  nlohmann::ordered_json overrides = nlohmann::ordered_json::object();
  for (const auto& [key, value] : c.overrides) overrides[key] = value;
  internal::write_string_attribute(
      g.get(), "overrides",
      overrides.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace));
  internal::write_double_attribute(g.get(), "duration_s", c.duration_s);
  internal::write_string_attribute(g.get(), "truth", c.truth);
  internal::write_string_attribute(g.get(), "truth_note", c.truth_note);
  for (const auto& s : c.series) write_series(g.get(), s, c.truth);
}

void write_file(const fs::path& path, const SweepFile& sweep) {
  const std::string object = "/";
  Hid fcpl = internal::owned_plist(H5Pcreate(H5P_FILE_CREATE), object, "cannot create properties");
  internal::check(H5Pset_obj_track_times(fcpl.get(), 0), object, "cannot switch off times");
  Hid file = internal::owned_file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, fcpl.get(), H5P_DEFAULT),
                                  object, fmt::format("cannot create '{}'", path.string()));
  write_parameters(file.get(), sweep);
  {
    Hid g = create_group(file.get(), "sweep");
    for (const auto& c : sweep.cases) write_case(g.get(), c);
  }
  file.close(object);
}

// ---- reading ----------------------------------------------------------------

Hid open_group(hid_t loc, const std::string& name, const std::string& missing_hint = "") {
  const std::string object = child_path(loc, name);
  if (H5Lexists(loc, name.c_str(), H5P_DEFAULT) <= 0) {
    internal::hdf5_last_error();
    throw Hdf5Error(object, "group is missing" + missing_hint);
  }
  return internal::owned_group(H5Gopen2(loc, name.c_str(), H5P_DEFAULT), object,
                               "cannot open the group");
}

// names of a group's children in creation order
std::vector<std::string> child_names(hid_t group) {
  const std::string object = internal::object_path(group);
  H5G_info_t info{};
  internal::check(H5Gget_info(group, &info), object, "cannot list the group");
  Hid gcpl = internal::owned_plist(H5Gget_create_plist(group), object, "cannot read properties");
  unsigned order_flags = 0;
  internal::check(H5Pget_link_creation_order(gcpl.get(), &order_flags), object,
                  "cannot read properties");
  const H5_index_t index =
      (order_flags & H5P_CRT_ORDER_TRACKED) != 0 ? H5_INDEX_CRT_ORDER : H5_INDEX_NAME;
  std::vector<std::string> names;
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t n =
        H5Lget_name_by_idx(group, ".", index, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    if (n < 0) internal::check(-1, object, "cannot list the group");
    std::string name(static_cast<std::size_t>(n) + 1, '\0');
    H5Lget_name_by_idx(group, ".", index, H5_ITER_INC, i, name.data(), name.size(), H5P_DEFAULT);
    name.resize(static_cast<std::size_t>(n));
    names.push_back(std::move(name));
  }
  return names;
}

// the length of a one-dimensional dataset
hsize_t dataset_length(hid_t d, const std::string& object) {
  Hid space = internal::owned_space(H5Dget_space(d), object, "cannot read the dataset's space");
  hsize_t n = 0;
  if (H5Sget_simple_extent_ndims(space.get()) != 1 ||
      H5Sget_simple_extent_dims(space.get(), &n, nullptr) < 0) {
    internal::hdf5_last_error();
    throw Hdf5Error(object, "expected shape [n]");
  }
  return n;
}

std::vector<std::string> read_string_dataset(hid_t loc, const char* name) {
  Hid d = internal::open_dataset(loc, name);
  const std::string object = internal::object_path(d.get());
  Hid file_type = internal::owned_type(H5Dget_type(d.get()), object, "cannot read the type");
  if (H5Tget_class(file_type.get()) != H5T_STRING || H5Tis_variable_str(file_type.get()) <= 0) {
    throw Hdf5Error(object, "is not a variable-length string dataset");
  }
  const hsize_t n = dataset_length(d.get(), object);
  std::vector<char*> ptrs(n, nullptr);
  std::vector<std::string> out;
  if (n == 0) return out;
  Hid mem = internal::vlen_utf8_type(object);
  internal::check(H5Dread(d.get(), mem.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, ptrs.data()), object,
                  "cannot read the dataset");
  // HDF5 allocated each string; we free them
  for (char* p : ptrs) {
    out.emplace_back(p != nullptr ? p : "");
    if (p != nullptr) H5free_memory(p);
  }
  return out;
}

std::vector<std::int64_t> read_int64_dataset(hid_t loc, const char* name) {
  Hid d = internal::open_dataset(loc, name);
  const std::string object = internal::object_path(d.get());
  std::vector<std::int64_t> out(dataset_length(d.get(), object));
  if (!out.empty()) {
    internal::check(H5Dread(d.get(), H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()),
                    object, "cannot read the dataset");
  }
  return out;
}

std::vector<double> read_double_array_attribute(hid_t loc, const char* name) {
  const std::string object = internal::object_path(loc) + "@" + name;
  Hid a = internal::open_attribute(loc, name);
  std::vector<double> out(internal::attribute_size(a.get(), object));
  if (!out.empty()) internal::read_numbers(loc, name, H5T_NATIVE_DOUBLE, out.data(), out.size());
  return out;
}

RunStatus parse_status(const std::string& s, const std::string& object) {
  for (RunStatus st : {RunStatus::ok, RunStatus::diverged, RunStatus::unsupported}) {
    if (s == run_status_name(st)) return st;
  }
  throw Hdf5Error(object, fmt::format("status '{}' is not ok, diverged or unsupported", s));
}

SweepSeries read_series(hid_t case_group, const std::string& name) {
  Hid g = open_group(case_group, name);
  const std::string object = internal::object_path(g.get());
  SweepSeries s;
  s.name = name;
  s.engine = internal::read_string_attribute(g.get(), "engine");
  s.knob = internal::read_string_attribute(g.get(), "knob");
  s.knob_key = internal::read_string_attribute(g.get(), "knob_key");
  s.default_value = internal::read_double_attribute(g.get(), "default_value");
  s.fixed_settings = internal::read_string_attribute(g.get(), "fixed_settings");
  {
    Hid d = internal::open_dataset(g.get(), "value");
    s.knob_unit = internal::read_string_attribute(d.get(), "unit");
  }
  const auto value = internal::read_double_dataset(g.get(), "value", 0);
  const auto wall = internal::read_double_dataset(g.get(), "wall_time_s", 0);
  const auto steps = read_int64_dataset(g.get(), "steps");
  const auto error = internal::read_double_dataset(g.get(), "position_error_m", 0);
  const auto status = read_string_dataset(g.get(), "status");
  const auto reason = read_string_dataset(g.get(), "reason");
  const std::size_t n = value.size();
  if (wall.size() != n || steps.size() != n || error.size() != n || status.size() != n ||
      reason.size() != n) {
    throw Hdf5Error(object, fmt::format("datasets differ in length (value has {})", n));
  }
  for (std::size_t i = 0; i < n; ++i) {
    SweepRung r;
    r.value = value[i];
    r.wall_time_s = wall[i];
    r.steps = static_cast<long>(steps[i]);
    r.position_error_m = error[i];
    r.status = parse_status(status[i], object + "/status");
    r.reason = reason[i];
    s.rungs.push_back(std::move(r));
  }
  return s;
}

SweepCase read_case(hid_t sweep, const std::string& name) {
  Hid g = open_group(sweep, name);
  SweepCase c;
  c.case_name = name;
  c.case_text = internal::read_string_attribute(g.get(), "case_text");
  c.case_path = internal::read_string_attribute(g.get(), "case_path");
  if (internal::read_string_attribute(g.get(), "case_sha256") !=
      internal::sha256_hex(c.case_text)) {
    throw Hdf5Error(internal::object_path(g.get()), "case_sha256 does not match case_text");
  }
  const std::string text = internal::read_string_attribute(g.get(), "overrides");
  nlohmann::ordered_json overrides;
  try {
    overrides = nlohmann::ordered_json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw Hdf5Error(internal::object_path(g.get()),
                    fmt::format("attribute 'overrides' is not JSON ({})", e.what()));
  }
  if (!overrides.is_object()) {
    throw Hdf5Error(internal::object_path(g.get()), "attribute 'overrides' is not a JSON object");
  }
  for (const auto& [key, value] : overrides.items()) {
    c.overrides.emplace_back(key, value.is_string() ? value.get<std::string>() : value.dump());
  }
  c.duration_s = internal::read_double_attribute(g.get(), "duration_s");
  c.truth = internal::read_string_attribute(g.get(), "truth");
  c.truth_note = internal::read_string_attribute(g.get(), "truth_note");
  for (const auto& s : child_names(g.get())) c.series.push_back(read_series(g.get(), s));
  return c;
}

SweepFile read_file(hid_t file) {
  SweepFile s;
  {
    Hid p = open_group(file, "parameters", " (not a planarbench sweep file)");
    if (H5Aexists(p.get(), "file_kind") <= 0 ||
        internal::read_string_attribute(p.get(), "file_kind") != "sweep") {
      internal::hdf5_last_error();
      throw Hdf5Error("/parameters", "file_kind is not 'sweep' (not a planarbench sweep file)");
    }
    s.provenance.command_line = internal::read_string_attribute(p.get(), "command_line");
    s.provenance.utc_time = internal::read_string_attribute(p.get(), "utc_time");
    s.provenance.host = internal::read_string_attribute(p.get(), "host");
    s.repeat = static_cast<int>(internal::read_int64_attribute(p.get(), "repeat"));
    s.quick = internal::read_int64_attribute(p.get(), "quick") != 0;
    s.dt_ladder = read_double_array_attribute(p.get(), "dt_ladder");
    s.rtol_ladder = read_double_array_attribute(p.get(), "rtol_ladder");
    // files written before the rule (issue 12) ran every rung
    if (H5Aexists(p.get(), "ladder_stop_rule") > 0) {
      s.ladder_stop_rule = internal::read_string_attribute(p.get(), "ladder_stop_rule");
    }
  }
  Hid sweep = open_group(file, "sweep", " (not a planarbench sweep file)");
  for (const auto& name : child_names(sweep.get())) s.cases.push_back(read_case(sweep.get(), name));
  return s;
}

}  // namespace

void write_sweep_file(const fs::path& path, const SweepFile& sweep) {
  internal::QuietHdf5 quiet;
  (void)write_atomically("--out", path, [&](const fs::path& tmp) {
    try {
      write_file(tmp, sweep);
    } catch (const Hdf5Error& e) {
      throw std::runtime_error(
          fmt::format("{}: cannot write the sweep: {}", path.string(), e.what()));
    }
  });
}

SweepFile read_sweep_file(const fs::path& path) {
  internal::QuietHdf5 quiet;
  const std::string file = path.string();
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(file, 0, "", "does not exist");
  if (fs::is_directory(path, ec)) throw InputError(file, 0, "", "is a directory, not a file");
  if (H5Fis_hdf5(file.c_str()) <= 0) {
    internal::hdf5_last_error();
    throw InputError(file, 0, "", "is not an HDF5 file");
  }
  try {
    Hid f = internal::owned_file(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), "/",
                                 "cannot be opened: truncated or damaged HDF5 file");
    SweepFile sweep = read_file(f.get());
    f.close("/");
    return sweep;
  } catch (const Hdf5Error& e) {
    throw InputError(file, 0, e.object(), e.what_is_wrong());
  }
}

}  // namespace pb
