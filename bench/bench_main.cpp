// main() of every planarbench benchmark binary: Google Benchmark's own, plus
// planarbench's context keys in the JSON output and the benchmarks registered
// at run time from the case files (deferred_registration.hpp). It exits 1 when
// a benchmark failed (bench_errors.hpp).
#include <benchmark/benchmark.h>

#include <exception>
#include <iostream>

#include "bench_context.hpp"
#include "bench_errors.hpp"
#include "deferred_registration.hpp"

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  // a case file that fails to load is an error of the suite, not a skip
  try {
    pb::bench::add_context();
    pb::bench::run_deferred_registrations();
  } catch (const std::exception& e) {
    std::cerr << argv[0] << ": cannot set up the benchmarks: " << e.what() << '\n';
    return 1;
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  // a benchmark that failed is reported in the output; the exit code tells CTest
  if (pb::bench::error_count() > 0) {
    std::cerr << argv[0] << ": " << pb::bench::error_count() << " benchmark(s) failed\n";
    return 1;
  }
  return 0;
}
