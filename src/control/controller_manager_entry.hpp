#pragma once
// ControllerManager's internals shared by its two sources (controller_manager.cpp: loading,
// switching and listing, outside the tick; controller_manager_tick.cpp: the real-time tick): a
// loaded controller's entry and the tick's allocation-free statistics helpers. Not part of the
// control layer's interface.

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstring>
#include <mutex>

#include "control/controller_manager.hpp"

namespace mechsim::control {

struct ControllerManager::Entry {
  std::string name;
  std::string type;
  std::unique_ptr<Controller> controller;
  std::vector<ResourceClaim> claims;
  std::vector<SensorUse> sensors;
  std::vector<JointHandle> handles;  // every claimed joint, made safe after a failure
  std::vector<int> joint_indices;    // for conflict checks
  bool model_plugin = false;         // add_model_plugin
  std::string origin;                // model plugins: "file:line" of the <plugin> element
  bool claims_base = false;
  // ros2_control: the controller's own update period (s; 0: every manager update) and the time
  // of its last update (NaN: none since it started).
  double update_period = 0.0;
  double last_update = 0.0;
  bool updated_since_start = false;

  std::atomic<ControllerLifecycle> state{ControllerLifecycle::Initialized};
  std::atomic<std::uint64_t> updates{0};
  std::atomic<std::uint64_t> time_sum_ns{0};
  std::atomic<std::uint64_t> time_max_ns{0};
  std::atomic<std::uint64_t> overruns{0};
  std::atomic<std::uint64_t> failures{0};

  // The failure text is written by the tick (try-lock, fixed buffer) and read outside.
  mutable std::mutex failure_mutex;
  char failure[256] = {};
};

namespace manager_detail {

using Clock = std::chrono::steady_clock;

inline std::uint64_t elapsed_ns(Clock::time_point from, Clock::time_point to) noexcept {
  return static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(to - from).count());
}

// Statistics have one writer, the tick: plain load + store (no locked read-modify-write),
// atomic only so that readers on other threads see whole values.
inline void rt_add(std::atomic<std::uint64_t>& target, std::uint64_t value) noexcept {
  target.store(target.load(std::memory_order_relaxed) + value, std::memory_order_relaxed);
}

inline void rt_max(std::atomic<std::uint64_t>& target, std::uint64_t value) noexcept {
  if (value > target.load(std::memory_order_relaxed)) target.store(value, std::memory_order_relaxed);
}

// Appends `text` to the fixed buffer without allocating.
inline std::size_t append(char* buffer, std::size_t capacity, std::size_t used, const char* text) noexcept {
  if (text == nullptr) return used;
  const std::size_t room = capacity - 1 - used;
  const std::size_t n = std::min(room, std::strlen(text));
  std::memcpy(buffer + used, text, n);
  buffer[used + n] = '\0';
  return used + n;
}

}  // namespace manager_detail
}  // namespace mechsim::control
