#pragma once
// ROS 2 QoS profiles as mechsim's endpoints use them (the subset of DDS QoS that rmw maps: history
// depth, reliability, durability). Each profile names the upstream code it follows.
//
// Matching (DDS, as rmw_dds_common::qos_profile_check_compatible states it): a best-effort writer
// does not match a reliable reader, a volatile writer does not match a transient-local reader;
// everything else matches. So a reliable transient-local writer matches every reader, and a
// best-effort volatile reader matches every writer.

#include <cstdint>
#include <string>

namespace mechsim::ros2 {

enum class Reliability : std::uint8_t { Reliable, BestEffort };
enum class Durability : std::uint8_t { Volatile, TransientLocal };

struct Qos {
  Reliability reliability = Reliability::Reliable;
  Durability durability = Durability::Volatile;
  int depth = 10;  // KEEP_LAST depth

  // rclcpp::QoS(10) / rmw_qos_profile_default: reliable, volatile, keep last 10.
  static Qos defaults() { return {}; }
  // rclcpp::SensorDataQoS: best effort, volatile, keep last 5 (gazebo_ros' sensor plugins).
  static Qos sensor_data() { return {Reliability::BestEffort, Durability::Volatile, 5}; }
  // gazebo_ros_init's /clock: rmw_qos_profile_default with transient-local durability, so that a
  // late subscriber gets the last time while the world is paused; matches ClockQoS readers
  // (best effort, volatile, depth 1).
  static Qos clock() { return {Reliability::Reliable, Durability::TransientLocal, 10}; }
  // tf2_ros::StaticBroadcasterQoS and robot_state_publisher's robot_description: reliable,
  // transient local, keep last 1.
  static Qos latched() { return {Reliability::Reliable, Durability::TransientLocal, 1}; }
  // tf2_ros::DynamicBroadcasterQoS: reliable, volatile, keep last 100.
  static Qos tf() { return {Reliability::Reliable, Durability::Volatile, 100}; }
  // What mechsim's command subscriptions ask for: best effort, volatile, keep last 1. It matches
  // every writer (rclcpp's reliable default, a best-effort teleop, a transient-local latch), as
  // ros2_controllers' SystemDefaultsQoS subscriptions do under rmw_fastrtps (Fast DDS's default
  // reader is best effort), and a command is only ever the newest one.
  static Qos command_reader() { return {Reliability::BestEffort, Durability::Volatile, 1}; }

  std::string describe() const;  // "reliable, transient local, keep last 1"
};

inline std::string Qos::describe() const {
  return std::string(reliability == Reliability::Reliable ? "reliable" : "best effort") + ", " +
         (durability == Durability::Volatile ? "volatile" : "transient local") + ", keep last " +
         std::to_string(depth);
}

}  // namespace mechsim::ros2
