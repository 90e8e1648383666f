// Tests for reports/src/report_provenance.cpp
#include "report_provenance.hpp"

#include <gtest/gtest.h>

#include <map>

#include "planarbench/errors.hpp"
#include "planarbench/results_file.hpp"
#include "report_files.hpp"

namespace pb::internal {
namespace {

namespace fs = std::filesystem;

TEST(ReadFileProvenance, EveryParameterAndTheCaseDigest) {
  const fs::path d = fs::temp_directory_path() / "pb_report_provenance_test";
  fs::remove_all(d);
  ensure_directory(d);
  ResultsFile results;
  results.provenance = {"planarbench run --case x", "2026-01-02T03:04:05Z", "hostname"};
  CaseRuns cr;
  cr.case_name = "x";
  cr.case_text = "abc";  // FIPS 180-2 test vector
  cr.case_path = "x.toml";
  results.cases.push_back(cr);
  write_results_file(d / "r.h5", results);

  const FileProvenance p = read_file_provenance(d / "r.h5");
  const std::map<std::string, std::string> params(p.parameters.begin(), p.parameters.end());
  EXPECT_EQ(params.at("command_line"), "planarbench run --case x");
  EXPECT_EQ(params.at("utc_time"), "2026-01-02T03:04:05Z");
  EXPECT_EQ(params.at("host"), "hostname");
  // written from the build's provenance; present whatever their value
  for (const char* key : {"build_revision", "compiler", "compiler_flags", "planarbench_version"}) {
    EXPECT_EQ(params.count(key), 1u) << key;
  }
  // SHA-256("abc"), FIPS 180-2 appendix B.1
  EXPECT_EQ(p.case_sha256.at("x"),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  fs::remove_all(d);
}

TEST(ReadFileProvenance, NotAnHdf5FileIsAnInputError) {
  const fs::path d = fs::temp_directory_path() / "pb_report_provenance_test_bad";
  ensure_directory(d);
  write_text_atomically(d / "x.h5", "plain text");
  EXPECT_THROW((void)read_file_provenance(d / "x.h5"), InputError);
  fs::remove_all(d);
}

}  // namespace
}  // namespace pb::internal
