#pragma once
// The simulated sensors on ROS 2, as gazebo_ros' sensor plugins publish them (README.md,
// "Sensors"): sensor_msgs/msg/LaserScan, Imu, Image + CameraInfo (+ a 32FC1 depth Image, its
// CameraInfo and a PointCloud2 for depth cameras), geometry_msgs/msg/WrenchStamped,
// nav_msgs/msg/Odometry (p3d), with rclcpp::SensorDataQoS (best effort, volatile, keep last 5),
// stamped in simulated time, one node per sensor plugin (its name, in its namespace).
//
// Topic names (plugin_names.hpp): a plugin written for gazebo_ros' ROS 2 plugins (a <ros> block,
// or the ROS 2 plugin's own parameters) gets ROS 2's names (<ros><namespace>, <remapping>,
// ~/out, <camera_name>/image_raw, ...); a ROS 1 plugin block (robotNamespace, topicName,
// cameraName, ...) keeps the names it has under gazebo_ros 1, so that a description written for
// Gazebo classic + ROS 1 publishes where its users' nodes already look.
//
// Cost: a sensor is sampled only while one of its topics has a matched subscriber (as the camera
// and laser plugins activate their sensor on the first connection): unsubscribed, a tick pays one
// atomic load per topic. The tick fills a message; the outbox thread (outbox.hpp) writes it, and
// images and clouds go out through Fast DDS's asynchronous writers besides.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "bridge/sim_bridge.hpp"
#include "ros2/dds_participant.hpp"
#include "ros2/outbox.hpp"

namespace mechsim::ros2 {

struct SensorPublishStats {
  std::uint64_t messages = 0;       // published
  std::uint64_t camera_frames = 0;  // camera readings published
};

class SensorTopics {
 public:
  // Makes the nodes and publishers; logs each topic and each sensor it leaves out, and why.
  // Samples go out through `outbox` (the loop thread fills them, the outbox thread writes them).
  SensorTopics(Participant& participant, bridge::SimBridge& bridge, Outbox& outbox);
  ~SensorTopics();
  SensorTopics(const SensorTopics&) = delete;
  SensorTopics& operator=(const SensorTopics&) = delete;

  // Enables the sensors with subscribers, disables the others, publishes each new reading.
  // Loop thread.
  void publish();
  // Every sensor off (publishing paused); publish() turns on again the ones with subscribers.
  void disable_all();
  // "sensor -> topic (type, frame F)" per topic.
  const std::vector<std::string>& topics() const { return topics_; }
  SensorPublishStats stats() const { return stats_; }

  struct Output;

 private:
  void add(std::size_t sensor);
  Participant& participant_;
  bridge::SimBridge& bridge_;
  Outbox& outbox_;
  std::vector<std::unique_ptr<Output>> outputs_;
  std::vector<std::string> topics_;
  SensorPublishStats stats_;
};

}  // namespace mechsim::ros2
