// mechsim_point_head_action: pr2_head_action's node (the pr2_head_action package of
// src/ros/packages), as pr2_default_controllers.launch starts it in the namespace of
// head_traj_controller. Its names and semantics are pr2_head_action's:
//   action      point_head_action (pr2_controllers_msgs/PointHeadAction) in the node's namespace:
//               /head_traj_controller/point_head_action
//   uses        command (trajectory_msgs/JointTrajectory), state
//               (pr2_controllers_msgs/JointTrajectoryControllerState) in the node's namespace, the
//               service /head_traj_controller/query_state (pr2_controllers_msgs/
//               QueryTrajectoryState), /robot_description, and TF for the target's frame
//   parameters  ~pan_link (head_pan_link), ~default_pointing_frame (head_tilt_link),
//               ~success_angle_threshold (0.1 rad)
// A goal: the target point is put in the root frame (the pan link's parent, torso_lift_link)
// through TF; an empty pointing_frame means ~default_pointing_frame with axis (1, 0, 0); a
// pointing axis shorter than 0.1 means (0, 0, 1) for an optical frame, else (1, 0, 0). The joint
// positions that point the axis at the target (ros/head_pointing.hpp, within the joints' limits)
// go to the controller as a two-point trajectory from where it is now (query_state) over
// max(min_duration, 0.01 s, joint distance / max_velocity). Feedback: pointing_angle_error, from
// each controller state; SUCCEEDED when it falls below ~success_angle_threshold. A newer goal
// preempts the active one; a cancel stops the head (an empty trajectory); the goal is aborted when
// the controller's state has not come for 5 s of ROS time. The target is put in the root frame
// with the latest transform TF has (waited for up to 5 s). Rejected (with the reason logged): an
// unknown frame, a chain the URDF lacks, a failed query_state, joints that are not the chain's.
#include <algorithm>
#include <cmath>
#include <memory>

#include <actionlib/server/action_server.h>
#include <pr2_controllers_msgs/JointTrajectoryControllerState.h>
#include <pr2_controllers_msgs/PointHeadAction.h>
#include <pr2_controllers_msgs/QueryTrajectoryState.h>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>
#include <trajectory_msgs/JointTrajectory.h>

#include "description/urdf/urdf_parser.hpp"
#include "physics/transform.hpp"
#include "ros/head_pointing.hpp"

namespace {

using Server = actionlib::ActionServer<pr2_controllers_msgs::PointHeadAction>;
using GoalHandle = Server::GoalHandle;
using mechsim::description::Vec3;

class PointHeadAction {
 public:
  PointHeadAction() : pnh_("~"), tf_listener_(tf_buffer_), server_(nh_, "point_head_action", false) {
    pan_link_ = strip(pnh_.param<std::string>("pan_link", "head_pan_link"));
    default_frame_ = strip(pnh_.param<std::string>("default_pointing_frame", "head_tilt_link"));
    threshold_ = pnh_.param("success_angle_threshold", 0.1);
    std::string urdf;
    nh_.param<std::string>("/robot_description", urdf, "");
    mechsim::description::UrdfOptions options;
    options.lenient = true;
    robot_ = mechsim::description::parse_urdf_string(urdf, "/robot_description", options);
    command_pub_ = nh_.advertise<trajectory_msgs::JointTrajectory>("command", 2);
    state_sub_ = nh_.subscribe("state", 1, &PointHeadAction::on_state, this);
    query_ = nh_.serviceClient<pr2_controllers_msgs::QueryTrajectoryState>("/head_traj_controller/query_state");
    server_.registerGoalCallback([this](GoalHandle gh) { on_goal(gh); });
    server_.registerCancelCallback([this](GoalHandle gh) { on_cancel(gh); });
    server_.start();
    watchdog_ = nh_.createTimer(::ros::Duration(1.0), &PointHeadAction::watchdog, this);
    ROS_INFO_STREAM("mechsim point_head_action: " << nh_.resolveName("point_head_action") << " over "
                                                  << nh_.resolveName("command"));
  }

 private:
  static std::string strip(std::string frame) {
    if (!frame.empty() && frame.front() == '/') frame.erase(0, 1);
    return frame;
  }

  void reject(GoalHandle& gh, const std::string& why) {
    ROS_ERROR_STREAM("mechsim point_head_action: goal rejected: " << why);
    gh.setRejected(pr2_controllers_msgs::PointHeadResult(), why);
  }

  void on_goal(GoalHandle gh) {
    const pr2_controllers_msgs::PointHeadGoal& goal = *gh.getGoal();
    std::string frame = strip(goal.pointing_frame);
    Vec3 axis{goal.pointing_axis.x, goal.pointing_axis.y, goal.pointing_axis.z};
    if (frame.empty()) {
      frame = default_frame_;
      axis = {1.0, 0.0, 0.0};
    } else if (std::sqrt(axis.x * axis.x + axis.y * axis.y + axis.z * axis.z) < 0.1) {
      axis = frame.find("optical_frame") != std::string::npos ? Vec3{0.0, 0.0, 1.0} : Vec3{1.0, 0.0, 0.0};
    }
    std::unique_ptr<mechsim::ros::HeadPointing> chain;
    try {
      chain = std::make_unique<mechsim::ros::HeadPointing>(robot_, pan_link_, frame);
    } catch (const std::exception& e) {
      reject(gh, e.what());
      return;
    }
    // The target in the root frame.
    Vec3 target;
    try {
      // The latest transform, waited for up to 5 s of wall time (the callbacks, the clock's
      // included, run on this one thread: a wait in ROS time would not end).
      const std::string source = strip(goal.target.header.frame_id);
      const ::ros::WallTime deadline = ::ros::WallTime::now() + ::ros::WallDuration(5.0);
      while (!tf_buffer_.canTransform(chain->root(), source, ::ros::Time(0)) && ::ros::WallTime::now() < deadline)
        ::ros::WallDuration(0.01).sleep();
      const geometry_msgs::TransformStamped t = tf_buffer_.lookupTransform(chain->root(), source, ::ros::Time(0));
      mechsim::description::Pose X;
      X.position = {t.transform.translation.x, t.transform.translation.y, t.transform.translation.z};
      X.orientation = {t.transform.rotation.w, t.transform.rotation.x, t.transform.rotation.y, t.transform.rotation.z};
      const Vec3 p = mechsim::physics::rotate(X.orientation, {goal.target.point.x, goal.target.point.y, goal.target.point.z});
      target = {X.position.x + p.x, X.position.y + p.y, X.position.z + p.z};
    } catch (const std::exception& e) {
      reject(gh, std::string("transform failure: ") + e.what());
      return;
    }
    pr2_controllers_msgs::QueryTrajectoryState query;
    query.request.time = ::ros::Time::now() + ::ros::Duration(0.01);
    if (!query_.call(query)) {
      reject(gh, "the call to " + query_.getService() + " failed");
      return;
    }
    if (query.response.name != chain->joint_names() || query.response.position.size() != query.response.name.size()) {
      reject(gh, "the controller's joints are not the chain's from " + chain->root() + " to " + frame);
      return;
    }
    const std::vector<double> q_goal = chain->solve(axis, target);
    double distance = 0.0;
    for (std::size_t k = 0; k < q_goal.size(); ++k) distance += std::pow(q_goal[k] - query.response.position[k], 2);
    double duration = std::max(0.01, goal.min_duration.toSec());
    if (goal.max_velocity > 0.0) duration = std::max(duration, std::sqrt(distance) / goal.max_velocity);

    if (active_) {
      active_goal_.setCanceled(pr2_controllers_msgs::PointHeadResult(), "preempted by a newer goal");
      active_ = false;
    }
    gh.setAccepted();
    active_goal_ = gh;
    active_ = true;
    chain_ = std::move(chain);
    axis_ = axis;
    target_ = target;
    trajectory_msgs::JointTrajectory trajectory;
    trajectory.header.stamp = query.request.time;
    trajectory.joint_names = query.response.name;
    trajectory.points.resize(2);
    trajectory.points[0].positions = query.response.position;
    trajectory.points[0].velocities = query.response.velocity;
    trajectory.points[0].time_from_start = ::ros::Duration(0.0);
    trajectory.points[1].positions = q_goal;
    trajectory.points[1].velocities.assign(q_goal.size(), 0.0);
    trajectory.points[1].time_from_start = ::ros::Duration(duration);
    command_pub_.publish(trajectory);
  }

  void stop_head() {
    trajectory_msgs::JointTrajectory empty;
    if (chain_) empty.joint_names = chain_->joint_names();
    command_pub_.publish(empty);
  }

  void on_cancel(GoalHandle gh) {
    if (!active_ || !(active_goal_ == gh)) return;
    stop_head();
    active_goal_.setCanceled();
    active_ = false;
  }

  void on_state(const pr2_controllers_msgs::JointTrajectoryControllerState::ConstPtr& msg) {
    last_state_ = msg;
    if (!active_ || !chain_) return;
    if (msg->joint_names != chain_->joint_names() || msg->actual.positions.size() != msg->joint_names.size()) return;
    pr2_controllers_msgs::PointHeadFeedback feedback;
    feedback.pointing_angle_error = chain_->pointing_error(msg->actual.positions, axis_, target_);
    active_goal_.publishFeedback(feedback);
    if (feedback.pointing_angle_error < threshold_) {
      active_goal_.setSucceeded();
      active_ = false;
    }
  }

  void watchdog(const ::ros::TimerEvent&) {
    if (!active_) return;
    const char* why = !last_state_ ? "the controller's state has never come"
                      : (::ros::Time::now() - last_state_->header.stamp).toSec() > 5.0
                          ? "the controller's state has not come for 5 s"
                          : nullptr;
    if (why == nullptr) return;
    ROS_WARN_STREAM("mechsim point_head_action: aborting the goal: " << why);
    stop_head();
    active_goal_.setAborted(pr2_controllers_msgs::PointHeadResult(), why);
    active_ = false;
  }

  ::ros::NodeHandle nh_, pnh_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  Server server_;
  std::string pan_link_, default_frame_;
  double threshold_ = 0.1;
  mechsim::description::RobotModel robot_;
  ::ros::Publisher command_pub_;
  ::ros::Subscriber state_sub_;
  ::ros::ServiceClient query_;
  ::ros::Timer watchdog_;
  bool active_ = false;
  GoalHandle active_goal_;
  std::unique_ptr<mechsim::ros::HeadPointing> chain_;
  Vec3 axis_, target_;
  pr2_controllers_msgs::JointTrajectoryControllerState::ConstPtr last_state_;
};

}  // namespace

int main(int argc, char** argv) {
  ::ros::init(argc, argv, "point_head_action");
  try {
    PointHeadAction node;
    // One thread for every callback (actionlib's and this node's own state need no other lock);
    // TF's listener has its own.
    ::ros::spin();
  } catch (const std::exception& e) {
    ROS_FATAL_STREAM("mechsim point_head_action: " << e.what());
    return 1;
  }
  return 0;
}
