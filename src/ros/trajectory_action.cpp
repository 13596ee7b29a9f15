#include "ros/trajectory_action.hpp"

#include <algorithm>

namespace mechsim::ros {

namespace {

control::TrajectoryPoint from_msg(const trajectory_msgs::JointTrajectoryPoint& p) {
  control::TrajectoryPoint out;
  out.positions = p.positions;
  out.velocities = p.velocities;
  out.accelerations = p.accelerations;
  out.effort = p.effort;
  out.time_from_start = p.time_from_start.toSec();
  return out;
}

trajectory_msgs::JointTrajectoryPoint to_msg(const control::TrajectoryPointState& p) {
  trajectory_msgs::JointTrajectoryPoint out;
  out.positions = p.positions;
  out.velocities = p.velocities;
  out.accelerations = p.accelerations;
  out.time_from_start = ::ros::Duration(p.time_from_start);
  return out;
}

std::vector<control::JointTolerance> from_msg(const std::vector<control_msgs::JointTolerance>& list) {
  std::vector<control::JointTolerance> out;
  for (const auto& t : list) out.push_back({t.name, t.position, t.velocity, t.acceleration});
  return out;
}

control_msgs::FollowJointTrajectoryResult to_msg(const control::TrajectoryResult& r) {
  control_msgs::FollowJointTrajectoryResult out;
  out.error_code = static_cast<int>(r.error_code);
  out.error_string = r.error_string;
  return out;
}

}  // namespace

control::JointTrajectory from_msg(const trajectory_msgs::JointTrajectory& msg) {
  control::JointTrajectory out;
  out.start_time = msg.header.stamp.toSec();
  out.joint_names = msg.joint_names;
  for (const auto& p : msg.points) out.points.push_back(from_msg(p));
  return out;
}

control_msgs::JointTrajectoryControllerState to_msg(const control::JointTrajectoryControllerState& state) {
  control_msgs::JointTrajectoryControllerState out;
  out.header.stamp = ::ros::Time(state.stamp);
  out.joint_names = state.joint_names;
  out.desired = to_msg(state.desired);
  out.actual = to_msg(state.actual);
  out.error = to_msg(state.error);
  return out;
}

TrajectoryActionServer::TrajectoryActionServer(::ros::NodeHandle nh, const std::string& name, PortRef port)
    : port_(std::move(port)) {
  server_ = std::make_unique<Server>(
      nh, name, [this](GoalHandle gh) { on_goal(gh); }, [this](GoalHandle gh) { on_cancel(gh); },
      /*auto_start=*/false);
  server_->start();
  timer_ = nh.createWallTimer(::ros::WallDuration(0.05), [this](const ::ros::WallTimerEvent&) { poll(); });
}

TrajectoryActionServer::~TrajectoryActionServer() {
  shutdown();
  timer_.stop();
  server_.reset();
}

// Goal handles are finished outside mutex_: actionlib calls on_goal() holding its own lock,
// so taking that lock while holding mutex_ could deadlock.
void TrajectoryActionServer::shutdown() {
  std::vector<Tracked> goals;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!alive_) return;
    alive_ = false;
    goals.swap(goals_);
  }
  control_msgs::FollowJointTrajectoryResult result;
  result.error_code = control_msgs::FollowJointTrajectoryResult::INVALID_GOAL;
  result.error_string = "the controller was unloaded";
  for (Tracked& t : goals) t.handle.setAborted(result, result.error_string);
}

void TrajectoryActionServer::on_goal(GoalHandle handle) {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto goal = handle.getGoal();
  if (!alive_) {
    handle.setRejected(control_msgs::FollowJointTrajectoryResult(), "the controller is being unloaded");
    return;
  }
  control::FollowJointTrajectoryGoal g;
  g.trajectory = from_msg(goal->trajectory);
  g.path_tolerance = from_msg(goal->path_tolerance);
  g.goal_tolerance = from_msg(goal->goal_tolerance);
  g.goal_time_tolerance = goal->goal_time_tolerance.toSec();
  GoalTicket ticket;
  if (!submit_goal(port_, g, ticket) || !ticket.accepted) {
    handle.setRejected(to_msg(ticket.result), ticket.result.error_string);
    return;
  }
  handle.setAccepted();
  goals_.push_back({handle, ticket.id});
}

void TrajectoryActionServer::on_cancel(GoalHandle handle) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!alive_) return;
  for (const Tracked& t : goals_) {
    if (t.handle == handle) cancel_goal(port_, t.id);  // poll() finishes the handle
  }
}

void TrajectoryActionServer::poll() {
  struct Finished {
    GoalHandle handle;
    control::GoalStatus status;
    control::TrajectoryResult result;
  };
  std::vector<Finished> finished;
  std::vector<std::pair<GoalHandle, control_msgs::FollowJointTrajectoryFeedback>> feedback;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!alive_ || goals_.empty()) return;
    const bool fresh = read_goal_feedback(port_, feedback_, &feedback_sequence_);
    for (auto it = goals_.begin(); it != goals_.end();) {
      const auto status = goal_status(port_, it->id);
      if (fresh && feedback_.goal_id == it->id && status == control::GoalStatus::Active) {
        control_msgs::FollowJointTrajectoryFeedback fb;
        const auto state = to_msg(feedback_.state);
        fb.header = state.header;
        fb.joint_names = state.joint_names;
        fb.desired = state.desired;
        fb.actual = state.actual;
        fb.error = state.error;
        feedback.emplace_back(it->handle, fb);
      }
      if (!status || !control::goal_finished(*status)) {
        ++it;
        continue;
      }
      finished.push_back({it->handle, *status, goal_result(port_, it->id).value_or(control::TrajectoryResult{})});
      it = goals_.erase(it);
    }
  }
  for (auto& [handle, fb] : feedback) handle.publishFeedback(fb);
  for (Finished& f : finished) {
    const auto msg = to_msg(f.result);
    switch (f.status) {
      case control::GoalStatus::Succeeded: f.handle.setSucceeded(msg, f.result.error_string); break;
      case control::GoalStatus::Preempted: f.handle.setCanceled(msg, f.result.error_string); break;
      default: f.handle.setAborted(msg, f.result.error_string); break;  // aborted, or rejected by the tick
    }
  }
}

}  // namespace mechsim::ros
