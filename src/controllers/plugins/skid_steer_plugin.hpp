#pragma once
// libgazebo_ros_skid_steer_drive.so (gazebo_plugins' GazeboRosSkidSteerDrive) as a model plugin
// controller. Every 1/updateRate s (every tick for 0): the odometry goes out on "odom" (always
// the base's world pose, as the plugin's; z left at 0; odom -> base on /tf with broadcastTF),
// then the latest cmd_vel (linear.x, angular.z; held, no timeout) becomes rim speeds v -+ w s/2
// for the two left and the two right wheels (controllers/drive/diff_drive_kinematics.hpp),
// commanded as joint velocities (rim speed / radius) through velocity motors bounded by torque.
// A skid steer slips when it turns: its effective track is wider than the wheels' separation, so
// Gazebo users set wheelSeparation to what turns the robot as commanded.
//
// Elements (gazebo_plugins' names and defaults):
//   leftFrontJoint left_front_joint, rightFrontJoint right_front_joint,
//   leftRearJoint left_rear_joint, rightRearJoint right_rear_joint
//   wheelSeparation 0.4 (m), wheelDiameter 0.15 (m), torque 5 (N m): all > 0
//   commandTopic cmd_vel, odometryTopic odom, odometryFrame odom, robotBaseFrame base_footprint
//   updateRate 100 (Hz, >= 0), broadcastTF false
//   covariance_x 0.0001, covariance_y 0.0001, covariance_yaw 0.01 (pose and twist; z, roll,
//   pitch 1e12), robotNamespace ""
// Ports: "cmd_vel" TwistCommandPort, "odom" StatePort<OdometrySnapshot>.

#include <array>

#include "control/ports.hpp"
#include "controllers/drive/rover_drive_ports.hpp"
#include "controllers/plugins/model_plugin.hpp"

namespace mechsim::control {

inline constexpr const char* kSkidSteerPluginFile = "libgazebo_ros_skid_steer_drive.so";

class SkidSteerPlugin : public ModelPlugin {
 public:
  bool init(RobotHardware& hardware, const Params& params, std::string& error) override;
  void starting(double time) override;
  UpdateStatus update(double time, double period) override;
  std::vector<Port*> ports() override;

  static std::vector<std::string> joints(const Params& params);

  double wheel_separation() const { return separation_; }
  double wheel_diameter() const { return diameter_; }
  double torque() const { return torque_; }

 private:
  double separation_ = 0.4, diameter_ = 0.15, torque_ = 5.0, update_period_ = 0.01;
  std::array<JointHandle, 4> wheels_;  // left front, right front, left rear, right rear
  const mechanism::BaseState* base_ = nullptr;
  double last_update_ = 0.0;
  TwistCommandPort command_{"cmd_vel"};
  StatePort<OdometrySnapshot> odom_{"odom"};
};

}  // namespace mechsim::control
