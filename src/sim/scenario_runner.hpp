#pragma once
// Runs a Scenario headless and writes its report: CSV files of joint states, controller states
// and the base pose, summary.json, and PNG plots drawn by gnuplot.
//
// Output folder. Every CSV row stamped t holds the state at t: the rows are sampled inside the
// tick at t after the controllers' update, every 1/record_rate s and at the run's last tick (one
// period before its end; summary.json's final pose is the state at the end).
//   joints.csv       time, then per mechanism joint (those a transmission drives, in mechanism
//                    order): position, velocity, measured effort, command (effort, or the set
//                    point of a position/velocity interface); then every other non-fixed joint
//                    of the physics (passive ones: the CC8's rocker and bogies): position, velocity
//   controllers.csv  time, then per controller with a joint state port: set point, process value, error, command
//   base.csv         time, ground-truth base pose (x, y, z, roll, pitch, yaw) and odometry (x, y, yaw) if any
//   trajectory.csv   time, then per joint of each controller given a trajectory goal in the
//                    timeline: desired and actual position (rad, m) from its state
//   summary.json     completed (false, with the error, when the physics diverged or an event
//                    stopped the run), events (leaving the usable ground: time, where), distance,
//                    final pose, tracking error per controller, trajectory goals (RMS
//                    and max error per joint while active, result code), gripper goals (status,
//                    time to finish, reached/stalled, gap, effort), real-time factor, checks
//   path.png, tracking.png, errors.png, trajectory.png (desired vs actual per joint) (gnuplot)
//   sensors/<name>.csv  a row per sample of each simulated sensor (sim/sensor_report.hpp): laser
//                    ranges, IMU orientation/rates/acceleration, contact totals, wrenches, ground truth
//   sensors/<name>.png  per IMU: angular velocity, acceleration and orientation over time
//   laser_scans.png  the laser scans seen from above over the world at laser_picture_times
//   wheels.csv, wheels.png  with a soil (world.soil): per wheel slip, slip angle, sinkage, load,
//                    traction, lateral force, torque, rut depth met (sim/wheel_report.hpp)

#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "controllers/gripper/pr2_gripper_ports.hpp"
#include "controllers/trajectory/trajectory_msgs.hpp"
#include "sim/scenario.hpp"
#include "sim/tick_timing.hpp"

namespace mechsim::sim {

class Simulation;

struct RunProgress {
  double time = 0.0;      // s of simulation time done
  double duration = 0.0;  // s in all
  double real_time_factor = 0.0;
};

struct RunOptions {
  std::string output_dir;  // created if needed; empty: no files at all
  bool plots = true;       // draw PNGs with gnuplot (needs gnuplot on PATH)
  std::function<void(const RunProgress&)> progress;  // called about every 0.5 s of sim time
  // Called with each warning when it arises (at spawn, during the run), besides
  // ScenarioResult::warnings.
  std::function<void(const std::string&)> warning;
  // Non-zero (a signal number, set by a signal handler): the run stops before its next tick and
  // its report says "interrupted". Read once per tick; lock-free, so a handler may write it.
  const std::atomic<int>* interrupt = nullptr;
  // > 0: measure every tick and write timing.csv with one row per this many s of simulated time
  // (tick_timing.hpp: tick time p50/p99/max, CPU time, resident memory); ScenarioResult::timing.
  double timing_window = 0.0;
  // > 0: the run is paced so that simulation time runs this many times as fast as wall-clock
  // time (1: real time, for watching it live); 0: as fast as it goes. A run that falls behind
  // goes on from where it is instead of racing to catch up (Simulation's kMaxPaceLag).
  double real_time_factor = 0.0;
  // Called once the simulation is built and its controllers started, before the first tick
  // (a live view attaches its observer here). It may throw: the run then does not start.
  std::function<void(Simulation&)> on_start;
};

// Something that happened to the robot during a run (summary.json "events").
struct RunEvent {
  double time = 0.0;  // s
  std::string kind;   // left_terrain (the usable ground), fell_off_world
  std::string detail;
  double x = 0.0, y = 0.0;  // m, where the base was (world frame)
};

// How an `others:` robot's base moved in a run (the first robot's figures are ScenarioResult's
// own fields of the same names).
struct RobotMotion {
  std::string name;
  double distance = 0.0;  // m, in the horizontal plane
  double final_x = 0.0, final_y = 0.0, final_z = 0.0, final_yaw = 0.0;  // m, rad
  double yaw_change = 0.0;  // rad, unwrapped
  bool has_odometry = false;
  double odometry_error = 0.0;      // m
  double odometry_yaw_error = 0.0;  // rad
};

struct CheckOutcome {
  std::string name;
  bool passed = false;
  std::string detail;  // measured value against the bound
};

struct TrackingError {
  std::string controller;
  double rms = 0.0;  // of the state port's error over the recorded samples
  double max = 0.0;
  std::size_t samples = 0;
};

// What became of one trajectory goal of the timeline.
struct TrajectoryGoalOutcome {
  std::string controller;
  std::size_t index = 0;   // 1-based among the controller's trajectory events
  double sent_at = 0.0;    // s
  bool accepted = false;   // false: rejected when submitted (result says why)
  std::string status;      // at the end: not_sent, or control::goal_status_name (pending, active, succeeded, ...)
  bool finished = false;
  double finished_at = 0.0;  // s, when it finished (finished only)
  control::TrajectoryResult result;  // finished only
  // Desired - actual per joint of the controller, sampled from its state while ACTIVE.
  std::vector<std::string> joints;
  std::vector<double> rms, max;  // rad or m
  std::size_t samples = 0;
};

// What became of one gripper goal of the timeline.
struct GripperGoalOutcome {
  std::string controller;
  std::size_t index = 0;  // 1-based among the controller's gripper events
  double sent_at = 0.0;   // s
  control::GripperCommand command;
  bool accepted = false;
  std::string error;      // why it was rejected
  std::string status;     // as TrajectoryGoalOutcome::status
  bool finished = false;
  double finished_after = 0.0;  // s after it was sent (finished only)
  control::GripperResult result;  // finished only: gap (m), effort (N), stalled, reached_goal
};

// One wheel in the soil (world.soil) over a run: means while it was in the soil (the slip's while
// it moved: physics::WheelSoilReading::moving).
struct WheelOutcome {
  std::string link;
  double radius = 0.0, width = 0.0;  // m, as the soil sees it
  bool narrow = false;               // width <= radius
  double grouser_height = 0.0;       // m
  int grouser_count = 0;
  std::string origin;                // why it is a wheel (physics::SoilWheelInfo::origin)
  double mean_slip = 0.0;      // physics::WheelSoilReading::slip
  double mean_traction = 0.0;  // N
  double max_sinkage = 0.0;    // m
  double mean_sinkage = 0.0;   // m
  double mean_rut_depth = 0.0;  // m: the ruts of other wheels it ran in (soil multi_pass), 0 without
  double time_in_soil = 0.0;   // s
};

// A test rig's steady state (Scenario::steady_states): one window's means of one wheel.
struct SteadyStateRow {
  double from = 0.0, to = 0.0;  // s
  double slip = 0.0;            // while moving
  double drawbar = 0.0;         // N, the soil's net pull along the heading
  double load = 0.0;            // N, the normal force
  double torque = 0.0;          // N m, the soil's on the axle (< 0 resists a driven wheel)
  double sinkage = 0.0;         // m
  long samples = 0;             // ticks in the soil
};

struct ScenarioResult {
  bool completed = false;  // ran its whole duration (no divergence, not stopped by an event)
  bool passed = false;     // completed and every check passed
  int interrupted_by = 0;  // the signal that stopped the run (RunOptions::interrupt), or 0
  std::string error;       // why it did not complete
  std::vector<RunEvent> events;
  double sim_time = 0.0;   // s
  double wall_time = 0.0;  // s
  double real_time_factor = 0.0;
  double distance = 0.0;   // m, length of the base's path in the horizontal plane
  double final_x = 0.0, final_y = 0.0, final_z = 0.0, final_yaw = 0.0;  // m, rad
  double max_tilt = 0.0;   // rad
  bool has_odometry = false;
  double odometry_error = 0.0;  // m, final |odom - truth| in the plane
  double yaw_change = 0.0;      // rad, net true rotation of the base over the run (unwrapped)
  double odometry_yaw_error = 0.0;  // rad, |odom yaw - true rotation| at the end
  std::vector<TrackingError> tracking;
  std::vector<TrajectoryGoalOutcome> trajectory_goals;  // in timeline order
  std::vector<GripperGoalOutcome> gripper_goals;
  std::vector<CheckOutcome> checks;
  std::vector<RobotMotion> others;   // the scenario's `others:`, in order
  std::vector<WheelOutcome> wheels;  // with a soil only
  // With a soil: what looks like a wheel but is not a soil wheel, one line each with the reason
  // (physics::PhysicsModel::not_wheels, physics::Physics::soil_wheel_notes).
  std::vector<std::string> not_wheels;
  std::string steady_state_wheel;             // Scenario::steady_states' wheel
  std::vector<SteadyStateRow> steady_states;  // one per window
  std::vector<TimingWindow> timing;  // RunOptions::timing_window
  std::vector<std::string> files;  // written, relative to output_dir
  std::vector<std::string> warnings;
};

// Throws ScenarioError for a scenario that cannot start (robot, world, controllers, unknown
// controller or port in the timeline, a report folder that cannot be written or a disk without
// room); a divergence during the run is reported in the result. While the run goes, the report
// folder's summary.json says "completed": false, "status": "running"; the final one replaces it
// whole (written aside, then renamed), so a killed run never leaves a summary that reads complete.
ScenarioResult run_scenario(const Scenario& scenario, const RunOptions& options);

}  // namespace mechsim::sim
