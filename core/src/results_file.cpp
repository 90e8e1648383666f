#include "planarbench/results_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "internal/hdf5_attributes.hpp"
#include "internal/hdf5_datasets.hpp"
#include "internal/hdf5_copy.hpp"
#include "internal/hdf5_handle.hpp"
#include "internal/hdf5_sha256.hpp"
#include "internal/results_layout.hpp"
#include "internal/results_validation.hpp"
#include "internal/run_spool_data.hpp"
#include "planarbench/run_spool.hpp"
#include "planarbench/build_info.hpp"
#include "planarbench/errors.hpp"
#include "planarbench/machine.hpp"
#include "planarbench/output_file.hpp"

namespace pb {

namespace fs = std::filesystem;
using internal::ContactRecord;
using internal::EventRecord;
using internal::Hdf5Error;
using internal::Hid;
using internal::contact_layout;
using internal::event_layout;
using internal::put_name;

namespace {

std::string child_path(hid_t loc, const std::string& name) {
  const std::string parent = internal::object_path(loc);
  return (parent == "/" ? "" : parent) + "/" + name;
}

// ---- writing ----------------------------------------------------------------

// a group that records no times and remembers the order its children were made
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

void write_h5md(hid_t file) {
  // H5MD 1.1 metadata (https://www.nongnu.org/h5md/h5md.html#h5md-metadata)
  Hid h5md = create_group(file, "h5md");
  internal::write_int32_array_attribute(h5md.get(), "version", {1, 1});
  Hid author = create_group(h5md.get(), "author");
  internal::write_string_attribute(author.get(), "name", "planarbench");
  Hid creator = create_group(h5md.get(), "creator");
  internal::write_string_attribute(creator.get(), "name", "planarbench");
  internal::write_string_attribute(creator.get(), "version", build_info::kVersion);
}

void write_parameters(hid_t file, const ResultsProvenance& p) {
  Hid g = create_group(file, "parameters");
  internal::write_string_attribute(g.get(), "build_revision", build_info::kRevision);
  internal::write_string_attribute(g.get(), "compiler", build_info::kCompiler);
  internal::write_string_attribute(g.get(), "compiler_flags", build_info::kFlags);
  internal::write_string_attribute(g.get(), "build_type", build_info::kBuildType);
  internal::write_string_attribute(g.get(), "host", p.host);
  // the machine behind every wall time in the file
  internal::write_string_attribute(g.get(), "machine_cpu_model", machine_cpu_model());
  internal::write_string_attribute(g.get(), "machine_cpus", std::to_string(machine_cpus()));
  internal::write_string_attribute(g.get(), "utc_time", p.utc_time);
  internal::write_string_attribute(g.get(), "planarbench_version", build_info::kVersion);
  internal::write_string_attribute(g.get(), "command_line", p.command_line);
}

// a list of 2-vectors as row-major [n, 2] doubles
std::vector<double> flatten(const std::vector<Vec2>& v) {
  std::vector<double> out;
  out.reserve(2 * v.size());
  for (const Vec2& x : v) {
    out.push_back(x.x());
    out.push_back(x.y());
  }
  return out;
}

void write_body(hid_t bodies, const BodyTrajectory& b, internal::ChunkWriter* writer) {
  Hid g = create_group(bodies, b.name);
  const std::vector<double> columns[] = {b.time_s, flatten(b.position_m), b.angle_rad,
                                         flatten(b.velocity_mps), b.angular_velocity_radps};
  for (std::size_t k = 0; k < std::size(internal::kBodyColumns); ++k) {
    const auto& c = internal::kBodyColumns[k];
    internal::write_double_dataset(g.get(), c.name, columns[k], c.cols, c.unit, writer);
  }
}

// dataset `name` of loc from a spool whose rows are the bytes of file_type
// (checked: equal to the rows' type in memory, mem_type)
Hid write_spooled(hid_t loc, const char* name, hid_t file_type, hid_t mem_type, hsize_t cols,
                  const internal::DatasetSpool& spool) {
  const std::string object = child_path(loc, name);
  if (H5Tequal(file_type, mem_type) <= 0) {
    throw Hdf5Error(object, "the spooled rows are not in the file's byte layout");
  }
  const hsize_t dims[2] = {spool.rows(), cols};
  Hid d = internal::create_dataset(loc, name, file_type, cols == 0 ? 1 : 2, dims);
  spool.write(d.get(), file_type, object);
  return d;
}

// the bodies and the contacts table of a run whose samples went to a spool
void write_spooled_run(hid_t run, const RunSpool& spool) {
  const auto& data = spool.data();
  Hid bodies = create_group(run, "bodies");
  for (const auto& b : data.bodies) {
    Hid g = create_group(bodies.get(), b.name);
    for (std::size_t k = 0; k < std::size(internal::kBodyColumns); ++k) {
      const auto& c = internal::kBodyColumns[k];
      Hid d = write_spooled(g.get(), c.name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, c.cols,
                            b.columns[k]);
      internal::write_string_attribute(d.get(), "unit", c.unit);
      d.close(child_path(g.get(), c.name));
    }
  }
  const std::string object = child_path(run, "contacts");
  Hid file_type = internal::table_type(contact_layout(), true, object);
  Hid mem_type = internal::table_type(contact_layout(), false, object);
  Hid d = write_spooled(run, "contacts", file_type.get(), mem_type.get(), 0, data.contacts);
  internal::write_table_attributes(d, contact_layout());
  d.close(object);
}

void write_contacts(hid_t run, const RunResult& r, internal::ChunkWriter* writer) {
  const std::string object = child_path(run, "contacts");
  std::vector<ContactRecord> rows;
  rows.reserve(r.contacts.size());
  for (const ContactRow& c : r.contacts) {
    rows.push_back(internal::contact_record(c.time_s, c.sample, r.body_names, object));
  }
  internal::write_table(run, "contacts", contact_layout(), rows.data(), rows.size(), writer);
}

void write_events(hid_t run, const RunResult& r, internal::ChunkWriter* writer) {
  const std::string object = child_path(run, "events");
  std::vector<EventRecord> rows(r.events.size(), EventRecord{});
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const ContactEpisode& e = r.events[i];
    EventRecord& row = rows[i];
    put_name(row.body_a, r.body_names, e.body_a, object);
    put_name(row.body_b, r.body_names, e.body_b, object);
    row.onset_time_s = e.onset_time_s;
    row.offset_time_s = e.offset_time_s;
    row.approach_speed_mps = e.approach_speed_mps;
    row.separation_speed_mps = e.separation_speed_mps;
    row.restitution = e.restitution;
    row.peak_force_n = e.peak_force_n;
    row.impulse_ns = e.impulse_ns;
    row.max_penetration_m = e.max_penetration_m;
  }
  internal::write_table(run, "events", event_layout(), rows.data(), rows.size(), writer);
}

// JSON text; invalid UTF-8 in a string becomes U+FFFD instead of failing the write
template <typename Json>
std::string json_text(const Json& j) {
  return j.dump(-1, ' ', false, Json::error_handler_t::replace);
}

// a run's attributes and datasets into its (empty) group g
void fill_run(hid_t group, const RunResult& r, internal::ChunkWriter* writer) {
  const hid_t g = group;
  internal::write_string_attribute(g, "engine_version", r.engine_version);
  internal::write_string_attribute(g, "status", run_status_name(r.status));
  internal::write_string_attribute(g, "reason", r.reason);
  internal::write_double_attribute(g, "diverged_at_s", r.diverged_at_s);
  internal::write_string_attribute(g, "settings", json_text(r.settings));
  internal::write_string_attribute(g, "mapping", json_text(r.mapping));
  internal::write_string_attribute(g, "extra", json_text(r.extra));
  internal::write_double_attribute(g, "wall_time_s", r.wall_time_s);
  if (!r.wall_time_repeats_s.empty()) {
    internal::write_double_array_attribute(g, "wall_time_repeats_s", r.wall_time_repeats_s);
  }
  internal::write_int64_attribute(g, "steps", static_cast<std::int64_t>(r.steps));
  internal::write_string_array_attribute(g, "body_names", r.body_names);

  if (r.spool) {
    write_spooled_run(g, *r.spool);
  } else {
    // an unsupported run has no trajectories: no bodies group (SPEC §5)
    if (r.status != RunStatus::unsupported || !r.bodies.empty()) {
      Hid bodies = create_group(g, "bodies");
      for (const auto& b : r.bodies) write_body(bodies.get(), b, writer);
    }
    // tables are always present, zero rows when empty, so readers need no special case
    write_contacts(g, r, writer);
  }
  write_events(g, r, writer);
}

// --set overrides as a JSON object, in the order given
nlohmann::ordered_json overrides_json(const std::vector<std::pair<std::string, std::string>>& o) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const auto& [key, value] : o) j[key] = value;
  return j;
}

// the case's group and attributes, with one empty group per run in order
void write_case_header(hid_t runs, const CaseRuns& c) {
  Hid g = create_group(runs, c.case_name);
  internal::write_string_attribute(g.get(), "case_text", c.case_text);
  internal::write_string_attribute(g.get(), "case_sha256", internal::sha256_hex(c.case_text));
  internal::write_string_attribute(g.get(), "case_path", c.case_path);
  internal::write_string_attribute(g.get(), "overrides", json_text(overrides_json(c.overrides)));
  for (const auto& r : c.runs) (void)create_group(g.get(), r.engine_name);
}


// ---- the campaign table (campaign_table.hpp) ----------------------------------

// rows of a column, row-major [n, cols]; NaN where a run has fewer values
std::vector<double> padded_rows(const std::vector<CampaignRun>& runs, std::size_t cols,
                                const std::vector<double> CampaignRun::*member) {
  std::vector<double> out(runs.size() * cols, std::nan(""));
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const auto& v = runs[i].*member;
    std::copy_n(v.begin(), std::min(v.size(), cols), out.begin() + i * cols);
  }
  return out;
}

void write_campaign(hid_t file, const CampaignTable& t) {
  Hid g = create_group(file, "campaign");
  internal::write_string_attribute(g.get(), "kind", t.kind);
  internal::write_string_attribute(g.get(), "source_text", t.source_text);
  internal::write_string_attribute(g.get(), "source_sha256", internal::sha256_hex(t.source_text));
  internal::write_string_attribute(g.get(), "source_path", t.source_path);
  internal::write_string_attribute(g.get(), "description", json_text(t.description));
  internal::write_int64_attribute(g.get(), "planned_runs", t.planned_runs);
  internal::write_string_array_attribute(g.get(), "engines", t.engines);
  internal::write_string_attribute(g.get(), "shard", t.shard);
  internal::write_int64_attribute(g.get(), "trace_points", t.trace_points);
  internal::write_int64_attribute(g.get(), "trace_bodies", t.trace_bodies);
  {
    Hid cases = create_group(g.get(), "cases");
    for (const auto& c : t.cases) {
      Hid cg = create_group(cases.get(), c.name);
      internal::write_string_attribute(cg.get(), "case_text", c.text);
      internal::write_string_attribute(cg.get(), "case_sha256", internal::sha256_hex(c.text));
      internal::write_string_attribute(cg.get(), "case_path", c.path);
      internal::write_string_attribute(cg.get(), "overrides", json_text(overrides_json(c.overrides)));
      internal::write_double_attribute(cg.get(), "duration_s", c.duration_s);
      internal::write_string_attribute(cg.get(), "truth", c.truth);
      internal::write_string_attribute(cg.get(), "truth_note", c.truth_note);
      internal::write_string_array_attribute(cg.get(), "moving_bodies", c.moving_bodies);
      internal::write_string_attribute(cg.get(), "extra", json_text(c.extra));
    }
  }
  {
    Hid axes = create_group(g.get(), "axes");
    for (const auto& a : t.axes) {
      Hid ag = create_group(axes.get(), a.name);
      internal::write_string_attribute(ag.get(), "key", a.key);
      internal::write_string_attribute(ag.get(), "kind", a.kind);
      internal::write_string_attribute(ag.get(), "unit", a.unit);
      internal::write_string_attribute(ag.get(), "spec", json_text(a.spec));
      internal::write_double_dataset(ag.get(), "values", a.values, 0, a.unit);
    }
  }
  Hid runs = create_group(g.get(), "runs");
  const std::size_t n = t.runs.size();
  std::vector<std::int64_t> id(n), steps(n);
  std::vector<std::string> case_name(n), engine(n), series(n), overrides(n), physics(n), status(n),
      reason(n);
  std::vector<double> wall(n);
  for (std::size_t i = 0; i < n; ++i) {
    const CampaignRun& r = t.runs[i];
    id[i] = r.id;
    steps[i] = r.steps;
    case_name[i] = r.case_name;
    engine[i] = r.engine;
    series[i] = r.series;
    overrides[i] = r.overrides;
    physics[i] = r.physics;
    status[i] = run_status_name(r.status);
    reason[i] = r.reason;
    wall[i] = r.wall_time_s;
  }
  // a measurement of this machine, not a result: an attribute (in the file's
  // dense attribute storage, which the 1.8 format allows past 64 KiB)
  internal::write_double_array_attribute(runs.get(), "wall_time_s", wall);
  internal::write_string_attribute(runs.get(), "wall_time_unit", "s");
  internal::write_int64_dataset(runs.get(), "id", id, "1");
  internal::write_string_dataset(runs.get(), "case", case_name, "");
  internal::write_string_dataset(runs.get(), "engine", engine, "");
  internal::write_string_dataset(runs.get(), "series", series, "");
  internal::write_string_dataset(runs.get(), "overrides", overrides, "");
  internal::write_string_dataset(runs.get(), "physics", physics, "");
  internal::write_string_dataset(runs.get(), "status", status, "");
  internal::write_string_dataset(runs.get(), "reason", reason, "");
  internal::write_int64_dataset(runs.get(), "steps", steps, "1");
  {
    Hid axis = create_group(runs.get(), "axis");
    for (std::size_t k = 0; k < t.axes.size(); ++k) {
      std::vector<double> col(n);
      for (std::size_t i = 0; i < n; ++i) col[i] = t.runs[i].axis_values.at(k);
      internal::write_double_dataset(axis.get(), t.axes[k].name.c_str(), col, 0, t.axes[k].unit);
    }
  }
  {
    Hid metric = create_group(runs.get(), "metric");
    for (std::size_t k = 0; k < t.metrics.size(); ++k) {
      std::vector<double> col(n);
      for (std::size_t i = 0; i < n; ++i) col[i] = t.runs[i].metrics.at(k);
      const std::string name = t.metrics[k].name;
      internal::write_double_dataset(metric.get(), name.c_str(), col, 0, t.metrics[k].unit);
      Hid d = internal::open_dataset(metric.get(), name.c_str());
      internal::write_string_attribute(d.get(), "doc", t.metrics[k].doc);
    }
  }
  if (t.trace_points > 0) {
    const auto tp = static_cast<std::size_t>(t.trace_points);
    const auto cols = 2 * static_cast<std::size_t>(t.trace_bodies) * tp;
    internal::write_double_dataset(runs.get(), "trace_time_s",
                                   padded_rows(t.runs, tp, &CampaignRun::trace_time_s), tp, "s");
    internal::write_double_dataset(runs.get(), "trace_position_m",
                                   padded_rows(t.runs, cols, &CampaignRun::trace_position_m), cols,
                                   "m");
  }
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

// names of a group's children, in creation order when the file tracks it
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

template <typename Json>
Json parse_json_attribute(hid_t loc, const char* name) {
  const std::string text = internal::read_string_attribute(loc, name);
  try {
    return Json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw Hdf5Error(internal::object_path(loc),
                    fmt::format("attribute '{}' is not JSON ({})", name, e.what()));
  }
}

// a case group's `overrides` attribute (a JSON object) back to its pairs, in order
std::vector<std::pair<std::string, std::string>> read_overrides(hid_t case_group) {
  const auto overrides = parse_json_attribute<nlohmann::ordered_json>(case_group, "overrides");
  if (!overrides.is_object()) {
    throw Hdf5Error(internal::object_path(case_group), "attribute 'overrides' is not a JSON object");
  }
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& [key, value] : overrides.items()) {
    out.emplace_back(key, value.is_string() ? value.get<std::string>() : value.dump());
  }
  return out;
}

RunStatus parse_status_name(const std::string& s, const std::string& object) {
  for (RunStatus st : {RunStatus::ok, RunStatus::diverged, RunStatus::unsupported}) {
    if (s == run_status_name(st)) return st;
  }
  throw Hdf5Error(object, fmt::format("status '{}' is not ok, diverged or unsupported", s));
}

RunStatus parse_status(hid_t run) {
  return parse_status_name(internal::read_string_attribute(run, "status"),
                           internal::object_path(run));
}

std::vector<Vec2> unflatten(const std::vector<double>& flat) {
  std::vector<Vec2> out(flat.size() / 2);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = Vec2(flat[2 * i], flat[2 * i + 1]);
  return out;
}

BodyTrajectory read_body(hid_t bodies, const std::string& name) {
  Hid g = open_group(bodies, name);
  // dtypes, shapes and lengths before anything is read (results_validation.hpp)
  internal::check_body_columns(g.get());
  BodyTrajectory b;
  b.name = name;
  b.time_s = internal::read_double_dataset(g.get(), "time", 0);
  internal::check_sample_times(b.time_s, internal::object_path(g.get()) + "/time");
  b.position_m = unflatten(internal::read_double_dataset(g.get(), "position", 2));
  b.angle_rad = internal::read_double_dataset(g.get(), "angle", 0);
  b.velocity_mps = unflatten(internal::read_double_dataset(g.get(), "velocity", 2));
  b.angular_velocity_radps = internal::read_double_dataset(g.get(), "angular_velocity", 0);
  return b;
}

// a table cell's name back to its index in body_names
int body_index(const char (&cell)[internal::kNameBytes], const std::vector<std::string>& names,
               const std::string& object, std::size_t row) {
  std::size_t len = 0;
  while (len < internal::kNameBytes && cell[len] != '\0') ++len;
  const std::string name(cell, len);
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) return static_cast<int>(i);
  }
  throw Hdf5Error(object, fmt::format("row {}: body '{}' is not in body_names", row, name));
}

RunResult read_run(hid_t case_group, const std::string& case_name, const std::string& engine,
                   bool samples = true) {
  Hid g = open_group(case_group, engine);
  const std::string object = internal::object_path(g.get());
  RunResult r;
  r.case_name = case_name;
  r.engine_name = engine;
  r.engine_version = internal::read_string_attribute(g.get(), "engine_version");
  r.status = parse_status(g.get());
  r.reason = internal::read_string_attribute(g.get(), "reason");
  r.diverged_at_s = internal::read_double_attribute(g.get(), "diverged_at_s");
  r.settings = parse_json_attribute<nlohmann::json>(g.get(), "settings");
  r.mapping = parse_json_attribute<nlohmann::json>(g.get(), "mapping");
  r.extra = parse_json_attribute<nlohmann::json>(g.get(), "extra");
  r.wall_time_s = internal::read_double_attribute(g.get(), "wall_time_s");
  // written only for a repeated run
  if (H5Aexists(g.get(), "wall_time_repeats_s") > 0) {
    r.wall_time_repeats_s = internal::read_double_array_attribute(g.get(), "wall_time_repeats_s");
  }
  r.steps = static_cast<long>(internal::read_int64_attribute(g.get(), "steps"));
  r.body_names = internal::read_strings(g.get(), "body_names");
  if (!samples) return r;

  // bodies are absent for unsupported runs
  if (H5Lexists(g.get(), "bodies", H5P_DEFAULT) > 0) {
    Hid bodies = open_group(g.get(), "bodies");
    for (const auto& name : child_names(bodies.get())) {
      r.bodies.push_back(read_body(bodies.get(), name));
    }
  } else {
    internal::hdf5_last_error();
    if (r.status != RunStatus::unsupported) {
      throw Hdf5Error(object + "/bodies", "group is missing (required unless unsupported)");
    }
  }

  const auto contacts = internal::read_table<ContactRecord>(g.get(), "contacts", contact_layout());
  r.contacts.reserve(contacts.size());
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const ContactRecord& row = contacts[i];
    ContactRow c;
    c.time_s = row.time_s;
    c.sample.body_a = body_index(row.body_a, r.body_names, object + "/contacts", i);
    c.sample.body_b = body_index(row.body_b, r.body_names, object + "/contacts", i);
    c.sample.force_n = row.force_n;
    c.sample.penetration_m = row.penetration_m;
    c.sample.normal = Vec2(row.normal[0], row.normal[1]);
    c.sample.point_m = Vec2(row.point_m[0], row.point_m[1]);
    c.sample.tangential_force_n = row.tangential_force_n;
    c.sample.slip_mps = row.slip_mps;
    r.contacts.push_back(c);
  }

  const auto events = internal::read_table<EventRecord>(g.get(), "events", event_layout());
  r.events.reserve(events.size());
  for (std::size_t i = 0; i < events.size(); ++i) {
    const EventRecord& row = events[i];
    ContactEpisode e;
    e.body_a = body_index(row.body_a, r.body_names, object + "/events", i);
    e.body_b = body_index(row.body_b, r.body_names, object + "/events", i);
    e.onset_time_s = row.onset_time_s;
    e.offset_time_s = row.offset_time_s;
    e.approach_speed_mps = row.approach_speed_mps;
    e.separation_speed_mps = row.separation_speed_mps;
    e.restitution = row.restitution;
    e.peak_force_n = row.peak_force_n;
    e.impulse_ns = row.impulse_ns;
    e.max_penetration_m = row.max_penetration_m;
    r.events.push_back(e);
  }
  return r;
}

CaseRuns read_case(hid_t runs, const std::string& name) {
  Hid g = open_group(runs, name);
  CaseRuns c;
  c.case_name = name;
  c.case_text = internal::read_string_attribute(g.get(), "case_text");
  c.case_path = internal::read_string_attribute(g.get(), "case_path");
  // the stored digest guards against a case text damaged or edited in the file
  const std::string sha = internal::read_string_attribute(g.get(), "case_sha256");
  if (sha != internal::sha256_hex(c.case_text)) {
    throw Hdf5Error(internal::object_path(g.get()), "case_sha256 does not match case_text");
  }
  c.overrides = read_overrides(g.get());
  for (const auto& engine : child_names(g.get())) c.runs.push_back(read_run(g.get(), name, engine));
  return c;
}


// the [n, cols] rows of a dataset back into each run's member
void read_rows(hid_t loc, const char* name, std::size_t cols, std::vector<CampaignRun>& runs,
               std::vector<double> CampaignRun::*member) {
  const auto flat = internal::read_double_dataset(loc, name, cols);
  if (flat.size() != runs.size() * cols) {
    throw Hdf5Error(child_path(loc, name), "has not one row per run");
  }
  for (std::size_t i = 0; i < runs.size(); ++i) {
    (runs[i].*member).assign(flat.begin() + i * cols, flat.begin() + (i + 1) * cols);
  }
}

CampaignTable read_campaign(hid_t file) {
  CampaignTable t;
  Hid g = open_group(file, "campaign");
  t.kind = internal::read_string_attribute(g.get(), "kind");
  t.source_text = internal::read_string_attribute(g.get(), "source_text");
  t.source_path = internal::read_string_attribute(g.get(), "source_path");
  if (internal::read_string_attribute(g.get(), "source_sha256") !=
      internal::sha256_hex(t.source_text)) {
    throw Hdf5Error("/campaign", "source_sha256 does not match source_text");
  }
  t.description = parse_json_attribute<nlohmann::ordered_json>(g.get(), "description");
  t.planned_runs = internal::read_int64_attribute(g.get(), "planned_runs");
  t.engines = internal::read_strings(g.get(), "engines");
  t.shard = internal::read_string_attribute(g.get(), "shard");
  t.trace_points = static_cast<int>(internal::read_int64_attribute(g.get(), "trace_points"));
  t.trace_bodies = static_cast<int>(internal::read_int64_attribute(g.get(), "trace_bodies"));
  {
    Hid cases = open_group(g.get(), "cases");
    for (const auto& name : child_names(cases.get())) {
      Hid cg = open_group(cases.get(), name);
      CampaignCase c;
      c.name = name;
      c.text = internal::read_string_attribute(cg.get(), "case_text");
      if (internal::read_string_attribute(cg.get(), "case_sha256") != internal::sha256_hex(c.text)) {
        throw Hdf5Error(internal::object_path(cg.get()), "case_sha256 does not match case_text");
      }
      c.path = internal::read_string_attribute(cg.get(), "case_path");
      c.overrides = read_overrides(cg.get());
      c.duration_s = internal::read_double_attribute(cg.get(), "duration_s");
      c.truth = internal::read_string_attribute(cg.get(), "truth");
      c.truth_note = internal::read_string_attribute(cg.get(), "truth_note");
      c.moving_bodies = internal::read_strings(cg.get(), "moving_bodies");
      c.extra = parse_json_attribute<nlohmann::ordered_json>(cg.get(), "extra");
      t.cases.push_back(std::move(c));
    }
  }
  {
    Hid axes = open_group(g.get(), "axes");
    for (const auto& name : child_names(axes.get())) {
      Hid ag = open_group(axes.get(), name);
      CampaignAxis a;
      a.name = name;
      a.key = internal::read_string_attribute(ag.get(), "key");
      a.kind = internal::read_string_attribute(ag.get(), "kind");
      a.unit = internal::read_string_attribute(ag.get(), "unit");
      a.spec = parse_json_attribute<nlohmann::ordered_json>(ag.get(), "spec");
      a.values = internal::read_double_dataset(ag.get(), "values", 0);
      t.axes.push_back(std::move(a));
    }
  }
  Hid runs = open_group(g.get(), "runs");
  const std::string object = internal::object_path(runs.get());
  const auto id = internal::read_int64_dataset(runs.get(), "id");
  const std::size_t n = id.size();
  const auto steps = internal::read_int64_dataset(runs.get(), "steps");
  const auto wall = internal::read_double_array_attribute(runs.get(), "wall_time_s");
  std::vector<std::vector<std::string>> strings;
  for (const char* col : {"case", "engine", "series", "overrides", "physics", "status", "reason"}) {
    strings.push_back(internal::read_string_dataset(runs.get(), col));
    if (strings.back().size() != n) throw Hdf5Error(object + "/" + col, "has not one row per run");
  }
  if (steps.size() != n || wall.size() != n) {
    throw Hdf5Error(object, "steps or wall_time_s has not one value per run");
  }
  t.runs.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    CampaignRun& r = t.runs[i];
    r.id = id[i];
    r.steps = steps[i];
    r.wall_time_s = wall[i];
    r.case_name = strings[0][i];
    r.engine = strings[1][i];
    r.series = strings[2][i];
    r.overrides = strings[3][i];
    r.physics = strings[4][i];
    r.status = parse_status_name(strings[5][i], object + "/status");
    r.reason = strings[6][i];
  }
  {
    Hid axis = open_group(runs.get(), "axis");
    for (const auto& a : t.axes) {
      const auto col = internal::read_double_dataset(axis.get(), a.name.c_str(), 0);
      if (col.size() != n) throw Hdf5Error(object + "/axis/" + a.name, "has not one row per run");
      for (std::size_t i = 0; i < n; ++i) t.runs[i].axis_values.push_back(col[i]);
    }
  }
  {
    Hid metric = open_group(runs.get(), "metric");
    for (const auto& name : child_names(metric.get())) {
      Hid d = internal::open_dataset(metric.get(), name.c_str());
      CampaignMetric m{name, internal::read_string_attribute(d.get(), "unit"),
                       internal::read_string_attribute(d.get(), "doc")};
      const auto col = internal::read_double_dataset(metric.get(), name.c_str(), 0);
      if (col.size() != n) throw Hdf5Error(object + "/metric/" + name, "has not one row per run");
      for (std::size_t i = 0; i < n; ++i) t.runs[i].metrics.push_back(col[i]);
      t.metrics.push_back(std::move(m));
    }
  }
  if (t.trace_points > 0) {
    const auto tp = static_cast<std::size_t>(t.trace_points);
    read_rows(runs.get(), "trace_time_s", tp, t.runs, &CampaignRun::trace_time_s);
    read_rows(runs.get(), "trace_position_m", 2 * static_cast<std::size_t>(t.trace_bodies) * tp,
              t.runs, &CampaignRun::trace_position_m);
  }
  return t;
}

ResultsFile read_file(hid_t file) {
  ResultsFile results;
  {
    Hid h5md = open_group(file, "h5md", " (not a planarbench results file)");
    std::vector<std::int32_t> version(2, 0);
    internal::read_numbers(h5md.get(), "version", H5T_NATIVE_INT32, version.data(), 2);
    if (version[0] != 1) {
      throw Hdf5Error("/h5md",
                      fmt::format("H5MD version {}.{} is not 1.x", version[0], version[1]));
    }
  }
  {
    Hid p = open_group(file, "parameters", " (not a planarbench results file)");
    results.provenance.command_line = internal::read_string_attribute(p.get(), "command_line");
    results.provenance.utc_time = internal::read_string_attribute(p.get(), "utc_time");
    results.provenance.host = internal::read_string_attribute(p.get(), "host");
  }
  Hid runs = open_group(file, "runs", " (not a planarbench results file)");
  for (const auto& name : child_names(runs.get())) {
    results.cases.push_back(read_case(runs.get(), name));
  }
  if (H5Lexists(file, "campaign", H5P_DEFAULT) > 0) {
    results.campaign = read_campaign(file);
  } else {
    internal::hdf5_last_error();
  }
  return results;
}

}  // namespace

// ---- ResultsFileWriter ----------------------------------------------------------

struct ResultsFileWriter::State {
  internal::QuietHdf5 quiet;  // first: HDF5's printing stays off until the file is closed
  AtomicOutput out;
  fs::path path;
  Hid file;
  int threads = 1;
  std::mutex mutex;
  ResultsFile layout;  // provenance, case headers and engine names (no data)
  std::vector<std::vector<std::string>> run_groups;  // per case, per run: its group's path
  std::vector<std::vector<bool>> written;
  State(const fs::path& p) : out("--out", p), path(p) {}
  void open();  // creates the temporary with the header, once
  // the group of a run not written yet, the file open (caller holds mutex)
  const std::string& begin_run(std::size_t case_index, std::size_t run_index);
};

namespace {
// an HDF5 failure as the error the command reports
[[noreturn]] void rethrow_as_write_error(const fs::path& path, const Hdf5Error& e) {
  throw std::runtime_error(fmt::format("{}: cannot write results: {}", path.string(), e.what()));
}
}  // namespace

ResultsFileWriter::ResultsFileWriter(const fs::path& path, const ResultsFile& layout, int threads)
    : state_(std::make_unique<State>(path)) {
  State& st = *state_;
  st.threads = threads;
  st.layout.provenance = layout.provenance;
  st.layout.campaign = layout.campaign;
  for (const auto& c : layout.cases) {
    CaseRuns header{c.case_name, c.case_text, c.case_path, c.overrides, {}};
    std::vector<std::string> groups;
    for (const auto& r : c.runs) {
      RunResult slot;
      slot.engine_name = r.engine_name;
      header.runs.push_back(std::move(slot));
      groups.push_back("/runs/" + c.case_name + "/" + r.engine_name);
    }
    st.layout.cases.push_back(std::move(header));
    st.run_groups.push_back(std::move(groups));
    st.written.emplace_back(c.runs.size(), false);
  }
}

// The temporary is made when the first run is written (or at commit): a
// process killed while its first runs simulate leaves nothing behind; killed
// later it leaves `.NAME.tmp.PID`, which the next write to that target removes.
void ResultsFileWriter::State::open() {
  if (file.get() >= 0) return;
  try {
    const std::string object = "/";
    Hid fcpl =
        internal::owned_plist(H5Pcreate(H5P_FILE_CREATE), object, "cannot create properties");
    internal::check(H5Pset_obj_track_times(fcpl.get(), 0), object, "cannot switch off times");
    // a campaign's per-run wall times are one attribute, past the 64 KiB an
    // attribute may have in the oldest format: the 1.8 format (h5py and
    // every HDF5 since 2008 read it) for files with a campaign only
    Hid fapl = internal::owned_plist(H5Pcreate(H5P_FILE_ACCESS), object, "cannot create properties");
    if (layout.campaign) {
      internal::check(H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_V18, H5F_LIBVER_LATEST), object,
                      "cannot choose the 1.8 file format");
    }
    file = internal::owned_file(
        H5Fcreate(out.temporary().c_str(), H5F_ACC_TRUNC, fcpl.get(), fapl.get()), object,
        fmt::format("cannot create '{}'", out.temporary().string()));
    write_h5md(file.get());
    write_parameters(file.get(), layout.provenance);
    Hid runs = create_group(file.get(), "runs");
    for (const auto& c : layout.cases) write_case_header(runs.get(), c);
  } catch (const Hdf5Error& e) {
    rethrow_as_write_error(path, e);
  }
}

ResultsFileWriter::~ResultsFileWriter() = default;

const std::string& ResultsFileWriter::State::begin_run(std::size_t case_index, std::size_t run_index) {
  const std::string& object = run_groups.at(case_index).at(run_index);
  if (written[case_index][run_index]) throw std::logic_error(object + ": written twice");
  open();
  return object;
}

void ResultsFileWriter::write_run(std::size_t case_index, std::size_t run_index,
                                  const RunResult& r) {
  State& st = *state_;
  std::lock_guard<std::mutex> lock(st.mutex);
  const std::string& object = st.begin_run(case_index, run_index);
  try {
    Hid g = internal::owned_group(H5Gopen2(st.file.get(), object.c_str(), H5P_DEFAULT), object,
                                  "cannot open the group");
    internal::ChunkWriter writer(st.threads);
    fill_run(g.get(), r, &writer);
    writer.finish();
    g.close(object);
  } catch (const Hdf5Error& e) {
    rethrow_as_write_error(st.path, e);
  }
  st.written[case_index][run_index] = true;
  // the run's chunks are in the file: let the disk take them while the
  // other runs simulate (strace of the full matrix, --jobs 2: commit's fsync
  // of the 27 MB file took 55 ms before, 27 .. 39 ms after in 3 runs)
  st.out.start_writeback();
}

void ResultsFileWriter::copy_run(std::size_t case_index, std::size_t run_index,
                                 const fs::path& source) {
  State& st = *state_;
  std::lock_guard<std::mutex> lock(st.mutex);
  const std::string& object = st.begin_run(case_index, run_index);
  try {
    internal::QuietHdf5 quiet;
    Hid src = internal::owned_file(H5Fopen(source.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), object,
                                   fmt::format("cannot open '{}'", source.string()));
    Hid from = internal::owned_group(H5Gopen2(src.get(), object.c_str(), H5P_DEFAULT), object,
                                     fmt::format("cannot open the group in '{}'", source.string()));
    Hid to = internal::owned_group(H5Gopen2(st.file.get(), object.c_str(), H5P_DEFAULT), object,
                                   "cannot open the group");
    internal::copy_group_contents(from.get(), to.get(), child_names(from.get()), object);
    to.close(object);
  } catch (const Hdf5Error& e) {
    rethrow_as_write_error(st.path, e);
  }
  st.written[case_index][run_index] = true;
  st.out.start_writeback();
}

void ResultsFileWriter::commit() {
  State& st = *state_;
  std::lock_guard<std::mutex> lock(st.mutex);
  for (std::size_t c = 0; c < st.written.size(); ++c) {
    for (std::size_t k = 0; k < st.written[c].size(); ++k) {
      if (!st.written[c][k]) {
        throw std::logic_error(st.run_groups[c][k] + ": the run was never written");
      }
    }
  }
  st.open();
  try {
    if (st.layout.campaign) write_campaign(st.file.get(), *st.layout.campaign);
    st.file.close("/");
  } catch (const Hdf5Error& e) {
    rethrow_as_write_error(st.path, e);
  }
  (void)st.out.commit();
}

void write_results_file(const fs::path& path, const ResultsFile& results, int threads) {
  ResultsFileWriter w(path, results, threads);
  for (std::size_t c = 0; c < results.cases.size(); ++c) {
    for (std::size_t k = 0; k < results.cases[c].runs.size(); ++k) {
      w.write_run(c, k, results.cases[c].runs[k]);
    }
  }
  w.commit();
}

ResultsFile read_results_file(const fs::path& path) {
  internal::QuietHdf5 quiet;
  const std::string file = path.string();
  const std::string allowed = "give a results file written by `planarbench run`";
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(file, 0, "", "does not exist; " + allowed);
  if (fs::is_directory(path, ec)) throw InputError(file, 0, "", "is a folder, not a file; " + allowed);
  if (fs::file_size(path, ec) == 0 && !ec) {
    throw InputError(file, 0, "", "is empty (0 bytes), not an HDF5 file; " + allowed);
  }
  if (H5Fis_hdf5(file.c_str()) <= 0) {
    internal::hdf5_last_error();
    throw InputError(file, 0, "", "is not an HDF5 file (no HDF5 signature); " + allowed);
  }
  // a file cut short (a killed writer, a partial copy) fails here: HDF5
  // compares the end of file it finds with the one the superblock records
  const hid_t opened = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (opened < 0) {
    const std::string reason = internal::hdf5_last_error();
    throw InputError(file, 0, "",
                     fmt::format("is a truncated or damaged HDF5 file{}; {}",
                                 reason.empty() ? "" : " (HDF5: " + reason + ")", allowed));
  }
  try {
    Hid f(opened, H5Fclose);
    ResultsFile results = read_file(f.get());
    f.close("/");
    return results;
  } catch (const Hdf5Error& e) {
    throw InputError(file, 0, e.object(), e.what_is_wrong());
  }
}

RunResult read_run_header(const fs::path& path) {
  internal::QuietHdf5 quiet;
  const std::string file = path.string();
  try {
    Hid f = internal::owned_file(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), "/",
                                 "cannot open the file");
    Hid runs = open_group(f.get(), "runs");
    const auto cases = child_names(runs.get());
    if (cases.size() != 1) throw Hdf5Error("/runs", fmt::format("holds {} cases, not 1", cases.size()));
    Hid cg = open_group(runs.get(), cases[0]);
    const auto engines = child_names(cg.get());
    if (engines.size() != 1) {
      throw Hdf5Error("/runs/" + cases[0], fmt::format("holds {} runs, not 1", engines.size()));
    }
    return read_run(cg.get(), cases[0], engines[0], false);
  } catch (const Hdf5Error& e) {
    throw InputError(file, 0, e.object(), e.what_is_wrong());
  }
}

}  // namespace pb
