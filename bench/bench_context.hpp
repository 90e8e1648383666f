// The JSON context every planarbench benchmark records: planarbench's version,
// revision, build type, compiler, flags and sanitizer; every engine's version;
// the build type of the benchmark library; the CPU model and the OS.
#pragma once

namespace pb::bench {

// adds planarbench's keys to Google Benchmark's context (call before running)
void add_context();

}  // namespace pb::bench
