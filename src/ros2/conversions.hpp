#pragma once
// mechsim's plain data (bridge ports, sensor readings) into ROS 2 messages, and the small helpers
// the publishers share. Each fill function fills a message the caller keeps and reuses, so that a
// publisher allocates only while its message grows.

#include <cmath>
#include <cstdint>
#include <string>

#include <mechsim_ros2_msgs/builtin_interfaces.hpp>
#include <mechsim_ros2_msgs/geometry_msgs.hpp>
#include <mechsim_ros2_msgs/nav_msgs.hpp>
#include <mechsim_ros2_msgs/sensor_msgs.hpp>

#include "bridge/sim_bridge.hpp"
#include "sensors/sensor_output.hpp"

namespace mechsim::ros2 {

// Seconds of simulated time as builtin_interfaces/Time (nanoseconds rounded, never 1e9).
builtin_interfaces::msg::Time to_time(double seconds);
double to_seconds(const builtin_interfaces::msg::Time& t);
double to_seconds(const builtin_interfaces::msg::Duration& d);

// The first whole multiple of `period` after `time` (s, sim time); `time` itself when period is 0.
inline double next_due_after(double time, double period) {
  if (period <= 0.0) return time;
  return (std::floor(time / period + 1e-6) + 1.0) * period;
}

// A frame name as tf2 wants it: without a leading '/'.
std::string tf_frame(const std::string& frame);

void fill_joint_state(const bridge::JointStatesData& in, sensor_msgs::msg::JointState& out);
void fill_odometry(const bridge::OdometryData& in, nav_msgs::msg::Odometry& out);

// Sensor readings (as the Gazebo plugins publish them; ros/sensor_messages.hpp is the ROS 1 twin).
void fill_laser_scan(const sensors::LaserScan& in, int row, sensor_msgs::msg::LaserScan& out);
void fill_imu(const sensors::ImuReading& in, sensor_msgs::msg::Imu& out);
void fill_wrench(const sensors::WrenchReading& in, geometry_msgs::msg::WrenchStamped& out);
void fill_ground_truth(const sensors::GroundTruthReading& in, nav_msgs::msg::Odometry& out);
// rgb8 (as rendered), bgr8 or mono8.
std::string image_encoding(const std::string& sdf_format);
void fill_image(const sensors::CameraImage& in, const std::string& encoding, sensor_msgs::msg::Image& out);
void fill_depth_image(const sensors::CameraImage& in, sensor_msgs::msg::Image& out);  // 32FC1, m
void fill_camera_info(const sensors::CameraInfo& in, sensor_msgs::msg::CameraInfo& out);
// Organised cloud, fields x y z rgb (float32 at 0 4 8 16), point_step 32, NaN points kept.
void fill_point_cloud(const sensors::CameraImage& in, sensor_msgs::msg::PointCloud2& out);

}  // namespace mechsim::ros2
