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
#include <sensor_msgs/PointCloud.h>
#include <sensor_msgs/PointCloud2.h>
#include <sensor_msgs/Range.h>

#include "sensors/sensor_output.hpp"

namespace mechsim::ros {

// A frame name as tf2 wants it: without a leading '/' (the plugins' tf::resolve with an empty
// prefix); "" stays "".
std::string tf_frame(const std::string& frame);

// One row of the scan (`row`, vertical index; 0 for a planar scanner): LaserScan is planar.
void fill_laser_scan(const sensors::LaserScan& in, int row, sensor_msgs::LaserScan& out);
void fill_imu(const sensors::ImuReading& in, sensor_msgs::Imu& out);
// gazebo_ros_range's Range (radiation type, field of view, the ray sensor's limits, the range).
void fill_range(const sensors::RangeReading& in, sensor_msgs::Range& out);
// gazebo_ros_block_laser's PointCloud: the points and one channel of intensities, unnamed as the
// plugin leaves it.
void fill_block_cloud(const sensors::PointCloudReading& in, sensor_msgs::PointCloud& out);
// gazebo_ros_bumper's ContactsState, each state's `info` its debug line ("Debug:  i:(k/N)     my
// geom:...   other geom:...         time:SEC.NSEC") with the reading's stamp (s).
void fill_contacts(const sensors::ContactsReading& in, double stamp, gazebo_msgs::ContactsState& out);
void fill_wrench(const sensors::WrenchReading& in, geometry_msgs::WrenchStamped& out);
void fill_odometry(const sensors::GroundTruthReading& in, nav_msgs::Odometry& out);

// The image encoding gazebo_ros_camera_utils publishes an SDF <image><format> as: rgb8 (R8G8B8,
// RGB_INT8), bgr8 (B8G8R8, BGR_INT8), mono8 (L8, L_INT8), mono16 (L16, L_INT16, L_UINT16), rgb16
// (R16G16B16, RGB_INT16, RGB_UINT16), bayer_rggb8 ... (BAYER_*8); anything else bgr8, the plugin's
// fallback for a format it does not know.
std::string image_encoding(const std::string& sdf_format);
// Colour image (rgb8 as rendered, converted to `encoding`: grey as ITU-R BT.601 luma, 16 bits as
// the 8-bit levels times 257 (little-endian), Bayer as the mosaic of the rendered colours).
void fill_image(const sensors::CameraImage& in, const std::string& encoding, sensor_msgs::Image& out);
// Depth image, 32FC1 in metres (NaN outside the plugin's cutoffs), as gazebo_ros_depth_camera
// and gazebo_ros_openni_kinect publish it.
void fill_depth_image(const sensors::CameraImage& in, sensor_msgs::Image& out);
void fill_camera_info(const sensors::CameraInfo& in, sensor_msgs::CameraInfo& out);
// Organised cloud (height x width) with fields x y z (float32 at 0, 4, 8) and rgb (float32 at
// 16), point_step 32, NaN points kept (is_dense false when there is one): the layout of
// gazebo_ros_depth_camera's and gazebo_ros_openni_kinect's PointCloud2. Their colour bytes are the
// image's as the plugins copy them: a 3-byte pixel's bytes in the image's order at 16, 17, 18 (so
// rgb8 gives r g b where PCL reads b g r), a 1-byte pixel's thrice, 0 for 16-bit images.
void fill_point_cloud(const sensors::CameraImage& in, const std::string& encoding, sensor_msgs::PointCloud2& out);

}  // namespace mechsim::ros
