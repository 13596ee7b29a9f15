// Reads and writes of controller ports through the opaque PortRef (C++20 side of the bridge).
#include <cmath>

#include "control/ports.hpp"
#include "controllers/drive/rover_drive_ports.hpp"
#include "controllers/sensor/sensor_state_controllers.hpp"
#include "bridge/port_cast.hpp"
#include "bridge/sim_bridge.hpp"

namespace mechsim::bridge {

using detail::fresh_state;
using detail::port_as;

bool write_scalar(const PortRef& port, double value, std::string* error) {
  auto* p = port_as<control::ScalarCommandPort>(port, error);
  return p && p->write(value, error);
}

bool write_array(const PortRef& port, const std::vector<double>& values, std::string* error) {
  auto* p = port_as<control::ArrayCommandPort>(port, error);
  return p && p->write(std::span<const double>(values.data(), values.size()), error);
}

bool write_twist(const PortRef& port, double vx, double vy, double vz, double wx, double wy, double wz,
                 std::string* error) {
  auto* p = port_as<control::TwistCommandPort>(port, error);
  if (!p) return false;
  control::Twist t;
  t.linear = {vx, vy, vz};
  t.angular = {wx, wy, wz};
  return p->write(t, error);
}

bool read_joint_controller_state(const PortRef& port, JointControllerStateData& out, std::uint64_t* sequence) {
  const auto* p = fresh_state<control::JointControllerState>(port, sequence);
  if (!p) return false;
  const control::JointControllerState s = p->read();
  out.stamp = s.stamp;
  out.set_point = s.set_point;
  out.process_value = s.process_value;
  out.process_value_dot = s.process_value_dot;
  out.error = s.error;
  out.time_step = s.time_step;
  out.command = s.command;
  out.p = s.gains.p;
  out.i = s.gains.i;
  out.d = s.gains.d;
  out.i_clamp = s.gains.i_max;
  out.antiwindup = s.gains.antiwindup;
  return true;
}

bool read_joint_states(const PortRef& port, JointStatesData& out, std::uint64_t* sequence) {
  const auto* p = fresh_state<control::JointStateSnapshot>(port, sequence);
  if (!p) return false;
  control::JointStateSnapshot s = p->read();
  out.stamp = s.stamp;
  out.names = std::move(s.names);
  out.position = std::move(s.position);
  out.velocity = std::move(s.velocity);
  out.effort = std::move(s.effort);
  return true;
}

bool read_odometry(const PortRef& port, OdometryData& out, std::uint64_t* sequence) {
  const auto* p = fresh_state<control::OdometrySnapshot>(port, sequence);
  if (!p) return false;
  const control::OdometrySnapshot s = p->read();
  out.stamp = s.stamp;
  out.frame_id = s.frame_id;
  out.child_frame_id = s.child_frame_id;
  out.x = s.x;
  out.y = s.y;
  out.z = s.z;
  const control::Quaternion q = s.orientation();
  out.qw = q.w;
  out.qx = q.x;
  out.qy = q.y;
  out.qz = q.z;
  out.vx = s.linear.x;
  out.vy = s.linear.y;
  out.wz = s.angular.z;
  out.pose_covariance.assign(s.pose_covariance.begin(), s.pose_covariance.end());
  out.twist_covariance.assign(s.twist_covariance.begin(), s.twist_covariance.end());
  return true;
}

bool read_twist_state(const PortRef& port, TwistStampedData& out, std::uint64_t* sequence) {
  const auto* p = fresh_state<control::TwistSnapshot>(port, sequence);
  if (!p) return false;
  const control::TwistSnapshot s = p->read();
  out.stamp = s.stamp;
  out.frame_id = s.frame_id;
  out.vx = s.twist.linear.x;
  out.vy = s.twist.linear.y;
  out.vz = s.twist.linear.z;
  out.wx = s.twist.angular.x;
  out.wy = s.twist.angular.y;
  out.wz = s.twist.angular.z;
  return true;
}

namespace {

void copy_vec(const std::array<double, 3>& in, description::Vec3& out) { out = {in[0], in[1], in[2]}; }

}  // namespace

bool read_imu_state(const PortRef& port, double& stamp, std::string& frame_id, sensors::ImuReading& out,
                    std::uint64_t* sequence) {
  const auto* p = fresh_state<control::ImuSnapshot>(port, sequence);
  if (!p) return false;
  const control::ImuSnapshot s = p->read();
  stamp = s.stamp;
  frame_id = s.imu.frame_id;
  out.orientation = {s.imu.orientation[3], s.imu.orientation[0], s.imu.orientation[1], s.imu.orientation[2]};
  copy_vec(s.imu.angular_velocity, out.angular_velocity);
  copy_vec(s.imu.linear_acceleration, out.linear_acceleration);
  out.orientation_covariance = s.imu.orientation_covariance;
  out.angular_velocity_covariance = s.imu.angular_velocity_covariance;
  out.linear_acceleration_covariance = s.imu.linear_acceleration_covariance;
  return true;
}

bool read_wrench_state(const PortRef& port, double& stamp, std::string& frame_id, sensors::WrenchReading& out,
                       std::uint64_t* sequence) {
  const auto* p = fresh_state<control::WrenchSnapshot>(port, sequence);
  if (!p) return false;
  const control::WrenchSnapshot s = p->read();
  stamp = s.stamp;
  frame_id = s.wrench.frame_id;
  copy_vec(s.wrench.force, out.force);
  copy_vec(s.wrench.torque, out.torque);
  return true;
}

}  // namespace mechsim::bridge
