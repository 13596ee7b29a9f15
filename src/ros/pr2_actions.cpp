#include "ros/pr2_actions.hpp"

#include "ros/trajectory_action.hpp"

namespace mechsim::ros {

namespace {

pr2_controllers_msgs::Pr2GripperCommandResult to_result(const GripperStateData& d) {
  pr2_controllers_msgs::Pr2GripperCommandResult r;
  r.position = d.position;
  r.effort = d.effort;
  r.stalled = d.stalled;
  r.reached_goal = d.reached_goal;
  return r;
}

pr2_controllers_msgs::Pr2GripperCommandFeedback to_feedback(const GripperStateData& d) {
  pr2_controllers_msgs::Pr2GripperCommandFeedback f;
  f.position = d.position;
  f.effort = d.effort;
  f.stalled = d.stalled;
  f.reached_goal = d.reached_goal;
  return f;
}

}  // namespace

// ---------------------------------------------------------------- joint_trajectory_action

Pr2TrajectoryActionServer::Pr2TrajectoryActionServer(::ros::NodeHandle nh, const std::string& name, PortRef port)
    : port_(std::move(port)) {
  server_ = std::make_unique<Server>(
      nh, name, [this](GoalHandle gh) { on_goal(gh); }, [this](GoalHandle gh) { on_cancel(gh); },
      /*auto_start=*/false);
  server_->start();
  timer_ = nh.createWallTimer(::ros::WallDuration(0.05), [this](const ::ros::WallTimerEvent&) { poll(); });
}

Pr2TrajectoryActionServer::~Pr2TrajectoryActionServer() {
  shutdown();
  timer_.stop();
  server_.reset();
}

// Goal handles are finished outside mutex_: actionlib calls on_goal() holding its own lock.
void Pr2TrajectoryActionServer::shutdown() {
  std::vector<Tracked> goals;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!alive_) return;
    alive_ = false;
    goals.swap(goals_);
  }
  for (Tracked& t : goals) t.handle.setAborted(pr2_controllers_msgs::JointTrajectoryResult(), "the controller was unloaded");
}

void Pr2TrajectoryActionServer::on_goal(GoalHandle handle) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!alive_) {
    handle.setRejected(pr2_controllers_msgs::JointTrajectoryResult(), "the controller is being unloaded");
    return;
  }
  // No tolerances in the goal: the controller's constraints apply (as the PR2's).
  control::FollowJointTrajectoryGoal g;
  g.trajectory = from_msg(handle.getGoal()->trajectory);
  GoalTicket ticket;
  if (!submit_goal(port_, g, ticket) || !ticket.accepted) {
    handle.setRejected(pr2_controllers_msgs::JointTrajectoryResult(), ticket.result.error_string);
    return;
  }
  handle.setAccepted();
  goals_.push_back({handle, ticket.id});
}

void Pr2TrajectoryActionServer::on_cancel(GoalHandle handle) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!alive_) return;
  for (const Tracked& t : goals_) {
    if (t.handle == handle) cancel_goal(port_, t.id);  // poll() finishes the handle
  }
}

void Pr2TrajectoryActionServer::poll() {
  struct Finished {
    GoalHandle handle;
    control::GoalStatus status;
    std::string text;
  };
  std::vector<Finished> finished;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!alive_ || goals_.empty()) return;
    for (auto it = goals_.begin(); it != goals_.end();) {
      const auto status = goal_status(port_, it->id);
      if (status && !control::goal_finished(*status)) {
        ++it;
        continue;
      }
      const control::TrajectoryResult r = goal_result(port_, it->id).value_or(control::TrajectoryResult{});
      finished.push_back({it->handle, status.value_or(control::GoalStatus::Aborted), r.error_string});
      it = goals_.erase(it);
    }
  }
  const pr2_controllers_msgs::JointTrajectoryResult empty;
  for (Finished& f : finished) {
    switch (f.status) {
      case control::GoalStatus::Succeeded: f.handle.setSucceeded(empty, f.text); break;
      case control::GoalStatus::Preempted: f.handle.setCanceled(empty, f.text); break;
      default: f.handle.setAborted(empty, f.text); break;  // aborted, or rejected by the tick
    }
  }
}

// ---------------------------------------------------------------- gripper_action

GripperActionServer::GripperActionServer(::ros::NodeHandle nh, const std::string& name, PortRef port)
    : port_(std::move(port)) {
  server_ = std::make_unique<Server>(
      nh, name, [this](GoalHandle gh) { on_goal(gh); }, [this](GoalHandle gh) { on_cancel(gh); },
      /*auto_start=*/false);
  server_->start();
  timer_ = nh.createWallTimer(::ros::WallDuration(0.05), [this](const ::ros::WallTimerEvent&) { poll(); });
}

GripperActionServer::~GripperActionServer() {
  shutdown();
  timer_.stop();
  server_.reset();
}

void GripperActionServer::shutdown() {
  std::vector<Tracked> goals;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!alive_) return;
    alive_ = false;
    goals.swap(goals_);
  }
  for (Tracked& t : goals) {
    t.handle.setAborted(pr2_controllers_msgs::Pr2GripperCommandResult(), "the controller was unloaded");
  }
}

void GripperActionServer::on_goal(GoalHandle handle) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!alive_) {
    handle.setRejected(pr2_controllers_msgs::Pr2GripperCommandResult(), "the controller is being unloaded");
    return;
  }
  const auto& command = handle.getGoal()->command;
  GripperTicket ticket;
  if (!submit_gripper_goal(port_, command.position, command.max_effort, ticket) || !ticket.accepted) {
    handle.setRejected(pr2_controllers_msgs::Pr2GripperCommandResult(), ticket.error);
    return;
  }
  handle.setAccepted();
  goals_.push_back({handle, ticket.id});
}

void GripperActionServer::on_cancel(GoalHandle handle) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!alive_) return;
  for (const Tracked& t : goals_) {
    if (t.handle == handle) cancel_gripper_goal(port_, t.id);  // poll() finishes the handle
  }
}

void GripperActionServer::poll() {
  struct Finished {
    GoalHandle handle;
    control::GoalStatus status;
    GripperStateData result;
  };
  std::vector<Finished> finished;
  std::vector<std::pair<GoalHandle, GripperStateData>> feedback;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!alive_ || goals_.empty()) return;
    GripperStateData fb;
    std::uint64_t fb_goal = 0;
    const bool fresh = read_gripper_feedback(port_, fb, &fb_goal, &feedback_sequence_);
    for (auto it = goals_.begin(); it != goals_.end();) {
      const control::GoalStatus status = gripper_goal_status(port_, it->id).value_or(control::GoalStatus::Aborted);
      if (fresh && fb_goal == it->id && status == control::GoalStatus::Active) feedback.emplace_back(it->handle, fb);
      if (!control::goal_finished(status)) {
        ++it;
        continue;
      }
      finished.push_back({it->handle, status, gripper_goal_result(port_, it->id).value_or(GripperStateData{})});
      it = goals_.erase(it);
    }
  }
  for (auto& [handle, fb] : feedback) handle.publishFeedback(to_feedback(fb));
  for (Finished& f : finished) {
    const auto msg = to_result(f.result);
    switch (f.status) {
      case control::GoalStatus::Succeeded: f.handle.setSucceeded(msg); break;
      case control::GoalStatus::Preempted: f.handle.setCanceled(msg); break;
      default: f.handle.setAborted(msg, f.result.stalled ? "stalled" : ""); break;
    }
  }
}

}  // namespace mechsim::ros
