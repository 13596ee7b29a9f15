#pragma once
// The built-in robot state publisher: for every URDF joint, the transform parent link -> child
// link = joint origin * joint motion (rotation about the axis by q for revolute/continuous,
// translation along it for prismatic), as robot_state_publisher computes it. Fixed joints go
// once to /tf_static (latched); moving joints to /tf at the caller's rate. Optionally the pose of
// the root link in the odom frame (from the physics) goes to /tf as well.

#include <string>
#include <vector>

#include <ros/ros.h>
#include <tf2_msgs/TFMessage.h>

#include "bridge/robot_frames.hpp"
#include "ros/bridge_names.hpp"

namespace mechsim::ros {

// The transforms come from the bridge layer's robot frames (bridge/robot_frames.hpp).
class TfPublisher {
 public:
  // `odom_frame` empty: no odom -> root transform.
  TfPublisher(::ros::NodeHandle& nh, const description::RobotModel& robot, std::string odom_frame);
  void publish_static(double time);
  // q: per robot.joints (SimBridge::joint_positions); X_OB: root link in the odom frame.
  void publish(double time, const std::vector<double>& q, const description::Pose& X_OB);

 private:
  const description::RobotModel& robot_;
  std::string odom_frame_;
  ::ros::Publisher tf_pub_, static_pub_;
  tf2_msgs::TFMessage message_;  // reused
  std::vector<JointFrame> frames_;  // reused
};

}  // namespace mechsim::ros
