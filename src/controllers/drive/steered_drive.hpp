#pragma once
// The machinery shared by the controllers that drive a base on steered wheels
// (mechsim/RoverDriveController, pr2_mechanism_controllers/Pr2BaseController2) and by the PR2's
// odometry: each controller keeps its own kinematics and command semantics and delegates here
//   - SteeredDrive: claiming the steering and wheel joints on the effort interface, one PID per
//     joint with its "gains/<joint>" port, the tick's PID loop (steering joints on position,
//     wheel joints on velocity) and the "state" snapshot;
//   - TwistCommandTimeout: the latest twist command and its timeout;
//   - PlanarOdometry: the integrated pose and its "odom" snapshot.

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "control/controller.hpp"
#include "control/pid.hpp"
#include "controllers/drive/rover_drive_ports.hpp"  // OdometrySnapshot, PlanarTwist, PlanarPose

namespace mechsim::control {

// `v` bounded to [-limit, limit].
inline double clamp_abs(double v, double limit) noexcept { return std::fmin(std::fmax(v, -limit), limit); }

// `from` moved towards `to` by at most `step`.
inline double step_towards(double from, double to, double step) noexcept { return from + clamp_abs(to - from, step); }

// Gains for `joint` from `params`: the `<joint>` namespace when it holds a `p`, else `fallback`.
void init_joint_pid(Pid& pid, const Params& params, const std::string& joint, const char* fallback);

// Steering joints under position PIDs and wheel joints under velocity PIDs, all on the effort
// interface. Joint order everywhere (PIDs, gains ports, efforts, state): steering joints first,
// then wheels.
class SteeredDrive {
 public:
  // Where each joint's gains come from.
  enum class Gains : std::uint8_t {
    Shared,        // the steering / wheel namespace given to init_pids()
    // the `<joint>` namespace when it holds a `p` (the PR2's YAML), else `<joint>/position_controller`
    // (pr2_controller_configuration_gazebo's casters), else the shared one
    JointOrShared
  };

  // Init (not real-time; throws on bad parameters). Claims the joints listed under
  // `steering_key` (at least `min_steering`) and `wheel_key` (at least `min_wheels`); a joint
  // that is unknown or taken is named by its parameter path "<namespace>/<key>[i]".
  void claim(RobotHardware& hardware, const Params& params, const char* steering_key, std::size_t min_steering,
             const char* wheel_key, std::size_t min_wheels);
  // Init, after claim(): a PID per joint with gains from `steering_gains` / `wheel_gains` (namespaces
  // under `params`), its "gains/<joint>" port, the working arrays and the "state" prototype.
  void init_pids(const Params& params, const char* steering_gains, const char* wheel_gains, Gains source);

  std::size_t steering_count() const noexcept { return steering_.size(); }
  std::size_t wheel_count() const noexcept { return wheels_.size(); }
  const JointHandle& steering(std::size_t s) const noexcept { return steering_[s]; }
  const JointHandle& wheel(std::size_t w) const noexcept { return wheels_[w]; }

  // Real-time set points, written by the controller before update(): steering joint angles (rad,
  // joint frame, so signed by the joint axis) and wheel joint velocities (rad/s).
  std::span<double> steering_setpoints() noexcept { return steering_setpoints_; }
  std::span<double> wheel_setpoints() noexcept { return wheel_setpoints_; }
  // N m, steering then wheels, as written by the last update().
  std::span<const double> efforts() const noexcept { return efforts_; }

  void reset_pids() noexcept;
  // Real-time: closes every PID and writes the efforts. Steering error = shortest angular
  // distance from the position to the set point; wheel error = set point - velocity. A wheel
  // flagged non-zero in `unpowered` (empty: none) gets effort 0 and its PID is reset.
  void update(double period, std::span<const std::uint8_t> unpowered = {}) noexcept;
  // Real-time: per joint, set point, process value (steering: position and velocity; wheel:
  // velocity), error, effort and gains.
  void publish_state(double time, double period) noexcept;

  StatePort<JointGroupControllerState>& state_port() noexcept { return state_; }
  // Appends the "gains/<joint>" ports.
  void append_gains_ports(std::vector<Port*>& out);

 private:
  std::vector<std::string> steering_names_, wheel_names_;
  std::vector<JointHandle> steering_;
  std::vector<JointHandle> wheels_;
  std::vector<std::unique_ptr<Pid>> pids_;  // steering joints, then wheels
  std::vector<std::unique_ptr<PidGainsPort>> gains_;
  std::vector<double> steering_setpoints_;  // rad, joint
  std::vector<double> wheel_setpoints_;     // rad/s, joint
  std::vector<double> efforts_;             // N m, steering then wheels
  StatePort<JointGroupControllerState> state_{"state"};
};

// The latest command of a TwistCommandPort, and its timeout.
class TwistCommandTimeout {
 public:
  // starting(): zeroes the port's command; the timeout counts from `time` (s).
  void start(TwistCommandPort& port, double time) noexcept;
  // Real-time: reads the latest command and returns its planar part (linear.x, linear.y in m/s,
  // angular.z in rad/s), or zero once no command arrived for more than `timeout` s (<= 0: never).
  PlanarTwist read(TwistCommandPort& port, double time, double timeout) noexcept;
  const Twist& value() const noexcept { return value_; }  // as last read
  bool timed_out() const noexcept { return timed_out_; }

 private:
  Twist value_;
  std::uint64_t last_seq_ = 0;
  double last_time_ = 0.0;  // s, when the latest command arrived
  bool timed_out_ = false;
};

// A planar pose integrated from the body twist that wheel odometry estimates, and its snapshot.
struct PlanarOdometry {
  PlanarPose pose;       // m, rad: base frame in the odometry frame
  PlanarTwist twist;     // m/s, rad/s, base frame: the latest estimate
  double residual = 0.0;  // m/s, of the latest estimate
  bool valid = false;    // false until an estimate succeeded

  // Real-time: takes `estimate` as the twist and integrates the pose over `period` (s).
  void advance(const PlanarTwist& estimate, double period) noexcept;
  // Real-time: publishes the pose, twist, residual and validity stamped `time`.
  void publish(StatePort<OdometrySnapshot>& port, double time) const noexcept;
};

// The "odom" port's prototype: frames, covariance diagonals (pose: x, y, z, roll, pitch, yaw;
// twist: vx, vy, vz, wx, wy, wz) and the starting pose.
OdometrySnapshot odometry_prototype(std::string frame_id, std::string child_frame_id,
                                    const std::array<double, 6>& pose_covariance_diagonal,
                                    const std::array<double, 6>& twist_covariance_diagonal, const PlanarPose& pose = {});

}  // namespace mechsim::control
