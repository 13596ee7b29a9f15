#pragma once
// The action goals of a scenario's timeline: FollowJointTrajectory goals to trajectory
// controllers and GripperCommand goals to PR2 gripper controllers. Bound to their controllers'
// ports before the run (every error found there names the event's file:line), submitted when
// due, followed after every tick (status; desired - actual of the trajectory controller's state
// while the goal is ACTIVE) and judged by the `trajectory` and `gripper` checks.
//
// Runs in the scenario loop's thread, between ticks: it reads the ports' thread-safe
// non-real-time side and never touches the tick.

#include <cstdint>
#include <string>
#include <vector>

#include "control/controller_manager.hpp"
#include "controllers/gripper/pr2_gripper_ports.hpp"
#include "controllers/trajectory/trajectory_goal.hpp"
#include "sim/scenario.hpp"
#include "sim/scenario_runner.hpp"

namespace mechsim::sim {

class ScenarioGoals {
 public:
  // Binds every trajectory and gripper event of `scenario` to its controller and checks that
  // every trajectory/gripper check names a goal of the timeline. Throws ScenarioError naming
  // the file and line of the event, or the check.
  ScenarioGoals(const Scenario& scenario, control::ControllerManager& manager);

  // Submits `event` (a Trajectory or Gripper event of the scenario) at simulation time `t` (s).
  // A goal the controller rejects is recorded as such (the checks then fail), not thrown.
  void submit(const TimelineEvent& event, double t);
  // After every tick: statuses, tracking samples.
  void poll(double t);

  const std::vector<TrajectoryGoalOutcome>& trajectory_goals() const { return trajectory_outcomes_; }
  const std::vector<GripperGoalOutcome>& gripper_goals() const { return gripper_outcomes_; }
  // The controllers given trajectory goals, in timeline order (each once).
  const std::vector<std::string>& trajectory_controllers() const { return trajectory_controllers_; }

  // Judges a Trajectory or Gripper check against the outcomes so far.
  CheckOutcome judge(const Check& check) const;

 private:
  struct TrajectoryGoal {
    const TimelineEvent* event = nullptr;
    control::FollowJointTrajectoryGoal goal;  // joints and `all` tolerances resolved
    control::TrajectoryGoalPort* port = nullptr;
    const control::StatePort<control::JointTrajectoryControllerState>* state = nullptr;
    std::uint64_t id = 0;
    std::uint64_t seen = 0;  // state sequence last sampled
    std::vector<double> sum_sq;
  };
  struct GripperGoal {
    const TimelineEvent* event = nullptr;
    control::GripperGoalPort* port = nullptr;
    std::uint64_t id = 0;
  };
  std::size_t find(const Check& check) const;  // index into the outcomes of the check's kind

  std::vector<TrajectoryGoal> trajectory_;
  std::vector<TrajectoryGoalOutcome> trajectory_outcomes_;  // same order
  std::vector<GripperGoal> gripper_;
  std::vector<GripperGoalOutcome> gripper_outcomes_;
  std::vector<std::string> trajectory_controllers_;
};

}  // namespace mechsim::sim
