// force_torque sensors (SDF) and gazebo_ros_ft_sensor: the wrench a joint transmits between its
// parent and child links.
#include "physics/transform.hpp"
#include "sensors/sensor_types.hpp"

namespace mechsim::sensors {

ForceTorqueSensor::ForceTorqueSensor(const description::SensorSpec& spec, const physics::PhysicsModel& model,
                                     const std::string& prefix)
    : Sensor(spec, prefix), ft_(std::get<description::ForceTorqueSpec>(this->spec().details)) {
  ForceTorqueSensor::bind(model);
}

void ForceTorqueSensor::bind(const physics::PhysicsModel& model) {
  const description::SensorSpec& spec = this->spec();
  child_ = resolve_link(model);
  parent_ = model.link_index(physics_name(ft_.parent_link));
  if (!parent_) throw SensorError(spec.where() + ": the physics has no link '" + ft_.parent_link + "'");
  if (model.links()[child_].body == model.links()[*parent_].body) {
    throw SensorError(spec.where() + ": joint '" + ft_.joint + "' joins links the physics merged into one body ('" +
                      ft_.child_link + "' has no mass of its own): there is no joint wrench to measure");
  }
}

std::unique_ptr<SensorState> ForceTorqueSensor::make_state(Rng rng) const {
  auto state = std::make_unique<ChannelState>();
  state->rng = std::move(rng);
  for (int i = 0; i < 3; ++i) state->channels.push_back(start_noise(ft_.force_noise, state->rng));
  for (int i = 0; i < 3; ++i) state->channels.push_back(start_noise(ft_.torque_noise, state->rng));
  return state;
}

void ForceTorqueSensor::sample(const physics::Physics& physics, double time, SensorState& base, SensorOutput& out) const {
  auto& state = static_cast<ChannelState&>(base);
  if (!std::holds_alternative<WrenchReading>(out)) out = WrenchReading{};
  using Frame = description::ForceTorqueSpec::Frame;
  // The joint frame is the child link's frame (URDF); a sensor frame sits at the sensor's pose in it.
  const Vec3 at = ft_.frame == Frame::Sensor ? spec().pose.position : Vec3{};
  physics::Wrench w = physics.joint_wrench(child_, at);  // on the child from the parent, world frame
  if (!ft_.parent_to_child) {
    w.force = {-w.force.x, -w.force.y, -w.force.z};
    w.torque = {-w.torque.x, -w.torque.y, -w.torque.z};
  }
  Quat q_WF = physics.link_pose(ft_.frame == Frame::Parent ? *parent_ : child_).orientation;
  if (ft_.frame == Frame::Sensor) q_WF = physics::quat_multiply(q_WF, spec().pose.orientation);
  const Quat q_FW = physics::quat_conjugate(q_WF);
  const Vec3 f = physics::rotate(q_FW, w.force), t = physics::rotate(q_FW, w.torque);
  const double dt = state.last_sample >= 0.0 ? time - state.last_sample : 0.0;
  const double fv[3] = {f.x, f.y, f.z}, tv[3] = {t.x, t.y, t.z};
  double fn[3], tn[3];
  for (std::size_t i = 0; i < 3; ++i) {
    fn[i] = apply_noise(ft_.force_noise, state.channels[i], fv[i], dt, state.rng);
    tn[i] = apply_noise(ft_.torque_noise, state.channels[3 + i], tv[i], dt, state.rng);
  }
  auto& r = std::get<WrenchReading>(out);
  r.force = {fn[0], fn[1], fn[2]};
  r.torque = {tn[0], tn[1], tn[2]};
}

}  // namespace mechsim::sensors
