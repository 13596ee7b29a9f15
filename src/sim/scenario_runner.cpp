#include "sim/scenario_runner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <thread>

#include "control/params.hpp"
#include "controllers/drive/rover_drive_ports.hpp"
#include "description/sensor_spec.hpp"
#include "sim/replay_recorder.hpp"
#include "sim/report.hpp"
#include "sim/pose_math.hpp"
#include "sim/route_follower.hpp"
#include "sim/scenario_build.hpp"
#include "sim/scenario_goals.hpp"
#include "sim/camera_report.hpp"
#include "sim/sensor_report.hpp"
#include "sim/wheel_report.hpp"
#include "sim/simulation.hpp"
#include "sim/terrain_watch.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;


template <class P>
P* find_port(control::Controller* c, control::PortKind kind) {
  if (c == nullptr) return nullptr;
  for (control::Port* p : c->ports()) {
    if (p->kind() == kind) return dynamic_cast<P*>(p);
  }
  return nullptr;
}

// A timeline event bound to its controller's port, checked before the run starts.
struct BoundEvent {
  const TimelineEvent* event = nullptr;
  control::Controller* controller = nullptr;
};

// Twist commands are held and re-sent at 50 Hz, as a teleoperation node publishes cmd_vel:
// drive controllers stop when their command times out.
struct HeldTwist {
  control::TwistCommandPort* port = nullptr;
  control::Twist twist;
};

void apply(const BoundEvent& b, std::optional<RouteFollower>& route, control::TwistCommandPort*& route_port,
           std::vector<HeldTwist>& held, ScenarioGoals& goals, double t) {
  const TimelineEvent& e = *b.event;
  std::string error;
  bool ok = true;
  switch (e.kind) {
    case TimelineEvent::Kind::Scalar:
      ok = find_port<control::ScalarCommandPort>(b.controller, control::PortKind::ScalarCommand)->write(e.scalar, &error);
      break;
    case TimelineEvent::Kind::Array:
      ok = find_port<control::ArrayCommandPort>(b.controller, control::PortKind::ArrayCommand)->write(e.array, &error);
      break;
    case TimelineEvent::Kind::Twist: {
      route.reset();
      auto* port = find_port<control::TwistCommandPort>(b.controller, control::PortKind::TwistCommand);
      ok = port->write(e.twist, &error);
      auto it = std::find_if(held.begin(), held.end(), [&](const HeldTwist& h) { return h.port == port; });
      if (it == held.end()) {
        held.push_back({port, e.twist});
      } else {
        it->twist = e.twist;
      }
      break;
    }
    case TimelineEvent::Kind::Mode:
      ok = find_port<control::DriveModeCommandPort>(b.controller, control::PortKind::DriveModeCommand)->write(e.mode, &error);
      break;
    case TimelineEvent::Kind::Route: {
      RouteParams params;
      params.speed = e.route.speed;
      params.tolerance = e.route.tolerance;
      params.lookahead = e.route.lookahead;
      params.max_yaw_rate = e.route.max_yaw_rate;
      route.emplace(e.route.waypoints, params);
      route_port = find_port<control::TwistCommandPort>(b.controller, control::PortKind::TwistCommand);
      break;
    }
    case TimelineEvent::Kind::Trajectory:
    case TimelineEvent::Kind::Gripper:
      goals.submit(e, t);  // a rejection is the goal's outcome, judged by the checks
      break;
  }
  if (!ok) throw ScenarioError("t=" + std::to_string(e.at) + " s: controller '" + e.controller + "' rejected the command: " + error);
}

// A robot's base motion through a run (RobotMotion): path length and net turn per tick, and at
// the end the odometry against the truth.
struct MotionTracker {
  const Simulation* sim = nullptr;
  physics::SpawnPose spawn;
  const control::StatePort<control::OdometrySnapshot>* odometry = nullptr;
  RobotMotion m;
  double last_x = 0.0, last_y = 0.0, last_yaw = 0.0;

  MotionTracker(Simulation& robot, const physics::SpawnPose& spawn_pose) : sim(&robot), spawn(spawn_pose) {
    m.name = robot.robot_name_in_world();
    for (const control::ControllerInfo& info : robot.controllers().list_controllers()) {
      if (auto* p = find_port<control::StatePort<control::OdometrySnapshot>>(robot.controllers().controller(info.name),
                                                                           control::PortKind::Odometry)) {
        odometry = p;
      }
    }
    m.has_odometry = odometry != nullptr;
    const description::Pose X = robot.base_pose();
    last_x = X.position.x;
    last_y = X.position.y;
    last_yaw = yaw_of(X.orientation);
  }
  void update(const description::Pose& after) {
    m.distance += std::hypot(after.position.x - last_x, after.position.y - last_y);
    last_x = after.position.x;
    last_y = after.position.y;
    const double yaw_after = yaw_of(after.orientation);
    m.yaw_change += wrap_angle(yaw_after - last_yaw);
    last_yaw = yaw_after;
  }
  const RobotMotion& finish() {
    const description::Pose X_WB = sim->base_pose();
    m.final_x = X_WB.position.x;
    m.final_y = X_WB.position.y;
    m.final_z = X_WB.position.z;
    m.final_yaw = yaw_of(X_WB.orientation);
    if (odometry != nullptr) {
      // Wheel odometry starts at the spawn pose's origin and heading: compare in the spawn frame.
      // A Gazebo plugin's "world" odometry is the world pose itself.
      const control::OdometrySnapshot odom = odometry->read();
      const double c = std::cos(spawn.yaw), sn = std::sin(spawn.yaw);
      const double ox = odom.in_world ? odom.x : spawn.x + c * odom.x - sn * odom.y;
      const double oy = odom.in_world ? odom.y : spawn.y + sn * odom.x + c * odom.y;
      m.odometry_error = std::hypot(ox - m.final_x, oy - m.final_y);
      const double odom_turn = odom.in_world ? wrap_angle(odom.yaw - spawn.yaw) : odom.yaw;
      m.odometry_yaw_error = std::abs(wrap_angle(odom_turn - m.yaw_change));
    }
    return m;
  }
};

control::PortKind port_kind_for(TimelineEvent::Kind kind) {
  switch (kind) {
    case TimelineEvent::Kind::Scalar: return control::PortKind::ScalarCommand;
    case TimelineEvent::Kind::Array: return control::PortKind::ArrayCommand;
    case TimelineEvent::Kind::Twist:
    case TimelineEvent::Kind::Route: return control::PortKind::TwistCommand;
    case TimelineEvent::Kind::Mode: return control::PortKind::DriveModeCommand;
    case TimelineEvent::Kind::Trajectory: return control::PortKind::TrajectoryGoal;
    case TimelineEvent::Kind::Gripper: return control::PortKind::GripperGoal;
  }
  return control::PortKind::ScalarCommand;
}

}  // namespace

ScenarioResult run_scenario(const Scenario& s, const RunOptions& options) {
  prepare_report_folder(s, options.output_dir);
  std::string urdf;
  std::unique_ptr<Simulation> sim = build_simulation(s, urdf);
  ScenarioResult result;

  ScenarioGoals goals(s, sim->controllers());  // binds (and checks) the trajectory and gripper events
  std::vector<BoundEvent> events;
  for (const TimelineEvent& e : s.timeline) {
    Simulation& robot = e.robot.empty() ? *sim : *sim->find_other(e.robot);  // names checked when read
    control::Controller* c = robot.controllers().controller(e.controller);
    if (c == nullptr)
      throw ScenarioError(s.file + ": timeline at t=" + std::to_string(e.at) + " s: no controller '" + e.controller +
                          "' is loaded" + (e.robot.empty() ? "" : " on robot '" + e.robot + "'"));
    bool has_port = false;
    for (control::Port* p : c->ports()) has_port = has_port || p->kind() == port_kind_for(e.kind);
    if (!has_port) {
      throw ScenarioError(s.file + ": timeline at t=" + std::to_string(e.at) + " s: controller '" + e.controller +
                          "' has no input for this kind of command");
    }
    events.push_back({&e, c});
  }

  Recorder recorder(*sim, options.output_dir, goals.trajectory_controllers());
  SensorReport sensor_report(*sim, s, options.output_dir);
  sim->add_observer([&](const Simulation& at) { sensor_report.observe(at); });
  WheelReport wheel_report(*sim, s, options.output_dir);
  sim->add_observer([&](const Simulation& at) { wheel_report.observe(at); });
  CameraReport camera_report(*sim, s, options.output_dir);
  sim->add_observer([&](const Simulation& at) { camera_report.observe(at); });
  sim->add_control_observer([&](const Simulation&) { camera_report.before_step(*sim); });
  MotionTracker first(*sim, s.spawn);
  std::vector<MotionTracker> others;
  for (std::size_t i = 0; i < sim->other_count(); ++i) others.emplace_back(sim->other(i), s.others[i].spawn);
  const control::StatePort<control::OdometrySnapshot>* odometry = first.odometry;
  result.has_odometry = odometry != nullptr;

  std::optional<RouteFollower> route;
  control::TwistCommandPort* route_port = nullptr;
  std::vector<HeldTwist> held;
  std::size_t next_event = 0;
  const std::uint64_t total_ticks = static_cast<std::uint64_t>(std::llround(s.duration / s.period));
  const std::uint64_t record_every = std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::llround(1.0 / (s.record_rate * s.period))));
  const std::uint64_t route_every = std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::llround(0.02 / s.period)));
  const std::uint64_t progress_every = std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::llround(0.5 / s.period)));
  // Rows are sampled inside the tick, after the controllers' update (every file's row t is the
  // state at t), every record period and at the run's last tick.
  sim->add_control_observer([&](const Simulation& at) {
    if (at.ticks() % record_every == 0 || at.ticks() + 1 == total_ticks) recorder.sample(odometry);
  });
  ReplayRecorder replay(*sim, s, options.output_dir, urdf);
  if (replay.active()) sim->add_control_observer([&](const Simulation& at) { replay.observe(at, total_ticks - 1); });

  std::vector<double> reach_best(s.checks.size(), 1e300);
  // Joint checks: the mechanism joint, and its position once sampled.
  std::vector<int> check_joint(s.checks.size(), -1);
  std::vector<std::optional<double>> joint_sample(s.checks.size());
  for (std::size_t k = 0; k < s.checks.size(); ++k) {
    const Check& c = s.checks[k];
    if (c.kind != Check::Kind::Joint) continue;
    check_joint[k] = sim->mechanism().joint_index(c.joint);
    if (check_joint[k] < 0) throw ScenarioError(s.file + ": checks: joint check: the robot's mechanism has no joint '" + c.joint + "'");
  }
  // Tracking checks: the controller's state port, and the largest |error| read so far.
  std::vector<const control::StatePort<control::JointControllerState>*> tracked(s.checks.size(), nullptr);
  std::vector<double> tracked_max(s.checks.size(), 0.0);
  std::vector<std::size_t> tracked_samples(s.checks.size(), 0);
  for (std::size_t k = 0; k < s.checks.size(); ++k) {
    const Check& c = s.checks[k];
    if (c.kind != Check::Kind::Tracking) continue;
    tracked[k] = find_port<control::StatePort<control::JointControllerState>>(sim->controllers().controller(c.controller),
                                                                            control::PortKind::JointControllerState);
    if (tracked[k] == nullptr) {
      throw ScenarioError(s.file + ": checks: tracking check: no loaded controller '" + c.controller +
                          "' with a joint controller state");
    }
  }
  auto joint_position = [&](std::size_t k) {
    return sim->mechanism_state().joints[static_cast<std::size_t>(check_joint[k])].position;
  };
  auto warn = [&](const std::string& text) {
    result.warnings.push_back(text);
    if (options.warning) options.warning(text);
  };
  // Leaving the usable ground is an event: the run stops (or goes on, as the scenario says).
  const TerrainWatch terrain(sim->world());
  bool off_terrain = false;
  auto watch_terrain = [&]() -> bool {  // true: stop the run
    if (!terrain.active()) return false;
    const physics::Bounds footprint = sim->physics().robot_bounds();
    const description::Vec3 where = sim->physics().base_pose().position;
    char at[48];
    std::snprintf(at, sizeof at, "t=%.3f s: ", sim->time());
    if (terrain.fallen(footprint)) {
      result.events.push_back({sim->time(), "fell_off_world", "the robot fell 10 m below the lowest ground", where.x, where.y});
      result.error = at + result.events.back().detail;
      return true;
    }
    const std::optional<std::string> outside = terrain.outside(footprint);
    if (!outside || off_terrain) {
      off_terrain = off_terrain && outside.has_value();
      return false;
    }
    off_terrain = true;
    result.events.push_back({sim->time(), "left_terrain", *outside, where.x, where.y});
    if (s.on_leaving == LeavingTerrain::Stop) {
      result.error = at + std::string("left the usable ground (world.on_leaving: stop): ") + *outside;
      return true;
    }
    warn(at + std::string("left the usable ground (world.on_leaving: continue): ") + *outside);
    return false;
  };
  if (terrain.active()) {
    if (const std::optional<std::string> outside = terrain.outside(sim->physics().robot_bounds())) {
      warn("at spawn, " + *outside + (s.on_leaving == LeavingTerrain::Stop ? " (world.on_leaving: stop ends the run at once)" : ""));
    }
  }
  const auto wall_start = std::chrono::steady_clock::now();
  auto rtf_now = [&] {
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    return wall > 0.0 ? sim->time() / wall : 0.0;
  };

  std::optional<TickTiming> timing;
  if (options.timing_window > 0.0) timing.emplace(options.timing_window, s.period);
  if (options.on_start) options.on_start(*sim);
  // Real-time pace (options.real_time_factor): simulation time pace_sim is due at wall time pace_wall.
  auto pace_wall = std::chrono::steady_clock::now();
  double pace_sim = sim->time();
  for (std::uint64_t tick = 0; tick < total_ticks; ++tick) {
    if (options.interrupt != nullptr) {
      if (const int signal = options.interrupt->load(std::memory_order_relaxed); signal != 0) {
        result.interrupted_by = signal;
        result.error = "interrupted by signal " + std::to_string(signal) + " at t=" + std::to_string(sim->time()) + " s";
        break;
      }
    }
    const double t = sim->time();
    while (next_event < events.size() && events[next_event].event->at <= t + 1e-9) {
      apply(events[next_event], route, route_port, held, goals, t);
      ++next_event;
    }
    const description::Pose X_WB = sim->physics().base_pose();
    const double yaw = yaw_of(X_WB.orientation);
    if (tick % route_every == 0) {
      if (route && route_port != nullptr) {
        route_port->write(route->update(X_WB.position.x, X_WB.position.y, yaw));
      } else {
        for (const HeldTwist& h : held) h.port->write(h.twist);
      }
    }

    if (options.real_time_factor > 0.0) {
      const auto due = pace_wall + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                       std::chrono::duration<double>((sim->time() - pace_sim) / options.real_time_factor));
      const auto now = std::chrono::steady_clock::now();
      if (now < due) {
        std::this_thread::sleep_until(due);
      } else if (now - due > std::chrono::duration<double>(kMaxPaceLag)) {
        pace_wall = now;
        pace_sim = sim->time();
      }
    }
    const auto tick_start = timing ? std::chrono::steady_clock::now() : std::chrono::steady_clock::time_point{};
    const TickResult r = sim->step();
    if (timing) timing->tick(std::chrono::duration<double>(std::chrono::steady_clock::now() - tick_start).count(), sim->time());
    if (!r) {
      result.error = r.error;
      break;
    }
    const description::Pose after = sim->physics().base_pose();
    first.update(after);
    for (MotionTracker& o : others) o.update(o.sim->base_pose());
    goals.poll(sim->time());
    if (watch_terrain()) break;
    result.max_tilt = std::max(result.max_tilt, tilt_of(after.orientation));
    for (std::size_t k = 0; k < s.checks.size(); ++k) {
      const Check& c = s.checks[k];
      if (c.kind == Check::Kind::Reach && sim->time() <= c.by + 1e-9) {
        reach_best[k] = std::min(reach_best[k], std::hypot(after.position.x - c.x, after.position.y - c.y));
      }
      if (c.kind == Check::Kind::Joint && c.at && !joint_sample[k] && sim->time() >= *c.at - 1e-9) joint_sample[k] = joint_position(k);
      if (c.kind == Check::Kind::Tracking && sim->time() >= c.at.value_or(0.0) - 1e-9 && tracked[k]->sequence() > 0) {
        tracked_max[k] = std::max(tracked_max[k], std::abs(tracked[k]->read().error));
        ++tracked_samples[k];
      }
    }
    if (options.progress && (tick + 1) % progress_every == 0) options.progress({sim->time(), s.duration, rtf_now()});
  }
  result.completed = result.error.empty();
  result.sim_time = sim->time();
  if (timing) {
    timing->finish(sim->time());
    result.timing = timing->windows();
  }
  result.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  result.real_time_factor = rtf_now();
  for (std::string& w : sim->physics_warnings()) result.warnings.push_back(std::move(w));
  const RobotMotion& motion = first.finish();
  result.distance = motion.distance;
  result.yaw_change = motion.yaw_change;
  result.final_x = motion.final_x;
  result.final_y = motion.final_y;
  result.final_z = motion.final_z;
  result.final_yaw = motion.final_yaw;
  result.odometry_error = motion.odometry_error;
  result.odometry_yaw_error = motion.odometry_yaw_error;
  for (MotionTracker& o : others) result.others.push_back(o.finish());
  // The robot a pose or odometry check names.
  const auto motion_of = [&](const Check& c) -> const RobotMotion& {
    for (const RobotMotion& o : result.others)
      if (o.name == c.robot) return o;
    return motion;
  };
  result.trajectory_goals = goals.trajectory_goals();
  result.gripper_goals = goals.gripper_goals();
  result.tracking = recorder.tracking();
  if (options.progress) options.progress({sim->time(), s.duration, result.real_time_factor});

  for (std::size_t k = 0; k < s.checks.size(); ++k) {
    const Check& c = s.checks[k];
    CheckOutcome out;
    char buf[512];
    switch (c.kind) {
      case Check::Kind::Reach:
        out.passed = reach_best[k] <= c.within;
        std::snprintf(buf, sizeof buf, "reach (%.2f, %.2f) within %.2f m by t=%.1f s: closest %.3f m", c.x, c.y, c.within, c.by, reach_best[k]);
        break;
      case Check::Kind::FinalPose: {
        const RobotMotion& m = motion_of(c);
        const double d = std::hypot(m.final_x - c.x, m.final_y - c.y);
        const double lateral = std::abs(m.final_y - c.y);
        out.passed = d <= c.within && (!c.lateral_within || lateral <= *c.lateral_within);
        std::snprintf(buf, sizeof buf, "final pose (%.3f, %.3f) within %.3f m of (%.2f, %.2f): off by %.3f m (lateral %.3f m)",
                      m.final_x, m.final_y, c.within, c.x, c.y, d, lateral);
        break;
      }
      case Check::Kind::FinalHeading: {
        const RobotMotion& m = motion_of(c);
        const double err = std::abs(wrap_angle(m.final_yaw - c.yaw));
        out.passed = err <= c.within_angle;
        std::snprintf(buf, sizeof buf, "final heading %.2f deg, wanted %.2f +- %.2f deg: off by %.2f deg", m.final_yaw * 180 / M_PI,
                      c.yaw * 180 / M_PI, c.within_angle * 180 / M_PI, err * 180 / M_PI);
        break;
      }
      case Check::Kind::Direction: {
        const double dx = result.final_x - s.spawn.x, dy = result.final_y - s.spawn.y;
        const double direction = std::atan2(dy, dx);
        const double err = std::abs(wrap_angle(direction - c.yaw));
        out.passed = std::hypot(dx, dy) > 1e-3 && err <= c.within_angle;
        std::snprintf(buf, sizeof buf, "direction of travel %.2f deg, wanted %.2f +- %.2f deg: off by %.2f deg", direction * 180 / M_PI,
                      c.yaw * 180 / M_PI, c.within_angle * 180 / M_PI, err * 180 / M_PI);
        break;
      }
      case Check::Kind::Upright:
        out.passed = result.max_tilt <= c.max_tilt;
        std::snprintf(buf, sizeof buf, "max tilt %.2f deg (limit %.2f deg)", result.max_tilt * 180 / M_PI, c.max_tilt * 180 / M_PI);
        break;
      case Check::Kind::Odometry: {
        const RobotMotion& m = motion_of(c);
        out.passed = m.has_odometry;
        std::string text;
        if (c.max_error_fraction) {
          const double fraction = m.distance > 1e-6 ? m.odometry_error / m.distance : 0.0;
          out.passed = out.passed && fraction <= *c.max_error_fraction;
          std::snprintf(buf, sizeof buf, "odometry error %.3f m over %.3f m = %.2f %% (limit %.2f %%)", m.odometry_error,
                        m.distance, 100 * fraction, 100 * *c.max_error_fraction);
          text += buf;
        }
        if (c.max_yaw_error_fraction) {
          const double turned = std::abs(m.yaw_change);
          const double fraction = turned > 1e-6 ? m.odometry_yaw_error / turned : 0.0;
          out.passed = out.passed && turned > 1e-6 && fraction <= *c.max_yaw_error_fraction;
          std::snprintf(buf, sizeof buf, "%sodometry yaw error %.3f deg over %.2f deg turned = %.2f %% (limit %.2f %%)",
                        text.empty() ? "" : "; ", m.odometry_yaw_error * 180 / M_PI, m.yaw_change * 180 / M_PI,
                        100 * fraction, 100 * *c.max_yaw_error_fraction);
          text += buf;
        }
        if (!m.has_odometry) text += " [no odometry]";
        std::snprintf(buf, sizeof buf, "%s", text.c_str());
        break;
      }
      case Check::Kind::Joint: {
        // Sampled after the first tick that ends at or after `at`: the state at that time.
        if (c.at && !joint_sample[k]) {  // a shortened run (--duration) or a divergence
          out.passed = false;
          std::snprintf(buf, sizeof buf, "joint %s at t=%.3f s: not sampled, the run ended at t=%.3f s", c.joint.c_str(), *c.at,
                        result.sim_time);
          break;
        }
        const double q = joint_sample[k] ? *joint_sample[k] : joint_position(k);
        out.passed = result.completed && std::abs(q - *c.position) <= c.within;
        std::snprintf(buf, sizeof buf, "joint %s at t=%.3f s: %.5f, wanted %.5f +- %.5f (off by %.5f)", c.joint.c_str(),
                      c.at ? *c.at : result.sim_time, q, *c.position, c.within, std::abs(q - *c.position));
        break;
      }
      case Check::Kind::Tracking:
        out.passed = result.completed && tracked_samples[k] > 0 && tracked_max[k] <= *c.max_abs_error;
        std::snprintf(buf, sizeof buf, "%s: largest |error| %.6f over %zu ticks from t=%.3f s, limit %.6f", c.controller.c_str(),
                      tracked_max[k], tracked_samples[k], c.at.value_or(0.0), *c.max_abs_error);
        break;
      case Check::Kind::Trajectory:
      case Check::Kind::Gripper:
        out = goals.judge(c);
        result.checks.push_back(out);
        continue;
      case Check::Kind::LaserRange:
      case Check::Kind::ImuTilt:
        result.checks.push_back(sensor_report.judge(c));
        continue;
      case Check::Kind::Slip:
        result.checks.push_back(wheel_report.judge(c));
        continue;
      case Check::Kind::Distance: {
        const RobotMotion& m = motion_of(c);
        out.passed = m.distance >= c.min_distance && m.distance <= c.max_distance;
        std::snprintf(buf, sizeof buf, "distance %.3f m in [%.3f, %.3g] m", m.distance, c.min_distance, c.max_distance);
        break;
      }
    }
    out.name = c.robot.empty() ? c.text : c.text + " (" + c.robot + ")";
    out.detail = c.robot.empty() ? std::string(buf) : c.robot + ": " + buf;
    result.checks.push_back(out);
  }
  if (options.output_dir.empty()) wheel_report.write(result, false);  // the figures only
  result.passed = result.completed && std::all_of(result.checks.begin(), result.checks.end(),
                                                  [](const CheckOutcome& c) { return c.passed; });
  if (!options.output_dir.empty()) {
    recorder.close();
    sensor_report.write(result, options.plots);  // before summary.json, which lists the files
    wheel_report.write(result, options.plots);
    camera_report.write(result);
    if (timing) {
      timing->write_csv((std::filesystem::path(options.output_dir) / "timing.csv").string());
      result.files.push_back("timing.csv");
    }
    if (replay.active()) result.files.push_back("replay/manifest.json");
    write_report(s, *sim, recorder, result, options);
    std::vector<std::string> sensor_files;
    for (std::size_t i = 0; i < sim->sensors().size(); ++i) sensor_files.push_back(sensor_report.csv_file(i));
    replay.finish(*sim, result.files, result.has_odometry, sensor_files);
  }
  return result;
}

}  // namespace mechsim::sim
