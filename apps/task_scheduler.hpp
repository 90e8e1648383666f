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

#include <algorithm>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
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

// runs fn(i) for every task i of `plan` on `jobs` threads, longest first;
// Box2D runs are serialised (task_scheduler.hpp); the first exception wins
template <typename Fn>
void run_parallel(const std::vector<SchedulerTask>& plan, int jobs, Fn fn) {
  TaskScheduler scheduler(plan);
  std::mutex error_mutex;
  std::exception_ptr first_error;
  auto worker = [&] {
    while (const auto next = scheduler.acquire()) {
      try {
        fn(*next);
      } catch (...) {
        std::lock_guard<std::mutex> lock(error_mutex);
        if (!first_error) first_error = std::current_exception();
        scheduler.cancel();
      }
      scheduler.release(*next);
    }
  };
  const int n_threads = std::min<int>(jobs, static_cast<int>(plan.size()));
  std::vector<std::thread> threads;
  for (int t = 1; t < n_threads; ++t) threads.emplace_back(worker);
  worker();
  for (auto& t : threads) t.join();
  if (first_error) std::rethrow_exception(first_error);
}

}  // namespace pb::cli
