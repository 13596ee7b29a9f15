#pragma once
// PID tuning in simulation (`mechsim tune`): closed-loop step experiments on one joint's
// controller (effort_controllers/JointPositionController or JointVelocityController and their
// robot_mechanism_controllers equivalents) with the rest of the robot held by its other
// controllers, and a Nelder-Mead search over the gains (in log space) that minimises a cost
// built from the stated targets: settling time and overshoot for position, time to 95 % and
// overshoot for velocity, and the final error, with a small cost per decade the gains move away
// from the YAML's. Times faster than 3/4 of the target and final errors under 0.5 % of the step
// earn nothing, so among gains that meet the targets with that margin the closest to the YAML's
// win (neither ever stiffer nor ever softer gains).

#include <optional>
#include <string>
#include <vector>

#include "control/pid.hpp"
#include "description/robot_model.hpp"
#include "sim/world.hpp"

namespace mechsim::sim {

struct StepMetrics {
  double step = 0.0;            // commanded change (rad, m, rad/s or m/s)
  double rise95 = -1.0;         // s from the step to 95 % of it; -1 when never reached
  double settling_time = -1.0;  // s from the step until it stays within 2 %; -1 when never
  double overshoot = 0.0;       // % of the step beyond the target
  double steady_state_error = 0.0;  // at the end, in units of the step's quantity
  double peak_effort = 0.0;     // N m or N
  bool diverged = false;
};

struct TuneTargets {
  double settling_time = 0.3;  // s (position)
  double rise95 = 0.2;         // s (velocity)
  double overshoot = 5.0;      // %
};

// A condition a robust tune (`mechsim tune --robust`) evaluates the gains in as well as the
// nominal experiment: the step scaled, another world, a payload. The search then minimises the
// worst condition's cost (minimax), and the targets count as met only when every condition meets
// them.
struct TuneCondition {
  std::string name;
  double step_scale = 1.0;           // times the nominal step; negative: the other way
  std::optional<WorldConfig> world;  // nullopt: the setup's
  std::string payload_link;          // empty: no payload
  double payload_mass = 0.0;         // kg added at the link's centre of mass
};

struct TuneSetup {
  description::RobotModel robot;
  WorldConfig world;
  double spawn_z = 0.02;        // m above the ground
  // Velocity controllers are tuned with the robot "on a stand", wheels free: no gravity and
  // spawned 1 m up, as wheel loops are tuned on blocks. Position controllers are tuned on the
  // ground, where steering meets its real load (tyre scrub).
  bool velocity_on_stand = true;
  std::string controllers_file;
  std::string controllers_namespace;  // "" when the controllers are at the top level
  std::string joint;            // the joint whose controller is tuned
  std::optional<double> step;   // default: 0.5 rad/m (position), 2.0 rad/s (velocity)
  double settle_before = 0.5;   // s of holding before the step
  double observe = 1.0;         // s after the step
  TuneTargets targets;
  int max_evaluations = 80;
  // Robust tuning: the nominal experiment and these conditions (robust with no conditions: the
  // default set of default_robust_conditions()).
  bool robust = false;
  std::vector<TuneCondition> conditions;
};

struct TuneResult {
  std::string controller;  // name in the YAML
  std::string type;
  bool velocity = false;   // a velocity controller (else position)
  // Position controllers: where the joint rests before the step (rad or m), the step applied
  // (the requested one, or its opposite when that left the joint's range) and whether it was
  // reversed; plan.limited false for continuous joints and velocity controllers.
  double start = 0.0;
  struct StepPlanInfo {
    double step = 0.0;
    bool reversed = false;
    bool limited = false;
    double lower = 0.0, upper = 0.0;  // the range checked (rad or m)
    bool soft = false;                // the range is the safety controller's soft limits
  } plan;
  control::PidGains before, after;
  StepMetrics before_metrics, after_metrics;
  int evaluations = 0;
  bool targets_met = false;  // robust: in every condition
  // Robust tuning: each condition (the nominal first) with its metrics under both sets of gains.
  struct ConditionOutcome {
    std::string name;
    StepMetrics before, after;
    bool met_before = false, met_after = false;
  };
  std::vector<ConditionOutcome> conditions;
};

// The conditions `mechsim tune --robust` uses when given none: position controllers a small step
// (0.2x), the step reversed and half the moved link's mass again as a payload on it; velocity
// controllers a slow (0.25x), a fast (2x) and a reversed step.
std::vector<TuneCondition> default_robust_conditions(const description::RobotModel& robot, const std::string& joint,
                                                     bool velocity);

// A conditions file:
//   conditions:
//     - name: small step          # optional; made from the rest when absent
//       step_scale: 0.2
//     - world: {name: slope, slope_deg: 10}   # a scenario's world keys (sim/scenario.hpp)
//     - payload: {link: r_gripper_palm_link, mass: 2.0}
// Throws std::runtime_error naming the file, line and key (unknown keys, empty list, a payload
// on a link the robot lacks is found later, by tune_joint).
std::vector<TuneCondition> read_tune_conditions(const std::string& file);

// The step a position experiment can take from `start` (rad or m) on `joint`: `step` when
// start + step lies within the joint's range (the safety controller's soft limits when the joint
// has one, else its limits), else -step (reversed). Continuous and unlimited joints take `step`
// as given. Throws std::runtime_error naming the joint, its range, the start and the step when
// neither direction stays in range.
TuneResult::StepPlanInfo plan_position_step(const description::Joint& joint, double start, double step);

// The controller of `setup.joint` in the YAML, its step response with the YAML's gains, and the
// tuned gains with theirs. Throws std::runtime_error naming the joint/controller when the YAML
// has no PID position/velocity controller for the joint, and (position controllers) when the step
// fits the joint's range in neither direction (see plan_position_step).
TuneResult tune_joint(const TuneSetup& setup);

// One step experiment with the given gains (exposed for tests).
StepMetrics measure_step(const TuneSetup& setup, const std::string& controller, bool velocity,
                         const control::PidGains& gains);

// Rewrites the controller's `pid: {...}` line in a YAML file (one-line flow maps, comments and
// layout kept). False when the file has no such line for the controller.
bool write_gains_in_place(const std::string& file, const std::string& controller, const control::PidGains& gains);

}  // namespace mechsim::sim
