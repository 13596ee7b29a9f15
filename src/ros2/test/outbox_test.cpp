// The writing thread: jobs in order, flush, the clock channel coalescing to the newest time and
// never going back, a full queue dropping (and counting) instead of blocking the producer.
#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>

#include <gtest/gtest.h>

#include "ros2/outbox.hpp"

namespace mechsim::ros2 {
namespace {

TEST(Outbox, RunsJobsInOrderAndFlushWaitsForThem) {
  std::vector<int> order;
  std::mutex m;
  Outbox outbox([](double) {});
  for (int i = 0; i < 100; ++i) {
    ASSERT_TRUE(outbox.post([&, i] {
      std::lock_guard<std::mutex> lock(m);
      order.push_back(i);
    }));
    outbox.end_of_tick();
  }
  outbox.flush();
  std::lock_guard<std::mutex> lock(m);
  ASSERT_EQ(order.size(), 100u);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(order[i], i);
}

TEST(Outbox, ClockGoesOutNewestFirstAndNeverBackwards) {
  std::vector<double> sent;
  std::mutex m;
  {
    Outbox outbox([&](double t) {
      std::this_thread::sleep_for(std::chrono::microseconds(200));  // a slow writer
      std::lock_guard<std::mutex> lock(m);
      sent.push_back(t);
    });
    for (int tick = 1; tick <= 3000; ++tick) {
      outbox.set_clock(tick * 0.001);
      outbox.end_of_tick();
    }
    outbox.flush();
    EXPECT_GT(outbox.stats().coalesced, 0u);
  }
  ASSERT_FALSE(sent.empty());
  EXPECT_DOUBLE_EQ(sent.back(), 3.0);  // the newest always goes out
  for (std::size_t i = 1; i < sent.size(); ++i) EXPECT_GT(sent[i], sent[i - 1]);
}

TEST(Outbox, AFullQueueDropsAndCounts) {
  std::atomic<bool> release{false};
  Outbox outbox([](double) {});
  outbox.post([&] {
    while (!release.load()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  });
  outbox.end_of_tick();
  std::this_thread::sleep_for(std::chrono::milliseconds(20));  // the thread is in the blocking job
  int refused = 0;
  for (int i = 0; i < 600; ++i) refused += outbox.post([] {}) ? 0 : 1;
  EXPECT_GT(refused, 0);
  release.store(true);
  outbox.flush();
  EXPECT_EQ(outbox.stats().dropped, static_cast<std::uint64_t>(refused));
}

}  // namespace
}  // namespace mechsim::ros2
