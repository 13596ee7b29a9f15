#pragma once
// The ports of the PR2 gripper controller (controllers/gripper/pr2_gripper_controller.hpp):
//   GripperCommandPort "command"        pr2_controllers_msgs/Pr2GripperCommand (position, max_effort)
//                                       without action semantics: the latest command is held
//   GripperGoalPort    "gripper_action" the control_msgs/GripperCommand (pr2_controllers_msgs/
//                                       Pr2GripperCommand) action: submit, cancel, status,
//                                       result, feedback
// Writes are validated in the caller's thread (finite values) and handed to the tick through
// realtime double buffers; the tick reports what became of goals through a lock-free ring that
// the goal port drains whenever it is queried.
//
// Goal life: submit -> Pending (Rejected at once when invalid or the controller is not running)
// -> Active when the tick takes it -> Succeeded (within goal_threshold of the position) /
// Aborted (stalled before reaching it) / Preempted (cancel, a newer goal, or a plain command).

#include <atomic>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <string>

#include "control/ports.hpp"
#include "controllers/trajectory/trajectory_goal.hpp"  // SpscRing
#include "controllers/trajectory/trajectory_msgs.hpp"  // GoalStatus

namespace mechsim::control {

// pr2_controllers_msgs/Pr2GripperCommand.
struct GripperCommand {
  double position = 0.0;     // m, the gap between the finger tips
  double max_effort = -1.0;  // N on the gap joint; negative: no limit (as the PR2)
};

// control_msgs/GripperCommandResult and Feedback.
struct GripperResult {
  double position = 0.0;  // m, the gap
  double effort = 0.0;    // N, the commanded effort on the gap joint
  bool stalled = false;   // it stopped moving before reaching the goal
  bool reached_goal = false;
};

struct GripperFeedback {
  double stamp = 0.0;        // s
  std::uint64_t goal_id = 0; // the goal this is about (the active or the last one); 0: none yet
  GripperResult state;
};

class GripperCommandPort : public Port, public RejectionLog {
 public:
  using Port::Port;
  PortKind kind() const override { return PortKind::GripperCommand; }
  // Non-real-time. False (and `error` set) when a value is not finite.
  bool write(const GripperCommand& command, std::string* error = nullptr);
  GripperCommand latest() const { return buffer_.latest(); }
  // Real-time safe: accepted writes so far.
  std::uint64_t accepted() const noexcept { return accepted_.load(std::memory_order_acquire); }
  const GripperCommand& read_from_rt() noexcept { return buffer_.read_from_rt(); }
  void reset_from_rt(const GripperCommand& c) noexcept {
    buffer_.reset_from_rt([&c](GripperCommand& v) { v = c; });
  }

 private:
  RealtimeBuffer<GripperCommand> buffer_;
  std::atomic<std::uint64_t> accepted_{0};
};

struct GripperGoalRequest {
  std::uint64_t id = 0;  // 0: none
  GripperCommand command;
};

struct GripperSubmission {
  std::uint64_t id = 0;
  bool accepted = false;
  std::string error;  // why it was rejected
};

// What the tick reports about a goal.
struct GripperGoalEvent {
  std::uint64_t id = 0;
  GoalStatus status = GoalStatus::Active;  // Active: taken
  GripperResult result;
};

class GripperGoalPort : public Port {
 public:
  using Port::Port;
  PortKind kind() const override { return PortKind::GripperGoal; }

  // Non-real-time, thread-safe.
  GripperSubmission submit(const GripperCommand& goal);
  bool cancel(std::uint64_t id);  // false when unknown or finished
  std::optional<GoalStatus> status(std::uint64_t id);
  std::optional<GripperResult> result(std::uint64_t id);  // once finished
  GripperFeedback feedback() const { return feedback_.read(); }
  std::uint64_t feedback_sequence() const noexcept { return feedback_.sequence(); }

  // Real-time (the controller's tick).
  // The newest goal not yet taken, if any.
  bool take_from_rt(GripperGoalRequest& out) noexcept;
  // The id of the latest cancel request (0: none).
  std::uint64_t cancel_request_from_rt() const noexcept { return cancel_.load(std::memory_order_acquire); }
  void report_from_rt(const GripperGoalEvent& event) noexcept;
  void set_running_from_rt(bool running) noexcept { running_.store(running, std::memory_order_release); }
  template <class F>
  bool publish_feedback_from_rt(F&& fill) noexcept {
    return feedback_.publish_from_rt(std::forward<F>(fill));
  }

 private:
  struct Record {
    GoalStatus status = GoalStatus::Pending;
    GripperResult result;
  };
  void drain();  // under mutex_

  std::mutex mutex_;
  std::uint64_t next_id_ = 1;
  std::map<std::uint64_t, Record> records_;
  RealtimeBuffer<GripperGoalRequest> goals_;
  std::uint64_t taken_id_ = 0;  // real-time side
  std::atomic<std::uint64_t> cancel_{0};
  std::atomic<bool> running_{false};
  SpscRing<GripperGoalEvent, 64> events_;
  SnapshotBuffer<GripperFeedback> feedback_;
};

}  // namespace mechsim::control
