#include "control/pr2_base_controller.hpp"

#include <cmath>

#include "control/angles.hpp"
#include "control/rover_drive_params.hpp"  // read_rover_joint_list

namespace mechsim::control {
namespace {

double clamp_abs(double v, double limit) noexcept { return std::fmin(std::fmax(v, -limit), limit); }
double step_towards(double from, double to, double step) noexcept { return from + clamp_abs(to - from, step); }

}  // namespace

void init_joint_pid(Pid& pid, const Params& params, const std::string& joint, const char* fallback) {
  if (auto own = params.find(joint); own && own->is_map() && own->has("p")) {
    pid.init(*own);
  } else {
    pid.init(params, fallback);
  }
}

bool Pr2BaseController::init(RobotHardware& hardware, const Params& params, std::string& /*error*/) {
  // Claim first, so that an unknown joint is reported as such before any geometry parameter.
  const auto casters = read_rover_joint_list(params, "caster_joints", 1);
  const auto wheels = read_rover_joint_list(params, "wheel_joints", 1);
  const auto claim = [&](const std::vector<std::string>& names, const char* key, std::vector<JointHandle>& out) {
    const std::string path = join_param_path(params.path(), key);
    for (std::size_t i = 0; i < names.size(); ++i) {
      out.push_back(hardware.claim_joint(names[i], HardwareInterface::Effort, path + "[" + std::to_string(i) + "]"));
    }
  };
  claim(casters, "caster_joints", casters_);
  claim(wheels, "wheel_joints", wheels_);
  config_ = read_pr2_base_config(params);

  std::vector<std::string> names = casters;
  names.insert(names.end(), wheels.begin(), wheels.end());
  for (std::size_t i = 0; i < names.size(); ++i) {
    pids_.push_back(std::make_unique<Pid>());
    init_joint_pid(*pids_.back(), params, names[i], i < casters.size() ? "caster_pid" : "wheel_pid");
    gains_.push_back(std::make_unique<PidGainsPort>("gains/" + names[i], pids_.back().get()));
  }
  measured_headings_.assign(casters.size(), 0.0);
  target_headings_.assign(casters.size(), 0.0);
  wheel_setpoints_.assign(wheels.size(), 0.0);
  efforts_.assign(names.size(), 0.0);

  JointGroupControllerState prototype;
  prototype.joint_names = names;
  prototype.joints.resize(names.size());
  state_.init(prototype);
  status_.init(Pr2BaseStatus{});
  return true;
}

std::vector<Port*> Pr2BaseController::ports() {
  std::vector<Port*> out{&command_, &state_, &status_};
  for (auto& g : gains_) out.push_back(g.get());
  return out;
}

void Pr2BaseController::starting(double time) {
  const Pr2BaseKinematics& k = config_.geometry.kinematics;
  for (std::size_t c = 0; c < casters_.size(); ++c) {
    measured_headings_[c] = normalize_angle(k.casters[c].axis_sign * casters_[c].position());
    target_headings_[c] = measured_headings_[c];
  }
  command_.reset_from_rt(Twist{});
  last_command_seq_ = command_.accepted();
  last_command_time_ = time;
  timed_out_ = false;
  applied_ = {};
  for (auto& pid : pids_) pid->reset();
}

PlanarTwist Pr2BaseController::limit_command(const PlanarTwist& target, double period) const noexcept {
  PlanarTwist t = target;
  const double speed = std::hypot(t.vx, t.vy);
  if (speed > config_.max_translational_velocity) {
    const double s = config_.max_translational_velocity / speed;
    t.vx *= s;
    t.vy *= s;
  }
  t.wz = clamp_abs(t.wz, config_.max_rotational_velocity);
  return {step_towards(applied_.vx, t.vx, config_.max_translational_acceleration_x * period),
          step_towards(applied_.vy, t.vy, config_.max_translational_acceleration_y * period),
          step_towards(applied_.wz, t.wz, config_.max_rotational_acceleration * period)};
}

UpdateStatus Pr2BaseController::update(double time, double period) {
  if (!(period > 0.0)) return UpdateStatus::Ok();
  const Pr2BaseKinematics& k = config_.geometry.kinematics;
  const std::size_t nc = casters_.size(), nw = wheels_.size();

  // 1-2. Command, timeout, limits.
  command_value_ = command_.read_from_rt();
  const std::uint64_t seq = command_.accepted();
  if (seq != last_command_seq_) {
    last_command_seq_ = seq;
    last_command_time_ = time;
  }
  timed_out_ = config_.timeout > 0.0 && time - last_command_time_ > config_.timeout;
  const PlanarTwist target =
      timed_out_ ? PlanarTwist{} : PlanarTwist{command_value_.linear.x, command_value_.linear.y, command_value_.angular.z};
  applied_ = limit_command(target, period);

  // 3. Caster headings.
  for (std::size_t c = 0; c < nc; ++c) {
    measured_headings_[c] = normalize_angle(k.casters[c].axis_sign * casters_[c].position());
  }
  caster_headings(k, applied_, measured_headings_, target_headings_, target_headings_, config_.caster_hold_speed);
  max_caster_error_ = 0.0;
  reversed_ = 0;
  for (std::size_t c = 0; c < nc; ++c) {
    double vx = 0.0, vy = 0.0;
    point_velocity(applied_, k.casters[c].x, k.casters[c].y, vx, vy);
    if (vx * std::cos(target_headings_[c]) + vy * std::sin(target_headings_[c]) < 0.0) ++reversed_;
    max_caster_error_ =
        std::fmax(max_caster_error_, std::abs(shortest_angular_distance(measured_headings_[c], target_headings_[c])));
  }

  // 4. Wheel set points from the measured caster state.
  for (std::size_t w = 0; w < nw; ++w) {
    const std::size_t c = k.wheels[w].caster;
    const double heading = measured_headings_[c];
    const double rate = k.casters[c].axis_sign * casters_[c].velocity();
    const double speed = std::isfinite(heading) && std::isfinite(rate) ? wheel_rolling_speed(k, w, applied_, heading, rate) : 0.0;
    wheel_setpoints_[w] = k.wheels[w].axis_sign * speed / k.wheel_radius;
  }

  // 5. PIDs.
  for (std::size_t c = 0; c < nc; ++c) {
    const double set_point = k.casters[c].axis_sign * target_headings_[c];
    efforts_[c] = pids_[c]->compute_command(shortest_angular_distance(casters_[c].position(), set_point), period);
    casters_[c].set_command(efforts_[c]);
  }
  for (std::size_t w = 0; w < nw; ++w) {
    efforts_[nc + w] = pids_[nc + w]->compute_command(wheel_setpoints_[w] - wheels_[w].velocity(), period);
    wheels_[w].set_command(efforts_[nc + w]);
  }
  publish(time, period);
  return UpdateStatus::Ok();
}

void Pr2BaseController::publish(double time, double period) noexcept {
  const Pr2BaseKinematics& k = config_.geometry.kinematics;
  const std::size_t nc = casters_.size();
  state_.publish_from_rt([&](JointGroupControllerState& s) {
    s.stamp = time;
    for (std::size_t j = 0; j < s.joints.size(); ++j) {
      JointControllerState& js = s.joints[j];
      js.stamp = time;
      js.time_step = period;
      js.command = efforts_[j];
      js.gains = pids_[j]->rt_gains();
      if (j < nc) {
        const JointHandle& h = casters_[j];
        js.set_point = k.casters[j].axis_sign * target_headings_[j];
        js.process_value = h.position();
        js.process_value_dot = h.velocity();
        js.error = shortest_angular_distance(h.position(), js.set_point);
      } else {
        const JointHandle& h = wheels_[j - nc];
        js.set_point = wheel_setpoints_[j - nc];
        js.process_value = h.velocity();
        js.process_value_dot = 0.0;
        js.error = js.set_point - js.process_value;
      }
    }
  });
  status_.publish_from_rt([&](Pr2BaseStatus& st) {
    st.stamp = time;
    st.command = command_value_;
    st.applied = applied_;
    st.timed_out = timed_out_;
    st.max_caster_error = max_caster_error_;
    st.reversed_casters = reversed_;
  });
}

}  // namespace mechsim::control
