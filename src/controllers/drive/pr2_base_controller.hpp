#pragma once
// pr2_mechanism_controllers/Pr2BaseController2 (and the older Pr2BaseController, registered to
// the same implementation): drives the PR2's four powered casters from a body twist. It claims
// every caster rotation joint and every wheel joint on the effort interface and closes a
// position PID per caster and a velocity PID per wheel. Kinematics:
// controllers/drive/pr2_base_kinematics.hpp; parameters read by controllers/drive/pr2_base_params.hpp.
//
// Each tick:
//   1. command = the latest "command" twist (linear.x, linear.y in m/s, angular.z in rad/s, base
//      frame; the other components are ignored), or zero once none arrived for `timeout` seconds
//      (the base then brakes within its acceleration limits);
//   2. |(vx, vy)| is scaled down to max_translational_velocity and |wz| clamped to
//      max_rotational_velocity, then each component moves towards it by at most its
//      acceleration limit * period (the PR2's interpolated command);
//   3. each caster's target heading rolls its wheels along its pivot's velocity, flipped by pi
//      (wheels reversed) when that is the shorter turn from the measured heading; a caster whose
//      pivot barely moves keeps its heading;
//   4. each wheel's set point is the rolling speed the twist asks of it with its caster at the
//      MEASURED heading and rate: the wheels drive only the component of the pivot velocity
//      along where the caster points (cos of the steering error: zero at 90 deg, so the wheels
//      wait for the caster), and roll apart to turn the caster in place (-offset * caster rate);
//   5. PIDs turn set points into efforts (caster: shortest angular error, derivative from the
//      error; wheel: velocity error).
//
// Parameters (under the controller's namespace; units in brackets). Geometry: see
// controllers/drive/pr2_base_params.hpp (caster_joints, wheel_joints, wheel_radius,
// wheel_radius_multiplier, caster_positions, wheel_casters, wheel_offsets, axis signs; the
// simulation fills them from the URDF with control::fill_pr2_base_geometry). Then:
//   caster_pid                     {p, i, d, i_clamp, ...}  position gains of every caster [N m/rad ...]
//   wheel_pid                      {p, i, d, i_clamp, ...}  velocity gains of every wheel [N m s/rad ...]
//   <joint>                        {p, i, d, ...}  optional per-joint gains, overriding the two above
//                                  (the PR2's YAML names its gains by joint this way)
//   max_translational_velocity     [m/s]     default 0.5
//   max_rotational_velocity        [rad/s]   default 10.0
//   max_translational_acceleration/x, /y [m/s^2] default 0.2 each
//   max_rotational_acceleration    [rad/s^2] default 10.0
//   timeout                        [s]       default 0.2; <= 0: never time out
//   caster_hold_speed              [m/s]     default 1e-5: slower pivots keep their heading
//
// Ports:
//   "command"        TwistCommandPort (cmd_vel; non-finite twists rejected and counted)
//   "state"          StatePort<JointGroupControllerState>: casters first (set point = target
//                    joint angle, rad), then wheels (set point = joint velocity, rad/s); error
//                    = set point - process value; command = effort (N m)
//   "status"         StatePort<Pr2BaseStatus>
//   "gains/<joint>"  PidGainsPort per joint
//
// starting() holds the measured caster headings, zeroes the command and resets the PIDs.
//
// A minimal YAML for the PR2 (the geometry comes from the URDF through
// control::fill_pr2_base_geometry_all, which the simulation calls on the controller namespace):
//   base_controller:
//     type: pr2_mechanism_controllers/Pr2BaseController2
//     caster_names: fl_caster_rotation_link fr_caster_rotation_link bl_caster_rotation_link br_caster_rotation_link
//     caster_pid: {p: 100.0, d: 8.0}
//     wheel_pid: {p: 8.0, i: 0.5, i_clamp: 2.0}
//   base_odometry:
//     type: pr2_mechanism_controllers/Pr2Odometry
//     caster_names: fl_caster_rotation_link fr_caster_rotation_link bl_caster_rotation_link br_caster_rotation_link
// (gains to be tuned in simulation; the values above are a starting point, not the PR2's).

#include <vector>

#include "control/controller.hpp"
#include "controllers/drive/pr2_base_params.hpp"
#include "controllers/drive/steered_drive.hpp"

namespace mechsim::control {

// The base's state beyond its joints.
struct Pr2BaseStatus {
  double stamp = 0.0;         // s
  Twist command;              // the latest command read from "command" (m/s, rad/s)
  PlanarTwist applied;        // after timeout and limits: what the casters and wheels realise
  bool timed_out = false;     // no command for `timeout`: braking to zero
  double max_caster_error = 0.0;  // rad: the largest |target heading - measured heading|
  int reversed_casters = 0;   // casters whose target points against their pivot velocity
};

template <>
constexpr PortKind state_port_kind<Pr2BaseStatus>() { return PortKind::Pr2BaseStatus; }

class Pr2BaseController : public Controller {
 public:
  bool init(RobotHardware& hardware, const Params& params, std::string& error) override;
  void starting(double time) override;
  UpdateStatus update(double time, double period) override;
  std::vector<Port*> ports() override;

  TwistCommandPort& command_port() { return command_; }
  StatePort<JointGroupControllerState>& state_port() { return drive_.state_port(); }
  StatePort<Pr2BaseStatus>& status_port() { return status_; }
  const Pr2BaseConfig& config() const { return config_; }

 private:
  PlanarTwist limit_command(const PlanarTwist& target, double period) const noexcept;
  void publish(double time, double period) noexcept;

  Pr2BaseConfig config_;
  SteeredDrive drive_;  // casters (steering), then wheels: PIDs, set points, efforts, "state"
  TwistCommandTimeout command_timeout_;

  // Real-time working state, sized at init.
  std::vector<double> measured_headings_;  // rad
  std::vector<double> target_headings_;    // rad
  PlanarTwist applied_;
  double max_caster_error_ = 0.0;
  int reversed_ = 0;

  TwistCommandPort command_{"command"};
  StatePort<Pr2BaseStatus> status_{"status"};
};

}  // namespace mechsim::control
