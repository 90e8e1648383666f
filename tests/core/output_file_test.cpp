// Tests for core/src/output_file.cpp: what a command may replace (issue 15).
// Special files are made in a temporary folder (a FIFO, links); no real
// device is ever written.
#include "planarbench/output_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "planarbench/errors.hpp"

namespace pb {
namespace {

namespace fs = std::filesystem;

class OutputFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("pb_output_file_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  static std::string read(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
  }
  // the folder's entries other than the ones given: temporaries left behind
  std::size_t entries() const {
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), {}));
  }
  // the message of the InputError that f throws ("" if none)
  template <typename F>
  static std::string refusal(F f) {
    try {
      f();
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }

  fs::path dir_;
};

TEST_F(OutputFileTest, NewAndRegularFilesAreWrittenWhole) {
  const fs::path p = dir_ / "a.txt";
  EXPECT_EQ(write_text_atomically("--out", p, "one"), p);
  EXPECT_EQ(read(p), "one");
  EXPECT_EQ(write_text_atomically("--out", p, "two"), p);
  EXPECT_EQ(read(p), "two");
  EXPECT_EQ(entries(), 1u);  // no temporary left
}

TEST_F(OutputFileTest, FifoIsRefusedBeforeAnythingAndStaysAFifo) {
  const fs::path fifo = dir_ / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string why = refusal([&] { (void)output_target("--out", fifo); });
  EXPECT_NE(why.find("--out"), std::string::npos) << why;
  EXPECT_NE(why.find("is a FIFO (named pipe), which is not replaced"), std::string::npos) << why;
  bool filled = false;
  EXPECT_NE(refusal([&] {
              (void)write_atomically("--out", fifo, [&](const fs::path&) { filled = true; });
            }),
            "");
  EXPECT_FALSE(filled) << "work was done for an output that is refused";
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(fifo)));
  EXPECT_EQ(entries(), 1u);
}

TEST_F(OutputFileTest, LinkToAFifoIsRefusedAndBothStay) {
  const fs::path fifo = dir_ / "fifo";
  const fs::path link = dir_ / "link";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  fs::create_symlink(fifo, link);
  const std::string why = refusal([&] { (void)write_text_atomically("--junit", link, "x"); });
  EXPECT_NE(why.find("--junit"), std::string::npos) << why;
  EXPECT_NE(why.find("is a symbolic link to a FIFO"), std::string::npos) << why;
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link)));
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(fifo)));
  EXPECT_EQ(entries(), 2u);
}

TEST_F(OutputFileTest, LinkToARegularFileWritesThroughAndStaysALink) {
  const fs::path target = dir_ / "target.txt";
  const fs::path link = dir_ / "link.txt";
  std::ofstream(target) << "old";
  fs::create_symlink(target, link);
  EXPECT_EQ(write_text_atomically("--out", link, "new"), fs::canonical(target));
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link)));
  EXPECT_EQ(read(target), "new");
  EXPECT_EQ(entries(), 2u);
}

TEST_F(OutputFileTest, DanglingLinkFolderAndMissingFolderAreRefused) {
  const fs::path dangling = dir_ / "dangling";
  fs::create_symlink(dir_ / "nothing", dangling);
  EXPECT_NE(refusal([&] { (void)output_target("--out", dangling); }).find("which does not exist"),
            std::string::npos);
  EXPECT_NE(refusal([&] { (void)output_target("--out", dir_); }).find("is a folder, not a file"),
            std::string::npos);
  EXPECT_NE(refusal([&] { (void)output_target("--out", dir_ / "no" / "x.h5"); })
                .find("does not exist"),
            std::string::npos);
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dangling)));
}

TEST_F(OutputFileTest, AFailedFillLeavesTheTargetAndNoTemporary) {
  const fs::path p = dir_ / "a.txt";
  std::ofstream(p) << "kept";
  EXPECT_THROW((void)write_atomically("--out", p,
                                      [](const fs::path& tmp) {
                                        std::ofstream(tmp) << "half";
                                        throw std::runtime_error("disk full");
                                      }),
               std::runtime_error);
  EXPECT_EQ(read(p), "kept");
  EXPECT_EQ(entries(), 1u);
}

}  // namespace
}  // namespace pb
