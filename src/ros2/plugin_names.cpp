// Sensor plugins' ROS 2 names (plugin_names.hpp).
#include "ros2/plugin_names.hpp"

#include <cctype>
#include <variant>

namespace mechsim::ros2 {

namespace {

std::string param(const description::SensorPlugin& p, const std::string& key, const std::string& fallback) {
  const auto it = p.parameters.find(key);
  return it != p.parameters.end() && !it->second.empty() ? it->second : fallback;
}

bool ros2_style(const description::SensorPlugin& p) {
  if (p.ros2_block) return true;
  for (const char* key : {"frame_name", "camera_name", "output_type"}) {
    if (p.parameters.count(key) > 0) return true;
  }
  return p.filename == "libgazebo_ros_ray_sensor.so";
}

}  // namespace

std::string node_name_of(const std::string& plugin_name) {
  std::string out;
  for (char c : plugin_name) out.push_back(std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' ? c : '_');
  if (out.empty()) return "sensor";
  if (std::isdigit(static_cast<unsigned char>(out[0])) != 0) out.insert(out.begin(), '_');
  return out;
}

SensorNames sensor_names(const description::SensorSpec& spec) {
  SensorNames n;
  const description::SensorPlugin& p = *spec.plugin;
  n.node_name = node_name_of(p.name.empty() ? spec.name : p.name);
  const std::string kind = spec.kind_name();
  n.ros2_plugin = ros2_style(p);
  if (!n.ros2_plugin) {
    // gazebo_ros 1 names, as description/ resolved them.
    n.node_namespace = p.robot_namespace.empty() ? "/" : p.robot_namespace;
    n.frame = p.frame;
    if (kind == "camera") {
      const auto& camera = std::get<description::CameraSpec>(spec.details);
      n.images = camera.image_topics;
      n.infos = camera.info_topics;
      if (camera.depth) {
        n.depth = camera.depth_topic;
        n.depth_info = camera.depth_info_topic;
        n.points = camera.points_topic;
      }
    } else {
      n.output = p.full_topic();
    }
    if (!p.unsupported.empty()) n.unsupported = p.unsupported;
    return n;
  }
  n.node_namespace = p.ros2_namespace.empty() ? "/" : p.ros2_namespace;
  for (const std::string& rule : p.ros2_remappings) n.remaps.push_back(parse_remap(rule));
  n.frame = param(p, "frame_name", spec.link);
  if (kind == "ray") {
    if (p.filename != "libgazebo_ros_ray_sensor.so") {
      n.unsupported = "a ray sensor's ROS 2 plugin is libgazebo_ros_ray_sensor.so, not " + p.filename;
      return n;
    }
    const std::string type = param(p, "output_type", "sensor_msgs/PointCloud2");
    if (type != "sensor_msgs/LaserScan" && type != "sensor_msgs/msg/LaserScan") {
      n.unsupported = "<output_type> " + type + ": mechsim publishes ray sensors as sensor_msgs/LaserScan only";
      return n;
    }
    n.output = "~/out";
  } else if (kind == "imu") {
    n.output = "~/out";
  } else if (kind == "camera") {
    const std::string camera = param(p, "camera_name", spec.name);
    const auto& c = std::get<description::CameraSpec>(spec.details);
    if (c.lenses.size() > 1) {
      n.unsupported = "a multicamera's ROS 2 plugin (libgazebo_ros_camera.so on a multicamera) is not published by mechsim";
      return n;
    }
    n.images = {camera + "/image_raw"};
    n.infos = {camera + "/camera_info"};
    if (c.depth) {
      n.depth = camera + "/depth/image_raw";
      n.depth_info = camera + "/depth/camera_info";
      n.points = camera + "/points";
    }
  } else {
    n.unsupported = "mechsim publishes no ROS 2 output for a " + kind + " sensor's ROS 2 plugin (" + p.filename + ")";
  }
  return n;
}

}  // namespace mechsim::ros2
