// Hands the tasks of a case x engine matrix to worker threads.
//
// Order: longest expected task first (LPT, Graham 1969: with two workers the
// makespan is within 7/6 of the optimum), so that one long run does not start
// last and leave the other core idle. Exclusive groups: at most one task of a
// group runs at a time (Box2D 2.4.1 increments process-global counters such as
// b2_gjkCalls and b2_toiCalls from every world: a data race when two worlds step
// in two threads; /work/shared/ENGINES.md). Where a task runs never changes its
// result: results are stored by task index.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace pb::cli {

struct SchedulerTask {
  double expected_cost = 0.0;   // any unit, only the order matters
  std::string exclusive_group;  // "" = may run beside anything
};

class TaskScheduler {
 public:
  explicit TaskScheduler(std::vector<SchedulerTask> tasks);

  // the index of the next task this worker should run; blocks while every
  // remaining task waits for its group; nullopt when none is left (or after cancel)
  [[nodiscard]] std::optional<std::size_t> acquire();
  // the task finished (its group is free again)
  void release(std::size_t index);
  // hand out nothing more
  void cancel();

 private:
  std::vector<SchedulerTask> tasks_;
  std::vector<std::size_t> pending_;  // task indices, most expensive first
  std::vector<std::string> busy_groups_;
  bool cancelled_ = false;
  std::mutex mutex_;
  std::condition_variable freed_;
};

// Expected wall time of running `engine` on case `case_name` of `duration_s`
// simulated seconds: measured for the shipped cases, a coarse per-engine
// guess for others. Good enough to put the long runs first; it never changes
// a result.
[[nodiscard]] double expected_cost(const std::string& case_name, const std::string& engine,
                                   double duration_s);

// The exclusive group of an engine ("" when its worlds are independent).
[[nodiscard]] std::string exclusive_group(const std::string& engine);

}  // namespace pb::cli
