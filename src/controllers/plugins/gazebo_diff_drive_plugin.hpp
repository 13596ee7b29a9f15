#pragma once
// libDiffDrivePlugin.so (Gazebo classic's own DiffDrivePlugin, gazebo11 plugins/DiffDrivePlugin.cc:
// no ROS) as a model plugin controller. Its wheel behaviour is Gazebo's: every tick the latest
// velocity command (v m/s, va rad/s) becomes rim speeds v + va s/2 (left) and v - va s/2 (right),
// each commanded as the wheel joint's velocity (rim speed / r); zero until a command comes, held
// until the next one. The plugin's turn rate is clockwise-positive (its left wheel speeds up for
// a positive va), unlike a ROS Twist's angular.z. Kinematics shared with the other drives
// (controllers/drive/diff_drive_kinematics.hpp, with -va).
//
// The plugin reads no geometry elements: s is the distance between the two wheel joints' anchors
// and r half the largest edge of the left wheel link's bounding box, as Gazebo's Init() measures
// them (gazebo_diff_drive_geometry: the joints' origins and the wheel's collision shapes, in the
// model's root frame at zero joint angles; Gazebo boxes the link in the world frame at the model's
// initial pose, which is the same for a model standing upright and unrotated).
//
// Commanding it: Gazebo's plugin takes gazebo.msgs.Pose messages on the Gazebo-transport topic
// ~/<model>/vel_cmd (position.x = v, the orientation's yaw = va). mechsim has no Gazebo transport:
// the port "vel_cmd" is on the ROS topic /<model>/vel_cmd as geometry_msgs/Pose with the same
// meaning (PluginTopic::message), whatever the model's robot namespace (Gazebo's topic ignores it
// too). The plugin publishes nothing.
//
// Elements: left_joint, right_joint (required: Gazebo logs an error and fails without them);
// torque (N m, > 0): Gazebo 11 ignores it (Joint::SetVelocity sets the velocity outright), older
// Gazebo used it as the motors' force limit. mechsim's velocity motors are bounded by it where
// given, else by the joints' own effort limits (none for a joint without one: closest to Gazebo
// 11's set velocity).
// Ports: "vel_cmd" TwistCommandPort (linear.x = v, angular.z = va).

#include <string>

#include "control/ports.hpp"
#include "controllers/plugins/model_plugin.hpp"
#include "description/robot_model.hpp"

namespace mechsim::control {

inline constexpr const char* kGazeboDiffDrivePluginFile = "libDiffDrivePlugin.so";

struct GazeboDiffDriveGeometry {
  double separation = 1.0;  // m: between the wheel joints' anchors
  double radius = 1.0;      // m: half the left wheel's largest bounding-box edge
};

// Measures what Gazebo's Init() measures. Throws ControllerConfigError naming the joint or link
// (a joint not below the root link, a wheel link without collision shapes or with a mesh one,
// coincident anchors).
GazeboDiffDriveGeometry gazebo_diff_drive_geometry(const description::RobotModel& robot, const std::string& left_joint,
                                                   const std::string& right_joint);

// The ROS topic that stands in for Gazebo's ~/<model>/vel_cmd.
std::string gazebo_vel_cmd_topic(const std::string& model_name);

class GazeboDiffDrivePlugin : public ModelPlugin {
 public:
  GazeboDiffDrivePlugin(std::string model_name, GazeboDiffDriveGeometry geometry)
      : model_name_(std::move(model_name)), geometry_(geometry) {}
  bool init(RobotHardware& hardware, const Params& params, std::string& error) override;
  void starting(double time) override;
  UpdateStatus update(double time, double period) override;
  std::vector<Port*> ports() override { return {&command_}; }

  // left_joint, right_joint (required).
  static std::vector<std::string> joints(const Params& params);

  const GazeboDiffDriveGeometry& geometry() const { return geometry_; }
  double torque() const { return torque_; }  // 0: the joints' own limits

 private:
  std::string model_name_;
  GazeboDiffDriveGeometry geometry_;
  double torque_ = 0.0;
  JointHandle left_, right_;
  TwistCommandPort command_{"vel_cmd"};
};

}  // namespace mechsim::control
