// Simulation: where robots stand when they come in: the first on a terrain's slope
// (settle_on_ground), its spawn joints, and the other robots of a world (sim::OtherRobot): their
// construction over the host's physics, and spawning and deleting them during a run.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "physics/transform.hpp"
#include "sim/ground_plane.hpp"
#include "sim/simulation.hpp"

#include "description/ros2_control.hpp"

namespace mechsim::sim {

namespace {
constexpr double kLevelSlope = 1e-4;  // rad: a fitted slope below this is level ground
}  // namespace

std::optional<description::Pose> Simulation::fitted_spawn(const physics::Bounds& robot,
                                                          const physics::SpawnPose& spawn) const {
  if (!world_.spec.terrain || robot.empty()) return std::nullopt;
  const GroundPlane plane = fit_ground_plane(*world_.spec.terrain, {robot.min.x, robot.max.x, robot.min.y, robot.max.y},
                                             spawn.x, spawn.y);
  if (plane.slope() < kLevelSlope) return std::nullopt;  // level ground (the Mars Yard's start pad): as built
  const RollPitch rp = roll_pitch_on(plane, spawn.yaw);
  // The clearance spawn.z along the normal (as on level ground) is spawn.z / cos(slope) upright.
  const double z = plane.z0 + spawn.z / std::cos(plane.slope());
  return description::Pose{{spawn.x, spawn.y, z}, physics::quat_from_rpy(rp.roll, rp.pitch, spawn.yaw)};
}

void Simulation::settle_on_ground() {
  const physics::Bounds robot = physics_->collision_bounds("");  // spawned level; without other robots
  if (const auto X = fitted_spawn(robot, options_.spawn)) physics_->set_spawn_pose(*X);
}

void Simulation::apply_initial_joints() {
  for (const auto& [joint, position] : options_.initial_joints) {
    const auto j = physics_model_->joint_index(prefix_ + joint);
    if (!j) throw std::invalid_argument("spawn/joints/" + joint + ": the robot's physics has no joint '" + joint + "'");
    if (!std::isfinite(position)) throw std::invalid_argument("spawn/joints/" + joint + ": position must be finite");
    physics_->set_joint_state(*j, position);
  }
}

Simulation::Simulation(Simulation& host, OtherRobot other)
    : robot_(std::move(other.robot)),
      name_(std::move(other.name)),
      prefix_(name_ + "::"),
      host_(&host),
      world_(host.world_),
      options_(host.options_) {
  options_.spawn = other.spawn;
  options_.initial_joints = std::move(other.initial_joints);
  for (const auto& [joint, position] : description::ros2_control_initial_positions(robot_)) {
    options_.initial_joints.emplace(joint, position);
  }
  options_.ros2_control = other.ros2_control;
  options_.controller_update_rate = other.controller_update_rate;
  options_.parameter_root = std::move(other.parameter_root);
  options_.settle_on_ground = false;
  ticks_ = host.ticks_;
  physics_model_ = host.physics_model_;
  physics_ = host.physics_;
  root_link_ = physics_model_->link_index(prefix_ + robot_.root_link);
  if (!root_link_) throw std::logic_error("other robot '" + name_ + "': its root link is not in the physics");
  physics::Twist V;
  floating_ = physics_->free_link_state(*root_link_, spawn_pose_, V);
  spawn_pose_ = physics_->link_pose(*root_link_);
  physics::StageTimer timer;
  startup_times_.mechanism = timer.lap();
  build_robot(std::move(other.controllers));
}

std::vector<OtherRobot> Simulation::other_specs() const {
  std::vector<OtherRobot> out;
  for (const auto& o : others_) {
    OtherRobot spec;
    spec.name = o->name_;
    spec.robot = o->robot_;
    spec.spawn = o->options_.spawn;
    out.push_back(std::move(spec));
  }
  return out;
}

Simulation& Simulation::add_other(OtherRobot other) {
  if (host_ != nullptr) return host_->add_other(std::move(other));
  if (find_other(other.name) != nullptr)
    throw std::invalid_argument("other robot '" + other.name + "': a robot of that name is in the world already");
  std::vector<OtherRobot> specs = other_specs();
  OtherRobot spec;
  spec.name = other.name;
  spec.robot = other.robot;
  spec.spawn = other.spawn;
  specs.push_back(std::move(spec));
  const std::shared_ptr<physics::Physics> before = physics_;
  const std::shared_ptr<const physics::PhysicsModel> model_before = physics_model_;
  rebuild_physics(specs, options_.settle_on_ground ? &specs.back() : nullptr);
  try {
    others_.push_back(std::unique_ptr<Simulation>(new Simulation(*this, std::move(other))));
  } catch (...) {
    // Its controllers or plugins could not be built: the world goes back to the physics it had.
    physics_model_ = model_before;
    physics_ = before;
    bind_physics();
    for (const auto& o : others_) o->bind_physics();
    throw;
  }
  return *others_.back();
}

bool Simulation::remove_other(const std::string& name) {
  if (host_ != nullptr) return host_->remove_other(name);
  const auto it = std::find_if(others_.begin(), others_.end(), [&](const auto& o) { return o->name_ == name; });
  if (it == others_.end()) return false;
  Simulation& gone = **it;
  // Its controllers first: stopped (their stopping() runs), then unloaded.
  std::vector<std::string> running, loaded;
  for (const control::ControllerInfo& info : gone.manager_->list_controllers()) {
    loaded.push_back(info.name);
    if (info.state == control::ControllerLifecycle::Running) running.push_back(info.name);
  }
  if (!running.empty()) {
    gone.manager_->switch_controllers({}, running, control::SwitchStrictness::BestEffort);
    gone.manager_->apply_pending_switch(time());
  }
  for (const std::string& c : loaded) gone.manager_->unload_controller(c);
  std::vector<OtherRobot> specs;
  for (OtherRobot& spec : other_specs())
    if (spec.name != name) specs.push_back(std::move(spec));
  others_.erase(it);
  // Wrenches and efforts from outside are held by link and joint index, which the robots after
  // the deleted one no longer have: they end with it.
  external_.clear();
  rebuild_physics(specs);
  return true;
}

Simulation* Simulation::find_other(const std::string& name) {
  for (const auto& o : others_)
    if (o->name_ == name) return o.get();
  return nullptr;
}

void Simulation::fit_to_ground(const physics::PhysicsModel& model, physics::Physics& physics,
                               const OtherRobot& other) const {
  const std::string prefix = other.name + "::";
  const auto root = model.link_index(prefix + other.robot.root_link);
  if (!root) return;
  if (const auto X = fitted_spawn(physics.collision_bounds(prefix), other.spawn)) physics.set_free_link_spawn_pose(*root, *X);
}

}  // namespace mechsim::sim
