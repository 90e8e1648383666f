// Tests for core/src/machine.cpp against other programs' view of the machine:
// `nproc` (coreutils, the affinity mask) and `lscpu` (util-linux, its own
// parser of /proc/cpuinfo).
#include "planarbench/machine.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace pb {
namespace {

// the first line a shell command prints, without its newline; "" if none
std::string first_line(const char* command) {
  std::string out;
  if (FILE* p = popen(command, "r")) {
    char buf[512];
    if (fgets(buf, sizeof buf, p) != nullptr) out = buf;
    pclose(p);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
  return out;
}

TEST(Machine, CpusAsNprocCounts) {
  const std::string n = first_line("nproc 2>/dev/null");
  if (n.empty()) GTEST_SKIP() << "nproc is not available";
  EXPECT_EQ(machine_cpus(), std::stoi(n));
}

TEST(Machine, CpuModelAsLscpuNamesIt) {
  const std::string line = first_line("LC_ALL=C lscpu 2>/dev/null | grep -m1 '^Model name:'");
  if (line.empty()) GTEST_SKIP() << "lscpu names no model here (not x86, or util-linux missing)";
  const std::string model = line.substr(line.find_first_not_of(' ', line.find(':') + 1));
  EXPECT_EQ(machine_cpu_model(), model);
}

}  // namespace
}  // namespace pb
