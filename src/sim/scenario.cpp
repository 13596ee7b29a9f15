#include "sim/scenario.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <initializer_list>
#include <numbers>
#include <set>
#include <string_view>

#include "control/params.hpp"
#include "control/ros2_params.hpp"
#include "sim/scenario_read.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;
using namespace scenario_read;

control::Twist read_twist(const Params& p) {
  only_keys(p, {"vx", "vy", "wz", "linear", "angular"});
  control::Twist t;
  t.linear.x = p.get<double>("vx", p.get<double>("linear/x", 0.0));
  t.linear.y = p.get<double>("vy", p.get<double>("linear/y", 0.0));
  t.angular.z = p.get<double>("wz", p.get<double>("angular/z", 0.0));
  return t;
}

std::vector<control::JointTolerance> read_tolerances(const Params& p) {
  std::vector<control::JointTolerance> out;
  if (!p.is_map()) fail(p, "expected a map of joint name (or 'all') -> {position, velocity, acceleration}");
  for (const std::string& joint : p.keys()) {
    const Params t = p.child(joint);
    only_keys(t, {"position", "velocity", "acceleration"});
    out.push_back({joint, finite(t, "position", 0.0), finite(t, "velocity", 0.0), finite(t, "acceleration", 0.0)});
  }
  return out;
}

control::FollowJointTrajectoryGoal read_trajectory(const Params& t) {
  only_keys(t, {"joints", "points", "goal_time_tolerance", "goal_tolerance", "path_tolerance"});
  control::FollowJointTrajectoryGoal goal;
  if (t.has("joints")) {
    goal.trajectory.joint_names = t.get<std::vector<std::string>>("joints");
    if (goal.trajectory.joint_names.empty()) fail(t.child("joints"), "must name at least one joint (or be left out)");
  }
  // Without `joints`, the first point's positions fix the count; the run checks it against
  // the controller.
  std::size_t n = goal.trajectory.joint_names.size();
  const Params points = t.child("points");
  if (!points.is_list() || points.size() == 0) fail(points, "expected a non-empty list of points");
  double last_time = -1.0;
  for (const Params& pt : points.items()) {
    only_keys(pt, {"time", "positions", "velocities", "accelerations"});
    control::TrajectoryPoint point;
    point.time_from_start = pt.get<double>("time");
    if (!std::isfinite(point.time_from_start) || point.time_from_start < 0.0) fail(pt.child("time"), "must be >= 0 s");
    if (point.time_from_start <= last_time) fail(pt.child("time"), "point times must increase");
    last_time = point.time_from_start;
    point.positions = values_of(pt, "positions", n);
    if (n == 0) n = point.positions.size();
    if (n == 0) fail(pt.child("positions"), "needs one value per joint");
    if (pt.has("velocities")) point.velocities = values_of(pt, "velocities", n);
    if (pt.has("accelerations")) {
      if (!pt.has("velocities")) fail(pt.child("accelerations"), "accelerations need velocities too");
      point.accelerations = values_of(pt, "accelerations", n);
    }
    goal.trajectory.points.push_back(std::move(point));
  }
  goal.goal_time_tolerance = finite(t, "goal_time_tolerance", 0.0);
  if (t.has("goal_tolerance")) goal.goal_tolerance = read_tolerances(t.child("goal_tolerance"));
  if (t.has("path_tolerance")) goal.path_tolerance = read_tolerances(t.child("path_tolerance"));
  return goal;
}

control::GripperCommand read_gripper(const Params& g) {
  only_keys(g, {"position", "max_effort"});
  control::GripperCommand c;
  c.position = g.get<double>("position");
  if (!std::isfinite(c.position) || c.position < 0.0) fail(g.child("position"), "must be a gap >= 0 m");
  c.max_effort = finite(g, "max_effort", -1.0);
  return c;
}

TimelineEvent read_event(const Params& e) {
  TimelineEvent ev;
  ev.location = e.location().empty() ? e.path() : e.location();
  only_keys(e, {"at", "robot", "controller", "command", "twist", "mode", "route", "trajectory", "gripper"});
  ev.at = e.get<double>("at");
  ev.robot = e.get<std::string>("robot", "");
  if (!(ev.at >= 0.0)) fail(e.child("at"), "must be >= 0 s");
  ev.controller = e.get<std::string>("controller");
  int kinds = 0;
  if (e.has("command")) {
    ++kinds;
    const Params c = e.child("command");
    if (c.is_list()) {
      ev.kind = TimelineEvent::Kind::Array;
      ev.array = c.as<std::vector<double>>();
    } else {
      ev.kind = TimelineEvent::Kind::Scalar;
      ev.scalar = c.as<double>();
    }
  }
  if (e.has("twist")) {
    ++kinds;
    ev.kind = TimelineEvent::Kind::Twist;
    ev.twist = read_twist(e.child("twist"));
  }
  if (e.has("mode")) {
    ++kinds;
    ev.kind = TimelineEvent::Kind::Mode;
    ev.mode = e.get<std::string>("mode");
  }
  if (e.has("route")) {
    ++kinds;
    ev.kind = TimelineEvent::Kind::Route;
    const Params r = e.child("route");
    only_keys(r, {"waypoints", "speed", "tolerance", "lookahead", "max_yaw_rate"});
    for (const Params& w : r.child("waypoints").items()) {
      const auto xy = w.as<std::vector<double>>();
      if (xy.size() != 2) fail(w, "a waypoint is [x, y]");
      ev.route.waypoints.push_back({xy[0], xy[1]});
    }
    if (ev.route.waypoints.empty()) fail(r.child("waypoints"), "a route needs at least one waypoint");
    ev.route.speed = r.get<double>("speed", ev.route.speed);
    ev.route.tolerance = r.get<double>("tolerance", ev.route.tolerance);
    ev.route.lookahead = r.get<double>("lookahead", ev.route.lookahead);
    ev.route.max_yaw_rate = r.get<double>("max_yaw_rate", ev.route.max_yaw_rate);
    if (!(ev.route.speed > 0.0)) fail(r, "speed must be > 0 m/s");
  }
  if (e.has("trajectory")) {
    ++kinds;
    ev.kind = TimelineEvent::Kind::Trajectory;
    ev.trajectory = read_trajectory(e.child("trajectory"));
  }
  if (e.has("gripper")) {
    ++kinds;
    ev.kind = TimelineEvent::Kind::Gripper;
    ev.gripper = read_gripper(e.child("gripper"));
  }
  if (kinds != 1) fail(e, "an event has exactly one of command, twist, mode, route, trajectory, gripper");
  return ev;
}

// controllers.params: every leaf (scalar or list) must name a parameter of the controllers file.
void read_controller_params(const Params& overlay, const Params& file_params, const std::string& key,
                            std::vector<ControllerParam>& out) {
  if (!overlay.is_map()) fail(overlay, "expected a map of controller name -> parameters");
  for (const std::string& k : overlay.keys()) {
    const Params value = overlay.child(k);
    const std::string path = key.empty() ? k : key + "/" + k;
    const std::optional<Params> target = file_params.find(path);
    if (!target) {
      fail(value, "the controllers file has no parameter " + control::join_param_path(file_params.path(), path) +
                      " (write it there to override it)");
    }
    if (value.is_map() && target->is_map()) {
      read_controller_params(value, file_params, path, out);
    } else if (value.is_map()) {
      fail(value, "is a map, but " + target->path() + " in the controllers file is not");
    } else {
      out.push_back({path, value});
    }
  }
}

}  // namespace

Scenario load_scenario(const std::string& path) {
  if (!fs::exists(path)) throw ScenarioError(path + ": no such scenario file");
  Params root;
  try {
    root = Params::from_yaml_file(path);
  } catch (const std::exception& e) {
    throw ScenarioError(e.what());
  }
  return load_scenario(root, path);
}

Scenario load_scenario(const Params& root, const std::string& path) {
  const fs::path base = fs::absolute(path).parent_path();
  Scenario s;
  s.file = path;
  try {
    s.name = root.get<std::string>("name", fs::path(path).stem().string());
    const Params robot = root.child("robot");
    s.description = resolve_path(base, robot.get<std::string>("description"));
    if (!fs::exists(s.description)) fail(robot.child("description"), "no such file: " + s.description);
    if (auto args = robot.find("args")) {
      for (const std::string& k : args->keys()) s.xacro_args[k] = scalar_text(args->child(k));
    }
    if (auto packages = robot.find("packages")) {
      for (const std::string& k : packages->keys()) s.packages[k] = resolve_path(base, packages->get<std::string>(k));
    }
    s.lenient = robot.get<bool>("lenient", false);
    const std::string differential = robot.get<std::string>("differential", "mimic");
    if (differential == "mimic") {
      s.differential = physics::DifferentialMode::MimicConstraint;
    } else if (differential == "plugin") {
      s.differential = physics::DifferentialMode::PluginLaw;
    } else {
      fail(robot.child("differential"), "expected 'mimic' or 'plugin', got '" + differential + "'");
    }

    s.seed = static_cast<std::uint64_t>(root.get<int>("seed", 1));
    if (auto world = root.find("world")) {
      s.world = read_world_config(*world, base);
      if (auto boxes = world->find("boxes")) s.boxes = read_boxes(*boxes, base);
      const std::string leaving = world->get<std::string>("on_leaving", "stop");
      if (leaving == "stop") {
        s.on_leaving = LeavingTerrain::Stop;
      } else if (leaving == "continue") {
        s.on_leaving = LeavingTerrain::Continue;
      } else {
        fail(world->child("on_leaving"), "expected 'stop' or 'continue', got '" + leaving + "'");
      }
    }
    if (auto spawn = root.find("spawn")) {
      s.spawn.x = spawn->get<double>("x", 0.0);
      s.spawn.y = spawn->get<double>("y", 0.0);
      s.spawn.z = spawn->get<double>("z", 0.0);
      s.spawn.roll = spawn->get<double>("roll", 0.0);
      s.spawn.pitch = spawn->get<double>("pitch", 0.0);
      s.spawn.yaw = spawn->get<double>("yaw", 0.0);
      s.settle_on_ground = !spawn->has("roll") && !spawn->has("pitch");
      if (auto joints = spawn->find("joints")) {
        if (!joints->is_map()) fail(*joints, "expected a map of joint name -> position (rad or m)");
        for (const std::string& j : joints->keys()) s.initial_joints[j] = finite(*joints, j, 0.0);
      }
    }
    // A robot driven by its Gazebo model plugins alone needs no controllers.
    if (auto controllers = root.find("controllers")) {
      if (controllers->has("file")) {
        s.controllers_file = resolve_path(base, controllers->get<std::string>("file"));
        if (!fs::exists(s.controllers_file)) fail(controllers->child("file"), "no such file: " + s.controllers_file);
      }
      if (auto files = controllers->find("files")) {
        for (const Params& f : files->items()) {
          const std::string file_path = resolve_path(base, f.as<std::string>());
          if (!fs::exists(file_path)) fail(f, "no such file: " + file_path);
          s.controllers_files.push_back(file_path);
        }
      }
      // ROS 2 parameter files (ros__parameters), or none: the description's ros2_control plugin's.
      std::vector<std::string> all_files = s.controllers_files;
      if (!s.controllers_file.empty()) all_files.insert(all_files.begin(), s.controllers_file);
      std::size_t ros2 = 0;
      for (const std::string& f : all_files) ros2 += control::is_ros2_parameter_file(f) ? 1 : 0;
      if (ros2 != 0 && ros2 != all_files.size()) {
        fail(*controllers, "mixes ROS 2 parameter files (ros__parameters) with ROS 1 controller files");
      }
      if (!s.controllers_files.empty() && ros2 == 0) {
        fail(controllers->child("files"), "`files` is for ROS 2 parameter files (ros__parameters); give a ROS 1 file as `file`");
      }
      s.ros2_control = all_files.empty() || ros2 != 0;
      s.controllers_namespace = controllers->get<std::string>("namespace", "");
      s.start = controllers->get<std::vector<std::string>>("start", {});
      if (auto overlay = controllers->find("params")) {
        Params file_params;
        try {
          if (s.ros2_control) {
            if (all_files.empty()) fail(*overlay, "needs controllers.file or files (the parameters it lays values over)");
            const std::string cm = (s.controllers_namespace.empty() || s.controllers_namespace == "/"
                                        ? std::string()
                                        : (s.controllers_namespace.front() == '/' ? "" : "/") + s.controllers_namespace) +
                                   "/controller_manager";
            file_params = control::ros2_control_setup(control::Ros2ParameterSet::from_files(all_files), cm).controllers;
          } else {
            file_params = Params::from_yaml_file(s.controllers_file);
            if (!s.controllers_namespace.empty()) file_params = file_params.child(s.controllers_namespace);
          }
        } catch (const ScenarioError&) {
          throw;
        } catch (const std::exception& e) {
          fail(*overlay, std::string("cannot read the controllers file: ") + e.what());
        }
        read_controller_params(*overlay, file_params, "", s.controller_params);
      }
    }

    if (auto others = root.find("others")) {
      if (!others->is_list()) fail(*others, "expected a list of robots ({name, spawn, robot, controllers})");
      std::set<std::string> names;
      for (const Params& o : others->items()) {
        only_keys(o, {"name", "spawn", "robot", "controllers"});
        OtherRobotConfig c;
        c.location = o.location().empty() ? o.path() : o.location();
        c.name = o.get<std::string>("name");
        if (c.name.empty() || c.name.find("::") != std::string::npos || c.name.find('/') != std::string::npos)
          fail(o.child("name"), "a robot's name is its namespace: non-empty, without '::' or '/'");
        if (!names.insert(c.name).second) fail(o.child("name"), "robot '" + c.name + "' is named twice");
        c.description = s.description;
        c.xacro_args = s.xacro_args;
        c.packages = s.packages;
        c.lenient = s.lenient;
        if (auto own = o.find("robot")) {
          only_keys(*own, {"description", "args", "packages", "lenient"});
          if (own->has("description")) {
            c.description = resolve_path(base, own->get<std::string>("description"));
            if (!fs::exists(c.description)) fail(own->child("description"), "no such file: " + c.description);
            c.xacro_args.clear();
          }
          if (auto args = own->find("args"))
            for (const std::string& k : args->keys()) c.xacro_args[k] = scalar_text(args->child(k));
          if (auto packages = own->find("packages"))
            for (const std::string& k : packages->keys()) c.packages[k] = resolve_path(base, packages->get<std::string>(k));
          c.lenient = own->get<bool>("lenient", c.lenient);
        }
        if (auto spawn = o.find("spawn")) {
          only_keys(*spawn, {"x", "y", "z", "roll", "pitch", "yaw", "joints"});
          c.spawn.x = finite(*spawn, "x", 0.0);
          c.spawn.y = finite(*spawn, "y", 0.0);
          c.spawn.z = finite(*spawn, "z", 0.0);
          c.spawn.roll = finite(*spawn, "roll", 0.0);
          c.spawn.pitch = finite(*spawn, "pitch", 0.0);
          c.spawn.yaw = finite(*spawn, "yaw", 0.0);
          if (auto joints = spawn->find("joints")) {
            if (!joints->is_map()) fail(*joints, "expected a map of joint name -> position (rad or m)");
            for (const std::string& j : joints->keys()) c.initial_joints[j] = finite(*joints, j, 0.0);
          }
        }
        c.controllers_file = s.controllers_file;
        c.controllers_namespace = s.controllers_namespace;
        c.start = s.start;
        c.controllers_files = s.controllers_files;
        c.ros2_control = s.ros2_control;
        if (auto controllers = o.find("controllers")) {
          only_keys(*controllers, {"file", "files", "namespace", "start"});
          if (controllers->has("file")) {
            c.controllers_file = resolve_path(base, controllers->get<std::string>("file"));
            if (!fs::exists(c.controllers_file)) fail(controllers->child("file"), "no such file: " + c.controllers_file);
            c.controllers_files.clear();
          }
          if (auto files = controllers->find("files")) {
            c.controllers_files.clear();
            for (const Params& f : files->items()) {
              const std::string file_path = resolve_path(base, f.as<std::string>());
              if (!fs::exists(file_path)) fail(f, "no such file: " + file_path);
              c.controllers_files.push_back(file_path);
            }
          }
          if (controllers->has("file") || controllers->has("files")) {
            c.ros2_control = !c.controllers_files.empty() ||
                             (!c.controllers_file.empty() && control::is_ros2_parameter_file(c.controllers_file));
          }
          c.controllers_namespace = controllers->get<std::string>("namespace", c.controllers_namespace);
          c.start = controllers->get<std::vector<std::string>>("start", c.start);
        }
        s.others.push_back(std::move(c));
      }
    }

    s.duration = root.get<double>("duration");
    if (!(s.duration > 0.0) || s.duration > 1e6) fail(root.child("duration"), "must be in (0, 1e6] s");
    s.period = root.get<double>("period", 0.001);
    if (!(s.period > 0.0) || s.period > 0.1) fail(root.child("period"), "must be in (0, 0.1] s");
    if (root.has("integrator")) {
      const std::string integrator = root.get<std::string>("integrator");
      const auto parsed = physics::parse_integrator(integrator);
      if (!parsed) fail(root.child("integrator"), "expected 'implicit', 'euler' or 'rk4', got '" + integrator + "'");
      s.integrator = *parsed;
    }
    s.record_rate = root.get<double>("record_rate", 50.0);
    if (!(s.record_rate > 0.0)) fail(root.child("record_rate"), "must be > 0 Hz");
    s.replay_rate = root.get<double>("replay_rate", 30.0);
    if (!(s.replay_rate >= 0.0) || s.replay_rate > 1e4) fail(root.child("replay_rate"), "must be in [0, 1e4] Hz (0: no replay)");

    if (auto timeline = root.find("timeline")) {
      for (const Params& e : timeline->items()) s.timeline.push_back(read_event(e));
    }
    std::stable_sort(s.timeline.begin(), s.timeline.end(),
                     [](const TimelineEvent& a, const TimelineEvent& b) { return a.at < b.at; });
    if (auto checks = root.find("checks")) {
      for (const Params& c : checks->items()) s.checks.push_back(read_check(c));
    }
    const auto known_robot = [&](const std::string& name) {
      return name.empty() || std::any_of(s.others.begin(), s.others.end(), [&](const OtherRobotConfig& o) { return o.name == name; });
    };
    for (const TimelineEvent& e : s.timeline) {
      if (!known_robot(e.robot))
        throw ScenarioError(e.location + ": timeline: robot '" + e.robot + "' is none of the scenario's others");
      if (!e.robot.empty() && (e.kind == TimelineEvent::Kind::Trajectory || e.kind == TimelineEvent::Kind::Gripper))
        throw ScenarioError(e.location + ": timeline: trajectory and gripper goals go to the first robot only (robot '" +
                            e.robot + "')");
    }
    if (auto checks = root.find("checks")) {
      std::size_t k = 0;
      for (const Params& c : checks->items()) {
        if (!known_robot(s.checks[k].robot)) fail(c, "robot '" + s.checks[k].robot + "' is none of the scenario's others");
        ++k;
      }
    }
    if (auto sensors = root.find("sensors")) {
      if (!sensors->is_list()) fail(*sensors, "expected a list of Gazebo <gazebo reference=\"LINK\"> blocks (XML text)");
      for (const Params& block : sensors->items()) {
        if (!block.is_scalar()) fail(block, "expected XML text (a YAML block: '- |' then the <gazebo> elements)");
        SensorBlock b;
        b.xml = block.as<std::string>();
        // A block scalar's node starts at its '|' line; the text on the next.
        const std::string at = block.location();
        b.file = path;
        b.line = at.empty() ? 0 : std::atoi(at.substr(at.rfind(':') + 1).c_str()) + 1;
        s.sensor_blocks.push_back(std::move(b));
      }
    }
    if (root.has("laser_picture_times")) {
      s.laser_picture_times = root.get<std::vector<double>>("laser_picture_times");
      for (const double t : s.laser_picture_times)
        if (!(t >= 0.0) || !std::isfinite(t)) fail(root.child("laser_picture_times"), "times must be >= 0 s");
    }
    if (auto overrides = root.find("camera_overrides")) {
      if (!overrides->is_map()) fail(*overrides, "expected a map: camera sensor name (or all) -> {rate, width, height}");
      for (const std::string& name : overrides->keys()) {
        const Params o = overrides->child(name);
        only_keys(o, {"rate", "width", "height"});
        description::CameraOverride c;
        c.origin = o.location().empty() ? o.path() : o.location();
        if (o.has("rate")) c.rate = o.get<double>("rate");
        if (o.has("width")) c.width = o.get<int>("width");
        if (o.has("height")) c.height = o.get<int>("height");
        if (!c.rate && !c.width && !c.height) fail(o, "an override sets rate, width or height");
        s.camera_overrides[name] = c;
      }
    }
    if (auto steady = root.find("steady_states")) {
      only_keys(*steady, {"wheel", "windows"});
      SteadyStateSpec spec;
      spec.wheel = steady->get<std::string>("wheel", "");
      const Params windows = steady->child("windows");
      if (!windows.is_list() || windows.size() == 0) fail(windows, "expected a list of [from, to] windows (s)");
      for (const Params& w : windows.items()) {
        const std::vector<double> v = w.as<std::vector<double>>();
        if (v.size() != 2 || !(v[0] >= 0.0) || !(v[1] > v[0]) || !std::isfinite(v[1]))
          fail(w, "a window is [from, to] with 0 <= from < to (s)");
        spec.windows.push_back({v[0], v[1]});
      }
      s.steady_states = std::move(spec);
    }
    if (root.has("camera_picture_times")) {
      s.camera_picture_times = root.get<std::vector<double>>("camera_picture_times");
      for (const double t : s.camera_picture_times)
        if (!(t >= 0.0) || !std::isfinite(t) || t > s.duration)
          fail(root.child("camera_picture_times"), "times must be within the run (0 to duration s)");
    }
  } catch (const ScenarioError&) {
    throw;
  } catch (const std::exception& e) {
    throw ScenarioError(e.what());
  }
  return s;
}

}  // namespace mechsim::sim
