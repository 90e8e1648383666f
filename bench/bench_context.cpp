#include "bench_context.hpp"

#include <benchmark/benchmark.h>

#include <fstream>
#include <sstream>
#include <string>

#include "planarbench/build_info.hpp"
#include "planarbench/engines.hpp"
#include "planarbench/machine.hpp"

namespace pb::bench {

namespace {

// The build type the benchmark library was compiled as, in its own words.
// Google Benchmark 1.7.1 has no API for it: its JSON reporter writes
// "library_build_type" ("debug" when the library was compiled without NDEBUG,
// src/json_reporter.cc), so the reporter is asked to write its context into a
// string and the value is read back. Debian's libbenchmark1debian is built
// with CMAKE_BUILD_TYPE=None (-g -O2, no NDEBUG) and says "debug".
std::string library_build_type() {
  std::ostringstream out;
  std::ostringstream err;
  benchmark::JSONReporter reporter;
  reporter.SetOutputStream(&out);
  reporter.SetErrorStream(&err);
  reporter.ReportContext(benchmark::BenchmarkReporter::Context{});
  const std::string text = out.str();
  const std::string key = "\"library_build_type\": \"";
  const auto at = text.find(key);
  if (at == std::string::npos) return "unknown";
  const auto begin = at + key.size();
  const auto end = text.find('"', begin);
  return end == std::string::npos ? "unknown" : text.substr(begin, end - begin);
}

// the value of the first line of `path` that starts with `prefix`, or "unknown"
std::string line_value(const char* path, const std::string& prefix) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(prefix, 0) != 0) continue;
    std::string value = line.substr(prefix.size());
    // /etc/os-release quotes its values
    if (value.size() >= 2 && value.front() == '"' && value.back() == '"') {
      value = value.substr(1, value.size() - 2);
    }
    return value;
  }
  return "unknown";
}

}  // namespace

void add_context() {
  // what was built: compare.py warns when any of these differ from the baseline
  benchmark::AddCustomContext("planarbench_version", build_info::kVersion);
  benchmark::AddCustomContext("planarbench_revision", build_info::kRevision);
  benchmark::AddCustomContext("planarbench_build_type", build_info::kBuildType);
  benchmark::AddCustomContext("planarbench_compiler", build_info::kCompiler);
  benchmark::AddCustomContext("planarbench_flags", build_info::kFlags);
  const std::string sanitize = build_info::kSanitize;
  benchmark::AddCustomContext("planarbench_sanitize", sanitize.empty() ? "none" : sanitize);

  // every engine's version as the engine reports it, key "engine.<name>"
  for (const auto& name : engine_names()) {
    benchmark::AddCustomContext("engine." + name, make_engine(name)->version());
  }

  // the benchmark library's own build ("debug" for Debian's package: see above)
  benchmark::AddCustomContext("benchmark_library_build_type", library_build_type());

  // the machine, beyond the library's host name and CPU count: the CPU model
  // (x86 /proc/cpuinfo) and the OS
  benchmark::AddCustomContext("machine_cpu_model", machine_cpu_model());
  benchmark::AddCustomContext("machine_os", line_value("/etc/os-release", "PRETTY_NAME="));
}

}  // namespace pb::bench
