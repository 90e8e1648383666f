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

namespace {

// Wall seconds per simulated second of each shipped case on each engine at
// its default settings, measured with `planarbench run --case all --engine
// all --jobs 1` (the runs' wall_time_s; Release, Debian 12, 2 cores,
// 2026-11-25). The spread is a factor 50 and does not follow the engine
// alone: dual_pendulum runs every engine at the case's 1e-5 s step (Box2D,
// ODE, MuJoCo its three costliest runs), the reference's outline search is
// costliest on sustained face contact (incline_launch), Box2D on a
// 30-piece ellipse.
struct MeasuredCost {
  const char* case_name;
  const char* engine;
  double wall_s_per_sim_s;
};
constexpr MeasuredCost kMeasured[] = {
    {"dual_pendulum", "box2d", 0.92},          {"dual_pendulum", "ode", 0.55},
    {"incline_launch", "reference", 0.35},     {"ellipse_incline", "box2d", 0.35},
    {"dual_pendulum", "mujoco", 0.27},         {"sliding_paper", "reference", 0.11},
    {"head_on", "reference", 0.11},            {"sliding", "reference", 0.08},
    {"ellipse_incline", "ode", 0.08},          {"incline_launch", "mujoco", 0.067},
    {"sliding_paper", "mujoco", 0.063},        {"ellipse_incline", "reference", 0.059},
    {"sliding", "mujoco", 0.056},              {"incline_launch", "ode", 0.055},
    {"head_on", "mujoco", 0.051},              {"concave_arch", "box2d", 0.047},
    {"concave_arch", "mujoco", 0.043},         {"sliding_paper", "box2d", 0.04},
    {"incline_launch", "box2d", 0.04},         {"sliding_paper", "ode", 0.038},
    {"sliding", "ode", 0.036},                 {"head_on", "ode", 0.034},
    {"square_landing", "mujoco", 0.034},       {"ellipse_incline", "mujoco", 0.032},
    {"sliding", "box2d", 0.03},                {"pendulum_wall", "box2d", 0.029},
    {"pendulum_wall", "ode", 0.028},           {"falling_ball_paper", "box2d", 0.028},
    {"pendulum_wall", "mujoco", 0.027},        {"concave_arch", "ode", 0.027},
    {"falling_ball", "box2d", 0.026},          {"falling_ball_paper", "mujoco", 0.025},
    {"square_landing", "box2d", 0.024},        {"falling_ball", "mujoco", 0.024},
    {"falling_ball", "ode", 0.023},            {"concave_arch", "reference", 0.023},
    {"falling_ball_paper", "ode", 0.023},      {"square_landing", "ode", 0.022},
    {"head_on", "box2d", 0.021},               {"pendulum_wall", "reference", 0.017},
    {"square_landing", "reference", 0.016},    {"falling_ball", "reference", 0.012},
    {"falling_ball_paper", "reference", 0.012}, {"dual_pendulum", "reference", 0.012},
    {"dual_pendulum", "analytic", 0.01},       {"incline_launch", "analytic", 0.01},
};

}  // namespace

double expected_cost(const std::string& case_name, const std::string& engine, double duration_s) {
  for (const MeasuredCost& m : kMeasured) {
    if (case_name == m.case_name && engine == m.engine) return m.wall_s_per_sim_s * duration_s;
  }
  // any other case: the median of each engine's measured costs above (the
  // closed forms: ~0); a guess that only puts long runs before short ones
  double per_sim_s = 0.025;
  if (engine == "reference") per_sim_s = 0.03;
  if (engine == "ode") per_sim_s = 0.05;
  if (engine == "analytic") per_sim_s = 0.001;
  return per_sim_s * duration_s;
}

std::string exclusive_group(const std::string& engine) {
  return engine == "box2d" ? "box2d" : "";
}

}  // namespace pb::cli
