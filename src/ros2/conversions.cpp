// Plain data into ROS 2 messages (conversions.hpp).
#include "ros2/conversions.hpp"

#include <algorithm>
#include <cstring>

namespace mechsim::ros2 {

namespace {

geometry_msgs::msg::Vector3 vector3(const description::Vec3& v) {
  geometry_msgs::msg::Vector3 out;
  out.x = v.x;
  out.y = v.y;
  out.z = v.z;
  return out;
}

geometry_msgs::msg::Quaternion quaternion(const description::Quat& q) {
  geometry_msgs::msg::Quaternion out;
  out.w = q.w;
  out.x = q.x;
  out.y = q.y;
  out.z = q.z;
  return out;
}

}  // namespace

builtin_interfaces::msg::Time to_time(double seconds) {
  builtin_interfaces::msg::Time t;
  double whole = std::floor(seconds);
  auto nanos = static_cast<std::int64_t>(std::llround((seconds - whole) * 1e9));
  if (nanos >= 1000000000) {
    whole += 1.0;
    nanos -= 1000000000;
  }
  t.sec = static_cast<std::int32_t>(whole);
  t.nanosec = static_cast<std::uint32_t>(nanos);
  return t;
}

double to_seconds(const builtin_interfaces::msg::Time& t) { return static_cast<double>(t.sec) + 1e-9 * t.nanosec; }
double to_seconds(const builtin_interfaces::msg::Duration& d) { return static_cast<double>(d.sec) + 1e-9 * d.nanosec; }

std::string tf_frame(const std::string& frame) {
  std::size_t start = 0;
  while (start < frame.size() && frame[start] == '/') ++start;
  return frame.substr(start);
}

void fill_joint_state(const bridge::JointStatesData& in, sensor_msgs::msg::JointState& out) {
  out.header.stamp = to_time(in.stamp);
  out.name = in.names;
  out.position = in.position;
  out.velocity = in.velocity;
  out.effort = in.effort;
}

void fill_odometry(const bridge::OdometryData& in, nav_msgs::msg::Odometry& out) {
  out.header.stamp = to_time(in.stamp);
  out.header.frame_id = in.frame_id;
  out.child_frame_id = in.child_frame_id;
  out.pose.pose.position.x = in.x;
  out.pose.pose.position.y = in.y;
  out.pose.pose.position.z = in.z;
  out.pose.pose.orientation.w = in.qw;
  out.pose.pose.orientation.x = in.qx;
  out.pose.pose.orientation.y = in.qy;
  out.pose.pose.orientation.z = in.qz;
  out.twist.twist.linear.x = in.vx;
  out.twist.twist.linear.y = in.vy;
  out.twist.twist.angular.z = in.wz;
  for (std::size_t k = 0; k < 36; ++k) {
    out.pose.covariance[k] = k < in.pose_covariance.size() ? in.pose_covariance[k] : 0.0;
    out.twist.covariance[k] = k < in.twist_covariance.size() ? in.twist_covariance[k] : 0.0;
  }
}

void fill_laser_scan(const sensors::LaserScan& in, int row, sensor_msgs::msg::LaserScan& out) {
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

void fill_imu(const sensors::ImuReading& in, sensor_msgs::msg::Imu& out) {
  out.orientation = quaternion(in.orientation);
  out.angular_velocity = vector3(in.angular_velocity);
  out.linear_acceleration = vector3(in.linear_acceleration);
  std::copy(in.orientation_covariance.begin(), in.orientation_covariance.end(), out.orientation_covariance.begin());
  std::copy(in.angular_velocity_covariance.begin(), in.angular_velocity_covariance.end(),
            out.angular_velocity_covariance.begin());
  std::copy(in.linear_acceleration_covariance.begin(), in.linear_acceleration_covariance.end(),
            out.linear_acceleration_covariance.begin());
}

void fill_wrench(const sensors::WrenchReading& in, geometry_msgs::msg::WrenchStamped& out) {
  out.wrench.force = vector3(in.force);
  out.wrench.torque = vector3(in.torque);
}

void fill_ground_truth(const sensors::GroundTruthReading& in, nav_msgs::msg::Odometry& out) {
  out.pose.pose.position.x = in.pose.position.x;
  out.pose.pose.position.y = in.pose.position.y;
  out.pose.pose.position.z = in.pose.position.z;
  out.pose.pose.orientation = quaternion(in.pose.orientation);
  out.twist.twist.linear = vector3(in.linear);
  out.twist.twist.angular = vector3(in.angular);
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

void fill_image(const sensors::CameraImage& in, const std::string& encoding, sensor_msgs::msg::Image& out) {
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
    for (std::size_t i = 0; i < pixels; ++i)
      out.data[i] = static_cast<std::uint8_t>(std::lround(0.299 * src[3 * i] + 0.587 * src[3 * i + 1] + 0.114 * src[3 * i + 2]));
    return;
  }
  out.step = out.width * 3;
  out.data.assign(src, src + pixels * 3);
  if (encoding == "bgr8")
    for (std::size_t i = 0; i < pixels; ++i) std::swap(out.data[3 * i], out.data[3 * i + 2]);
}

void fill_depth_image(const sensors::CameraImage& in, sensor_msgs::msg::Image& out) {
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

void fill_camera_info(const sensors::CameraInfo& in, sensor_msgs::msg::CameraInfo& out) {
  out.width = static_cast<std::uint32_t>(in.width);
  out.height = static_cast<std::uint32_t>(in.height);
  out.distortion_model = in.distortion_model;
  out.d.assign(in.D.begin(), in.D.end());
  std::copy(in.K.begin(), in.K.end(), out.k.begin());
  std::copy(in.R.begin(), in.R.end(), out.r.begin());
  std::copy(in.P.begin(), in.P.end(), out.p.begin());
  out.binning_x = out.binning_y = 0;
  out.roi = sensor_msgs::msg::RegionOfInterest();
}

void fill_point_cloud(const sensors::CameraImage& in, sensor_msgs::msg::PointCloud2& out) {
  if (out.fields.size() != 4) {
    out.fields.resize(4);
    const char* names[4] = {"x", "y", "z", "rgb"};
    const std::uint32_t offsets[4] = {0, 4, 8, 16};
    for (std::size_t i = 0; i < 4; ++i) {
      out.fields[i].name = names[i];
      out.fields[i].offset = offsets[i];
      out.fields[i].datatype = sensor_msgs::msg::PointField::FLOAT32;
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

}  // namespace mechsim::ros2
