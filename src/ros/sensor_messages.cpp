// Sensor readings into ROS messages (sensor_messages.hpp).
#include "ros/sensor_messages.hpp"

#include <algorithm>
#include <cmath>
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

void fill_contacts(const sensors::ContactsReading& in, gazebo_msgs::ContactsState& out) {
  const std::size_t count = std::min(in.count, in.states.size());
  out.states.resize(count);
  for (std::size_t k = 0; k < count; ++k) {
    const sensors::ContactState& s = in.states[k];
    gazebo_msgs::ContactState& d = out.states[k];
    d.info = s.info;
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
  if (f == "B8G8R8" || f == "BGR_INT8") return "bgr8";
  if (f == "L8" || f == "L_INT8") return "mono8";
  return "rgb8";
}

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
    // ITU-R BT.601 luma, as Gazebo's L8 format renders grey.
    for (std::size_t i = 0; i < pixels; ++i)
      out.data[i] = static_cast<std::uint8_t>(
          std::lround(0.299 * src[3 * i] + 0.587 * src[3 * i + 1] + 0.114 * src[3 * i + 2]));
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

void fill_point_cloud(const sensors::CameraImage& in, sensor_msgs::PointCloud2& out) {
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
  for (std::size_t i = 0; i < pixels; ++i) {
    std::uint8_t* p = out.data.data() + i * out.point_step;
    std::memcpy(p, &in.points[3 * i], 3 * sizeof(float));
    if (colour) {  // packed 0x00RRGGBB, little-endian: b g r 0
      p[16] = in.rgb[3 * i + 2];
      p[17] = in.rgb[3 * i + 1];
      p[18] = in.rgb[3 * i];
    }
  }
}

}  // namespace mechsim::ros
