// imu sensors and IMU plugins (gazebo_ros_imu_sensor, gazebo_ros_imu, hector's): what a real
// IMU measures, in the sensor frame.
#include <cmath>

#include "physics/transform.hpp"
#include "sensors/sensor_types.hpp"

namespace mechsim::sensors {

namespace {

struct ImuState : ChannelState {
  bool have_reference = false;
  Quat reference_inverse;  // q_RW: the world seen from the reference frame
};

constexpr std::size_t kYaw = 6;  // channels: 0-2 angular velocity, 3-5 acceleration, 6 heading

}  // namespace

ImuSensor::ImuSensor(const description::SensorSpec& spec, const physics::PhysicsModel& model, const std::string& prefix)
    : Sensor(spec, prefix), imu_(std::get<description::ImuSpec>(this->spec().details)) {
  ImuSensor::bind(model);
}

void ImuSensor::bind(const physics::PhysicsModel& model) { link_ = resolve_link(model); }

std::unique_ptr<SensorState> ImuSensor::make_state(Rng rng) const {
  auto state = std::make_unique<ImuState>();
  state->rng = std::move(rng);
  for (const auto& n : imu_.rate_noise) state->channels.push_back(start_noise(n, state->rng));
  for (const auto& n : imu_.accel_noise) state->channels.push_back(start_noise(n, state->rng));
  state->channels.push_back(start_noise(imu_.yaw_noise, state->rng));
  return state;
}

void ImuSensor::sample(const physics::Physics& physics, double time, SensorState& base, SensorOutput& out) const {
  auto& state = static_cast<ImuState&>(base);
  if (!std::holds_alternative<ImuReading>(out)) out = ImuReading{};
  ImuReading& r = std::get<ImuReading>(out);
  const description::Pose X_WS = physics::compose(physics.link_pose(link_), spec().pose);
  const Quat q_SW = physics::quat_conjugate(X_WS.orientation);
  const Vec3 w_S = physics::rotate(q_SW, physics.link_twist(link_).angular);
  const Vec3 f_S = physics::rotate(q_SW, physics.link_acceleration(link_, spec().pose.position).specific_force);
  const double dt = state.last_sample >= 0.0 ? time - state.last_sample : 0.0;

  const double w[3] = {w_S.x, w_S.y, w_S.z}, f[3] = {f_S.x, f_S.y, f_S.z};
  double wn[3], fn[3];
  for (std::size_t i = 0; i < 3; ++i) {
    wn[i] = apply_noise(imu_.rate_noise[i], state.channels[i], w[i], dt, state.rng);
    fn[i] = apply_noise(imu_.accel_noise[i], state.channels[3 + i], f[i], dt, state.rng);
  }
  r.angular_velocity = {wn[0], wn[1], wn[2]};
  r.linear_acceleration = {fn[0], fn[1], fn[2]};

  if (imu_.initial_orientation_as_reference && !state.have_reference) {
    state.reference_inverse = q_SW;
    state.have_reference = true;
  }
  Quat q = imu_.initial_orientation_as_reference ? physics::quat_multiply(state.reference_inverse, X_WS.orientation)
                                                 : X_WS.orientation;
  q = physics::quat_multiply(imu_.offset.orientation, q);
  if (imu_.yaw_noise.active()) {
    const double yaw = apply_noise(imu_.yaw_noise, state.channels[kYaw], 0.0, dt, state.rng);
    q = physics::quat_multiply(Quat{std::cos(yaw / 2), 0.0, 0.0, std::sin(yaw / 2)}, q);
  }
  r.orientation = physics::quat_normalized(q);

  for (std::size_t i = 0; i < 3; ++i) {
    r.angular_velocity_covariance[4 * i] = imu_.rate_noise[i].stddev * imu_.rate_noise[i].stddev;
    r.linear_acceleration_covariance[4 * i] = imu_.accel_noise[i].stddev * imu_.accel_noise[i].stddev;
  }
  r.orientation_covariance[8] = imu_.yaw_noise.stddev * imu_.yaw_noise.stddev;
}

}  // namespace mechsim::sensors
