// Errors inside a benchmark (an engine that throws, a case it cannot build).
// Google Benchmark records SkipWithError in the output but still exits 0; the
// suite counts them so that main() exits 1 and the quick CTest fails.
#pragma once

#include <benchmark/benchmark.h>

#include <atomic>
#include <string>

namespace pb::bench {

// benchmarks that ended in an error so far
inline std::atomic<int>& error_count() {
  static std::atomic<int> count{0};
  return count;
}

// marks the running benchmark as failed (call, then leave the timing loop)
inline void skip_with_error(benchmark::State& state, const std::string& message) {
  ++error_count();
  state.SkipWithError(message.c_str());
}

}  // namespace pb::bench
