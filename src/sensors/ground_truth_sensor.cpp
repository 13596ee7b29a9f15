// gazebo_ros_p3d: the true pose and twist of a link, in the world or another link's frame.
#include "physics/transform.hpp"
#include "sensors/sensor_types.hpp"

namespace mechsim::sensors {

GroundTruthSensor::GroundTruthSensor(const description::SensorSpec& spec, const physics::PhysicsModel& model,
                                     const std::string& prefix)
    : Sensor(spec, prefix), gt_(std::get<description::GroundTruthSpec>(this->spec().details)) {
  GroundTruthSensor::bind(model);
}

void GroundTruthSensor::bind(const physics::PhysicsModel& model) {
  link_ = resolve_link(model);
  if (gt_.frame != "world" && gt_.frame != "map") {
    reference_ = model.link_index(physics_name(gt_.frame));
    if (!reference_) throw SensorError(spec().where() + ": the physics has no link '" + gt_.frame + "'");
  }
}

std::unique_ptr<SensorState> GroundTruthSensor::make_state(Rng rng) const {
  auto state = std::make_unique<ChannelState>();
  state->rng = std::move(rng);
  description::NoiseSpec n;
  n.stddev = gt_.gaussian_noise;
  for (int i = 0; i < 6; ++i) state->channels.push_back(start_noise(n, state->rng));
  return state;
}

void GroundTruthSensor::sample(const physics::Physics& physics, double time, SensorState& base, SensorOutput& out) const {
  auto& state = static_cast<ChannelState&>(base);
  if (!std::holds_alternative<GroundTruthReading>(out)) out = GroundTruthReading{};
  auto& r = std::get<GroundTruthReading>(out);
  description::Pose X = physics.link_pose(link_);
  const physics::Twist V = physics.link_twist(link_);
  Vec3 v = V.linear, w = V.angular;
  if (reference_) {
    // As p3d: the pose relative to the reference link, velocities relative to its (those of
    // its origin) expressed in its orientation.
    const description::Pose X_WR = physics.link_pose(*reference_);
    const physics::Twist V_R = physics.link_twist(*reference_);
    const Quat q_RW = physics::quat_conjugate(X_WR.orientation);
    X = physics::compose(physics::inverse(X_WR), X);
    v = physics::rotate(q_RW, {v.x - V_R.linear.x, v.y - V_R.linear.y, v.z - V_R.linear.z});
    w = physics::rotate(q_RW, {w.x - V_R.angular.x, w.y - V_R.angular.y, w.z - V_R.angular.z});
  }
  X.position = {X.position.x + gt_.offset.position.x, X.position.y + gt_.offset.position.y,
                X.position.z + gt_.offset.position.z};
  X.orientation = physics::quat_normalized(physics::quat_multiply(gt_.offset.orientation, X.orientation));
  const double dt = state.last_sample >= 0.0 ? time - state.last_sample : 0.0;
  description::NoiseSpec n;
  n.stddev = gt_.gaussian_noise;
  const double raw[6] = {v.x, v.y, v.z, w.x, w.y, w.z};
  double noisy[6];
  for (std::size_t i = 0; i < 6; ++i) noisy[i] = apply_noise(n, state.channels[i], raw[i], dt, state.rng);
  r.pose = X;
  r.linear = {noisy[0], noisy[1], noisy[2]};
  r.angular = {noisy[3], noisy[4], noisy[5]};
  r.pose_variance = r.twist_variance = gt_.gaussian_noise * gt_.gaussian_noise;
}

}  // namespace mechsim::sensors
