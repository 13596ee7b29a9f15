#pragma once
// The robot's Gazebo model plugins on ROS, under the names gazebo_plugins gives them: each
// plugin's ports (SimBridge::model_plugins) bound to <robotNamespace>/<topic>:
//   diff drive, skid steer, planar move,  cmd_vel (geometry_msgs/Twist, subscribed),
//   tricycle drive                         odom (nav_msgs/Odometry) and odom -> base on /tf
//                                          (publishOdomTF / broadcastTF / always for planar
//                                          move and tricycle drive)
//   diff/tricycle drive                   joint_states (sensor_msgs/JointState)
//   publishWheelJointState, joint state
//   publisher
//   diff/tricycle drive publishWheelTF    each wheel's parent -> child link transform on /tf
//   Gazebo's own libDiffDrivePlugin.so    /<model>/vel_cmd (geometry_msgs/Pose, subscribed): it
//                                          stands in for the Gazebo-transport topic
//                                          ~/<model>/vel_cmd (gazebo.msgs.Pose) mechsim lacks
// Outputs are published when the plugin has written a new snapshot (the plugin keeps its
// updateRate / odometryRate, in simulated time), stamped in simulated time. The mimic joint plugin
// publishes nothing (neither does Gazebo's). At start, the plugins mechsim does not simulate are
// logged once each (WARN), never fatal.
//
// Threads: publish() runs in the loop thread after each tick; cmd_vel callbacks on the spinner
// threads write the plugin's port (thread-safe; plugins live as long as the simulation).

#include <cstdint>
#include <string>
#include <vector>

#include <ros/ros.h>

#include "ros/bridge_names.hpp"

namespace mechsim::ros {

class ModelPluginTopics {
 public:
  ModelPluginTopics(::ros::NodeHandle& root, SimBridge& bridge);
  ~ModelPluginTopics();
  ModelPluginTopics(const ModelPluginTopics&) = delete;
  ModelPluginTopics& operator=(const ModelPluginTopics&) = delete;
  void publish(double time);
  std::size_t plugin_count() const { return plugins_; }

 private:
  struct Output;
  void publish_odometry(Output& out);
  void publish_joint_states(Output& out);

  SimBridge& bridge_;
  std::size_t plugins_ = 0;
  std::vector<::ros::Subscriber> subscribers_;
  std::vector<Output> outputs_;
  ::ros::Publisher tf_pub_;
};

}  // namespace mechsim::ros
