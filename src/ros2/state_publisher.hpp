#pragma once
// The robot_state_publisher of a mechsim ROS 2 world, as robot_state_publisher (ROS 2) publishes:
//   /robot_description  std_msgs/msg/String, the URDF, reliable + transient local, keep last 1
//                       (late subscribers get it), in the node's namespace
//   /tf_static          tf2_msgs/msg/TFMessage, every fixed joint's parent -> child in ONE
//                       message, tf2_ros::StaticBroadcasterQoS (reliable, transient local, 1)
//   /tf                 tf2_msgs/msg/TFMessage, every moving joint's parent -> child = origin *
//                       motion, at `rate` Hz of sim time, tf2_ros::DynamicBroadcasterQoS
// Node `robot_state_publisher`. The loop thread fills /tf (only while it has subscribers), the
// outbox thread writes it.

#include <memory>
#include <string>
#include <vector>

#include <mechsim_ros2_msgs/std_msgs.hpp>
#include <mechsim_ros2_msgs/tf2_msgs.hpp>

#include "bridge/robot_frames.hpp"
#include "description/robot_model.hpp"
#include "ros2/node.hpp"
#include "ros2/outbox.hpp"

namespace mechsim::ros2 {

// The transforms come from the bridge layer's robot frames (bridge/robot_frames.hpp), as the
// ROS 1 binding's.
class StatePublisher {
 public:
  // `ns`: the node's namespace (robot_description is relative to it); `odom_frame` non-empty adds
  // odom_frame -> root link from the physics to /tf.
  StatePublisher(Participant& participant, Outbox& outbox, const std::string& ns, const description::RobotModel& robot,
                 const std::string& urdf, std::string odom_frame);
  // /tf_static (once; transient local keeps it for late subscribers).
  void publish_static(double time);
  // q: per robot.joints (SimBridge::joint_positions); X_OB: the root link in the odom frame.
  void publish(double time, const std::vector<double>& q, const description::Pose& X_OB);

 private:
  const description::RobotModel& robot_;
  Outbox& outbox_;
  std::string odom_frame_;
  Node node_;
  std::unique_ptr<Publisher<std_msgs::msg::String>> description_pub_;
  std::shared_ptr<Publisher<tf2_msgs::msg::TFMessage>> tf_pub_;
  std::unique_ptr<Publisher<tf2_msgs::msg::TFMessage>> static_pub_;
  std::vector<bridge::JointFrame> frames_;  // the loop thread's, reused
};

}  // namespace mechsim::ros2
