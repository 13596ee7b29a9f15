// Sensor readings into ROS messages (sensor_messages.hpp).
#include "ros/sensor_messages.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

namespace mechsim::ros {

namespace {

geometry_msgs::Vector3 vector3(const description::Vec3& v) {
  geometry_msgs::Vector3 out;
  out.x = v.x;
  out.y = v.y;
  out.z = v.z;
  return out;
}

geometry_msgs::Quaternion quaternion(const description::Quat& q) {
  geometry_msgs::Quaternion out;
  out.w = q.w;
  out.x = q.x;
  out.y = q.y;
  out.z = q.z;
  return out;
}

template <class Array>
void copy9(const sensors::Covariance& from, Array& to) {
  for (std::size_t i = 0; i < 9; ++i) to[i] = from[i];
}

}  // namespace

std::string tf_frame(const std::string& frame) {
  std::size_t start = 0;
  while (start < frame.size() && frame[start] == '/') ++start;
  return frame.substr(start);
}

void fill_laser_scan(const sensors::LaserScan& in, int row, sensor_msgs::LaserScan& out) {
  out.angle_min = static_cast<float>(in.angle_min);
  out.angle_max = static_cast<float>(in.angle_max);
  out.angle_increment = static_cast<float>(in.angle_increment);
  out.time_increment = static_cast<float>(in.time_increment);
  out.scan_time = static_cast<float>(in.scan_time);
  out.range_min = static_cast<float>(in.range_min);
  out.range_max = static_cast<float>(in.range_max);
  const std::size_t n = static_cast<std::size_t>(std::max(in.horizontal_count, 0));
  const std::size_t first = static_cast<std::size_t>(std::clamp(row, 0, std::max(in.vertical_count - 1, 0))) * n;
  auto copy_row = [&](const std::vector<float>& from, std::vector<float>& to) {
    if (from.size() < first + n) {
      to.clear();
      return;
    }
    to.assign(from.begin() + static_cast<std::ptrdiff_t>(first), from.begin() + static_cast<std::ptrdiff_t>(first + n));
  };
  copy_row(in.ranges, out.ranges);
  copy_row(in.intensities, out.intensities);
}

void fill_imu(const sensors::ImuReading& in, sensor_msgs::Imu& out) {
  out.orientation = quaternion(in.orientation);
  out.angular_velocity = vector3(in.angular_velocity);
  out.linear_acceleration = vector3(in.linear_acceleration);
  copy9(in.orientation_covariance, out.orientation_covariance);
  copy9(in.angular_velocity_covariance, out.angular_velocity_covariance);
  copy9(in.linear_acceleration_covariance, out.linear_acceleration_covariance);
}

void fill_range(const sensors::RangeReading& in, sensor_msgs::Range& out) {
  out.radiation_type = static_cast<std::uint8_t>(in.radiation);
  out.field_of_view = static_cast<float>(in.field_of_view);
  out.min_range = static_cast<float>(in.min_range);
  out.max_range = static_cast<float>(in.max_range);
  out.range = static_cast<float>(in.range);
}

void fill_block_cloud(const sensors::PointCloudReading& in, sensor_msgs::PointCloud& out) {
  out.points.resize(in.points.size());
  for (std::size_t i = 0; i < in.points.size(); ++i) {
    out.points[i].x = static_cast<float>(in.points[i].x);
    out.points[i].y = static_cast<float>(in.points[i].y);
    out.points[i].z = static_cast<float>(in.points[i].z);
  }
  out.channels.resize(1);
  out.channels[0].name.clear();
  out.channels[0].values.assign(in.intensities.begin(), in.intensities.end());
}

void fill_contacts(const sensors::ContactsReading& in, double stamp, gazebo_msgs::ContactsState& out) {
  const std::size_t count = std::min(in.count, in.states.size());
  out.states.resize(count);
  const ::ros::Time time(stamp);
  char nsec[16];
  std::snprintf(nsec, sizeof nsec, "%09u", time.nsec);
  for (std::size_t k = 0; k < count; ++k) {
    const sensors::ContactState& s = in.states[k];
    gazebo_msgs::ContactState& d = out.states[k];
    // gazebo_ros_bumper's debug line, with ros::Time's "sec.nsec".
    d.info = "Debug:  i:(" + std::to_string(k) + "/" + std::to_string(count) + ")     my geom:" + s.collision1_name +
             "   other geom:" + s.collision2_name + "         time:" + std::to_string(time.sec) + "." + nsec + "\n";
    d.collision1_name = s.collision1_name;
    d.collision2_name = s.collision2_name;
    d.wrenches.resize(s.wrenches.size());
    for (std::size_t p = 0; p < s.wrenches.size(); ++p) {
      d.wrenches[p].force = vector3(s.wrenches[p].force);
      d.wrenches[p].torque = vector3(s.wrenches[p].torque);
    }
    d.total_wrench.force = vector3(s.total_wrench.force);
    d.total_wrench.torque = vector3(s.total_wrench.torque);
    d.contact_positions.resize(s.contact_positions.size());
    for (std::size_t p = 0; p < s.contact_positions.size(); ++p) d.contact_positions[p] = vector3(s.contact_positions[p]);
    d.contact_normals.resize(s.contact_normals.size());
    for (std::size_t p = 0; p < s.contact_normals.size(); ++p) d.contact_normals[p] = vector3(s.contact_normals[p]);
    d.depths.assign(s.depths.begin(), s.depths.end());
  }
}

void fill_wrench(const sensors::WrenchReading& in, geometry_msgs::WrenchStamped& out) {
  out.wrench.force = vector3(in.force);
  out.wrench.torque = vector3(in.torque);
}

void fill_odometry(const sensors::GroundTruthReading& in, nav_msgs::Odometry& out) {
  out.pose.pose.position.x = in.pose.position.x;
  out.pose.pose.position.y = in.pose.position.y;
  out.pose.pose.position.z = in.pose.position.z;
  out.pose.pose.orientation = quaternion(in.pose.orientation);
  out.twist.twist.linear = vector3(in.linear);
  out.twist.twist.angular = vector3(in.angular);
  // p3d's diagonal: the same variance on the six axes.
  for (std::size_t k = 0; k < 6; ++k) {
    out.pose.covariance[7 * k] = in.pose_variance;
    out.twist.covariance[7 * k] = in.twist_variance;
  }
}

std::string image_encoding(const std::string& f) {
  if (f == "R8G8B8" || f == "RGB_INT8") return "rgb8";
  if (f == "B8G8R8" || f == "BGR_INT8") return "bgr8";
  if (f == "L8" || f == "L_INT8") return "mono8";
  if (f == "L16" || f == "L_INT16" || f == "L_UINT16") return "mono16";
  if (f == "R16G16B16" || f == "RGB_INT16" || f == "RGB_UINT16") return "rgb16";
  if (f == "BAYER_RGGB8") return "bayer_rggb8";
  if (f == "BAYER_BGGR8") return "bayer_bggr8";
  if (f == "BAYER_GBRG8") return "bayer_gbrg8";
  if (f == "BAYER_GRBG8") return "bayer_grbg8";
  return "bgr8";
}

namespace {

// The colour channel (0 r, 1 g, 2 b) a Bayer mosaic keeps at (row, column).
int bayer_channel(const std::string& encoding, std::size_t row, std::size_t col) {
  const char* pattern = encoding.c_str() + 6;  // "bayer_rggb8" -> "rggb8"
  const char c = pattern[(row % 2) * 2 + (col % 2)];
  return c == 'r' ? 0 : c == 'g' ? 1 : 2;
}

std::uint8_t luma(const std::uint8_t* p) {
  // ITU-R BT.601 luma, as Gazebo's L8 format renders grey.
  return static_cast<std::uint8_t>(std::lround(0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2]));
}

void put16(std::uint8_t* at, unsigned v) {  // little-endian
  at[0] = static_cast<std::uint8_t>(v & 0xffu);
  at[1] = static_cast<std::uint8_t>(v >> 8);
}

}  // namespace

void fill_image(const sensors::CameraImage& in, const std::string& encoding, sensor_msgs::Image& out) {
  const std::size_t pixels = static_cast<std::size_t>(in.info.width) * static_cast<std::size_t>(in.info.height);
  out.height = static_cast<std::uint32_t>(in.info.height);
  out.width = static_cast<std::uint32_t>(in.info.width);
  out.encoding = encoding;
  out.is_bigendian = 0;
  if (in.rgb.size() < pixels * 3) {  // nothing rendered (no OpenGL context)
    out.data.clear();
    out.height = out.width = out.step = 0;
    return;
  }
  const std::uint8_t* src = in.rgb.data();
  if (encoding == "mono8") {
    out.step = out.width;
    out.data.resize(pixels);
    for (std::size_t i = 0; i < pixels; ++i) out.data[i] = luma(src + 3 * i);
    return;
  }
  // MuJoCo's renderer reads 8 bits per channel: a 16-bit image spreads them over the full range.
  if (encoding == "mono16") {
    out.step = out.width * 2;
    out.data.resize(pixels * 2);
    for (std::size_t i = 0; i < pixels; ++i) put16(&out.data[2 * i], 257u * luma(src + 3 * i));
    return;
  }
  if (encoding == "rgb16") {
    out.step = out.width * 6;
    out.data.resize(pixels * 6);
    for (std::size_t i = 0; i < pixels * 3; ++i) put16(&out.data[2 * i], 257u * src[i]);
    return;
  }
  if (encoding.rfind("bayer_", 0) == 0) {
    out.step = out.width;
    out.data.resize(pixels);
    const std::size_t w = out.width;
    for (std::size_t i = 0; i < pixels; ++i) out.data[i] = src[3 * i + static_cast<std::size_t>(bayer_channel(encoding, i / w, i % w))];
    return;
  }
  out.step = out.width * 3;
  out.data.assign(src, src + pixels * 3);
  if (encoding == "bgr8")
    for (std::size_t i = 0; i < pixels; ++i) std::swap(out.data[3 * i], out.data[3 * i + 2]);
}

void fill_depth_image(const sensors::CameraImage& in, sensor_msgs::Image& out) {
  const std::size_t pixels = static_cast<std::size_t>(in.info.width) * static_cast<std::size_t>(in.info.height);
  out.encoding = "32FC1";
  out.is_bigendian = 0;
  if (in.depth.size() < pixels) {
    out.data.clear();
    out.height = out.width = out.step = 0;
    return;
  }
  out.height = static_cast<std::uint32_t>(in.info.height);
  out.width = static_cast<std::uint32_t>(in.info.width);
  out.step = out.width * static_cast<std::uint32_t>(sizeof(float));
  out.data.resize(pixels * sizeof(float));
  std::memcpy(out.data.data(), in.depth.data(), pixels * sizeof(float));
}

void fill_camera_info(const sensors::CameraInfo& in, sensor_msgs::CameraInfo& out) {
  out.width = static_cast<std::uint32_t>(in.width);
  out.height = static_cast<std::uint32_t>(in.height);
  out.distortion_model = in.distortion_model;
  out.D.assign(in.D.begin(), in.D.end());
  std::copy(in.K.begin(), in.K.end(), out.K.begin());
  std::copy(in.R.begin(), in.R.end(), out.R.begin());
  std::copy(in.P.begin(), in.P.end(), out.P.begin());
  out.binning_x = out.binning_y = 0;
  out.roi = sensor_msgs::RegionOfInterest();
}

void fill_point_cloud(const sensors::CameraImage& in, const std::string& encoding, sensor_msgs::PointCloud2& out) {
  if (out.fields.size() != 4) {
    out.fields.resize(4);
    const char* names[4] = {"x", "y", "z", "rgb"};
    const std::uint32_t offsets[4] = {0, 4, 8, 16};
    for (std::size_t i = 0; i < 4; ++i) {
      out.fields[i].name = names[i];
      out.fields[i].offset = offsets[i];
      out.fields[i].datatype = sensor_msgs::PointField::FLOAT32;
      out.fields[i].count = 1;
    }
  }
  const std::size_t pixels = static_cast<std::size_t>(in.info.width) * static_cast<std::size_t>(in.info.height);
  out.is_bigendian = false;
  out.is_dense = false;
  out.point_step = 32;
  if (in.points.size() < pixels * 3) {
    out.data.clear();
    out.height = out.width = out.row_step = 0;
    return;
  }
  out.height = static_cast<std::uint32_t>(in.info.height);
  out.width = static_cast<std::uint32_t>(in.info.width);
  out.row_step = out.point_step * out.width;
  out.data.assign(pixels * out.point_step, 0);
  const bool colour = in.rgb.size() >= pixels * 3;
  // The image's bytes per pixel as the plugins find them in their image message.
  const bool three = encoding == "rgb8" || encoding == "bgr8";
  const bool one = encoding == "mono8" || encoding.rfind("bayer_", 0) == 0;
  const std::size_t w = in.info.width > 0 ? static_cast<std::size_t>(in.info.width) : 1;
  bool dense = true;
  for (std::size_t i = 0; i < pixels; ++i) {
    std::uint8_t* p = out.data.data() + i * out.point_step;
    std::memcpy(p, &in.points[3 * i], 3 * sizeof(float));
    if (std::isnan(in.points[3 * i + 2])) dense = false;
    if (!colour) continue;
    const std::uint8_t* px = &in.rgb[3 * i];
    if (three) {
      const bool bgr = encoding == "bgr8";
      p[16] = bgr ? px[2] : px[0];
      p[17] = px[1];
      p[18] = bgr ? px[0] : px[2];
    } else if (one) {
      const std::uint8_t v = encoding == "mono8" ? luma(px) : px[bayer_channel(encoding, i / w, i % w)];
      p[16] = p[17] = p[18] = v;
    }
  }
  out.is_dense = dense;
}

}  // namespace mechsim::ros
