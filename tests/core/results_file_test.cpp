// Tests for core/src/results_file.cpp
#include "planarbench/results_file.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <unistd.h>
#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include "../../core/src/internal/hdf5_sha256.hpp"
#include "planarbench/errors.hpp"

namespace pb {
namespace {

namespace fs = std::filesystem;

// ---- a results file with every feature the format has ------------------------

// a quiet NaN with a payload: bitwise comparison shows it survives unchanged
double nan_with_payload() {
  return std::bit_cast<double>(std::uint64_t{0x7ff8000000000123});
}

BodyTrajectory trajectory(const std::string& name, int n, double phase) {
  BodyTrajectory b;
  b.name = name;
  for (int i = 0; i < n; ++i) {
    const double t = 1e-3 * i;
    b.time_s.push_back(t);
    b.position_m.emplace_back(std::sin(t + phase), std::cos(3.0 * t) - phase);
    b.angle_rad.push_back(0.1 * i + phase);
    b.velocity_mps.emplace_back(std::cos(t + phase), -3.0 * std::sin(3.0 * t));
    b.angular_velocity_radps.push_back(0.1 / 1e-3);
  }
  return b;
}

ContactRow contact(double t, int a, int b, double force, double pen) {
  ContactRow c;
  c.time_s = t;
  c.sample.body_a = a;
  c.sample.body_b = b;
  c.sample.force_n = force;
  c.sample.penetration_m = pen;
  c.sample.normal = Vec2(0.6, -0.8);
  c.sample.point_m = Vec2(1.0 / 3.0, -2.5e-7);
  c.sample.tangential_force_n = -0.3 * force;
  c.sample.slip_mps = 1.0 / 7.0 + t;
  return c;
}

ContactEpisode episode(int a, int b, double onset, double offset) {
  ContactEpisode e;
  e.body_a = a;
  e.body_b = b;
  e.onset_time_s = onset;
  e.offset_time_s = offset;
  e.approach_speed_mps = 1.9809;
  e.separation_speed_mps = 1.5;
  e.restitution = 1.5 / 1.9809;
  e.peak_force_n = 1234.5;
  e.impulse_ns = 0.35;
  e.max_penetration_m = 1e-4;
  return e;
}

// Two cases. falling_ball: an ok run with contacts, events and special
// doubles (NaN with payload, -0, inf, subnormal), a diverged run with empty
// tables, two unsupported runs (one with no body names at all). dual_pendulum:
// an ok run of 5000 samples, above the 4096-row compression threshold.
ResultsFile sample_results() {
  ResultsFile f;
  f.provenance.command_line = "planarbench run --case all --engine all --out r.h5 --set dt=1e-4";
  f.provenance.utc_time = "2024-05-06T07:08:09Z";
  f.provenance.host = "test-host";

  CaseRuns ball;
  ball.case_name = "falling_ball";
  ball.case_text = "# bille tombante — µ = 0.3, δ ≥ 0, 落下\n[ball]\nradius = 0.1\n";
  ball.case_path = "cases/falling_ball.toml";
  ball.overrides = {{"dt", "1e-4"}, {"contact.stiffness", "2e4"}, {"b.z", "ü"}};

  RunResult ok;
  ok.case_name = "falling_ball";
  ok.engine_name = "reference";
  ok.engine_version = "planarbench 0.1.0 (paper algorithm)";
  ok.status = RunStatus::ok;
  ok.settings = {{"dt", 1e-4}, {"outline_points", 180}, {"geometry", "outline"}};
  ok.mapping = {{"contact_law", "native"}, {"notes", {"a", "b — ü"}}};
  ok.extra = {{"valid_until_s", 2.5}};
  ok.wall_time_s = 0.123456789;
  ok.steps = 20001;
  ok.body_names = {"ground", "ball"};
  ok.bodies.push_back(trajectory("ball", 7, 0.25));
  ok.bodies[0].angle_rad[1] = nan_with_payload();
  ok.bodies[0].angle_rad[2] = -0.0;
  ok.bodies[0].angle_rad[3] = std::numeric_limits<double>::infinity();
  ok.bodies[0].angular_velocity_radps[4] = std::numeric_limits<double>::denorm_min();
  ok.contacts = {contact(0.45, 0, 1, 10.0, 1e-5), contact(0.46, 0, 1, 20.0, nan_with_payload()),
                 contact(0.47, 1, 0, 0.0, 0.0)};
  ok.events = {episode(0, 1, 0.449, 0.4712), episode(1, 0, 1.2, std::nan(""))};

  RunResult diverged;
  diverged.case_name = "falling_ball";
  diverged.engine_name = "mujoco";
  diverged.engine_version = "MuJoCo 2.2.2";
  diverged.status = RunStatus::diverged;
  diverged.reason = "NaN in qacc at t = 0.5 s";
  diverged.diverged_at_s = 0.5;
  diverged.steps = 5000;
  diverged.body_names = {"ground", "ball"};
  diverged.bodies.push_back(trajectory("ball", 2, 0.0));

  RunResult unsupported;
  unsupported.case_name = "falling_ball";
  unsupported.engine_name = "box2d";
  unsupported.engine_version = "Box2D 2.4.1";
  unsupported.status = RunStatus::unsupported;
  unsupported.reason = "Box2D has no compliant normal contact";
  unsupported.body_names = {"ground", "ball"};

  RunResult bare = unsupported;
  bare.engine_name = "ode";
  bare.body_names.clear();
  bare.mapping = nlohmann::json::array({1, 2.5, nullptr});

  ball.runs = {ok, diverged, unsupported, bare};

  CaseRuns pendulum;
  pendulum.case_name = "dual_pendulum";
  pendulum.case_text = "abc";  // its SHA-256 is FIPS 180-2's first vector
  pendulum.case_path = "/abs/cases/dual_pendulum.toml";
  RunResult big;
  big.case_name = "dual_pendulum";
  big.engine_name = "analytic";
  big.engine_version = "closed form";
  big.body_names = {"ground", "upper", "lower"};
  big.bodies = {trajectory("upper", 5000, 0.5), trajectory("lower", 5000, 1.5)};
  for (int i = 0; i < 5000; ++i) big.contacts.push_back(contact(1e-3 * i, 1, 2, i, 1e-9 * i));
  pendulum.runs = {big};

  f.cases = {ball, pendulum};
  return f;
}

// ---- comparison, bitwise for doubles -------------------------------------------

bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

#define EXPECT_SAME_DOUBLE(a, b) \
  EXPECT_TRUE(same_bits((a), (b))) << #a << " = " << (a) << " vs " << (b)

void expect_same(const std::vector<double>& a, const std::vector<double>& b, const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_TRUE(same_bits(a[i], b[i])) << what << "[" << i << "] " << a[i] << " vs " << b[i];
  }
}

void expect_same(const std::vector<Vec2>& a, const std::vector<Vec2>& b, const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_TRUE(same_bits(a[i].x(), b[i].x()) && same_bits(a[i].y(), b[i].y()))
        << what << "[" << i << "]";
  }
}

void expect_same(const RunResult& a, const RunResult& b) {
  SCOPED_TRACE(a.case_name + "/" + a.engine_name);
  EXPECT_EQ(a.case_name, b.case_name);
  EXPECT_EQ(a.engine_name, b.engine_name);
  EXPECT_EQ(a.engine_version, b.engine_version);
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.reason, b.reason);
  EXPECT_SAME_DOUBLE(a.diverged_at_s, b.diverged_at_s);
  EXPECT_EQ(a.settings, b.settings);
  EXPECT_EQ(a.mapping, b.mapping);
  EXPECT_EQ(a.extra, b.extra);
  EXPECT_SAME_DOUBLE(a.wall_time_s, b.wall_time_s);
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.body_names, b.body_names);
  ASSERT_EQ(a.bodies.size(), b.bodies.size());
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    EXPECT_EQ(a.bodies[i].name, b.bodies[i].name);
    expect_same(a.bodies[i].time_s, b.bodies[i].time_s, "time_s");
    expect_same(a.bodies[i].position_m, b.bodies[i].position_m, "position_m");
    expect_same(a.bodies[i].angle_rad, b.bodies[i].angle_rad, "angle_rad");
    expect_same(a.bodies[i].velocity_mps, b.bodies[i].velocity_mps, "velocity_mps");
    expect_same(a.bodies[i].angular_velocity_radps, b.bodies[i].angular_velocity_radps,
                "angular_velocity_radps");
  }
  ASSERT_EQ(a.contacts.size(), b.contacts.size());
  for (std::size_t i = 0; i < a.contacts.size(); ++i) {
    const auto &x = a.contacts[i], &y = b.contacts[i];
    EXPECT_SAME_DOUBLE(x.time_s, y.time_s);
    EXPECT_EQ(x.sample.body_a, y.sample.body_a);
    EXPECT_EQ(x.sample.body_b, y.sample.body_b);
    EXPECT_SAME_DOUBLE(x.sample.force_n, y.sample.force_n);
    EXPECT_SAME_DOUBLE(x.sample.penetration_m, y.sample.penetration_m);
    EXPECT_SAME_DOUBLE(x.sample.tangential_force_n, y.sample.tangential_force_n);
    EXPECT_SAME_DOUBLE(x.sample.slip_mps, y.sample.slip_mps);
    expect_same({x.sample.normal, x.sample.point_m}, {y.sample.normal, y.sample.point_m},
                "normal, point");
  }
  ASSERT_EQ(a.events.size(), b.events.size());
  for (std::size_t i = 0; i < a.events.size(); ++i) {
    const auto &x = a.events[i], &y = b.events[i];
    EXPECT_EQ(x.body_a, y.body_a);
    EXPECT_EQ(x.body_b, y.body_b);
    expect_same({x.onset_time_s, x.offset_time_s, x.approach_speed_mps, x.separation_speed_mps,
                 x.restitution, x.peak_force_n, x.impulse_ns, x.max_penetration_m},
                {y.onset_time_s, y.offset_time_s, y.approach_speed_mps, y.separation_speed_mps,
                 y.restitution, y.peak_force_n, y.impulse_ns, y.max_penetration_m},
                "event fields");
  }
}

void expect_same(const ResultsFile& a, const ResultsFile& b) {
  EXPECT_EQ(a.provenance.command_line, b.provenance.command_line);
  EXPECT_EQ(a.provenance.utc_time, b.provenance.utc_time);
  EXPECT_EQ(a.provenance.host, b.provenance.host);
  ASSERT_EQ(a.cases.size(), b.cases.size());
  for (std::size_t c = 0; c < a.cases.size(); ++c) {
    EXPECT_EQ(a.cases[c].case_name, b.cases[c].case_name);
    EXPECT_EQ(a.cases[c].case_text, b.cases[c].case_text);
    EXPECT_EQ(a.cases[c].case_path, b.cases[c].case_path);
    EXPECT_EQ(a.cases[c].overrides, b.cases[c].overrides);
    ASSERT_EQ(a.cases[c].runs.size(), b.cases[c].runs.size());
    for (std::size_t r = 0; r < a.cases[c].runs.size(); ++r) {
      expect_same(a.cases[c].runs[r], b.cases[c].runs[r]);
    }
  }
}

// ---- direct HDF5 access, independent of the code under test --------------------

struct H5File {
  hid_t id;
  H5File(const fs::path& p, unsigned flags) : id(H5Fopen(p.c_str(), flags, H5P_DEFAULT)) {}
  ~H5File() {
    if (id >= 0) H5Fclose(id);
  }
};

std::string read_vlen_string_attribute(hid_t file, const char* object, const char* name) {
  const hid_t a = H5Aopen_by_name(file, object, name, H5P_DEFAULT, H5P_DEFAULT);
  const hid_t t = H5Aget_type(a);
  EXPECT_EQ(H5Tis_variable_str(t), 1) << object << "@" << name;
  EXPECT_EQ(H5Tget_cset(t), H5T_CSET_UTF8) << object << "@" << name;
  char* p = nullptr;
  EXPECT_GE(H5Aread(a, t, &p), 0);
  std::string s = p != nullptr ? p : "";
  H5free_memory(p);
  H5Tclose(t);
  H5Aclose(a);
  return s;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// a fresh directory per test, removed afterwards
class ResultsFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("pb_results_file_test_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // everything in dir_, names only
  std::vector<std::string> listing() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename());
    std::sort(names.begin(), names.end());
    return names;
  }

  template <typename F>
  std::string input_error_message(F&& f) {
    try {
      f();
    } catch (const InputError& e) {
      return e.what();
    } catch (const std::exception& e) {
      ADD_FAILURE() << "not an InputError: " << e.what();
      return "";
    }
    ADD_FAILURE() << "no exception";
    return "";
  }

  fs::path dir_;
};

// ---- round trip ----------------------------------------------------------------

TEST_F(ResultsFileTest, RoundTripKeepsEveryFieldBitwise) {
  const ResultsFile in = sample_results();
  const fs::path p = dir_ / "r.h5";
  write_results_file(p, in);
  EXPECT_EQ(listing(), std::vector<std::string>{"r.h5"});  // no temporary left
  const ResultsFile out = read_results_file(p);
  expect_same(in, out);
}

// The layout seen by a reader that knows only HDF5: H5MD version {1, 1},
// strings as variable-length UTF-8, no bodies group for an unsupported run,
// zero-row tables present, the case digest equal to FIPS 180-2's "abc" vector,
// large datasets chunked with shuffle and deflate, small ones contiguous.
TEST_F(ResultsFileTest, LayoutAsSpecified) {
  const fs::path p = dir_ / "r.h5";
  write_results_file(p, sample_results());
  H5File f(p, H5F_ACC_RDONLY);
  ASSERT_GE(f.id, 0);

  int version[2] = {0, 0};
  const hid_t va = H5Aopen_by_name(f.id, "/h5md", "version", H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(H5Aread(va, H5T_NATIVE_INT, version), 0);
  H5Aclose(va);
  EXPECT_EQ(version[0], 1);
  EXPECT_EQ(version[1], 1);
  EXPECT_EQ(read_vlen_string_attribute(f.id, "/h5md/author", "name"), "planarbench");
  EXPECT_EQ(read_vlen_string_attribute(f.id, "/parameters", "host"), "test-host");
  EXPECT_EQ(read_vlen_string_attribute(f.id, "/runs/dual_pendulum", "case_sha256"),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(read_vlen_string_attribute(f.id, "/runs/falling_ball", "overrides"),
            R"({"dt":"1e-4","contact.stiffness":"2e4","b.z":"ü"})");
  EXPECT_EQ(read_vlen_string_attribute(f.id, "/runs/falling_ball/box2d", "status"), "unsupported");
  EXPECT_EQ(
      read_vlen_string_attribute(f.id, "/runs/falling_ball/reference/bodies/ball/position", "unit"),
      "m");

  EXPECT_EQ(H5Lexists(f.id, "/runs/falling_ball/box2d/bodies", H5P_DEFAULT), 0);
  EXPECT_GT(H5Lexists(f.id, "/runs/falling_ball/reference/bodies", H5P_DEFAULT), 0);

  // zero-row tables of the diverged run exist with shape [0]
  for (const char* t : {"/runs/falling_ball/mujoco/contacts", "/runs/falling_ball/mujoco/events",
                        "/runs/falling_ball/box2d/events"}) {
    const hid_t d = H5Dopen2(f.id, t, H5P_DEFAULT);
    ASSERT_GE(d, 0) << t;
    const hid_t s = H5Dget_space(d);
    hsize_t n = 99;
    H5Sget_simple_extent_dims(s, &n, nullptr);
    EXPECT_EQ(n, 0u) << t;
    H5Sclose(s);
    H5Dclose(d);
  }

  // storage: 5000 rows are chunked + shuffled + deflated, 7 rows contiguous
  auto layout = [&](const char* name, int* nfilters) {
    const hid_t d = H5Dopen2(f.id, name, H5P_DEFAULT);
    const hid_t pl = H5Dget_create_plist(d);
    const H5D_layout_t l = H5Pget_layout(pl);
    *nfilters = H5Pget_nfilters(pl);
    H5Pclose(pl);
    H5Dclose(d);
    return l;
  };
  int nf = -1;
  EXPECT_EQ(layout("/runs/dual_pendulum/analytic/bodies/upper/position", &nf), H5D_CHUNKED);
  EXPECT_EQ(nf, 2);  // shuffle, deflate
  EXPECT_EQ(layout("/runs/dual_pendulum/analytic/contacts", &nf), H5D_CHUNKED);
  EXPECT_EQ(nf, 2);
  EXPECT_EQ(layout("/runs/falling_ball/reference/bodies/ball/time", &nf), H5D_CONTIGUOUS);
  EXPECT_EQ(nf, 0);
}

// A file written before the contacts table had its friction columns (issue 32)
// still reads; its tangential force and slip are "not recorded" (NaN), never
// 0, and every other column is as written. The old table is made by h5py
// from the new one, without the two fields.
TEST_F(ResultsFileTest, AFileWithoutTheFrictionColumnsReadsThemAsNotRecorded) {
  const fs::path p = dir_ / "old.h5";
  const ResultsFile in = sample_results();
  write_results_file(p, in);
  const std::string py =
      "/usr/bin/python3 -c 'import h5py, numpy, sys\n"
      "with h5py.File(sys.argv[1], \"r+\") as f:\n"
      "    def strip(name, obj):\n"
      "        if isinstance(obj, h5py.Dataset) and name.endswith(\"/contacts\"):\n"
      "            rows = obj[()]\n"
      "            keep = [n for n in rows.dtype.names if n not in (\"tangential_force_n\", \"slip_mps\")]\n"
      "            old = numpy.empty(len(rows), dtype=[(n, rows.dtype[n]) for n in keep])\n"
      "            for n in keep: old[n] = rows[n]\n"
      "            todo.append((name, old))\n"
      "    todo = []\n"
      "    f.visititems(strip)\n"
      "    for name, old in todo:\n"
      "        del f[name]\n"
      "        f.create_dataset(name, data=old)\n"
      "' " + p.string();
  ASSERT_EQ(std::system(py.c_str()), 0) << py;
  const ResultsFile out = read_results_file(p);
  std::size_t rows = 0;
  for (std::size_t c = 0; c < in.cases.size(); ++c) {
    for (std::size_t r = 0; r < in.cases[c].runs.size(); ++r) {
      const auto& a = in.cases[c].runs[r].contacts;
      const auto& b = out.cases[c].runs[r].contacts;
      ASSERT_EQ(a.size(), b.size());
      for (std::size_t i = 0; i < a.size(); ++i, ++rows) {
        EXPECT_TRUE(std::isnan(b[i].sample.tangential_force_n));
        EXPECT_TRUE(std::isnan(b[i].sample.slip_mps));
        EXPECT_SAME_DOUBLE(a[i].sample.force_n, b[i].sample.force_n);
        EXPECT_SAME_DOUBLE(a[i].time_s, b[i].time_s);
      }
    }
  }
  EXPECT_GT(rows, 5000u);
}

// ---- atomic writing ------------------------------------------------------------

TEST_F(ResultsFileTest, MissingDirectoryThrowsAndCreatesNothing) {
  const fs::path p = dir_ / "missing" / "r.h5";
  const std::string msg = input_error_message([&] { write_results_file(p, sample_results()); });
  EXPECT_NE(msg.find("--out"), std::string::npos) << msg;
  EXPECT_NE(msg.find((dir_ / "missing").string()), std::string::npos) << msg;
  EXPECT_NE(msg.find("does not exist"), std::string::npos) << msg;
  EXPECT_TRUE(listing().empty());
}

// A target that is an existing directory cannot be replaced: the write fails,
// the directory stays, and no temporary file is left beside it.
TEST_F(ResultsFileTest, TargetThatIsADirectoryFailsCleanly) {
  const fs::path p = dir_ / "r.h5";
  fs::create_directory(p);
  const std::string msg = input_error_message([&] { write_results_file(p, sample_results()); });
  EXPECT_NE(msg.find("is a folder, not a file"), std::string::npos) << msg;
  EXPECT_TRUE(fs::is_directory(p));
  EXPECT_EQ(listing(), std::vector<std::string>{"r.h5"});
}

// A failure in the middle of writing (a body name that cannot be a group
// name) leaves the previous file at the target untouched and no temporary.
TEST_F(ResultsFileTest, FailureMidWriteKeepsThePreviousFile) {
  const fs::path p = dir_ / "r.h5";
  const ResultsFile good = sample_results();
  write_results_file(p, good);
  const std::string before = slurp(p);

  ResultsFile bad = sample_results();
  bad.cases[1].runs[0].bodies[1].name = "lower/arm";
  EXPECT_THROW(write_results_file(p, bad), std::runtime_error);
  EXPECT_EQ(listing(), std::vector<std::string>{"r.h5"});
  EXPECT_EQ(slurp(p), before);

  // a table name longer than the 32-byte column fails the same way
  bad = sample_results();
  bad.cases[0].runs[0].body_names[1] = std::string(33, 'x');
  EXPECT_THROW(write_results_file(p, bad), std::runtime_error);
  EXPECT_EQ(listing(), std::vector<std::string>{"r.h5"});
  EXPECT_EQ(slurp(p), before);
}

// A write with no file there before creates nothing when it fails.
TEST_F(ResultsFileTest, FailedFirstWriteLeavesNoFile) {
  ResultsFile bad = sample_results();
  bad.cases[0].runs[0].contacts[0].sample.body_b = 7;  // not an index into body_names
  EXPECT_THROW(write_results_file(dir_ / "r.h5", bad), std::runtime_error);
  EXPECT_TRUE(listing().empty());
}

// ---- rejected inputs -----------------------------------------------------------

TEST_F(ResultsFileTest, MissingFileIsAnInputError) {
  const fs::path p = dir_ / "nope.h5";
  const std::string msg = input_error_message([&] { (void)read_results_file(p); });
  EXPECT_NE(msg.find(p.string()), std::string::npos) << msg;
  EXPECT_NE(msg.find("does not exist"), std::string::npos) << msg;
}

// The first 1000 bytes of a good file keep the HDF5 signature but lose the
// rest: HDF5 notices that the end of file is before the stored end address.
TEST_F(ResultsFileTest, TruncatedFileIsAnInputError) {
  const fs::path good = dir_ / "good.h5";
  write_results_file(good, sample_results());
  const std::string bytes = slurp(good);
  ASSERT_GT(bytes.size(), 1000u);
  const fs::path cut = dir_ / "cut.h5";
  std::ofstream(cut, std::ios::binary).write(bytes.data(), 1000);
  const std::string msg = input_error_message([&] { (void)read_results_file(cut); });
  EXPECT_NE(msg.find(cut.string()), std::string::npos) << msg;
  EXPECT_NE(msg.find("truncated"), std::string::npos) << msg;

  // and a file that is not HDF5 at all
  const fs::path text = dir_ / "text.h5";
  std::ofstream(text) << "not an HDF5 file\n";
  const std::string msg2 = input_error_message([&] { (void)read_results_file(text); });
  EXPECT_NE(msg2.find(text.string()), std::string::npos) << msg2;
  EXPECT_NE(msg2.find("not an HDF5 file"), std::string::npos) << msg2;
}

// An HDF5 file from elsewhere (one dataset, no /h5md) is named as foreign.
TEST_F(ResultsFileTest, ForeignFileNamesTheMissingGroup) {
  const fs::path p = dir_ / "foreign.h5";
  {
    const hid_t f = H5Fcreate(p.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    const hsize_t n = 3;
    const double x[3] = {1, 2, 3};
    const hid_t s = H5Screate_simple(1, &n, nullptr);
    const hid_t d = H5Dcreate2(f, "x", H5T_IEEE_F64LE, s, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, x);
    H5Dclose(d);
    H5Sclose(s);
    H5Fclose(f);
  }
  const std::string msg = input_error_message([&] { (void)read_results_file(p); });
  EXPECT_EQ(msg, p.string() + ": /h5md: group is missing (not a planarbench results file)");
}

// Objects removed from a good file are named: an attribute, a table, and a
// case text edited so that it no longer matches its digest.
TEST_F(ResultsFileTest, DamagedFileNamesTheObject) {
  const fs::path p = dir_ / "r.h5";
  write_results_file(p, sample_results());
  auto damage_and_read = [&](auto&& damage) {
    write_results_file(p, sample_results());
    {
      H5File f(p, H5F_ACC_RDWR);
      damage(f.id);
    }
    return input_error_message([&] { (void)read_results_file(p); });
  };

  std::string msg = damage_and_read(
      [](hid_t f) { H5Adelete_by_name(f, "/runs/falling_ball/mujoco", "status", H5P_DEFAULT); });
  EXPECT_EQ(msg, p.string() + ": /runs/falling_ball/mujoco: attribute 'status' is missing");

  msg = damage_and_read(
      [](hid_t f) { H5Ldelete(f, "/runs/dual_pendulum/analytic/contacts", H5P_DEFAULT); });
  EXPECT_EQ(msg, p.string() + ": /runs/dual_pendulum/analytic/contacts: dataset is missing");

  msg = damage_and_read([](hid_t f) {
    H5Adelete_by_name(f, "/runs/dual_pendulum", "case_sha256", H5P_DEFAULT);
    const hid_t g = H5Gopen2(f, "/runs/dual_pendulum", H5P_DEFAULT);
    const hid_t t = H5Tcopy(H5T_C_S1);
    H5Tset_size(t, H5T_VARIABLE);
    const hid_t s = H5Screate(H5S_SCALAR);
    const hid_t a = H5Acreate2(g, "case_sha256", t, s, H5P_DEFAULT, H5P_DEFAULT);
    const char* wrong = "0000";
    H5Awrite(a, t, &wrong);
    H5Aclose(a);
    H5Sclose(s);
    H5Tclose(t);
    H5Gclose(g);
  });
  EXPECT_EQ(msg, p.string() + ": /runs/dual_pendulum: case_sha256 does not match case_text");
}

// ---- determinism ---------------------------------------------------------------

// Two writes of the same results, more than a second apart (HDF5 timestamps
// have one-second resolution), give the same bytes; a different utc_time gives
// different bytes, so the comparison can fail.
TEST_F(ResultsFileTest, SameInputsGiveSameBytes) {
  const ResultsFile in = sample_results();
  write_results_file(dir_ / "a.h5", in);
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  write_results_file(dir_ / "b.h5", in);
  EXPECT_TRUE(slurp(dir_ / "a.h5") == slurp(dir_ / "b.h5"));

  ResultsFile later = in;
  later.provenance.utc_time = "2024-05-06T07:08:10Z";
  write_results_file(dir_ / "c.h5", later);
  EXPECT_FALSE(slurp(dir_ / "a.h5") == slurp(dir_ / "c.h5"));
}

// ---- the writer run by run (issue 12: runs written as they end) ---------------------

// Runs written in any order give the file the in-order writer gives, value
// for value, listed in the layout's order; nothing exists before the first
// run is written; a missing run fails the commit and leaves nothing.
TEST_F(ResultsFileTest, RunsWrittenInAnyOrderGiveTheSameDatasets) {
  const ResultsFile in = sample_results();
  write_results_file(dir_ / "in_order.h5", in);
  {
    ResultsFileWriter w(dir_ / "reversed.h5", in);
    EXPECT_EQ(listing(), std::vector<std::string>{"in_order.h5"}) << "made before any run";
    for (std::size_t c = in.cases.size(); c-- > 0;) {
      for (std::size_t k = in.cases[c].runs.size(); k-- > 0;) {
        w.write_run(c, k, in.cases[c].runs[k]);
      }
    }
    w.commit();
  }
  expect_same(read_results_file(dir_ / "in_order.h5"), read_results_file(dir_ / "reversed.h5"));
  {
    ResultsFileWriter w(dir_ / "partial.h5", in);
    w.write_run(0, 0, in.cases[0].runs[0]);
    EXPECT_THROW(w.commit(), std::logic_error);
  }
  EXPECT_EQ(listing(), (std::vector<std::string>{"in_order.h5", "reversed.h5"}));
}

// ---- SHA-256 -------------------------------------------------------------------

// FIPS 180-2 Appendix B vectors; the lengths around the one- and two-block
// padding boundaries (55, 56, 63, 64, 65, 119, 120 bytes of 'a') are from
// Python's hashlib.sha256, an independent implementation.
TEST(Sha256, Fips180Vectors) {
  using internal::sha256_hex;
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256_hex(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, PaddingBoundaries) {
  using internal::sha256_hex;
  const std::pair<int, const char*> cases[] = {
      {55, "9f4390f8d30c2dd92ec9f095b65e2b9ae9b0a925a5258e241c9f1e910f734318"},
      {56, "b35439a4ac6f0948b6d6f9e3c6af0f5f590ce20f1bde7090ef7970686ec6738a"},
      {63, "7d3e74a05d7db15bce4ad9ec0658ea98e3f06eeecf16b4c6fff2da457ddc2f34"},
      {64, "ffe054fe7ae0cb6dc65c3af9b61d5209f439851db43d0ba5997337df154668eb"},
      {65, "635361c48bb9eab14198e76ea8ab7f1a41685d6ad62aa9146d301d4f17eb0ae0"},
      {119, "31eba51c313a5c08226adf18d4a359cfdfd8d2e816b13f4af952f7ea6584dcfb"},
      {120, "2f3d335432c70b580af0e8e1b3674a7c020d683aa5f73aaaedfdc55af904c21c"}};
  for (const auto& [n, hex] : cases) EXPECT_EQ(sha256_hex(std::string(n, 'a')), hex) << n;
  // UTF-8 bytes are hashed as bytes (hashlib of 'héllo — δ ≥ 0'.encode())
  EXPECT_EQ(sha256_hex("héllo — δ ≥ 0"),
            "64b1f53a6c46546ccdc1955faf106a15ce2c85f396f4c8e043d14155875a16da");
}

}  // namespace
}  // namespace pb
