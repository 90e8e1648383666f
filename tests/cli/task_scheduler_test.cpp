// Tests for apps/task_scheduler.cpp
#include "task_scheduler.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

namespace pb::cli {
namespace {

std::vector<std::size_t> drain(TaskScheduler& s) {
  std::vector<std::size_t> order;
  while (const auto i = s.acquire()) {
    order.push_back(*i);
    s.release(*i);
  }
  return order;
}

TEST(TaskScheduler, HandsOutTheMostExpensiveFirstAndKeepsMatrixOrderOnTies) {
  TaskScheduler s({{1.0, ""}, {5.0, ""}, {1.0, ""}, {3.0, ""}});
  EXPECT_EQ(drain(s), (std::vector<std::size_t>{1, 3, 0, 2}));
}

TEST(TaskScheduler, SkipsATaskWhoseGroupIsBusy) {
  TaskScheduler s({{9.0, "box2d"}, {8.0, "box2d"}, {1.0, ""}});
  const auto first = s.acquire();
  ASSERT_TRUE(first);
  EXPECT_EQ(*first, 0u);
  // task 1 waits for box2d: the next worker gets task 2
  const auto second = s.acquire();
  ASSERT_TRUE(second);
  EXPECT_EQ(*second, 2u);
  s.release(0);
  const auto third = s.acquire();
  ASSERT_TRUE(third);
  EXPECT_EQ(*third, 1u);
  s.release(1);
  s.release(2);
  EXPECT_FALSE(s.acquire());
}

TEST(TaskScheduler, ABlockedWorkerGetsTheTaskWhenTheGroupIsFreed) {
  TaskScheduler s({{2.0, "g"}, {1.0, "g"}});
  ASSERT_EQ(s.acquire(), std::optional<std::size_t>(0));
  std::atomic<bool> got{false};
  std::optional<std::size_t> taken;
  std::thread waiter([&] {
    taken = s.acquire();
    got = true;
  });
  // while task 0 holds group g, the waiter cannot have task 1 (whatever the timing)
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_FALSE(got.load());
  s.release(0);
  waiter.join();
  EXPECT_EQ(taken, std::optional<std::size_t>(1));
}

TEST(TaskScheduler, NeverRunsTwoTasksOfOneGroupAtOnce) {
  std::vector<SchedulerTask> tasks;
  for (int i = 0; i < 200; ++i) tasks.push_back({static_cast<double>(i % 7), i % 3 ? "box2d" : ""});
  TaskScheduler s(std::move(tasks));
  std::atomic<int> in_group{0};
  std::atomic<int> worst{0};
  std::atomic<int> done{0};
  auto worker = [&] {
    while (const auto i = s.acquire()) {
      const bool grouped = *i % 3 != 0;
      if (grouped) {
        const int now = ++in_group;
        int w = worst.load();
        while (now > w && !worst.compare_exchange_weak(w, now)) {
        }
        std::this_thread::yield();
        --in_group;
      }
      ++done;
      s.release(*i);
    }
  };
  std::thread a(worker), b(worker), c(worker);
  a.join();
  b.join();
  c.join();
  EXPECT_EQ(done.load(), 200);
  EXPECT_EQ(worst.load(), 1);
}

TEST(TaskScheduler, CancelStopsHandingOutAndWakesWaiters) {
  TaskScheduler s({{2.0, "g"}, {1.0, "g"}});
  ASSERT_TRUE(s.acquire());
  std::optional<std::size_t> taken{99};
  std::thread waiter([&] { taken = s.acquire(); });
  s.cancel();
  waiter.join();
  EXPECT_FALSE(taken);
}

TEST(TaskScheduler, Box2dIsTheOnlyExclusiveEngine) {
  EXPECT_EQ(exclusive_group("box2d"), "box2d");
  for (const char* e : {"analytic", "reference", "mujoco", "ode"}) EXPECT_EQ(exclusive_group(e), "");
}

// the order the costs give, not their values: the dual pendulum at its 1e-5 s
// step on Box2D and ODE (the longest runs of the matrix) first, the closed
// forms last, longer cases before shorter ones, and a case the table does
// not know still ordered by duration
TEST(TaskScheduler, ExpectedCostsPutTheLongestRunsFirst) {
  for (const char* c : {"falling_ball", "sliding", "sliding_paper", "square_landing"}) {
    for (const char* e : {"reference", "mujoco", "box2d", "ode"}) {
      EXPECT_GT(expected_cost("dual_pendulum", "box2d", 2.0), expected_cost(c, e, 2.5)) << c << e;
      EXPECT_GT(expected_cost("dual_pendulum", "ode", 2.0), expected_cost(c, e, 2.5)) << c << e;
    }
  }
  EXPECT_GT(expected_cost("my_case", "mujoco", 1.0), expected_cost("my_case", "analytic", 1.0));
  EXPECT_GT(expected_cost("my_case", "mujoco", 2.0), expected_cost("my_case", "mujoco", 1.0));
}

}  // namespace
}  // namespace pb::cli
