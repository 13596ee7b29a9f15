// ros2_controllers' FollowJointTrajectory and GripperCommand actions over mechsim's goal ports
// (actions.hpp).
#include "ros2/actions.hpp"

#include <cstdio>

#include <mechsim_ros2_msgs/control_msgs.hpp>

#include "ros2/conversions.hpp"

namespace mechsim::ros2 {

std::string uuid_string(const GoalUuid& uuid) {
  std::string s;
  char hex[3];
  for (std::size_t i = 0; i < uuid.size(); ++i) {
    if (i == 4 || i == 6 || i == 8 || i == 10) s += '-';
    std::snprintf(hex, sizeof hex, "%02x", uuid[i]);
    s += hex;
  }
  return s;
}

double result_timeout(Distro distro) { return distro == Distro::Humble ? 15.0 * 60.0 : 10.0; }

namespace {

namespace ca = control_msgs::action;

// ros2_controllers' texts (joint_trajectory_controller.cpp).
constexpr const char* kSucceeded = "Goal successfully reached!";
constexpr const char* kPathViolated = "Aborted due to path tolerance violation";
constexpr const char* kGoalViolated = "Aborted due to goal tolerance violation";
constexpr const char* kSuperseded = "Current goal cancelled due to new incoming action.";
constexpr const char* kDeactivated = "Current goal cancelled during deactivate transition.";

// mechsim's reasons for a goal that ended because its controller stopped (trajectory_controller.cpp).
bool stopped_reason(const std::string& why) { return why.rfind("the controller", 0) == 0; }

trajectory_msgs::msg::JointTrajectoryPoint point_of(const control::TrajectoryPointState& p) {
  trajectory_msgs::msg::JointTrajectoryPoint out;
  out.positions = p.positions;
  out.velocities = p.velocities;
  out.accelerations = p.accelerations;
  out.time_from_start.sec = static_cast<std::int32_t>(std::floor(p.time_from_start));
  out.time_from_start.nanosec =
      static_cast<std::uint32_t>(std::min(999999999.0, std::round((p.time_from_start - std::floor(p.time_from_start)) * 1e9)));
  return out;
}

std::vector<control::JointTolerance> tolerances_of(const std::vector<control_msgs::msg::JointTolerance>& list) {
  std::vector<control::JointTolerance> out;
  for (const auto& t : list) out.push_back({t.name, t.position, t.velocity, t.acceleration});
  return out;
}

struct FollowJointTrajectoryPolicy {
  using Goal = ca::FollowJointTrajectory_Goal;
  using Result = ca::FollowJointTrajectory_Result;
  using Feedback = ca::FollowJointTrajectory_Feedback;
  using SendGoal = ca::FollowJointTrajectory_SendGoal;
  using GetResult = ca::FollowJointTrajectory_GetResult;
  using FeedbackMessage = ca::FollowJointTrajectory_FeedbackMessage;
  struct Submission {
    bool accepted = false;
    std::uint64_t id = 0;
    std::string why;
  };

  Submission submit(const bridge::PortRef& port, const Goal& goal) {
    Submission s;
    if (!goal.multi_dof_trajectory.joint_names.empty() || !goal.multi_dof_trajectory.points.empty()) {
      s.why = "multi-DOF trajectories are not supported (mechsim's trajectory controllers move single-DOF joints)";
      return s;
    }
    control::FollowJointTrajectoryGoal g;
    g.trajectory = trajectory_of(goal.trajectory);
    g.path_tolerance = tolerances_of(goal.path_tolerance);
    g.goal_tolerance = tolerances_of(goal.goal_tolerance);
    g.goal_time_tolerance = to_seconds(goal.goal_time_tolerance);
    bridge::GoalTicket ticket;
    if (!bridge::submit_goal(port, g, ticket)) {
      s.why = "port '" + port.name + "' of '" + port.controller + "' takes no goals";
      return s;
    }
    s.accepted = ticket.accepted;
    s.id = ticket.id;
    s.why = ticket.result.error_string;
    return s;
  }
  bool cancel(const bridge::PortRef& port, std::uint64_t id) { return bridge::cancel_goal(port, id); }
  std::optional<control::GoalStatus> status(const bridge::PortRef& port, std::uint64_t id) {
    return bridge::goal_status(port, id);
  }
  Result result(const bridge::PortRef& port, std::uint64_t id, control::GoalStatus status, GoalEnding ending) {
    Result out;
    const std::optional<control::TrajectoryResult> r = bridge::goal_result(port, id);
    const std::string why = r ? r->error_string : std::string();
    switch (status) {
      case control::GoalStatus::Succeeded:
        out.error_code = Result::SUCCESSFUL;
        out.error_string = kSucceeded;
        return out;
      case control::GoalStatus::Preempted:
        if (ending == GoalEnding::CancelRequested) return out;  // ros2_controllers: an empty result
        out.error_code = Result::INVALID_GOAL;
        out.error_string = ending == GoalEnding::Superseded ? kSuperseded : stopped_reason(why) ? kDeactivated : why;
        return out;
      default:
        break;
    }
    out.error_code = r ? static_cast<std::int32_t>(r->error_code) : Result::INVALID_GOAL;
    // mechsim's text is "<CODE NAME>: <what happened>": the name is in the code already.
    std::string detail = why;
    if (const auto colon = detail.find(": "); colon != std::string::npos && detail.compare(0, colon, control::result_code_name(
                                                                                                  r ? r->error_code : control::TrajectoryResultCode::InvalidGoal)) == 0)
      detail = detail.substr(colon + 2);
    if (out.error_code == Result::PATH_TOLERANCE_VIOLATED) out.error_string = std::string(kPathViolated) + ": " + detail;
    else if (out.error_code == Result::GOAL_TOLERANCE_VIOLATED) out.error_string = std::string(kGoalViolated) + ": " + detail;
    else out.error_string = detail;
    return out;
  }
  static Result shutdown_result() {
    Result out;
    out.error_code = Result::INVALID_GOAL;
    out.error_string = kDeactivated;
    return out;
  }
  bool read_feedback(const bridge::PortRef& port, std::uint64_t& goal_id, Feedback& out) {
    if (!bridge::read_goal_feedback(port, feedback_, &sequence_)) return false;
    goal_id = feedback_.goal_id;
    const control::JointTrajectoryControllerState& s = feedback_.state;
    out.header.stamp = to_time(s.stamp);
    out.joint_names = s.joint_names;
    out.desired = point_of(s.desired);
    out.actual = point_of(s.actual);
    out.error = point_of(s.error);
    return true;
  }

  control::FollowJointTrajectoryFeedback feedback_;
  std::uint64_t sequence_ = 0;
};

// ros2_controllers' gripper_action_controller: the result is the gripper's state as the goal
// ended (position, effort, stalled, reached_goal); a stall aborts (allow_stalling false, its
// default); a cancel or a newer goal cancels.
struct GripperCommandPolicy {
  using Goal = ca::GripperCommand_Goal;
  using Result = ca::GripperCommand_Result;
  using Feedback = ca::GripperCommand_Feedback;
  using SendGoal = ca::GripperCommand_SendGoal;
  using GetResult = ca::GripperCommand_GetResult;
  using FeedbackMessage = ca::GripperCommand_FeedbackMessage;
  struct Submission {
    bool accepted = false;
    std::uint64_t id = 0;
    std::string why;
  };

  Submission submit(const bridge::PortRef& port, const Goal& goal) {
    Submission s;
    bridge::GripperTicket ticket;
    if (!bridge::submit_gripper_goal(port, goal.command.position, goal.command.max_effort, ticket)) {
      s.why = "port '" + port.name + "' of '" + port.controller + "' takes no gripper goals";
      return s;
    }
    s.accepted = ticket.accepted;
    s.id = ticket.id;
    s.why = ticket.error;
    return s;
  }
  bool cancel(const bridge::PortRef& port, std::uint64_t id) { return bridge::cancel_gripper_goal(port, id); }
  std::optional<control::GoalStatus> status(const bridge::PortRef& port, std::uint64_t id) {
    return bridge::gripper_goal_status(port, id);
  }
  Result result(const bridge::PortRef& port, std::uint64_t id, control::GoalStatus, GoalEnding) {
    Result out;
    if (const std::optional<bridge::GripperStateData> r = bridge::gripper_goal_result(port, id)) {
      out.position = r->position;
      out.effort = r->effort;
      out.stalled = r->stalled;
      out.reached_goal = r->reached_goal;
    }
    return out;
  }
  static Result shutdown_result() { return {}; }
  bool read_feedback(const bridge::PortRef& port, std::uint64_t& goal_id, Feedback& out) {
    bridge::GripperStateData d;
    if (!bridge::read_gripper_feedback(port, d, &goal_id, &sequence_)) return false;
    out.position = d.position;
    out.effort = d.effort;
    out.stalled = d.stalled;
    out.reached_goal = d.reached_goal;
    return true;
  }

  std::uint64_t sequence_ = 0;
};

template <class Policy>
ControllerAction make(Node& node, const std::string& name, const bridge::PortRef& port, std::function<double()> now,
                      const char* type) {
  auto server = std::make_shared<ActionServer<Policy>>(node, name, port, std::move(now),
                                                        result_timeout(node.participant().distro()));
  ControllerAction a;
  a.name = server->name();
  a.type = type;
  // The callbacks hold the server too: it lives while anyone can still call them.
  a.shutdown = [server](const std::string& why) { server->shutdown(why); };
  a.stats = [server] { return server->stats(); };
  a.server = std::move(server);
  return a;
}

}  // namespace

control::JointTrajectory trajectory_of(const trajectory_msgs::msg::JointTrajectory& m) {
  control::JointTrajectory t;
  t.start_time = to_seconds(m.header.stamp);
  t.joint_names = m.joint_names;
  t.points.reserve(m.points.size());
  for (const auto& in : m.points) {
    control::TrajectoryPoint& out = t.points.emplace_back();
    out.positions = in.positions;
    out.velocities = in.velocities;
    out.accelerations = in.accelerations;
    out.effort = in.effort;
    out.time_from_start = to_seconds(in.time_from_start);
  }
  return t;
}

std::string default_action_name(const bridge::PortRef& port) {
  return port.type == bridge::PortType::GripperGoal ? "~/gripper_cmd" : "~/follow_joint_trajectory";
}

ControllerAction make_controller_action(Node& node, const std::string& name, const bridge::PortRef& port,
                                        std::function<double()> now) {
  if (port.type == bridge::PortType::GripperGoal)
    return make<GripperCommandPolicy>(node, name, port, std::move(now), "control_msgs/action/GripperCommand");
  return make<FollowJointTrajectoryPolicy>(node, name, port, std::move(now), "control_msgs/action/FollowJointTrajectory");
}

}  // namespace mechsim::ros2
