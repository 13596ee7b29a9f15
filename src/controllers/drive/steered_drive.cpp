#include "controllers/drive/steered_drive.hpp"

#include "control/angles.hpp"
#include "controllers/joint/pid_joint_controllers.hpp"  // fill_joint_controller_state
#include "controllers/drive/rover_drive_params.hpp"     // read_rover_joint_list

namespace mechsim::control {

void init_joint_pid(Pid& pid, const Params& params, const std::string& joint, const char* fallback) {
  auto own = params.find(joint);
  if (own && own->is_map() && own->has("p")) {
    pid.init(*own);
  } else if (auto position = own && own->is_map() ? own->find("position_controller") : std::nullopt;
             position && position->is_map() && position->has("p")) {
    // pr2_controller_configuration_gazebo's layout: <caster joint>/position_controller holds the
    // gains of the caster's angle loop (the steering loop here).
    pid.init(*position);
  } else {
    pid.init(params, fallback);
  }
}

// ---------------------------------------------------------------- SteeredDrive

void SteeredDrive::claim(RobotHardware& hardware, const Params& params, const char* steering_key,
                         std::size_t min_steering, const char* wheel_key, std::size_t min_wheels) {
  steering_names_ = read_rover_joint_list(params, steering_key, min_steering);
  wheel_names_ = read_rover_joint_list(params, wheel_key, min_wheels);
  const auto claim_list = [&](const std::vector<std::string>& names, const char* key, std::vector<JointHandle>& out) {
    const std::string path = join_param_path(params.path(), key);
    for (std::size_t i = 0; i < names.size(); ++i) {
      out.push_back(hardware.claim_joint(names[i], HardwareInterface::Effort, path + "[" + std::to_string(i) + "]"));
    }
  };
  claim_list(steering_names_, steering_key, steering_);
  claim_list(wheel_names_, wheel_key, wheels_);
}

void SteeredDrive::init_pids(const Params& params, const char* steering_gains, const char* wheel_gains, Gains source) {
  std::vector<std::string> names = steering_names_;
  names.insert(names.end(), wheel_names_.begin(), wheel_names_.end());
  const std::size_t ns = steering_.size();
  for (std::size_t i = 0; i < names.size(); ++i) {
    const char* shared = i < ns ? steering_gains : wheel_gains;
    pids_.push_back(std::make_unique<Pid>());
    if (source == Gains::JointOrShared) {
      init_joint_pid(*pids_.back(), params, names[i], shared);
    } else {
      pids_.back()->init(params, shared);
    }
    gains_.push_back(std::make_unique<PidGainsPort>("gains/" + names[i], pids_.back().get()));
  }
  steering_setpoints_.assign(ns, 0.0);
  wheel_setpoints_.assign(wheels_.size(), 0.0);
  efforts_.assign(names.size(), 0.0);

  JointGroupControllerState prototype;
  prototype.joint_names = names;
  prototype.joints.resize(names.size());
  state_.init(prototype);
}

void SteeredDrive::append_gains_ports(std::vector<Port*>& out) {
  for (auto& g : gains_) out.push_back(g.get());
}

void SteeredDrive::reset_pids() noexcept {
  for (auto& pid : pids_) pid->reset();
}

void SteeredDrive::update(double period, std::span<const std::uint8_t> unpowered) noexcept {
  const std::size_t ns = steering_.size();
  for (std::size_t s = 0; s < ns; ++s) {
    efforts_[s] = pids_[s]->compute_command(shortest_angular_distance(steering_[s].position(), steering_setpoints_[s]), period);
    steering_[s].set_command(efforts_[s]);
  }
  for (std::size_t w = 0; w < wheels_.size(); ++w) {
    if (w < unpowered.size() && unpowered[w] != 0) {
      // Unpowered: the wheel rolls with the ground.
      pids_[ns + w]->reset();
      efforts_[ns + w] = 0.0;
    } else {
      efforts_[ns + w] = pids_[ns + w]->compute_command(wheel_setpoints_[w] - wheels_[w].velocity(), period);
    }
    wheels_[w].set_command(efforts_[ns + w]);
  }
}

void SteeredDrive::publish_state(double time, double period) noexcept {
  const std::size_t ns = steering_.size();
  state_.publish_from_rt([&](JointGroupControllerState& st) {
    st.stamp = time;
    for (std::size_t j = 0; j < st.joints.size(); ++j) {
      const PidGains& gains = pids_[j]->rt_gains();
      if (j < ns) {
        const JointHandle& h = steering_[j];
        const double set_point = steering_setpoints_[j];
        fill_joint_controller_state(st.joints[j], time, period, set_point, h.position(), h.velocity(),
                                    shortest_angular_distance(h.position(), set_point), efforts_[j], gains);
      } else {
        const JointHandle& h = wheels_[j - ns];
        const double set_point = wheel_setpoints_[j - ns];
        fill_joint_controller_state(st.joints[j], time, period, set_point, h.velocity(), 0.0, set_point - h.velocity(),
                                    efforts_[j], gains);
      }
    }
  });
}

// ---------------------------------------------------------------- TwistCommandTimeout

void TwistCommandTimeout::start(TwistCommandPort& port, double time) noexcept {
  port.reset_from_rt(Twist{});
  last_seq_ = port.accepted();
  last_time_ = time;
  timed_out_ = false;
}

PlanarTwist TwistCommandTimeout::read(TwistCommandPort& port, double time, double timeout) noexcept {
  value_ = port.read_from_rt();
  const std::uint64_t seq = port.accepted();
  if (seq != last_seq_) {
    last_seq_ = seq;
    last_time_ = time;
  }
  timed_out_ = timeout > 0.0 && time - last_time_ > timeout;
  return timed_out_ ? PlanarTwist{} : PlanarTwist{value_.linear.x, value_.linear.y, value_.angular.z};
}

// ---------------------------------------------------------------- PlanarOdometry

void PlanarOdometry::advance(const PlanarTwist& estimate, double period) noexcept {
  twist = estimate;
  valid = true;
  pose = integrate_pose(pose, twist, period);
}

void PlanarOdometry::publish(StatePort<OdometrySnapshot>& port, double time) const noexcept {
  port.publish_from_rt([&](OdometrySnapshot& o) {
    o.stamp = time;
    o.x = pose.x;
    o.y = pose.y;
    o.yaw = pose.yaw;
    o.linear = {twist.vx, twist.vy, 0.0};
    o.angular = {0.0, 0.0, twist.wz};
    o.residual = residual;
    o.valid = valid;
  });
}

OdometrySnapshot odometry_prototype(std::string frame_id, std::string child_frame_id,
                                    const std::array<double, 6>& pose_covariance_diagonal,
                                    const std::array<double, 6>& twist_covariance_diagonal, const PlanarPose& pose) {
  OdometrySnapshot odom;
  odom.frame_id = std::move(frame_id);
  odom.child_frame_id = std::move(child_frame_id);
  for (std::size_t i = 0; i < 6; ++i) {
    odom.pose_covariance[i * 7] = pose_covariance_diagonal[i];
    odom.twist_covariance[i * 7] = twist_covariance_diagonal[i];
  }
  odom.x = pose.x;
  odom.y = pose.y;
  odom.yaw = pose.yaw;
  return odom;
}

}  // namespace mechsim::control
