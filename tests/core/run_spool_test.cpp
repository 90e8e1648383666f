// Tests for core/src/run_spool.cpp: a run whose samples stream to disk as it
// proceeds gives the results file a run kept in memory gives (issue 15).
// The engine is the real analytic truth (closed forms); the comparison is
// between the two write paths, bit for bit, not against stored numbers.
#include "planarbench/run_spool.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "planarbench/case_loader.hpp"
#include "planarbench/engines.hpp"
#include "planarbench/results_file.hpp"
#include "planarbench/runner.hpp"

namespace pb {
namespace {

namespace fs = std::filesystem;

std::string bytes_of(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), {}};
}

// bitwise equality of doubles (NaN payloads included)
bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

class RunSpoolTest : public ::testing::TestWithParam<const char*> {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("pb_run_spool_test_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// falling_ball: 2 bodies' worth of trajectories over 3 chunks, a few hundred
// contact rows (contiguous); sliding: contact rows in every sample (chunked)
TEST_P(RunSpoolTest, SpooledAndInMemoryRunsWriteTheSameFile) {
  const Case c = load_case(fs::path(PB_CASES_DIR) / (std::string(GetParam()) + ".toml"));
  ResultsFile files[2];
  for (int spooled = 0; spooled < 2; ++spooled) {
    auto engine = make_engine("analytic");
    RunOptions o;
    if (spooled) o.spool_dir = dir_;
    RunResult r = run_engine(*engine, c, {}, o);
    ASSERT_EQ(r.status, RunStatus::ok) << r.reason;
    EXPECT_EQ(r.spool != nullptr, spooled == 1);
    if (spooled) {
      EXPECT_TRUE(r.bodies.empty());
      EXPECT_TRUE(r.contacts.empty());
      ASSERT_EQ(r.spool->samples(0), static_cast<std::size_t>(c.output_samples()));
      EXPECT_EQ(r.spool->contact_rows(), files[0].cases[0].runs[0].contacts.size());
    }
    r.wall_time_s = 0.0;  // the one field that differs from run to run
    files[spooled].provenance = {"test", "2026-01-01T00:00:00Z", "host"};
    files[spooled].cases.push_back(CaseRuns{c.name, c.source_text, c.source_path, {}, {}});
    files[spooled].cases[0].runs.push_back(std::move(r));
  }
  // the spool's file is unlinked: nothing of it is in the folder
  EXPECT_TRUE(fs::is_empty(dir_));
  write_results_file(dir_ / "memory.h5", files[0], 1);
  write_results_file(dir_ / "spooled.h5", files[1], 1);
  // the same datasets, value for value
  const ResultsFile a = read_results_file(dir_ / "memory.h5");
  const ResultsFile b = read_results_file(dir_ / "spooled.h5");
  const RunResult& ra = a.cases[0].runs[0];
  const RunResult& rb = b.cases[0].runs[0];
  ASSERT_EQ(ra.bodies.size(), rb.bodies.size());
  for (std::size_t j = 0; j < ra.bodies.size(); ++j) {
    EXPECT_TRUE(same_bits(ra.bodies[j].time_s, rb.bodies[j].time_s));
    EXPECT_TRUE(same_bits(ra.bodies[j].angle_rad, rb.bodies[j].angle_rad));
    EXPECT_TRUE(same_bits(ra.bodies[j].angular_velocity_radps,
                          rb.bodies[j].angular_velocity_radps));
    EXPECT_EQ(ra.bodies[j].position_m, rb.bodies[j].position_m);
    EXPECT_EQ(ra.bodies[j].velocity_mps, rb.bodies[j].velocity_mps);
  }
  ASSERT_EQ(ra.contacts.size(), rb.contacts.size());
  // and the same bytes: the spool writes the chunks the in-memory path encodes
  EXPECT_EQ(bytes_of(dir_ / "memory.h5"), bytes_of(dir_ / "spooled.h5"));
}

INSTANTIATE_TEST_SUITE_P(Cases, RunSpoolTest, ::testing::Values("falling_ball", "sliding"));

}  // namespace
}  // namespace pb
