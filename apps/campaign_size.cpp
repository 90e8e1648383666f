#include "campaign_size.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <utility>

namespace pb::cli {

std::string plan_size_problem(std::int64_t runs) {
  if (runs <= kMaxPlannedRuns) return "";
  const double gib = static_cast<double>(runs) * static_cast<double>(kPlanBytesPerRun) /
                     static_cast<double>(kPlanMemoryLimitBytes);
  return fmt::format(
      "the campaign would have {} runs; its plan takes {} bytes per run ({:.3g} GiB), more than "
      "the limit of 1 GiB: at most {} runs (fewer axis points, cases or engines, or several "
      "campaigns)",
      runs, kPlanBytesPerRun, gib, kMaxPlannedRuns);
}

namespace {
using Clock = std::chrono::steady_clock;
// the plan's first step, and the last line printed (one plan per process)
Clock::time_point& plan_start() {
  static Clock::time_point t = Clock::now();
  return t;
}
Clock::time_point& last_line() {
  static Clock::time_point t = plan_start();
  return t;
}
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
}  // namespace

PlanProgress::PlanProgress(std::string what, std::int64_t total, bool quiet)
    : what_(std::move(what)), total_(total), quiet_(quiet) {
  (void)last_line();  // starts the plan's clock
}

void PlanProgress::say(const std::string& what) const {
  if (quiet_ || seconds_since(plan_start()) < 1.0) return;
  last_line() = Clock::now();
  std::fprintf(stderr, "campaign plan: %s, %.1f s\n", what.c_str(), seconds_since(plan_start()));
  std::fflush(stderr);
}

void PlanProgress::report(std::int64_t done) {
  if (seconds_since(last_line()) < 1.0) return;
  last_line() = Clock::now();
  std::fprintf(stderr, "campaign plan: %s: %lld of %lld runs (%.0f %%), %.1f s\n", what_.c_str(),
               static_cast<long long>(done), static_cast<long long>(total_),
               total_ > 0 ? 100.0 * static_cast<double>(done) / static_cast<double>(total_) : 100.0,
               seconds_since(plan_start()));
  std::fflush(stderr);
}

}  // namespace pb::cli
