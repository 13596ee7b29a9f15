#include "sim/scenario.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <initializer_list>
#include <numbers>
#include <string_view>

#include "control/params.hpp"
#include "sim/soil_config.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;
using control::Params;

constexpr double kDeg = std::numbers::pi / 180.0;

[[noreturn]] void fail(const Params& at, const std::string& what) {
  const std::string where = at.location().empty() ? at.path() : at.location() + ": " + at.path();
  throw ScenarioError(where + ": " + what);
}

// A scalar's text whatever its YAML type (xacro arguments are strings on the command line).
std::string scalar_text(const Params& p) {
  try {
    return p.as<std::string>();
  } catch (const std::exception&) {
  }
  try {
    const double v = p.as<double>();
    std::string s = std::to_string(v);
    s.erase(s.find_last_not_of('0') + 1);
    if (!s.empty() && s.back() == '.') s.pop_back();
    return s;
  } catch (const std::exception&) {
  }
  try {
    return p.as<bool>() ? "true" : "false";
  } catch (const std::exception&) {
  }
  fail(p, "expected a scalar value");
}

// Rejects keys outside `allowed` (a misspelt bound must not be ignored).
void only_keys(const Params& p, std::initializer_list<const char*> allowed) {
  if (!p.is_map()) fail(p, "expected a map");
  for (const std::string& k : p.keys()) {
    bool ok = false;
    std::string list;
    for (const char* a : allowed) {
      ok = ok || k == a;
      list += (list.empty() ? "" : ", ") + std::string(a);
    }
    if (!ok) fail(p.child(k), "unknown key '" + k + "' (expected one of: " + list + ")");
  }
}

std::string resolve_path(const fs::path& base, const std::string& file) {
  const fs::path p(file);
  return (p.is_absolute() ? p : (base / p)).lexically_normal().string();
}

control::Twist read_twist(const Params& p) {
  only_keys(p, {"vx", "vy", "wz", "linear", "angular"});
  control::Twist t;
  t.linear.x = p.get<double>("vx", p.get<double>("linear/x", 0.0));
  t.linear.y = p.get<double>("vy", p.get<double>("linear/y", 0.0));
  t.angular.z = p.get<double>("wz", p.get<double>("angular/z", 0.0));
  return t;
}

double finite(const Params& p, std::string_view key, double fallback) {
  if (!p.has(key)) return fallback;
  const double v = p.get<double>(key);
  if (!std::isfinite(v)) fail(p.child(key), "must be finite");
  return v;
}

std::vector<double> values_of(const Params& point, const char* key, std::size_t expected) {
  const Params v = point.child(key);
  const auto values = v.as<std::vector<double>>();
  if (expected != 0 && values.size() != expected) {
    fail(v, "has " + std::to_string(values.size()) + " values, expected " + std::to_string(expected) + " (one per joint)");
  }
  for (double x : values) {
    if (!std::isfinite(x)) fail(v, "values must be finite");
  }
  return values;
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
  only_keys(e, {"at", "controller", "command", "twist", "mode", "route", "trajectory", "gripper"});
  ev.at = e.get<double>("at");
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

Check read_check(const Params& c) {
  Check check;
  const std::vector<std::string> keys = c.keys();
  if (keys.size() != 1) {
    fail(c, "a check is a map with one key (reach, final_pose, final_heading, direction, upright, odometry, distance, trajectory, gripper, joint, tracking, laser_range, imu_tilt)");
  }
  const std::string& kind = keys.front();
  const Params p = c.child(kind);
  check.text = kind;
  if (kind == "reach") {
    check.kind = Check::Kind::Reach;
    only_keys(p, {"x", "y", "within", "by"});
    check.x = p.get<double>("x");
    check.y = p.get<double>("y");
    check.within = p.get<double>("within");
    check.by = p.get<double>("by");
  } else if (kind == "final_pose") {
    check.kind = Check::Kind::FinalPose;
    only_keys(p, {"x", "y", "within", "lateral_within"});
    check.x = p.get<double>("x");
    check.y = p.get<double>("y");
    check.within = p.get<double>("within");
    if (p.has("lateral_within")) check.lateral_within = p.get<double>("lateral_within");
  } else if (kind == "final_heading") {
    check.kind = Check::Kind::FinalHeading;
    only_keys(p, {"yaw_deg", "within_deg"});
    check.yaw = p.get<double>("yaw_deg") * kDeg;
    check.within_angle = p.get<double>("within_deg") * kDeg;
  } else if (kind == "direction") {
    check.kind = Check::Kind::Direction;
    only_keys(p, {"deg", "within_deg"});
    check.yaw = p.get<double>("deg") * kDeg;
    check.within_angle = p.get<double>("within_deg") * kDeg;
  } else if (kind == "upright") {
    check.kind = Check::Kind::Upright;
    only_keys(p, {"max_tilt_deg"});
    check.max_tilt = p.get<double>("max_tilt_deg") * kDeg;
  } else if (kind == "odometry") {
    check.kind = Check::Kind::Odometry;
    only_keys(p, {"max_error_fraction", "max_yaw_error_fraction"});
    if (p.has("max_error_fraction")) check.max_error_fraction = p.get<double>("max_error_fraction");
    if (p.has("max_yaw_error_fraction")) check.max_yaw_error_fraction = p.get<double>("max_yaw_error_fraction");
    if (!check.max_error_fraction && !check.max_yaw_error_fraction) fail(p, "needs max_error_fraction and/or max_yaw_error_fraction");
  } else if (kind == "distance") {
    check.kind = Check::Kind::Distance;
    only_keys(p, {"min", "max"});
    check.min_distance = p.get<double>("min", 0.0);
    check.max_distance = p.get<double>("max", 1e300);
  } else if (kind == "trajectory" || kind == "gripper") {
    const bool trajectory = kind == "trajectory";
    check.kind = trajectory ? Check::Kind::Trajectory : Check::Kind::Gripper;
    if (trajectory) {
      only_keys(p, {"controller", "goal", "max_rms_error", "max_error", "result"});
    } else {
      only_keys(p, {"controller", "goal", "reached", "stalled", "by", "position", "within", "effort", "effort_within"});
    }
    check.controller = p.get<std::string>("controller");
    if (p.has("goal")) {
      const int goal = p.get<int>("goal");
      if (goal < 1) fail(p.child("goal"), "is the 1-based index of the controller's goal in the timeline");
      check.goal = static_cast<std::size_t>(goal);
    }
    auto positive = [&](const char* key) {
      const double v = p.get<double>(key);
      if (!(v >= 0.0) || !std::isfinite(v)) fail(p.child(key), "must be >= 0");
      return v;
    };
    if (trajectory) {
      if (p.has("max_rms_error")) check.max_rms_error = positive("max_rms_error");
      if (p.has("max_error")) check.max_abs_error = positive("max_error");
      if (p.has("result")) {
        const std::string r = p.get<std::string>("result");
        using Code = control::TrajectoryResultCode;
        for (Code code : {Code::Successful, Code::InvalidGoal, Code::InvalidJoints, Code::OldHeaderTimestamp,
                          Code::PathToleranceViolated, Code::GoalToleranceViolated}) {
          if (r == control::result_code_name(code)) check.result = code;
        }
        if (!check.result) {
          fail(p.child("result"), "unknown result code '" + r +
                                      "' (SUCCESSFUL, INVALID_GOAL, INVALID_JOINTS, OLD_HEADER_TIMESTAMP, "
                                      "PATH_TOLERANCE_VIOLATED, GOAL_TOLERANCE_VIOLATED)");
        }
      }
      if (!check.max_rms_error && !check.max_abs_error && !check.result) fail(p, "needs max_rms_error, max_error and/or result");
    } else {
      if (p.has("reached")) check.reached = p.get<bool>("reached");
      if (p.has("stalled")) check.stalled = p.get<bool>("stalled");
      if (p.has("by")) check.finished_by = positive("by");
      if (p.has("position")) {
        check.position = p.get<double>("position");
        check.within = positive("within");
      } else if (p.has("within")) {
        fail(p.child("within"), "goes with position");
      }
      if (p.has("effort")) {
        check.effort = p.get<double>("effort");
        check.effort_within = positive("effort_within");
      } else if (p.has("effort_within")) {
        fail(p.child("effort_within"), "goes with effort");
      }
      if (!check.reached && !check.stalled && !check.finished_by && !check.position && !check.effort) {
        fail(p, "needs reached, stalled, by, position and/or effort");
      }
    }
  } else if (kind == "joint") {
    check.kind = Check::Kind::Joint;
    only_keys(p, {"name", "at", "position", "within"});
    check.joint = p.get<std::string>("name");
    if (p.has("at")) {
      check.at = p.get<double>("at");
      if (!(*check.at >= 0.0) || !std::isfinite(*check.at)) fail(p.child("at"), "must be >= 0 s");
    }
    check.position = finite(p, "position", 0.0);
    if (!p.has("position")) fail(p, "needs position (and within)");
    check.within = p.get<double>("within");
    if (!(check.within >= 0.0)) fail(p.child("within"), "must be >= 0");
  } else if (kind == "tracking") {
    check.kind = Check::Kind::Tracking;
    only_keys(p, {"controller", "max_error", "after"});
    check.controller = p.get<std::string>("controller");
    check.max_abs_error = p.get<double>("max_error");
    if (!(*check.max_abs_error >= 0.0) || !std::isfinite(*check.max_abs_error)) fail(p.child("max_error"), "must be >= 0");
    if (p.has("after")) {
      check.at = p.get<double>("after");
      if (!(*check.at >= 0.0) || !std::isfinite(*check.at)) fail(p.child("after"), "must be >= 0 s");
    }
  } else if (kind == "laser_range" || kind == "imu_tilt") {
    const bool laser = kind == "laser_range";
    check.kind = laser ? Check::Kind::LaserRange : Check::Kind::ImuTilt;
    if (laser) only_keys(p, {"sensor", "angle_deg", "range", "within", "at"});
    else only_keys(p, {"sensor", "tilt_deg", "within_deg", "at"});
    check.sensor = p.get<std::string>("sensor");
    if (p.has("at")) {
      check.at = p.get<double>("at");
      if (!(*check.at >= 0.0) || !std::isfinite(*check.at)) fail(p.child("at"), "must be >= 0 s");
    }
    if (laser) {
      check.angle = finite(p, "angle_deg", 0.0) * kDeg;
      const std::string range = scalar_text(p.child("range"));
      check.range = range == "inf" ? HUGE_VAL : p.get<double>("range");
      if (!(check.range > 0.0)) fail(p.child("range"), "must be > 0 m, or inf");
      check.within = p.get<double>("within");
      if (!(check.within >= 0.0)) fail(p.child("within"), "must be >= 0 m");
    } else {
      check.tilt = p.get<double>("tilt_deg") * kDeg;
      check.within_angle = p.get<double>("within_deg") * kDeg;
      if (!(check.within_angle >= 0.0)) fail(p.child("within_deg"), "must be >= 0 deg");
    }
  } else if (kind == "slip") {
    check.kind = Check::Kind::Slip;
    only_keys(p, {"wheel", "from", "to", "min_mean", "max_mean"});
    check.wheel = p.get<std::string>("wheel", "");
    check.from = finite(p, "from", 0.0);
    check.to = finite(p, "to", 1e300);
    if (!(check.from >= 0.0 && check.to > check.from)) fail(p, "needs 0 <= from < to (s)");
    if (p.has("min_mean")) check.min_mean = finite(p, "min_mean", 0.0);
    if (p.has("max_mean")) check.max_mean = finite(p, "max_mean", 0.0);
    if (!check.min_mean && !check.max_mean) fail(p, "needs min_mean and/or max_mean");
  } else {
    fail(c, "unknown check '" + kind + "' (reach, final_pose, final_heading, direction, upright, odometry, distance, trajectory, gripper, joint, tracking, laser_range, imu_tilt, slip)");
  }
  return check;
}

std::vector<physics::WorldBox> read_boxes(const Params& list) {
  if (!list.is_list()) fail(list, "expected a list of boxes");
  std::vector<physics::WorldBox> boxes;
  for (const Params& b : list.items()) {
    only_keys(b, {"name", "shape", "size", "radius", "length", "x", "y", "z", "roll", "pitch", "yaw", "quat", "fixed", "mass"});
    physics::WorldBox box;
    box.name = b.get<std::string>("name");
    for (const physics::WorldBox& other : boxes) {
      if (other.name == box.name) fail(b.child("name"), "box '" + box.name + "' is named twice");
    }
    const std::string shape = b.get<std::string>("shape", "box");
    auto positive = [&](const char* key, const char* what) {
      const double v = finite(b, key, 0.0);
      if (!b.has(key)) fail(b, std::string("a ") + shape + " needs '" + key + "' (" + what + ")");
      if (!(v > 0.0)) fail(b.child(key), "must be > 0 m");
      return v;
    };
    auto none_of = [&](std::initializer_list<const char*> keys) {
      for (const char* k : keys)
        if (b.has(k)) fail(b.child(k), "a " + shape + " takes no '" + k + "'");
    };
    if (shape == "box") {
      none_of({"radius", "length"});
      const auto size = values_of(b, "size", 3);
      for (double v : size) {
        if (!(v > 0.0)) fail(b.child("size"), "edge lengths must be > 0 m");
      }
      box.size = {size[0], size[1], size[2]};
    } else if (shape == "cylinder") {
      none_of({"size"});
      const double d = 2.0 * positive("radius", "m"), l = positive("length", "m, along its z axis");
      box.shape = physics::WorldBox::Shape::Cylinder;
      box.size = {d, d, l};
    } else if (shape == "sphere") {
      none_of({"size", "length"});
      const double d = 2.0 * positive("radius", "m");
      box.shape = physics::WorldBox::Shape::Sphere;
      box.size = {d, d, d};
    } else {
      fail(b.child("shape"), "expected box, cylinder or sphere, got '" + shape + "'");
    }
    box.pose.position = {finite(b, "x", 0.0), finite(b, "y", 0.0), finite(b, "z", 0.0)};
    if (b.has("quat")) {
      if (b.has("roll") || b.has("pitch") || b.has("yaw")) fail(b.child("quat"), "give quat or roll/pitch/yaw, not both");
      const auto q = values_of(b, "quat", 4);
      const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
      if (!(n > 1e-9)) fail(b.child("quat"), "must not be zero");
      box.pose.orientation = {q[0] / n, q[1] / n, q[2] / n, q[3] / n};
    } else {
      // ZYX: q = qz(yaw) qy(pitch) qx(roll).
      const double r = finite(b, "roll", 0.0) / 2, p = finite(b, "pitch", 0.0) / 2, y = finite(b, "yaw", 0.0) / 2;
      const double cr = std::cos(r), sr = std::sin(r), cp = std::cos(p), sp = std::sin(p), cy = std::cos(y), sy = std::sin(y);
      box.pose.orientation = {cr * cp * cy + sr * sp * sy, sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy,
                              cr * cp * sy - sr * sp * cy};
    }
    box.fixed = b.get<bool>("fixed", true);
    box.mass = finite(b, "mass", box.mass);
    if (!(box.mass > 0.0)) fail(b.child("mass"), "must be > 0 kg");
    boxes.push_back(box);
  }
  return boxes;
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

WorldConfig read_world_config(const Params& world, const fs::path& base) {
  WorldConfig w;
  const std::string name = world.get<std::string>("name", "empty");
  w.name = (name == "empty" || name == "mars_yard_2024" || name == "slope") ? name : resolve_path(base, name);
  if (world.has("slope_deg")) w.slope_deg = finite(world, "slope_deg", 10.0);
  if (auto soil = world.find("soil")) w.soil = read_soil(*soil);
  w.seed = static_cast<std::uint64_t>(world.get<int>("seed", static_cast<int>(physics::kMarsYardDefaultSeed)));
  if (world.has("size_x")) w.heightmap.size_x = world.get<double>("size_x");
  if (world.has("size_y")) w.heightmap.size_y = world.get<double>("size_y");
  if (world.has("z_min")) w.heightmap.z_min = world.get<double>("z_min");
  if (world.has("z_max")) w.heightmap.z_max = world.get<double>("z_max");
  return w;
}

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
      if (auto boxes = world->find("boxes")) s.boxes = read_boxes(*boxes);
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
      s.controllers_file = resolve_path(base, controllers->get<std::string>("file"));
      if (!fs::exists(s.controllers_file)) fail(controllers->child("file"), "no such file: " + s.controllers_file);
      s.controllers_namespace = controllers->get<std::string>("namespace", "");
      s.start = controllers->get<std::vector<std::string>>("start", {});
      if (auto overlay = controllers->find("params")) {
        Params file_params;
        try {
          file_params = Params::from_yaml_file(s.controllers_file);
          if (!s.controllers_namespace.empty()) file_params = file_params.child(s.controllers_namespace);
        } catch (const std::exception& e) {
          fail(*overlay, std::string("cannot read the controllers file: ") + e.what());
        }
        read_controller_params(*overlay, file_params, "", s.controller_params);
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
