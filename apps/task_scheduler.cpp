#include "task_scheduler.hpp"

#include <algorithm>

namespace pb::cli {

TaskScheduler::TaskScheduler(std::vector<SchedulerTask> tasks) : tasks_(std::move(tasks)) {
  pending_.resize(tasks_.size());
  for (std::size_t i = 0; i < tasks_.size(); ++i) pending_[i] = i;
  // most expensive first; equal costs keep the matrix order
  std::stable_sort(pending_.begin(), pending_.end(), [&](std::size_t a, std::size_t b) {
    return tasks_[a].expected_cost > tasks_[b].expected_cost;
  });
}

std::optional<std::size_t> TaskScheduler::acquire() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    if (cancelled_ || pending_.empty()) return std::nullopt;
    // the first pending task whose group is free
    const auto it = std::find_if(pending_.begin(), pending_.end(), [&](std::size_t i) {
      const std::string& g = tasks_[i].exclusive_group;
      return g.empty() || std::find(busy_groups_.begin(), busy_groups_.end(), g) == busy_groups_.end();
    });
    if (it != pending_.end()) {
      const std::size_t index = *it;
      pending_.erase(it);
      if (!tasks_[index].exclusive_group.empty()) busy_groups_.push_back(tasks_[index].exclusive_group);
      return index;
    }
    freed_.wait(lock);
  }
}

void TaskScheduler::release(std::size_t index) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const std::string& g = tasks_[index].exclusive_group;
    if (!g.empty()) {
      const auto it = std::find(busy_groups_.begin(), busy_groups_.end(), g);
      if (it != busy_groups_.end()) busy_groups_.erase(it);
    }
  }
  freed_.notify_all();
}

void TaskScheduler::cancel() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    cancelled_ = true;
  }
  freed_.notify_all();
}

double expected_cost(const std::string& engine, double duration_s) {
  // wall seconds per simulated second measured on the shipped cases (stop 1,
  // Release, 2-core Debian 12 machine): the reference solver ~0.2-3.5, the
  // three engines ~0.01-0.5, the closed forms ~0. Only the order matters.
  double per_sim_s = 0.1;
  if (engine == "reference") per_sim_s = 1.0;
  if (engine == "analytic") per_sim_s = 0.001;
  return per_sim_s * duration_s;
}

std::string exclusive_group(const std::string& engine) {
  return engine == "box2d" ? "box2d" : "";
}

}  // namespace pb::cli
