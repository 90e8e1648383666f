// Tests for reports/src/report_files.cpp
#include "report_files.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "planarbench/errors.hpp"

namespace pb::internal {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("pb_report_files_test_" + name);
  fs::remove_all(d);
  return d;
}

TEST(WriteTextAtomically, WritesWholeAndLeavesNoTemporary) {
  const fs::path d = fresh_dir("write");
  ensure_directory(d / "a" / "b");
  const fs::path f = d / "a" / "b" / "x.txt";
  write_text_atomically(f, "first");
  write_text_atomically(f, std::string("second\0bytes", 12));
  EXPECT_EQ(read_text_file(f), std::string("second\0bytes", 12));
  EXPECT_FALSE(fs::exists(f.string() + ".tmp"));
  fs::remove_all(d);
}

TEST(WriteTextAtomically, MissingFolderIsAnInputError) {
  const fs::path d = fresh_dir("missing");
  EXPECT_THROW(write_text_atomically(d / "nope" / "x.txt", "x"), InputError);
}

TEST(EnsureDirectory, AFileInTheWayIsAnInputError) {
  const fs::path d = fresh_dir("file");
  ensure_directory(d);
  write_text_atomically(d / "f", "x");
  EXPECT_THROW(ensure_directory(d / "f"), InputError);
  EXPECT_THROW((void)read_text_file(d / "absent"), InputError);
  fs::remove_all(d);
}

}  // namespace
}  // namespace pb::internal
