// MechanismStatistics (see mechanism_statistics.hpp).
#include "bridge/mechanism_statistics.hpp"

#include <algorithm>
#include <cmath>

#include "sim/simulation.hpp"

namespace mechsim::bridge {

namespace {

// Slack on the limit checks: the position servo holds joints *at* their limits, and the
// safety limits clamp efforts to exactly their bound.
constexpr double kPositionSlack = 1e-6;  // rad or m
constexpr double kEffortSlack = 1e-9;    // relative

}  // namespace

MechanismStatistics::MechanismStatistics(const sim::Simulation& simulation) {
  const description::RobotModel& robot = simulation.robot();
  const mechanism::MechanismModel& mechanism = simulation.mechanism();
  for (const description::Joint& joint : robot.joints) {
    if (joint.type == description::JointType::Fixed || joint.type == description::JointType::Floating ||
        joint.type == description::JointType::Planar) {
      continue;
    }
    Source s;
    s.mechanism = mechanism.joint_index(joint.name);
    if (auto index = simulation.physics().model().joint_index(simulation.physics_name(joint.name)))
      s.physics = static_cast<int>(*index);
    if (s.mechanism < 0 && s.physics < 0) continue;  // nothing simulates it
    s.lower = 1.0;
    s.upper = -1.0;
    if (joint.limits) {
      if (joint.type != description::JointType::Continuous && joint.limits->lower < joint.limits->upper) {
        s.lower = joint.limits->lower;
        s.upper = joint.limits->upper;
      }
      s.effort_limit = std::max(0.0, joint.limits->effort);
    }
    names_.push_back(joint.name);
    sources_.push_back(s);
  }
  windows_.resize(sources_.size());
  resets_seen_ = simulation.resets();
  generation_ = simulation.physics_generation();
}

MechanismStatistics::Sample MechanismStatistics::sample(const sim::Simulation& simulation,
                                                        const Source& source) const noexcept {
  Sample out;
  if (source.mechanism >= 0) {
    const mechanism::JointState& j = simulation.mechanism_state().joints[static_cast<std::size_t>(source.mechanism)];
    out.position = j.position;
    out.velocity = j.velocity;
    out.measured_effort = j.measured_effort;
    out.commanded_effort = j.commanded_effort;
  } else if (source.physics >= 0) {
    const auto index = static_cast<std::size_t>(source.physics);
    out.position = simulation.physics().position(index);
    out.velocity = simulation.physics().velocity(index);
    out.measured_effort = simulation.physics().effort(index);
  }
  return out;
}

void MechanismStatistics::update(const sim::Simulation& simulation) noexcept {
  // A robot spawned or deleted rebuilt the world's physics: joints of another robot move in it.
  if (simulation.physics_generation() != generation_) {
    generation_ = simulation.physics_generation();
    for (std::size_t k = 0; k < sources_.size(); ++k) {
      const auto index = simulation.physics().model().joint_index(simulation.physics_name(names_[k]));
      sources_[k].physics = index ? static_cast<int>(*index) : -1;
    }
  }
  // A reset moves every joint at once: no distance travelled.
  const bool reset = simulation.resets() != resets_seen_;
  resets_seen_ = simulation.resets();
  for (std::size_t k = 0; k < sources_.size(); ++k) {
    const Source& source = sources_[k];
    const Sample s = sample(simulation, source);
    Window& w = windows_[k];
    if (!w.initialized) {
      w.initialized = true;
      w.min_position = w.max_position = s.position;
      w.max_abs_velocity = std::abs(s.velocity);
      w.max_abs_effort = std::abs(s.measured_effort);
    } else {
      w.min_position = std::min(w.min_position, s.position);
      w.max_position = std::max(w.max_position, s.position);
      w.max_abs_velocity = std::max(w.max_abs_velocity, std::abs(s.velocity));
      w.max_abs_effort = std::max(w.max_abs_effort, std::abs(s.measured_effort));
      if (!reset && std::isfinite(s.position)) w.odometer += std::abs(s.position - w.last_position);
    }
    w.last_position = s.position;
    if (source.lower <= source.upper &&
        (s.position < source.lower - kPositionSlack || s.position > source.upper + kPositionSlack)) {
      w.violated = true;
    }
    if (source.effort_limit > 0.0 && std::abs(s.commanded_effort) >= source.effort_limit * (1.0 - kEffortSlack)) {
      w.violated = true;
    }
  }
}

void MechanismStatistics::joint_states(const sim::Simulation& simulation, JointStatesData& out) const {
  out.stamp = simulation.time();
  out.names = names_;
  out.position.resize(sources_.size());
  out.velocity.resize(sources_.size());
  out.effort.resize(sources_.size());
  for (std::size_t k = 0; k < sources_.size(); ++k) {
    const Sample s = sample(simulation, sources_[k]);
    out.position[k] = s.position;
    out.velocity[k] = s.velocity;
    out.effort[k] = s.measured_effort;
  }
}

void MechanismStatistics::take(const sim::Simulation& simulation, MechanismStatisticsData& out) {
  out.stamp = simulation.time();
  out.joints.resize(sources_.size());
  for (std::size_t k = 0; k < sources_.size(); ++k) {
    const Sample s = sample(simulation, sources_[k]);
    Window& w = windows_[k];
    JointStatisticsData& j = out.joints[k];
    j.name = names_[k];
    j.position = s.position;
    j.velocity = s.velocity;
    j.measured_effort = s.measured_effort;
    j.commanded_effort = s.commanded_effort;
    j.violated_limits = w.violated;
    j.odometer = w.odometer;
    j.min_position = w.initialized ? w.min_position : s.position;
    j.max_position = w.initialized ? w.max_position : s.position;
    j.max_abs_velocity = w.initialized ? w.max_abs_velocity : std::abs(s.velocity);
    j.max_abs_effort = w.initialized ? w.max_abs_effort : std::abs(s.measured_effort);
    // A new window; the odometer goes on.
    w.initialized = false;
    w.violated = false;
  }

  const mechanism::MechanismModel& mechanism = simulation.mechanism();
  const mechanism::MechanismState& state = simulation.mechanism_state();
  out.actuators.resize(mechanism.actuators.size());
  for (std::size_t a = 0; a < mechanism.actuators.size(); ++a) {
    ActuatorStatisticsData& d = out.actuators[a];
    d.name = mechanism.actuators[a].name;
    d.device_id = static_cast<int>(a);
    d.position = state.actuators[a].position;
    d.velocity = state.actuators[a].velocity;
    d.commanded_effort = state.actuators[a].commanded_effort;
    d.measured_effort = state.actuators[a].last_measured_effort;
  }

  // The manager's lock is free between ticks (only publish_list waits on the tick, and the tick
  // is over when observers run).
  out.controllers.clear();
  for (const control::ControllerInfo& info : simulation.controllers().list_controllers()) {
    ControllerStatisticsData c;
    c.name = info.name;
    c.running = info.state == control::ControllerLifecycle::Running;
    c.max_time = info.statistics.max_update_time;
    c.mean_time = info.statistics.mean_update_time;
    c.overruns = info.statistics.overruns;
    out.controllers.push_back(std::move(c));
  }
}

}  // namespace mechsim::bridge
