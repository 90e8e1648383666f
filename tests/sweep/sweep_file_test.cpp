// Tests for core/src/sweep_file.cpp
#include "planarbench/sweep_file.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "planarbench/errors.hpp"
#include "planarbench/results_file.hpp"

namespace {

namespace fs = std::filesystem;
using pb::RunStatus;

// a folder of this process's own: ctest may run these tests side by side
fs::path scratch(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("pb_sweep_file_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}

// A sweep of one case with two series: every kind of rung (ok, diverged with
// a reason, an error that is NaN) and values that must come back bit for bit.
pb::SweepFile sample() {
  pb::SweepFile s;
  s.provenance.command_line = "planarbench sweep --case falling_ball --engine all";
  s.provenance.utc_time = "2026-01-01T00:00:00Z";
  s.provenance.host = "testhost";
  s.repeat = 3;
  s.quick = true;
  s.dt_ladder = {1e-3, 1e-4};
  s.rtol_ladder = {1e-4, 1e-6};
  pb::SweepCase c;
  c.case_name = "falling_ball";
  c.case_text = "[case]\ndescription = \"x\"\n";
  c.case_path = "cases/falling_ball.toml";
  c.overrides = {{"reference.geometry", "exact"}};
  c.duration_s = 2.5;
  c.truth = "analytic";
  c.truth_note = "closed form";
  pb::SweepSeries a;
  a.name = "reference_rk45";
  a.engine = "reference";
  a.knob = "rtol";
  a.knob_key = "reference.rtol";
  a.knob_unit = "1";
  a.default_value = 1e-10;
  a.fixed_settings = R"({"reference.integrator":"rk45"})";
  a.rungs = {{1e-4, 0.0937, 260, 7.84e-4, RunStatus::ok, ""},
             {1e-6, 0.0957, 274, 1.13e-5, RunStatus::ok, ""}};
  pb::SweepSeries b;
  b.name = "mujoco";
  b.engine = "mujoco";
  b.knob = "dt";
  b.knob_key = "mujoco.dt";
  b.knob_unit = "s";
  b.default_value = 1e-4;
  b.fixed_settings = "{}";
  b.rungs = {{1e-3, 0.06, 498, std::nan(""), RunStatus::diverged, "at t = 0.498 s: energy runaway"},
             {1e-4, 0.3, 25000, 7.44e-3, RunStatus::ok, ""}};
  c.series = {a, b};
  s.cases = {c};
  return s;
}

TEST(SweepFile, RoundTripsEveryField) {
  const auto path = scratch("roundtrip.h5");
  const pb::SweepFile w = sample();
  pb::write_sweep_file(path, w);
  const pb::SweepFile r = pb::read_sweep_file(path);
  EXPECT_EQ(r.provenance.command_line, w.provenance.command_line);
  EXPECT_EQ(r.provenance.host, "testhost");
  EXPECT_EQ(r.repeat, 3);
  EXPECT_TRUE(r.quick);
  EXPECT_EQ(r.dt_ladder, w.dt_ladder);
  EXPECT_EQ(r.rtol_ladder, w.rtol_ladder);
  ASSERT_EQ(r.cases.size(), 1u);
  const auto& c = r.cases[0];
  EXPECT_EQ(c.case_name, "falling_ball");
  EXPECT_EQ(c.case_text, w.cases[0].case_text);
  EXPECT_EQ(c.overrides, w.cases[0].overrides);
  EXPECT_EQ(c.duration_s, 2.5);
  EXPECT_EQ(c.truth, "analytic");
  ASSERT_EQ(c.series.size(), 2u);
  // series come back in the order written (creation order)
  EXPECT_EQ(c.series[0].name, "reference_rk45");
  EXPECT_EQ(c.series[1].name, "mujoco");
  for (std::size_t k = 0; k < 2; ++k) {
    const auto& ws = w.cases[0].series[k];
    const auto& rs = c.series[k];
    EXPECT_EQ(rs.engine, ws.engine);
    EXPECT_EQ(rs.knob, ws.knob);
    EXPECT_EQ(rs.knob_key, ws.knob_key);
    EXPECT_EQ(rs.knob_unit, ws.knob_unit);
    EXPECT_EQ(rs.default_value, ws.default_value);
    EXPECT_EQ(rs.fixed_settings, ws.fixed_settings);
    ASSERT_EQ(rs.rungs.size(), ws.rungs.size());
    for (std::size_t i = 0; i < rs.rungs.size(); ++i) {
      // doubles are stored as IEEE little-endian: exact
      EXPECT_EQ(rs.rungs[i].value, ws.rungs[i].value);
      EXPECT_EQ(rs.rungs[i].wall_time_s, ws.rungs[i].wall_time_s);
      EXPECT_EQ(rs.rungs[i].steps, ws.rungs[i].steps);
      EXPECT_EQ(std::isnan(rs.rungs[i].position_error_m), std::isnan(ws.rungs[i].position_error_m));
      if (!std::isnan(ws.rungs[i].position_error_m)) {
        EXPECT_EQ(rs.rungs[i].position_error_m, ws.rungs[i].position_error_m);
      }
      EXPECT_EQ(rs.rungs[i].status, ws.rungs[i].status);
      EXPECT_EQ(rs.rungs[i].reason, ws.rungs[i].reason);
    }
  }
}

TEST(SweepFile, MissingDirectoryIsInputErrorAndLeavesNothing) {
  const fs::path dir = scratch("no_such_dir");
  fs::remove_all(dir);
  EXPECT_THROW(pb::write_sweep_file(dir / "s.h5", sample()), pb::InputError);
  EXPECT_FALSE(fs::exists(dir));
}

TEST(SweepFile, RewriteReplacesTheFileAndLeavesNoTemporary) {
  const auto path = scratch("rewrite.h5");
  pb::write_sweep_file(path, sample());
  pb::SweepFile second = sample();
  second.repeat = 5;
  pb::write_sweep_file(path, second);
  EXPECT_EQ(pb::read_sweep_file(path).repeat, 5);
  for (const auto& e : fs::directory_iterator(path.parent_path())) {
    EXPECT_EQ(e.path().filename().string().find(".tmp."), std::string::npos) << e.path();
  }
}

TEST(SweepFile, ResultsFileIsNotASweepFile) {
  const auto path = scratch("results.h5");
  pb::ResultsFile results;
  results.provenance.command_line = "planarbench run";
  pb::write_results_file(path, results);
  try {
    (void)pb::read_sweep_file(path);
    FAIL() << "a results file was read as a sweep file";
  } catch (const pb::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sweep"), std::string::npos) << e.what();
  }
}

TEST(SweepFile, NonHdf5FileIsInputErrorNamingIt) {
  const auto path = scratch("text.h5");
  std::ofstream(path) << "not hdf5\n";
  try {
    (void)pb::read_sweep_file(path);
    FAIL() << "a text file was read";
  } catch (const pb::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("text.h5"), std::string::npos) << e.what();
  }
}

}  // namespace
