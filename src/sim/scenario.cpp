#include "sim/scenario.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "control/params.hpp"

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

std::string resolve_path(const fs::path& base, const std::string& file) {
  const fs::path p(file);
  return (p.is_absolute() ? p : (base / p)).lexically_normal().string();
}

control::Twist read_twist(const Params& p) {
  control::Twist t;
  t.linear.x = p.get<double>("vx", p.get<double>("linear/x", 0.0));
  t.linear.y = p.get<double>("vy", p.get<double>("linear/y", 0.0));
  t.angular.z = p.get<double>("wz", p.get<double>("angular/z", 0.0));
  return t;
}

TimelineEvent read_event(const Params& e) {
  TimelineEvent ev;
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
  if (kinds != 1) fail(e, "an event has exactly one of command, twist, mode, route");
  return ev;
}

Check read_check(const Params& c) {
  Check check;
  const std::vector<std::string> keys = c.keys();
  if (keys.size() != 1) fail(c, "a check is a map with one key (reach, final_pose, final_heading, direction, upright, odometry, distance)");
  const std::string& kind = keys.front();
  const Params p = c.child(kind);
  check.text = kind;
  if (kind == "reach") {
    check.kind = Check::Kind::Reach;
    check.x = p.get<double>("x");
    check.y = p.get<double>("y");
    check.within = p.get<double>("within");
    check.by = p.get<double>("by");
  } else if (kind == "final_pose") {
    check.kind = Check::Kind::FinalPose;
    check.x = p.get<double>("x");
    check.y = p.get<double>("y");
    check.within = p.get<double>("within");
    if (p.has("lateral_within")) check.lateral_within = p.get<double>("lateral_within");
  } else if (kind == "final_heading") {
    check.kind = Check::Kind::FinalHeading;
    check.yaw = p.get<double>("yaw_deg") * kDeg;
    check.within_angle = p.get<double>("within_deg") * kDeg;
  } else if (kind == "direction") {
    check.kind = Check::Kind::Direction;
    check.yaw = p.get<double>("deg") * kDeg;
    check.within_angle = p.get<double>("within_deg") * kDeg;
  } else if (kind == "upright") {
    check.kind = Check::Kind::Upright;
    check.max_tilt = p.get<double>("max_tilt_deg") * kDeg;
  } else if (kind == "odometry") {
    check.kind = Check::Kind::Odometry;
    check.max_error_fraction = p.get<double>("max_error_fraction");
  } else if (kind == "distance") {
    check.kind = Check::Kind::Distance;
    check.min_distance = p.get<double>("min", 0.0);
    check.max_distance = p.get<double>("max", 1e300);
  } else {
    fail(c, "unknown check '" + kind + "' (reach, final_pose, final_heading, direction, upright, odometry, distance)");
  }
  return check;
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
      const std::string name = world->get<std::string>("name", "empty");
      s.world.name = (name == "empty" || name == "mars_yard_2024") ? name : resolve_path(base, name);
      s.world.seed = static_cast<std::uint64_t>(world->get<int>("seed", static_cast<int>(physics::kMarsYardDefaultSeed)));
      if (world->has("size_x")) s.world.heightmap.size_x = world->get<double>("size_x");
      if (world->has("size_y")) s.world.heightmap.size_y = world->get<double>("size_y");
      if (world->has("z_min")) s.world.heightmap.z_min = world->get<double>("z_min");
      if (world->has("z_max")) s.world.heightmap.z_max = world->get<double>("z_max");
    }
    if (auto spawn = root.find("spawn")) {
      s.spawn.x = spawn->get<double>("x", 0.0);
      s.spawn.y = spawn->get<double>("y", 0.0);
      s.spawn.z = spawn->get<double>("z", 0.0);
      s.spawn.roll = spawn->get<double>("roll", 0.0);
      s.spawn.pitch = spawn->get<double>("pitch", 0.0);
      s.spawn.yaw = spawn->get<double>("yaw", 0.0);
    }
    const Params controllers = root.child("controllers");
    s.controllers_file = resolve_path(base, controllers.get<std::string>("file"));
    if (!fs::exists(s.controllers_file)) fail(controllers.child("file"), "no such file: " + s.controllers_file);
    s.controllers_namespace = controllers.get<std::string>("namespace", "");
    s.start = controllers.get<std::vector<std::string>>("start");

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

    if (auto timeline = root.find("timeline")) {
      for (const Params& e : timeline->items()) s.timeline.push_back(read_event(e));
    }
    std::stable_sort(s.timeline.begin(), s.timeline.end(),
                     [](const TimelineEvent& a, const TimelineEvent& b) { return a.at < b.at; });
    if (auto checks = root.find("checks")) {
      for (const Params& c : checks->items()) s.checks.push_back(read_check(c));
    }
  } catch (const ScenarioError&) {
    throw;
  } catch (const std::exception& e) {
    throw ScenarioError(e.what());
  }
  return s;
}

}  // namespace mechsim::sim
