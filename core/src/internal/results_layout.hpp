// The row records and dataset columns of a run in the results file (SPEC §5),
// shared by the writer (results_file.cpp) and the run spool (run_spool.cpp),
// which must lay rows out byte for byte alike.
#pragma once

#include <cstddef>
#include <cstring>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "hdf5_datasets.hpp"
#include "planarbench/engine.hpp"

namespace pb::internal {

// ---- table rows as C++ records (field order = column order in the file) ----

struct ContactRecord {
  double time_s;
  char body_a[kNameBytes];
  char body_b[kNameBytes];
  double force_n;
  double penetration_m;
  double normal[2];
  double point_m[2];
  double tangential_force_n;
  double slip_mps;
};

struct EventRecord {
  char body_a[kNameBytes];
  char body_b[kNameBytes];
  double onset_time_s;
  double offset_time_s;
  double approach_speed_mps;
  double separation_speed_mps;
  double restitution;
  double peak_force_n;
  double impulse_ns;
  double max_penetration_m;
};

inline const TableLayout& contact_layout() {

  static const TableLayout layout{
      sizeof(ContactRecord),
      {{"time", FieldKind::f8, offsetof(ContactRecord, time_s), "s"},
       {"body_a", FieldKind::name, offsetof(ContactRecord, body_a), ""},
       {"body_b", FieldKind::name, offsetof(ContactRecord, body_b), ""},
       {"force_n", FieldKind::f8, offsetof(ContactRecord, force_n), "N"},
       {"penetration", FieldKind::f8, offsetof(ContactRecord, penetration_m), "m"},
       {"normal", FieldKind::f8x2, offsetof(ContactRecord, normal), "1"},
       {"point", FieldKind::f8x2, offsetof(ContactRecord, point_m), "m"},
       // issue 32: along t = n rotated by +90 deg; files before it lack them
       {"tangential_force_n", FieldKind::f8, offsetof(ContactRecord, tangential_force_n), "N", true},
       {"slip_mps", FieldKind::f8, offsetof(ContactRecord, slip_mps), "m/s", true}}};
  return layout;
}

inline const TableLayout& event_layout() {

  static const TableLayout layout{
      sizeof(EventRecord),
      {{"body_a", FieldKind::name, offsetof(EventRecord, body_a), ""},
       {"body_b", FieldKind::name, offsetof(EventRecord, body_b), ""},
       {"onset_time", FieldKind::f8, offsetof(EventRecord, onset_time_s), "s"},
       {"offset_time", FieldKind::f8, offsetof(EventRecord, offset_time_s), "s"},
       {"approach_speed", FieldKind::f8, offsetof(EventRecord, approach_speed_mps), "m/s"},
       {"separation_speed", FieldKind::f8, offsetof(EventRecord, separation_speed_mps), "m/s"},
       {"restitution", FieldKind::f8, offsetof(EventRecord, restitution), "1"},
       {"peak_force", FieldKind::f8, offsetof(EventRecord, peak_force_n), "N"},
       {"impulse", FieldKind::f8, offsetof(EventRecord, impulse_ns), "N s"},
       {"max_penetration", FieldKind::f8, offsetof(EventRecord, max_penetration_m), "m"}}};
  return layout;
}

// copies a body name into a NUL-padded table cell
inline void put_name(char (&cell)[kNameBytes], const std::vector<std::string>& names, int index,
                     const std::string& object) {
  if (index < 0 || static_cast<std::size_t>(index) >= names.size()) {
    throw Hdf5Error(
        object, fmt::format("body index {} is not in body_names ({} names)", index, names.size()));
  }
  const std::string& name = names[static_cast<std::size_t>(index)];
  if (name.size() > kNameBytes) {
    throw Hdf5Error(object,
                    fmt::format("body name '{}' is longer than {} bytes", name, kNameBytes));
  }
  std::memcpy(cell, name.data(), name.size());
}

// one row of the contacts table; names from the run's body_names
inline ContactRecord contact_record(double time_s, const ContactSample& c,
                                    const std::vector<std::string>& body_names,
                                    const std::string& object) {
  ContactRecord row{};
  row.time_s = time_s;
  put_name(row.body_a, body_names, c.body_a, object);
  put_name(row.body_b, body_names, c.body_b, object);
  row.force_n = c.force_n;
  row.penetration_m = c.penetration_m;
  row.normal[0] = c.normal.x();
  row.normal[1] = c.normal.y();
  row.point_m[0] = c.point_m.x();
  row.point_m[1] = c.point_m.y();
  row.tangential_force_n = c.tangential_force_n;
  row.slip_mps = c.slip_mps;
  return row;
}

// the datasets of /runs/<case>/<engine>/bodies/<body>/, in the order written
struct BodyColumn {
  const char* name;
  hsize_t cols;  // 0: shape [n], else [n, cols]
  const char* unit;
};
inline constexpr BodyColumn kBodyColumns[] = {{"time", 0, "s"},
                                              {"position", 2, "m"},
                                              {"angle", 0, "rad"},
                                              {"velocity", 2, "m/s"},
                                              {"angular_velocity", 0, "rad/s"}};

}  // namespace pb::internal
