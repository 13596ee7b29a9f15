#include "control/ports.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

namespace mechsim::control {
namespace {

TEST(Ports, ArrayCommandsAreNeverTornBetweenThreads) {
  ArrayCommandPort port("command", 64);
  std::atomic<bool> done{false};
  std::thread writer([&] {
    std::vector<double> v(64);
    for (int k = 1; k <= 20000; ++k) {
      std::fill(v.begin(), v.end(), static_cast<double>(k));
      ASSERT_TRUE(port.write(v));
    }
    done = true;
  });
  double last = 0.0;
  long reads = 0;
  while (!done || reads < 10) {
    const std::vector<double>& v = port.read_from_rt();
    ASSERT_EQ(v.size(), 64u);
    for (double x : v) ASSERT_EQ(x, v[0]);  // one write, whole
    ASSERT_GE(v[0], last);                  // never older than what was seen
    last = v[0];
    ++reads;
  }
  writer.join();
  EXPECT_EQ(port.read_from_rt()[0], 20000.0);
  EXPECT_EQ(port.count(), 0u);
}

TEST(Ports, StateSnapshotsAreWholeAndSequenced) {
  StatePort<JointGroupControllerState> port("state");
  JointGroupControllerState prototype;
  prototype.joints.resize(16);
  port.init(prototype);
  std::atomic<bool> done{false};
  std::uint64_t published = 0;
  std::thread tick([&] {
    for (int k = 1; k <= 20000; ++k) {
      // A tick that finds the snapshot being read skips its publication (try-lock), as
      // realtime_tools' publishers do; count the ones that went through.
      if (port.publish_from_rt([k](JointGroupControllerState& s) {
            s.stamp = k;
            for (auto& j : s.joints) j.command = k;
          })) {
        ++published;
      }
      if (k % 1000 == 0) std::this_thread::yield();
    }
    done = true;
  });
  std::uint64_t last_sequence = 0;
  while (!done) {
    const std::uint64_t seq = port.sequence();
    EXPECT_GE(seq, last_sequence);
    last_sequence = seq;
    auto s = port.read();
    for (const auto& j : s.joints) ASSERT_EQ(j.command, s.stamp);
    // A reader polls (a ROS publisher at its rate), it does not hold the snapshot continuously.
    std::this_thread::sleep_for(std::chrono::microseconds(20));
  }
  tick.join();
  EXPECT_EQ(port.sequence(), published);
  EXPECT_GT(published, 0u);
  EXPECT_LE(published, 20000u);
  if (published == 20000u) {
    EXPECT_EQ(port.read().stamp, 20000.0);
  }
}

TEST(Ports, ResetAtStartingDropsAPendingWrite) {
  ScalarCommandPort port("command");
  ASSERT_TRUE(port.write(4.0));  // written before the controller started
  port.reset_from_rt(1.5);       // starting(): hold the current position
  EXPECT_DOUBLE_EQ(port.read_from_rt(), 1.5);
  EXPECT_DOUBLE_EQ(port.latest(), 1.5);
  ASSERT_TRUE(port.write(2.0));
  EXPECT_DOUBLE_EQ(port.read_from_rt(), 2.0);
  EXPECT_EQ(port.accepted(), 2u);
}

}  // namespace
}  // namespace mechsim::control
