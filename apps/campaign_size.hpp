// How large a campaign may be, and what `campaign plan` says while a large
// one is planned (issue 24).
//
// Planning holds, per run, its estimated cost and id while the runs are
// dealt to shards (16 bytes: a double and an int64) and its id in its
// shard's list (8 bytes, which a growing list may double to 16): at most
// kPlanBytesPerRun = 32 bytes per run. A campaign whose plan would take more
// than kPlanMemoryLimitBytes = 1 GiB, more than kMaxPlannedRuns = 33,554,432
// runs, is refused when it is read (`campaign plan` and `campaign run`), with
// the formula and the limit in the message.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace pb::cli {

inline constexpr std::int64_t kPlanBytesPerRun = 32;
inline constexpr std::int64_t kPlanMemoryLimitBytes = std::int64_t{1} << 30;  // 1 GiB
inline constexpr std::int64_t kMaxPlannedRuns = kPlanMemoryLimitBytes / kPlanBytesPerRun;

// "" when a plan of `runs` fits the limit, else what is wrong and what is allowed
[[nodiscard]] std::string plan_size_problem(std::int64_t runs);

// Progress of the steps of a plan on stderr: nothing during the plan's first
// second (counted from the first step), then at most a line a second,
// "campaign plan: WHAT: K of N runs (P %), T s". Cheap to call per run (the
// clock is read every 4096 calls). One plan at a time (not thread-safe).
class PlanProgress {
 public:
  PlanProgress(std::string what, std::int64_t total, bool quiet);
  void tick(std::int64_t done) {
    if (quiet_ || (++calls_ & 4095) != 0) return;
    report(done);
  }
  // a line for a step without a count ("sorting ..."), past the first second
  void say(const std::string& what) const;

 private:
  void report(std::int64_t done);
  std::string what_;
  std::int64_t total_;
  bool quiet_;
  std::uint64_t calls_ = 0;
};

}  // namespace pb::cli
