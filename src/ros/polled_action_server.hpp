#pragma once
// PolledActionServer<Policy>: an actionlib server over a controller's goal port, the design the
// node's action interfaces share (follow_joint_trajectory, joint_trajectory_action,
// gripper_action). A goal is submitted to the port at once (a refused one is rejected with the
// policy's result and text); a wall timer (20 Hz) relays fresh feedback about active (and just
// finished) goals and finishes goal handles as the tick reports them: Succeeded -> succeeded, Preempted -> canceled,
// anything else finished (aborted, or rejected by the tick) -> aborted. A cancel request is
// passed to the port; the next poll finishes the handle.
//
// The Policy speaks one action and one kind of goal port. It is a member of the server and is
// only used under the server's mutex, except the static result()/text() conversions:
//   using Action = <pkg>::<Name>Action;
//   using Outcome = ...;  // what the port reports for a finished goal (default: none reported)
//   PolicySubmission<Result> submit(const PortRef&, const Goal&);
//   bool cancel(const PortRef&, std::uint64_t id);
//   std::optional<control::GoalStatus> status(const PortRef&, std::uint64_t id);  // nullopt: poll again
//   Outcome outcome(const PortRef&, std::uint64_t id);
//   bool read_feedback(const PortRef&, std::uint64_t& goal_id);  // true when fresh, kept in the policy
//   Feedback feedback() const;                                   // that feedback as the message
//   static Result result(const Outcome&);
//   static std::string text(control::GoalStatus, const Outcome&);  // the finished handle's text
//   static Result unloaded_result();  // for goals aborted by shutdown()
// Goal, Result and Feedback are the action's message types (PolledActionServer::Goal, ...).

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <actionlib/server/action_server.h>

#include "ros/bridge_names.hpp"

namespace mechsim::ros {

// What a policy's submit() reports.
template <class Result>
struct PolicySubmission {
  bool accepted = false;
  std::uint64_t id = 0;  // the port's goal id, when accepted
  Result result;         // the rejected goal's result
  std::string text;      // the rejected goal's text (why)
};

template <class Policy>
class PolledActionServer {
 public:
  using Action = typename Policy::Action;
  using Goal = typename Action::_action_goal_type::_goal_type;
  using Result = typename Action::_action_result_type::_result_type;
  using Feedback = typename Action::_action_feedback_type::_feedback_type;

  // Serves `name` (relative to nh) over `port`, the controller's goal port of the policy's kind.
  PolledActionServer(::ros::NodeHandle nh, const std::string& name, PortRef port) : port_(std::move(port)) {
    server_ = std::make_unique<Server>(
        nh, name, [this](GoalHandle gh) { on_goal(gh); }, [this](GoalHandle gh) { on_cancel(gh); },
        /*auto_start=*/false);
    server_->start();
    timer_ = nh.createWallTimer(::ros::WallDuration(0.05), [this](const ::ros::WallTimerEvent&) { poll(); });
  }

  ~PolledActionServer() {
    shutdown();
    timer_.stop();
    server_.reset();
  }

  PolledActionServer(const PolledActionServer&) = delete;
  PolledActionServer& operator=(const PolledActionServer&) = delete;

  // After this returns the port is never touched again; active goals are aborted.
  // Goal handles are finished outside mutex_: actionlib calls on_goal() holding its own lock,
  // so taking that lock while holding mutex_ could deadlock.
  void shutdown() {
    std::vector<Tracked> goals;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!alive_) return;
      alive_ = false;
      goals.swap(goals_);
    }
    for (Tracked& t : goals) t.handle.setAborted(Policy::unloaded_result(), "the controller was unloaded");
  }

 private:
  using Server = actionlib::ActionServer<Action>;
  using GoalHandle = typename Server::GoalHandle;
  struct Tracked {
    GoalHandle handle;
    std::uint64_t id;
  };

  void on_goal(GoalHandle handle) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!alive_) {
      handle.setRejected(Result(), "the controller is being unloaded");
      return;
    }
    PolicySubmission<Result> s = policy_.submit(port_, *handle.getGoal());
    if (!s.accepted) {
      handle.setRejected(s.result, s.text);
      return;
    }
    handle.setAccepted();
    goals_.push_back({handle, s.id});
  }

  void on_cancel(GoalHandle handle) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!alive_) return;
    for (const Tracked& t : goals_) {
      if (t.handle == handle) policy_.cancel(port_, t.id);  // poll() finishes the handle
    }
  }

  void poll() {
    struct Finished {
      GoalHandle handle;
      control::GoalStatus status;
      typename Policy::Outcome outcome;
    };
    std::vector<Finished> finished;
    std::vector<std::pair<GoalHandle, Feedback>> feedback;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!alive_ || goals_.empty()) return;
      std::uint64_t feedback_goal = 0;
      const bool fresh = policy_.read_feedback(port_, feedback_goal);
      for (auto it = goals_.begin(); it != goals_.end();) {
        const std::optional<control::GoalStatus> status = policy_.status(port_, it->id);
        // Fresh feedback goes out while the goal is active and, once, for a goal that finished
        // since the last poll (before its result): a goal shorter than the poll period still
        // gets its feedback, as a server relaying every controller state would send.
        if (fresh && feedback_goal == it->id && status &&
            (*status == control::GoalStatus::Active || control::goal_finished(*status))) {
          feedback.emplace_back(it->handle, policy_.feedback());
        }
        if (!status || !control::goal_finished(*status)) {
          ++it;
          continue;
        }
        finished.push_back({it->handle, *status, policy_.outcome(port_, it->id)});
        it = goals_.erase(it);
      }
    }
    for (auto& [handle, fb] : feedback) handle.publishFeedback(fb);
    for (Finished& f : finished) {
      const Result msg = Policy::result(f.outcome);
      const std::string text = Policy::text(f.status, f.outcome);
      switch (f.status) {
        case control::GoalStatus::Succeeded: f.handle.setSucceeded(msg, text); break;
        case control::GoalStatus::Preempted: f.handle.setCanceled(msg, text); break;
        default: f.handle.setAborted(msg, text); break;  // aborted, or rejected by the tick
      }
    }
  }

  PortRef port_;
  std::mutex mutex_;
  bool alive_ = true;          // under mutex_; false once shutdown() started
  std::vector<Tracked> goals_;  // under mutex_
  Policy policy_;               // under mutex_
  std::unique_ptr<Server> server_;
  ::ros::WallTimer timer_;
};

}  // namespace mechsim::ros
