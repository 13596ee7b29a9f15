#pragma once
// Ports: how the outside (ROS topics, scenario timelines, recorders, tests) reaches a
// controller. A command port is written by non-real-time threads and read in the tick; a state
// port is filled in the tick and read outside. Both are double buffers that never block the
// tick (control/realtime_buffer.hpp). Controllers know nothing of who binds their ports.
//
// Command ports reject non-finite values (and arrays of the wrong size): the previous command
// stays, the rejection is counted and its reason kept, so a NaN never reaches an actuator.

#include <array>
#include <atomic>
#include <cstdint>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "control/pid.hpp"
#include "control/realtime_buffer.hpp"

namespace mechsim::control {

enum class PortKind : std::uint8_t {
  ScalarCommand,        // ScalarCommandPort: one value (std_msgs/Float64)
  ArrayCommand,         // ArrayCommandPort: one value per joint (std_msgs/Float64MultiArray)
  TwistCommand,         // TwistCommandPort: geometry_msgs/Twist
  JointControllerState, // StatePort<JointControllerState>
  JointGroupState,      // StatePort<JointGroupControllerState>
  JointStates,          // StatePort<JointStateSnapshot> (sensor_msgs/JointState)
  PidGains,             // PidGainsPort: runtime gain changes (dynamic_reconfigure)
  DriveModeCommand,     // DriveModeCommandPort: a rover drive mode (controllers/drive/rover_drive_ports.hpp)
  Odometry,             // StatePort<OdometrySnapshot> (nav_msgs/Odometry)
  RoverDriveStatus,     // StatePort<RoverDriveStatus>
  TrajectoryCommand,    // TrajectoryCommandPort (trajectory_msgs/JointTrajectory), trajectory_goal.hpp
  TrajectoryGoal,       // TrajectoryGoalPort (control_msgs/FollowJointTrajectory action)
  JointTrajectoryState, // StatePort<JointTrajectoryControllerState>
  Pr2BaseStatus,        // StatePort<Pr2BaseStatus> (controllers/drive/pr2_base_controller.hpp)
  GripperCommand,       // GripperCommandPort (pr2_controllers_msgs/Pr2GripperCommand), pr2_gripper_ports.hpp
  GripperGoal,          // GripperGoalPort (control_msgs/GripperCommand action), pr2_gripper_ports.hpp
  PeriodicCommand,      // PeriodicCommandPort (pr2_msgs/PeriodicCmd), laser_scanner_traj_controller.hpp
  TrajectoryQuery,      // TrajectoryQueryPort (query_state), controllers/trajectory/trajectory_query.hpp
  TwistState,           // StatePort<TwistSnapshot> (geometry_msgs/TwistStamped: diff_drive_controller's cmd_vel_out)
  ImuState,             // StatePort<ImuSnapshot> (sensor_msgs/Imu), controllers/sensor/sensor_state_controllers.hpp
  WrenchState,          // StatePort<WrenchSnapshot> (geometry_msgs/WrenchStamped), the same
};

class Port {
 public:
  explicit Port(std::string name) : name_(std::move(name)) {}
  virtual ~Port() = default;
  Port(const Port&) = delete;
  Port& operator=(const Port&) = delete;
  const std::string& name() const { return name_; }  // "command", "state", "joint_states", "gains"
  virtual PortKind kind() const = 0;

 private:
  std::string name_;
};

// ---------------------------------------------------------------- commands

struct Vec3d {
  double x = 0.0, y = 0.0, z = 0.0;
};
// A body velocity command: linear (m/s) and angular (rad/s) in the robot's base frame.
struct Twist {
  Vec3d linear;
  Vec3d angular;
};

// Counts and explains rejected writes (shared by the command ports).
class RejectionLog {
 public:
  std::uint64_t count() const { return count_.load(std::memory_order_relaxed); }
  std::string last() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return last_;
  }

 protected:
  bool reject(std::string reason, std::string* error);

 private:
  std::atomic<std::uint64_t> count_{0};
  mutable std::mutex mutex_;
  std::string last_;
};

class ScalarCommandPort : public Port, public RejectionLog {
 public:
  using Port::Port;
  PortKind kind() const override { return PortKind::ScalarCommand; }
  // Non-real-time. False (and `error` set) when rejected.
  bool write(double value, std::string* error = nullptr);
  double latest() const { return buffer_.latest(); }
  std::uint64_t accepted() const { return buffer_.writes(); }
  // Real-time.
  double read_from_rt() noexcept { return buffer_.read_from_rt(); }
  // Real-time: drops any pending write and sets the command (ros_control's starting()).
  void reset_from_rt(double value) noexcept {
    buffer_.reset_from_rt([value](double& v) { v = value; });
  }

 private:
  RealtimeBuffer<double> buffer_;
};

class ArrayCommandPort : public Port, public RejectionLog {
 public:
  ArrayCommandPort(std::string name, std::size_t size);
  PortKind kind() const override { return PortKind::ArrayCommand; }
  std::size_t size() const { return size_; }
  // Non-real-time: rejected unless values.size() == size() and every value is finite.
  bool write(std::span<const double> values, std::string* error = nullptr);
  std::vector<double> latest() const { return buffer_.latest(); }
  // Real-time: size() values.
  const std::vector<double>& read_from_rt() noexcept { return buffer_.read_from_rt(); }
  void reset_from_rt(std::span<const double> values) noexcept;

 private:
  std::size_t size_;
  RealtimeBuffer<std::vector<double>> buffer_;
};

class TwistCommandPort : public Port, public RejectionLog {
 public:
  using Port::Port;
  PortKind kind() const override { return PortKind::TwistCommand; }
  bool write(const Twist& twist, std::string* error = nullptr);
  Twist latest() const { return buffer_.latest(); }
  // Accepted writes so far. Real-time safe (an atomic): a controller compares it between ticks
  // to see that a command arrived, even one equal to the last (command timeouts).
  std::uint64_t accepted() const noexcept { return accepted_.load(std::memory_order_acquire); }
  const Twist& read_from_rt() noexcept { return buffer_.read_from_rt(); }
  void reset_from_rt(const Twist& twist) noexcept {
    buffer_.reset_from_rt([&twist](Twist& v) { v = twist; });
  }

 private:
  RealtimeBuffer<Twist> buffer_;
  std::atomic<std::uint64_t> accepted_{0};
};

// Runtime gain changes of one PID (the tick picks them up on its next step).
class PidGainsPort : public Port {
 public:
  PidGainsPort(std::string name, Pid* pid) : Port(std::move(name)), pid_(pid) {}
  PortKind kind() const override { return PortKind::PidGains; }
  // False when a gain is not finite.
  bool write(const PidGains& gains, std::string* error = nullptr);
  PidGains latest() const { return pid_->gains(); }

 private:
  Pid* pid_;
};

// ---------------------------------------------------------------- state snapshots

// What control_msgs/JointControllerState carries.
struct JointControllerState {
  double stamp = 0.0;              // s, sim time of the update
  double set_point = 0.0;          // commanded position (rad, m) / velocity / effort
  double process_value = 0.0;      // measured quantity of the same kind
  double process_value_dot = 0.0;  // its rate (velocity for position controllers)
  double error = 0.0;              // set_point - process_value (PR2 controllers: the opposite)
  double time_step = 0.0;          // s, the period of the update
  double command = 0.0;            // what was written to the joint
  PidGains gains;                  // zero for controllers without PID
};

struct JointGroupControllerState {
  double stamp = 0.0;
  std::vector<std::string> joint_names;
  std::vector<JointControllerState> joints;  // same order as joint_names
};

// What sensor_msgs/JointState carries.
struct JointStateSnapshot {
  double stamp = 0.0;  // s
  std::vector<std::string> names;
  std::vector<double> position;  // rad or m
  std::vector<double> velocity;  // rad/s or m/s
  std::vector<double> effort;    // N m or N (measured)
};

// A twist with its time and frame (geometry_msgs/TwistStamped).
struct TwistSnapshot {
  double stamp = 0.0;  // s
  std::string frame_id;
  Twist twist;         // m/s, rad/s in frame_id
};

template <class T>
constexpr PortKind state_port_kind();
template <>
constexpr PortKind state_port_kind<JointControllerState>() { return PortKind::JointControllerState; }
template <>
constexpr PortKind state_port_kind<JointGroupControllerState>() { return PortKind::JointGroupState; }
template <>
constexpr PortKind state_port_kind<JointStateSnapshot>() { return PortKind::JointStates; }
template <>
constexpr PortKind state_port_kind<TwistSnapshot>() { return PortKind::TwistState; }

template <class T>
class StatePort : public Port {
 public:
  using Port::Port;
  PortKind kind() const override { return state_port_kind<T>(); }
  void init(const T& prototype) { buffer_.init(prototype); }  // non-real-time, before use
  T read() const { return buffer_.read(); }                    // non-real-time
  std::uint64_t sequence() const noexcept { return buffer_.sequence(); }
  template <class F>
  bool publish_from_rt(F&& fill) noexcept {
    return buffer_.publish_from_rt(std::forward<F>(fill));
  }

 private:
  SnapshotBuffer<T> buffer_;
};

}  // namespace mechsim::control
