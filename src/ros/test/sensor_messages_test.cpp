// Sensor readings into the Gazebo plugins' ROS messages (ros/sensor_messages.hpp): the layout a
// ROS consumer decodes (PointCloud2 fields, image steps and encodings), not just copied fields.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <map>

#include <ros/serialization.h>

#include "ros/sensor_messages.hpp"

namespace mechsim::ros {
namespace {

sensors::CameraImage image_2x3() {
  sensors::CameraImage im;
  im.info.width = 3;
  im.info.height = 2;
  im.info.K = {100, 0, 2, 0, 100, 1.5, 0, 0, 1};
  im.info.P = {100, 0, 2, -7, 0, 100, 1.5, 0, 0, 0, 1, 0};
  im.info.D = {0.1, -0.2, 0.001, 0.002, 0.03};
  im.info.R = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  for (int i = 0; i < 6; ++i) {
    im.rgb.push_back(static_cast<std::uint8_t>(10 * i));       // r
    im.rgb.push_back(static_cast<std::uint8_t>(10 * i + 1));   // g
    im.rgb.push_back(static_cast<std::uint8_t>(10 * i + 2));   // b
    im.depth.push_back(i == 4 ? std::numeric_limits<float>::quiet_NaN() : 0.5f + 0.25f * static_cast<float>(i));
    im.points.push_back(0.1f * static_cast<float>(i));
    im.points.push_back(-0.1f * static_cast<float>(i));
    im.points.push_back(im.depth.back());
  }
  return im;
}

TEST(SensorMessages, TfFrameDropsLeadingSlashes) {
  EXPECT_EQ(tf_frame("/base_laser_link"), "base_laser_link");
  EXPECT_EQ(tf_frame("//a/b"), "a/b");
  EXPECT_EQ(tf_frame(""), "");
}

TEST(SensorMessages, LaserScanTakesOneRowWithTheScanGeometry) {
  sensors::LaserScan in;
  in.angle_min = -1.0;
  in.angle_max = 1.0;
  in.angle_increment = 1.0;
  in.horizontal_count = 3;
  in.vertical_count = 2;
  in.range_min = 0.08;
  in.range_max = 10.0;
  in.scan_time = 0.05;
  in.ranges = {1, 2, 3, 4, std::numeric_limits<float>::infinity(), 6};
  in.intensities = {0, 0, 0, 0, 0, 0};
  sensor_msgs::LaserScan out;
  fill_laser_scan(in, 1, out);
  ASSERT_EQ(out.ranges.size(), 3u);
  EXPECT_EQ(out.ranges[0], 4.0f);
  EXPECT_TRUE(std::isinf(out.ranges[1]));
  EXPECT_EQ(out.intensities.size(), 3u);
  EXPECT_FLOAT_EQ(out.angle_min, -1.0f);
  EXPECT_FLOAT_EQ(out.range_min, 0.08f);
  EXPECT_FLOAT_EQ(out.scan_time, 0.05f);
  fill_laser_scan(in, 0, out);  // reused message: shrinks to the row
  EXPECT_EQ(out.ranges[2], 3.0f);
  fill_laser_scan(in, 7, out);  // out of range: the last row, not past the data
  EXPECT_EQ(out.ranges[0], 4.0f);
}

TEST(SensorMessages, ContactsUseOnlyTheStatesInUse) {
  sensors::ContactsReading in;
  in.states.resize(3);
  in.count = 1;
  in.states[0].collision1_name = "pr2::base_link::base_link_collision";
  in.states[0].contact_positions = {{1, 2, 3}};
  in.states[0].contact_normals = {{0, 0, 1}};
  in.states[0].wrenches = {{{0, 0, 5}, {0, 0, 0}}};
  in.states[0].depths = {0.001};
  in.states[0].collision2_name = "ground_plane::link::collision";
  gazebo_msgs::ContactsState out;
  fill_contacts(in, 12.05, out);
  ASSERT_EQ(out.states.size(), 1u);
  EXPECT_EQ(out.states[0].collision1_name, "pr2::base_link::base_link_collision");
  // gazebo_ros_bumper's debug line, the time as ros::Time prints it.
  EXPECT_EQ(out.states[0].info,
            "Debug:  i:(0/1)     my geom:pr2::base_link::base_link_collision   other geom:ground_plane::link::collision"
            "         time:12.050000000\n");
  EXPECT_DOUBLE_EQ(out.states[0].contact_positions.at(0).z, 3.0);
  EXPECT_DOUBLE_EQ(out.states[0].wrenches.at(0).force.z, 5.0);
  EXPECT_DOUBLE_EQ(out.states[0].depths.at(0), 0.001);
}

TEST(SensorMessages, OdometryCovarianceIsP3dsDiagonal) {
  sensors::GroundTruthReading in;
  in.pose.position = {1, 2, 0.05};
  in.linear = {0.5, 0, 0};
  in.pose_variance = 0.0;
  in.twist_variance = 1e-4;
  nav_msgs::Odometry out;
  fill_odometry(in, out);
  EXPECT_DOUBLE_EQ(out.pose.pose.position.y, 2.0);
  EXPECT_DOUBLE_EQ(out.twist.twist.linear.x, 0.5);
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c) EXPECT_DOUBLE_EQ(out.twist.covariance[6 * r + c], r == c ? 1e-4 : 0.0);
}

TEST(SensorMessages, RangeAsGazeboRosRangeFillsIt) {
  sensors::RangeReading in;
  in.radiation = 1;
  in.field_of_view = 0.5;
  in.min_range = 0.01;
  in.max_range = 0.75;
  in.range = 0.225;
  sensor_msgs::Range out;
  fill_range(in, out);
  EXPECT_EQ(out.radiation_type, sensor_msgs::Range::INFRARED);
  EXPECT_FLOAT_EQ(out.field_of_view, 0.5f);
  EXPECT_FLOAT_EQ(out.min_range, 0.01f);
  EXPECT_FLOAT_EQ(out.max_range, 0.75f);
  EXPECT_FLOAT_EQ(out.range, 0.225f);
}

TEST(SensorMessages, BlockLaserCloudHasOneUnnamedIntensityChannel) {
  sensors::PointCloudReading in;
  in.points = {{1, 2, 3}, {4, 5, -6}};
  in.intensities = {100.0f, 0.5f};
  sensor_msgs::PointCloud out;
  fill_block_cloud(in, out);
  ASSERT_EQ(out.points.size(), 2u);
  EXPECT_FLOAT_EQ(out.points[1].z, -6.0f);
  ASSERT_EQ(out.channels.size(), 1u);
  EXPECT_EQ(out.channels[0].name, "");
  EXPECT_EQ(out.channels[0].values, (std::vector<float>{100.0f, 0.5f}));
}

TEST(SensorMessages, SixteenBitAndBayerImages) {
  const sensors::CameraImage in = image_2x3();
  EXPECT_EQ(image_encoding("L16"), "mono16");
  EXPECT_EQ(image_encoding("L_INT16"), "mono16");
  EXPECT_EQ(image_encoding("R16G16B16"), "rgb16");
  EXPECT_EQ(image_encoding("RGB_INT16"), "rgb16");
  EXPECT_EQ(image_encoding("BAYER_GRBG8"), "bayer_grbg8");
  EXPECT_EQ(image_encoding("FLOAT32"), "bgr8") << "gazebo_ros_camera_utils' fallback";
  sensor_msgs::Image out;
  fill_image(in, "rgb16", out);
  EXPECT_EQ(out.step, 18u);
  ASSERT_EQ(out.data.size(), 36u);
  EXPECT_EQ(out.is_bigendian, 0);
  EXPECT_EQ(out.data[2 * (3 * 4 + 1)] | (out.data[2 * (3 * 4 + 1) + 1] << 8), 41 * 257);  // pixel 4's green
  fill_image(in, "mono16", out);
  EXPECT_EQ(out.step, 6u);
  ASSERT_EQ(out.data.size(), 12u);
  EXPECT_EQ(out.data[8] | (out.data[9] << 8), 257 * std::lround(0.299 * 40 + 0.587 * 41 + 0.114 * 42));
  fill_image(in, "bayer_rggb8", out);
  EXPECT_EQ(out.step, 3u);
  ASSERT_EQ(out.data.size(), 6u);
  // Row 0: r g r; row 1: g b g.
  EXPECT_EQ(out.data[0], 0);    // pixel 0's red
  EXPECT_EQ(out.data[1], 11);   // pixel 1's green
  EXPECT_EQ(out.data[4], 42);   // pixel 4's blue
  EXPECT_EQ(out.data[5], 51);   // pixel 5's green
}

TEST(SensorMessages, ImagesInTheirEncodings) {
  const sensors::CameraImage in = image_2x3();
  EXPECT_EQ(image_encoding("R8G8B8"), "rgb8");
  EXPECT_EQ(image_encoding("B8G8R8"), "bgr8");
  EXPECT_EQ(image_encoding("L8"), "mono8");
  sensor_msgs::Image out;
  fill_image(in, "rgb8", out);
  EXPECT_EQ(out.width, 3u);
  EXPECT_EQ(out.height, 2u);
  EXPECT_EQ(out.step, 9u);
  ASSERT_EQ(out.data.size(), 18u);
  EXPECT_EQ(out.data[3 * 4 + 0], 40);  // pixel 4's red
  fill_image(in, "bgr8", out);
  EXPECT_EQ(out.data[3 * 4 + 0], 42);  // pixel 4's blue first
  EXPECT_EQ(out.data[3 * 4 + 2], 40);
  fill_image(in, "mono8", out);
  EXPECT_EQ(out.step, 3u);
  ASSERT_EQ(out.data.size(), 6u);
  EXPECT_EQ(out.data[4], std::lround(0.299 * 40 + 0.587 * 41 + 0.114 * 42));
  sensors::CameraImage empty;  // nothing rendered: an empty image, not a read past the data
  empty.info.width = 3;
  empty.info.height = 2;
  fill_image(empty, "rgb8", out);
  EXPECT_TRUE(out.data.empty());
  EXPECT_EQ(out.width, 0u);
}

TEST(SensorMessages, DepthImageIs32FC1Metres) {
  const sensors::CameraImage in = image_2x3();
  sensor_msgs::Image out;
  fill_depth_image(in, out);
  EXPECT_EQ(out.encoding, "32FC1");
  EXPECT_EQ(out.step, 12u);
  ASSERT_EQ(out.data.size(), 24u);
  float d[6];
  std::memcpy(d, out.data.data(), sizeof d);
  EXPECT_FLOAT_EQ(d[1], 0.75f);
  EXPECT_TRUE(std::isnan(d[4]));
}

TEST(SensorMessages, CameraInfoCarriesKPD) {
  const sensors::CameraImage in = image_2x3();
  sensor_msgs::CameraInfo out;
  fill_camera_info(in.info, out);
  EXPECT_EQ(out.distortion_model, "plumb_bob");
  ASSERT_EQ(out.D.size(), 5u);
  EXPECT_DOUBLE_EQ(out.D[4], 0.03);
  EXPECT_DOUBLE_EQ(out.K[2], 2.0);
  EXPECT_DOUBLE_EQ(out.P[3], -7.0);
  EXPECT_DOUBLE_EQ(out.R[8], 1.0);
  EXPECT_EQ(out.width, 3u);
}

// Decoded as a ROS consumer does: by the fields' names and offsets, after a serialisation round trip.
TEST(SensorMessages, PointCloudDecodesByItsFields) {
  const sensors::CameraImage in = image_2x3();
  sensor_msgs::PointCloud2 cloud;
  fill_point_cloud(in, "bgr8", cloud);
  const std::uint32_t size = ::ros::serialization::serializationLength(cloud);
  std::vector<std::uint8_t> buffer(size);
  ::ros::serialization::OStream os(buffer.data(), size);
  ::ros::serialization::serialize(os, cloud);
  sensor_msgs::PointCloud2 got;
  ::ros::serialization::IStream is(buffer.data(), size);
  ::ros::serialization::deserialize(is, got);

  EXPECT_EQ(got.width, 3u);
  EXPECT_EQ(got.height, 2u);
  EXPECT_FALSE(got.is_dense);
  EXPECT_EQ(got.row_step, got.point_step * 3);
  std::map<std::string, std::uint32_t> offset;
  for (const sensor_msgs::PointField& f : got.fields) {
    EXPECT_EQ(f.datatype, sensor_msgs::PointField::FLOAT32) << f.name;
    offset[f.name] = f.offset;
  }
  ASSERT_EQ(offset.size(), 4u);
  for (std::size_t i = 0; i < 6; ++i) {
    const std::uint8_t* p = got.data.data() + i * got.point_step;
    float x, y, z;
    std::memcpy(&x, p + offset["x"], 4);
    std::memcpy(&y, p + offset["y"], 4);
    std::memcpy(&z, p + offset["z"], 4);
    std::uint32_t rgb;
    std::memcpy(&rgb, p + offset["rgb"], 4);
    EXPECT_FLOAT_EQ(x, 0.1f * static_cast<float>(i));
    EXPECT_FLOAT_EQ(y, -0.1f * static_cast<float>(i));
    if (i == 4) EXPECT_TRUE(std::isnan(z));
    else EXPECT_FLOAT_EQ(z, in.depth[i]);
    // A bgr8 image's bytes in order: PCL's packed 0x00RRGGBB.
    EXPECT_EQ((rgb >> 16) & 0xff, 10 * i) << "red of point " << i;
    EXPECT_EQ((rgb >> 8) & 0xff, 10 * i + 1);
    EXPECT_EQ(rgb & 0xff, 10 * i + 2);
  }
}

// The depth plugins copy the image's bytes as they are: an rgb8 image's red lands where PCL reads
// blue; a mono image's grey thrice; a 16-bit image gives no colour.
TEST(SensorMessages, PointCloudColourBytesAreTheImagesAsThePluginsCopyThem) {
  const sensors::CameraImage in = image_2x3();
  sensor_msgs::PointCloud2 cloud;
  const auto bytes = [&](std::size_t i) { return cloud.data.data() + i * cloud.point_step + 16; };
  fill_point_cloud(in, "rgb8", cloud);
  EXPECT_EQ(bytes(4)[0], 40);
  EXPECT_EQ(bytes(4)[1], 41);
  EXPECT_EQ(bytes(4)[2], 42);
  EXPECT_FALSE(cloud.is_dense);
  fill_point_cloud(in, "mono8", cloud);
  const auto grey = static_cast<std::uint8_t>(std::lround(0.299 * 40 + 0.587 * 41 + 0.114 * 42));
  EXPECT_EQ(bytes(4)[0], grey);
  EXPECT_EQ(bytes(4)[2], grey);
  fill_point_cloud(in, "mono16", cloud);
  EXPECT_EQ(bytes(4)[0], 0);
  EXPECT_EQ(bytes(4)[1], 0);
  sensors::CameraImage all = in;
  all.points[3 * 4 + 2] = 1.0f;
  fill_point_cloud(all, "rgb8", cloud);
  EXPECT_TRUE(cloud.is_dense) << "no NaN point";
}

}  // namespace
}  // namespace mechsim::ros
