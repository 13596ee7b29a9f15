#pragma once
// Where a sensor plugin publishes on ROS 2, and as which node.
//
// gazebo_ros (ROS 2) plugins, recognised by a <ros> block or their ROS 2 parameters (frame_name,
// camera_name, output_type), as gazebo_plugins' ROS 2 sources name them:
//   node             the plugin's name attribute, in <ros><namespace>
//   ray sensor       libgazebo_ros_ray_sensor.so: ~/out (sensor_msgs/msg/LaserScan with
//                    <output_type>sensor_msgs/LaserScan</output_type>; its default, PointCloud2,
//                    is not published by mechsim), frame <frame_name> or the sensor's link
//   IMU              libgazebo_ros_imu_sensor.so: ~/out
//   camera           libgazebo_ros_camera.so: <camera_name>/image_raw, <camera_name>/camera_info
//                    (camera_name: the sensor's name by default); on a depth sensor also
//                    <camera_name>/depth/image_raw, <camera_name>/depth/camera_info, <camera_name>/points
//   every name goes through the plugin's <remapping>s (e.g. ~/out:=scan).
// gazebo_ros (ROS 1) plugins keep their ROS 1 names (<robotNamespace> + <topicName>,
// <cameraName>/<imageTopicName>, ...), as description/ resolves them; node: the plugin's name in
// <robotNamespace>.

#include <optional>
#include <string>
#include <vector>

#include "description/sensor_spec.hpp"
#include "ros2/names.hpp"

namespace mechsim::ros2 {

struct SensorNames {
  std::string node_namespace = "/";
  std::string node_name;
  std::vector<Remap> remaps;
  bool ros2_plugin = false;  // named the ROS 2 way
  std::string frame;          // header.frame_id
  // Topics as given to the node (relative ones resolve in node_namespace): the main output (ray,
  // IMU, ...), and a camera's per-lens images and infos, depth, depth info, points.
  std::string output;
  std::vector<std::string> images, infos;
  std::string depth, depth_info, points;
  std::string unsupported;  // why the plugin is not published ("" when it is)
};

// The names of sensor `spec`'s plugin. `kind` is spec.kind_name().
SensorNames sensor_names(const description::SensorSpec& spec);

// A node name made of a plugin's name: characters outside [A-Za-z0-9_] become '_', a leading digit
// gets a '_' before it ("" -> "sensor").
std::string node_name_of(const std::string& plugin_name);

}  // namespace mechsim::ros2
