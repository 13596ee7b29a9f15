#include "controllers/plugins/skid_steer_plugin.hpp"

#include "controllers/drive/diff_drive_kinematics.hpp"
#include "controllers/plugins/plugin_params.hpp"
#include "controllers/plugins/world_odometry.hpp"

namespace mechsim::control {
namespace {

constexpr const char* kKeys[4] = {"leftFrontJoint", "rightFrontJoint", "leftRearJoint", "rightRearJoint"};
constexpr const char* kDefaults[4] = {"left_front_joint", "right_front_joint", "left_rear_joint", "right_rear_joint"};

}  // namespace

std::vector<std::string> SkidSteerPlugin::joints(const Params& params) {
  const PluginParams p(params);
  std::vector<std::string> out;
  for (int i = 0; i < 4; ++i) out.push_back(p.joint(kKeys[i], kDefaults[i]));
  return out;
}

bool SkidSteerPlugin::init(RobotHardware& hardware, const Params& params, std::string& /*error*/) {
  const PluginParams p(params);
  separation_ = p.positive("wheelSeparation", 0.4);
  diameter_ = p.positive("wheelDiameter", 0.15);
  torque_ = p.positive("torque", 5.0);
  update_period_ = period_of(p.rate("updateRate", 100.0));
  const double cx = p.non_negative("covariance_x", 0.0001), cy = p.non_negative("covariance_y", 0.0001);
  const double cyaw = p.non_negative("covariance_yaw", 0.01);
  const std::vector<std::string> names = joints(params);
  for (int i = 0; i < 4; ++i) {
    for (int k = 0; k < i; ++k) {
      if (names[static_cast<std::size_t>(k)] == names[static_cast<std::size_t>(i)]) {
        p.fail(kKeys[i], "names the same joint as <" + std::string(kKeys[k]) + "> ('" + names[static_cast<std::size_t>(i)] + "')");
      }
    }
    wheels_[static_cast<std::size_t>(i)] =
        hardware.claim_joint(names[static_cast<std::size_t>(i)], HardwareInterface::Velocity, p.location(kKeys[i]));
  }
  base_ = &hardware.base_state();
  if (!base_->floating) throw ControllerConfigError(params.location() + ": the robot is fixed to the world: a skid steer's base cannot move");
  const std::array<double, 6> diagonal{cx, cy, 1e12, 1e12, 1e12, cyaw};
  odom_.init(plugin_odometry_prototype(p.text("odometryFrame", "odom"), p.text("robotBaseFrame", "base_footprint"), diagonal,
                                       diagonal));
  ros_.robot_namespace = p.text("robotNamespace", "");
  ros_.topics = {{"cmd_vel", p.text("commandTopic", "cmd_vel"), ""}, {"odom", p.text("odometryTopic", "odom"), ""}};
  ros_.odom_tf = p.boolean("broadcastTF", false);
  return true;
}

void SkidSteerPlugin::starting(double time) {
  last_update_ = time;
  command_.reset_from_rt(Twist{});
  for (JointHandle& w : wheels_) {
    w.set_effort_limit(torque_);
    w.set_command(0.0);
  }
}

UpdateStatus SkidSteerPlugin::update(double time, double /*period*/) {
  if (time - last_update_ < update_period_ - 1e-9) return UpdateStatus::Ok();
  odom_.publish_from_rt([&](OdometrySnapshot& o) {
    fill_world_odometry(o, *base_, time);
    o.z = 0.0;  // the plugin publishes x and y only
  });
  const Twist& command = command_.read_from_rt();
  const WheelRimSpeeds rim = diff_drive_rim_speeds(command.linear.x, command.angular.z, separation_);
  const double radius = diameter_ / 2.0;
  wheels_[0].set_command(rim.left / radius);
  wheels_[1].set_command(rim.right / radius);
  wheels_[2].set_command(rim.left / radius);
  wheels_[3].set_command(rim.right / radius);
  last_update_ = update_period_ > 0.0 ? last_update_ + update_period_ : time;
  return UpdateStatus::Ok();
}

std::vector<Port*> SkidSteerPlugin::ports() { return {&command_, &odom_}; }

}  // namespace mechsim::control
