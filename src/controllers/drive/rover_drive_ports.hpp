#pragma once
// The ports of the rover drive controller that the generic ones (control/ports.hpp) do not
// cover: the drive mode command, the odometry snapshot (what nav_msgs/Odometry carries) and the
// drive's status.

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "control/ports.hpp"
#include "controllers/drive/rover_drive_kinematics.hpp"

namespace mechsim::control {

// The drive mode input: Auto (the default) lets the twist choose; any other mode forces it.
// Writes of a value outside DriveMode, or of an unknown name, are rejected and counted.
class DriveModeCommandPort : public Port, public RejectionLog {
 public:
  using Port::Port;
  PortKind kind() const override { return PortKind::DriveModeCommand; }
  // Non-real-time. False (and `error` set) when rejected.
  bool write(DriveMode mode, std::string* error = nullptr);
  // "auto", "ackermann", "crab", "point_turn" (a std_msgs/String binding).
  bool write(std::string_view name, std::string* error = nullptr);
  DriveMode latest() const { return buffer_.latest(); }
  // Real-time.
  DriveMode read_from_rt() noexcept { return buffer_.read_from_rt(); }

 private:
  RealtimeBuffer<DriveMode> buffer_{DriveMode::Auto};
};

// A unit quaternion (w, x, y, z), geometry_msgs/Quaternion's fields.
struct Quaternion {
  double w = 1.0, x = 0.0, y = 0.0, z = 0.0;
};

// What nav_msgs/Odometry carries, planar: the pose of `child_frame_id` in `frame_id` and its
// twist in `child_frame_id`. Covariances are row-major 6 x 6 over (x, y, z, roll, pitch, yaw),
// diagonal, from the controller's pose/twist_covariance_diagonal parameters.
struct OdometrySnapshot {
  double stamp = 0.0;  // s, sim time of the update
  std::string frame_id = "odom";
  std::string child_frame_id = "base_link";
  double x = 0.0, y = 0.0;  // m, position of the child frame in frame_id
  double z = 0.0;           // m; 0 for wheel odometry
  double yaw = 0.0;         // rad, in (-pi, pi]
  // The full attitude where the source knows it (Gazebo plugins' world odometry: the base's
  // world orientation, roll and pitch included); else the yaw alone is the orientation.
  bool has_attitude = false;
  Quaternion attitude;
  Quaternion orientation() const;  // unit quaternion (w, x, y, z): the attitude, else the yaw's
  // The pose is the base's pose in the world (Gazebo plugins' "world" odometry source), not
  // relative to where the odometry started.
  bool in_world = false;
  Vec3d linear;   // m/s, in child_frame_id (z = 0)
  Vec3d angular;  // rad/s, in child_frame_id (x = y = 0)
  std::array<double, 36> pose_covariance{};
  std::array<double, 36> twist_covariance{};
  // m/s: root mean square of the wheels' disagreement with the estimated twist (slip,
  // misaligned steering), weighted as the odometry weighed the wheels' rows; 0 for a rigid,
  // non-slipping drive.
  double residual = 0.0;
  bool valid = false;  // false until the wheels have given a twist
};

// The drive's state beyond its joints (which the "state" port carries).
struct RoverDriveStatus {
  double stamp = 0.0;             // s
  DriveMode requested_mode = DriveMode::Auto;
  DriveMode active_mode = DriveMode::Ackermann;  // never Auto
  Twist command;                  // the latest command read from "cmd_vel" (m/s, rad/s)
  PlanarTwist applied;            // the twist of A after timeout, limits and mode (m/s, rad/s)
  bool timed_out = false;         // no command for cmd_vel_timeout: braking to zero
  bool unsupported = false;       // this tick's command had components the mode cannot do
  std::uint64_t unsupported_count = 0;  // ticks with an unsupported command since init
  // 0..1: the factor the wheel speeds are scaled by while the steering is not aligned.
  double alignment_scale = 1.0;
  double max_steering_error = 0.0;  // rad: the largest |target heading - measured heading|
  double wheel_speed_scale = 1.0;   // 0..1: the factor max_wheel_speed imposed
  // Crab: the sensing wheels are unpowered and measure the ground (crab_sensing_wheels).
  bool crab_sensing = false;
  std::uint32_t sensing_wheels = 0;  // bit i: wheel i (wheel_joints order, first 32) is sensing
  // Crab heading hold: engaged, the odometry yaw it holds (rad, odom frame) and the yaw rate
  // correction it adds to the wheel speeds (rad/s).
  bool heading_hold = false;
  double held_yaw = 0.0;
  double yaw_correction = 0.0;
};

template <>
constexpr PortKind state_port_kind<OdometrySnapshot>() { return PortKind::Odometry; }
template <>
constexpr PortKind state_port_kind<RoverDriveStatus>() { return PortKind::RoverDriveStatus; }

}  // namespace mechsim::control
