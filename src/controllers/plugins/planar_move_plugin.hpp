#pragma once
// libgazebo_ros_planar_move.so (gazebo_plugins' GazeboRosPlanarMove) as a model plugin
// controller that moves the floating base itself through the base port (control::BaseHandle):
// every tick the latest cmd_vel (linear.x, linear.y m/s and angular.z rad/s in the base's
// heading frame; zero once older than cmdTimeout s when that is >= 0) is set as the base's
// velocity for the next physics step, linear (vx, vy) turned by the base's yaw into the world
// and 0 along z, angular (0, 0, wz), as the plugin's Model::SetLinearVel/SetAngularVel do (the
// base cannot fall faster than gravity acts in one step: the plugin's known hover). Every
// 1/odometryRate s the base's world pose goes out on "odom" with its twist from the pose change
// since the last odometry (in the heading frame), and odom -> base on /tf.
//
// Elements (gazebo_plugins' names and defaults):
//   commandTopic cmd_vel, odometryTopic odom, odometryFrame odom, robotBaseFrame base_footprint
//   odometryRate 20 (Hz, >= 0; 0: no odometry), cmdTimeout -1 (s; < 0: never; the issue's
//   spelling cmd_timeout is read too), robotNamespace ""
// Pose covariance diagonal (1e-5, 1e-5, 1e12, 1e12, 1e12, 1e-3); twist covariance zero.
// Ports: "cmd_vel" TwistCommandPort, "odom" StatePort<OdometrySnapshot>.

#include "control/ports.hpp"
#include "controllers/drive/rover_drive_ports.hpp"
#include "controllers/plugins/model_plugin.hpp"

namespace mechsim::control {

inline constexpr const char* kPlanarMovePluginFile = "libgazebo_ros_planar_move.so";

class PlanarMovePlugin : public ModelPlugin {
 public:
  bool init(RobotHardware& hardware, const Params& params, std::string& error) override;
  void starting(double time) override;
  UpdateStatus update(double time, double period) override;
  void stopping(double time) override;
  std::vector<Port*> ports() override;

  double odometry_rate() const { return odometry_rate_; }
  double command_timeout() const { return timeout_; }

 private:
  double odometry_rate_ = 20.0, timeout_ = -1.0;
  BaseHandle base_;
  double last_odometry_ = 0.0;      // s
  double last_x_ = 0.0, last_y_ = 0.0, last_yaw_ = 0.0;
  std::uint64_t last_sequence_ = 0;  // cmd_vel writes seen
  double last_command_ = 0.0;       // s, when the latest command arrived
  TwistCommandPort command_{"cmd_vel"};
  StatePort<OdometrySnapshot> odom_{"odom"};
};

}  // namespace mechsim::control
