#include "controllers/drive/pr2_odometry.hpp"

#include <cmath>

#include "control/angles.hpp"

namespace mechsim::control {

bool Pr2OdometryController::init(RobotHardware& hardware, const Params& params, std::string& /*error*/) {
  geometry_ = read_pr2_base_geometry(params);
  const auto read = [&](const std::vector<std::string>& names, const char* key, std::vector<JointStateHandle>& out) {
    const std::string path = join_param_path(params.path(), key);
    for (std::size_t i = 0; i < names.size(); ++i) {
      out.push_back(hardware.joint_state(names[i], path + "[" + std::to_string(i) + "]"));
    }
  };
  read(geometry_.caster_joints, "caster_joints", casters_);
  read(geometry_.wheel_joints, "wheel_joints", wheels_);

  iterations_ = params.get<int>("ils_max_iterations", 3);
  if (iterations_ < 0 || iterations_ > 100) {
    throw ControllerConfigError("parameter " + join_param_path(params.path(), "ils_max_iterations") +
                                " must be within 0..100 (got " + std::to_string(iterations_) + ")");
  }
  const std::string weight = params.get<std::string>("ils_weight_type", "Gaussian");
  if (weight == "Gaussian") {
    weight_ = IlsWeight::Gaussian;
  } else if (weight == "Cauchy") {
    weight_ = IlsWeight::Cauchy;
  } else if (weight == "Uniform") {
    weight_ = IlsWeight::Uniform;
  } else {
    throw ControllerConfigError("parameter " + join_param_path(params.path(), "ils_weight_type") + ": unknown weight '" +
                                weight + "' (Gaussian, Cauchy or Uniform)");
  }
  initial_ = {params.get<double>("odom/initial_x", 0.0), params.get<double>("odom/initial_y", 0.0),
              normalize_angle(params.get<double>("odom/initial_yaw", 0.0))};
  if (!std::isfinite(initial_.x) || !std::isfinite(initial_.y) || !std::isfinite(initial_.yaw)) {
    throw ControllerConfigError("parameter " + join_param_path(params.path(), "odom") + ": the initial pose is not finite");
  }
  odometry_.pose = initial_;

  headings_.assign(casters_.size(), 0.0);
  rates_.assign(casters_.size(), 0.0);
  speeds_.assign(wheels_.size(), 0.0);
  scratch_.resize(wheels_.size());

  std::string frame = params.get<std::string>("odom_frame", "odom");
  std::string child_frame = params.get<std::string>("base_footprint_frame", "base_footprint");
  const double sx = params.get<double>("sigma_x", 0.002), sy = params.get<double>("sigma_y", 0.002);
  const double st = params.get<double>("sigma_theta", 0.017);
  const std::array<double, 6> diag = {sx * sx, sy * sy, 1e6, 1e6, 1e6, st * st};
  odom_.init(odometry_prototype(std::move(frame), std::move(child_frame), diag, diag, odometry_.pose));
  return true;
}

UpdateStatus Pr2OdometryController::update(double time, double period) {
  if (reset_.exchange(false, std::memory_order_acq_rel)) odometry_.pose = initial_;
  if (!(period > 0.0)) return UpdateStatus::Ok();
  const Pr2BaseKinematics& k = geometry_.kinematics;
  bool finite = true;
  for (std::size_t c = 0; c < casters_.size(); ++c) {
    headings_[c] = normalize_angle(k.casters[c].axis_sign * casters_[c].position());
    rates_[c] = k.casters[c].axis_sign * casters_[c].velocity();
    finite = finite && std::isfinite(headings_[c]) && std::isfinite(rates_[c]);
  }
  for (std::size_t w = 0; w < wheels_.size(); ++w) {
    speeds_[w] = k.wheels[w].axis_sign * wheels_[w].velocity() * k.wheel_radius;
    finite = finite && std::isfinite(speeds_[w]);
  }
  PlanarTwist twist;
  if (finite && estimate_base_twist(k, headings_, rates_, speeds_, scratch_, twist, iterations_, weight_, &odometry_.residual)) {
    odometry_.advance(twist, period);
  }
  odometry_.publish(odom_, time);
  return UpdateStatus::Ok();  // a non-finite joint state holds the pose (the tick goes on)
}

}  // namespace mechsim::control
