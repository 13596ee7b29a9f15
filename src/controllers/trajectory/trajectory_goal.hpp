#pragma once
// How trajectories reach a trajectory controller from outside the tick:
//   TrajectoryCommandPort "command"   a JointTrajectory without action semantics (the
//                                     `command` topic): replaces the trajectory, preempts an
//                                     active goal; an empty one stops and holds
//   TrajectoryGoalPort "follow_joint_trajectory"
//                                     FollowJointTrajectory goals: submit, cancel, status,
//                                     result, feedback (the action server's view)
// Both validate in the caller's thread (joint names, sizes, finite values, increasing times,
// the configured maximum number of points) and hand a TrajectoryRequest of fixed shape to the
// tick through a realtime double buffer; the tick never allocates or blocks to take it. The
// tick reports what became of goals through a lock-free ring of events that the port drains
// whenever it is queried, and the port turns those into status and result strings.
//
// Goal life: submit -> Pending (or Rejected at once, with a result code) -> Active when the
// tick takes it -> Succeeded / Aborted (PATH_ or GOAL_TOLERANCE_VIOLATED) / Preempted (cancel,
// a newer goal or command) / Rejected (OLD_HEADER_TIMESTAMP found by the tick). A goal still
// pending when a newer one is taken is Preempted without having run.

#include <array>
#include <atomic>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "control/ports.hpp"
#include "controllers/trajectory/trajectory.hpp"

namespace mechsim::control {

template <>
constexpr PortKind state_port_kind<JointTrajectoryControllerState>() { return PortKind::JointTrajectoryState; }

// Lock-free ring of one producer and one consumer (each side serialised by its owner).
template <class T, std::size_t N>
class SpscRing {
 public:
  bool push(const T& value) noexcept {
    const std::size_t head = head_.load(std::memory_order_relaxed);
    if (head - tail_.load(std::memory_order_acquire) >= N) return false;
    slots_[head % N] = value;
    head_.store(head + 1, std::memory_order_release);
    return true;
  }
  bool pop(T& value) noexcept {
    const std::size_t tail = tail_.load(std::memory_order_relaxed);
    if (tail == head_.load(std::memory_order_acquire)) return false;
    value = slots_[tail % N];
    tail_.store(tail + 1, std::memory_order_release);
    return true;
  }

 private:
  std::array<T, N> slots_{};
  std::atomic<std::size_t> head_{0};
  std::atomic<std::size_t> tail_{0};
};

// What the tick reports about a request or goal.
struct TrajectoryEvent {
  enum class Kind : std::uint8_t { Taken, Finished };
  Kind kind = Kind::Taken;
  std::uint64_t sequence = 0;  // Taken: the request's sequence
  std::uint64_t goal_id = 0;   // 0: a plain command
  GoalStatus status = GoalStatus::Active;
  TrajectoryResultCode code = TrajectoryResultCode::Successful;
  const char* reason = "";  // a string literal
  ToleranceViolation violation;  // for tolerance aborts
  double time = 0.0;             // s, when it happened
};

// Configuration of the channel, fixed at init.
struct TrajectoryChannelConfig {
  std::vector<std::string> joints;  // the controller's joints, in order
  std::size_t max_points = 0;       // per trajectory
  bool allow_partial_joints_goal = false;
  TrajectoryTolerances default_tolerances;
};

struct GoalSubmission {
  std::uint64_t id = 0;   // the goal's id (rejected goals get one too)
  bool accepted = false;  // false: rejected at once, `result` says why
  TrajectoryResult result;
};

// The state shared by the two ports and the controller. Every non-real-time member is
// thread-safe (one mutex, which the tick never takes) and first drains the tick's events.
class TrajectoryChannel {
 public:
  explicit TrajectoryChannel(TrajectoryChannelConfig config);
  const TrajectoryChannelConfig& config() const { return config_; }

  // Non-real-time.
  GoalSubmission submit_goal(const FollowJointTrajectoryGoal& goal);
  // A plain command; Successful or the rejection code with `error` set.
  TrajectoryResultCode post_command(const JointTrajectory& trajectory, std::string& error);
  bool cancel(std::uint64_t id);
  std::optional<GoalStatus> status(std::uint64_t id);
  std::optional<TrajectoryResult> result(std::uint64_t id);
  std::uint64_t event_overflows() const { return event_overflows_.load(); }
  // Finished goals are remembered up to this many (the oldest are forgotten first: status()
  // and result() then return nothing for them).
  static constexpr std::size_t kMaxGoalRecords = 1024;

  // Real-time (the controller's tick).
  const TrajectoryRequest* take_from_rt() noexcept;  // the newest request not yet taken, or null
  void set_time_from_rt(double time) noexcept { time_.store(time, std::memory_order_relaxed); }
  void report_from_rt(const TrajectoryEvent& event) noexcept;
  bool next_cancel_from_rt(std::uint64_t& id) noexcept { return cancels_.pop(id); }
  // Real-time: starting()/stopping(). Goals and commands are refused while not running, as
  // ros_control refuses them ("Controller is not running").
  void set_running_from_rt(bool running) noexcept { running_.store(running, std::memory_order_release); }

 private:
  struct Record {
    std::uint64_t sequence = 0;
    GoalStatus status = GoalStatus::Pending;
    TrajectoryResult result;
  };
  TrajectoryResultCode validate(const JointTrajectory& t, const FollowJointTrajectoryGoal* goal, std::string& error);
  // Under mutex_: validates, fills scratch_ and hands it to the tick.
  TrajectoryResultCode post(const JointTrajectory& t, const FollowJointTrajectoryGoal* goal, std::uint64_t goal_id,
                            std::string& error, std::uint64_t& sequence);
  void drain();  // under mutex_
  std::string describe(const TrajectoryEvent& e) const;

  TrajectoryChannelConfig config_;
  std::mutex mutex_;
  TrajectoryRequest scratch_;
  RealtimeBuffer<TrajectoryRequest> buffer_;
  std::uint64_t next_sequence_ = 1;
  std::uint64_t next_goal_id_ = 1;
  std::map<std::uint64_t, Record> records_;
  std::uint64_t taken_sequence_ = 0;  // real-time side
  std::atomic<double> time_{0.0};
  std::atomic<bool> running_{false};
  SpscRing<TrajectoryEvent, 128> events_;
  SpscRing<std::uint64_t, 64> cancels_;
  std::atomic<std::uint64_t> event_overflows_{0};
};

class TrajectoryCommandPort : public Port, public RejectionLog {
 public:
  TrajectoryCommandPort(std::string name, TrajectoryChannel* channel) : Port(std::move(name)), channel_(channel) {}
  PortKind kind() const override { return PortKind::TrajectoryCommand; }
  // Non-real-time. False (and `error` set, the rejection counted) when invalid.
  bool write(const JointTrajectory& trajectory, std::string* error = nullptr);
  std::uint64_t accepted() const { return accepted_.load(); }

 private:
  TrajectoryChannel* channel_;
  std::atomic<std::uint64_t> accepted_{0};
};

class TrajectoryGoalPort : public Port {
 public:
  TrajectoryGoalPort(std::string name, TrajectoryChannel* channel) : Port(std::move(name)), channel_(channel) {}
  PortKind kind() const override { return PortKind::TrajectoryGoal; }
  const std::vector<std::string>& joint_names() const { return channel_->config().joints; }

  // Non-real-time, thread-safe.
  GoalSubmission submit(const FollowJointTrajectoryGoal& goal) { return channel_->submit_goal(goal); }
  // False when the id is unknown or the goal has already finished.
  bool cancel(std::uint64_t id) { return channel_->cancel(id); }
  std::optional<GoalStatus> status(std::uint64_t id) { return channel_->status(id); }
  // The result once the goal has finished.
  std::optional<TrajectoryResult> result(std::uint64_t id) { return channel_->result(id); }
  // The latest feedback: desired, actual and error of the goal being executed (or the last).
  FollowJointTrajectoryFeedback feedback() const { return feedback_.read(); }
  std::uint64_t feedback_sequence() const noexcept { return feedback_.sequence(); }

  // Controller side.
  void init_feedback(const FollowJointTrajectoryFeedback& prototype) { feedback_.init(prototype); }
  template <class F>
  bool publish_feedback_from_rt(F&& fill) noexcept {
    return feedback_.publish_from_rt(std::forward<F>(fill));
  }

 private:
  TrajectoryChannel* channel_;
  SnapshotBuffer<FollowJointTrajectoryFeedback> feedback_;
};

}  // namespace mechsim::control
