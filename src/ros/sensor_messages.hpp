#pragma once
// Sensor readings (sensors/sensor_output.hpp, plain data) into the ROS messages the Gazebo plugins
// publish: gazebo_ros_laser's LaserScan, gazebo_ros_imu(_sensor)'s Imu, gazebo_ros_bumper's
// ContactsState, gazebo_ros_ft_sensor's WrenchStamped, gazebo_ros_p3d's Odometry, and the camera
// plugins' Image, CameraInfo and PointCloud2. Each fills a message the caller keeps and reuses, so
// a publisher allocates only while its message grows.

#include <string>

#include <gazebo_msgs/ContactsState.h>
#include <geometry_msgs/WrenchStamped.h>
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/PointCloud2.h>

#include "sensors/sensor_output.hpp"

namespace mechsim::ros {

// A frame name as tf2 wants it: without a leading '/' (the plugins' tf::resolve with an empty
// prefix); "" stays "".
std::string tf_frame(const std::string& frame);

// One row of the scan (`row`, vertical index; 0 for a planar scanner): LaserScan is planar.
void fill_laser_scan(const sensors::LaserScan& in, int row, sensor_msgs::LaserScan& out);
void fill_imu(const sensors::ImuReading& in, sensor_msgs::Imu& out);
void fill_contacts(const sensors::ContactsReading& in, gazebo_msgs::ContactsState& out);
void fill_wrench(const sensors::WrenchReading& in, geometry_msgs::WrenchStamped& out);
void fill_odometry(const sensors::GroundTruthReading& in, nav_msgs::Odometry& out);

// The image encoding of an SDF <image><format>: rgb8 (R8G8B8, RGB_INT8, the default), bgr8
// (B8G8R8, BGR_INT8) or mono8 (L8, L_INT8).
std::string image_encoding(const std::string& sdf_format);
// Colour image (rgb8 as rendered, converted to `encoding`).
void fill_image(const sensors::CameraImage& in, const std::string& encoding, sensor_msgs::Image& out);
// Depth image, 32FC1 in metres (NaN outside the plugin's cutoffs), as gazebo_ros_depth_camera
// and gazebo_ros_openni_kinect publish it.
void fill_depth_image(const sensors::CameraImage& in, sensor_msgs::Image& out);
void fill_camera_info(const sensors::CameraInfo& in, sensor_msgs::CameraInfo& out);
// Organised cloud (height x width) with fields x y z (float32 at 0, 4, 8) and rgb (float32 at
// 16, bytes b g r 0), point_step 32, NaN points kept (is_dense false): the layout of
// gazebo_ros_depth_camera's and gazebo_ros_openni_kinect's PointCloud2.
void fill_point_cloud(const sensors::CameraImage& in, sensor_msgs::PointCloud2& out);

}  // namespace mechsim::ros
