// Sensor plugins' ROS 2 names: gazebo_ros' ROS 2 plugins (a <ros> block) the ROS 2 way, ROS 1
// plugin blocks with their ROS 1 names.
#include <gtest/gtest.h>

#include "description/sensor_spec.hpp"
#include "description/urdf/urdf_parser.hpp"
#include "ros2/plugin_names.hpp"

namespace mechsim::ros2 {
namespace {

constexpr const char* kRobot = R"(<?xml version="1.0"?>
<robot name="r">
  <link name="base_link">
    <inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
  </link>
  <gazebo reference="base_link">
    <sensor type="ray" name="laser">
      <ray><scan><horizontal><samples>10</samples><min_angle>-1</min_angle><max_angle>1</max_angle></horizontal></scan>
        <range><min>0.1</min><max>5</max></range></ray>
      <plugin name="laser_plugin" filename="libgazebo_ros_ray_sensor.so">
        <ros><namespace>/bot</namespace><remapping>~/out:=scan</remapping></ros>
        <output_type>sensor_msgs/LaserScan</output_type>
        <frame_name>laser_frame</frame_name>
      </plugin>
    </sensor>
    <sensor type="ray" name="cloud">
      <ray><scan><horizontal><samples>10</samples><min_angle>-1</min_angle><max_angle>1</max_angle></horizontal></scan>
        <range><min>0.1</min><max>5</max></range></ray>
      <plugin name="cloud_plugin" filename="libgazebo_ros_ray_sensor.so"><ros><namespace>/bot</namespace></ros></plugin>
    </sensor>
    <sensor type="camera" name="cam">
      <camera><image><width>8</width><height>6</height></image></camera>
      <plugin name="cam_plugin" filename="libgazebo_ros_camera.so">
        <ros><namespace>/bot</namespace><argument>--ros-args -r cam/image_raw:=image</argument></ros>
      </plugin>
    </sensor>
    <sensor type="imu" name="imu1">
      <plugin name="imu_plugin" filename="libgazebo_ros_imu_sensor.so">
        <robotNamespace>/old</robotNamespace>
        <topicName>imu/data</topicName>
        <frameName>imu_frame</frameName>
      </plugin>
    </sensor>
  </gazebo>
</robot>)";

const description::SensorSpec& sensor(const description::RobotModel& r, const std::string& name) {
  for (const auto& s : r.sensors)
    if (s.name == name) return s;
  throw std::runtime_error("no sensor " + name);
}

TEST(PluginNames, Ros2PluginsUseTheirRosBlock) {
  std::vector<std::string> warnings;
  const description::RobotModel r = description::parse_urdf_string(kRobot, "test.urdf", {}, &warnings);
  const SensorNames laser = sensor_names(sensor(r, "laser"));
  EXPECT_TRUE(laser.ros2_plugin);
  EXPECT_EQ(laser.node_namespace, "/bot");
  EXPECT_EQ(laser.node_name, "laser_plugin");
  EXPECT_EQ(laser.frame, "laser_frame");
  EXPECT_EQ(resolve_topic(laser.output, laser.node_namespace, laser.node_name, laser.remaps), "/bot/scan");

  // gazebo_ros' ray sensor publishes PointCloud2 unless told otherwise: left out, with why.
  EXPECT_NE(sensor_names(sensor(r, "cloud")).unsupported.find("PointCloud2"), std::string::npos);

  const SensorNames cam = sensor_names(sensor(r, "cam"));
  ASSERT_EQ(cam.images.size(), 1u);
  EXPECT_EQ(resolve_topic(cam.images[0], cam.node_namespace, cam.node_name, cam.remaps), "/bot/image");
  EXPECT_EQ(resolve_topic(cam.infos[0], cam.node_namespace, cam.node_name, cam.remaps), "/bot/cam/camera_info");
  EXPECT_EQ(cam.frame, "base_link");  // no <frame_name>: the sensor's link
}

TEST(PluginNames, Ros1PluginsKeepTheirNames) {
  std::vector<std::string> warnings;
  const description::RobotModel r = description::parse_urdf_string(kRobot, "test.urdf", {}, &warnings);
  const SensorNames imu = sensor_names(sensor(r, "imu1"));
  EXPECT_FALSE(imu.ros2_plugin);
  EXPECT_EQ(imu.node_namespace, "/old");
  EXPECT_EQ(imu.output, "/old/imu/data");
  EXPECT_EQ(imu.frame, "imu_frame");
}

TEST(PluginNames, NodeNamesAreTokens) {
  EXPECT_EQ(node_name_of("camera-controller 2"), "camera_controller_2");
  EXPECT_EQ(node_name_of("2d"), "_2d");
  EXPECT_EQ(node_name_of(""), "sensor");
}

}  // namespace
}  // namespace mechsim::ros2
