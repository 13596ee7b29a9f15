#include "controllers/drive/diff_drive_params.hpp"

#include <algorithm>
#include <cmath>

#include "control/hardware.hpp"
#include "controllers/param_checks.hpp"
#include "description/rover_geometry.hpp"

namespace mechsim::control {
namespace {

std::string path_of(const Params& params, std::string_view key) { return join_param_path(params.path(), key); }

std::array<double, 6> diagonal(const Params& params, const char* key) {
  std::array<double, 6> out{};
  if (!params.has(key)) return out;
  const auto v = params.get<std::vector<double>>(key);
  if (v.size() != 6) {
    throw ControllerConfigError("parameter " + path_of(params, key) + " must list 6 values (x, y, z, roll, pitch, yaw); got " +
                                std::to_string(v.size()));
  }
  for (std::size_t i = 0; i < 6; ++i) {
    if (!(v[i] >= 0.0) || !std::isfinite(v[i])) {
      throw ControllerConfigError("parameter " + path_of(params, key) + "[" + std::to_string(i) + "] must be finite and >= 0");
    }
    out[i] = v[i];
  }
  return out;
}

}  // namespace

std::vector<std::string> read_wheel_list(const Params& params, const char* key) {
  const std::string path = path_of(params, key);
  if (!params.has(key)) throw ControllerConfigError("parameter " + path + " not found (the wheel joint, or a list of them)");
  std::vector<std::string> names;
  const Params p = params.child(key);
  if (p.is_scalar()) names.push_back(p.as<std::string>());
  else names = p.as<std::vector<std::string>>();
  if (names.empty()) throw ControllerConfigError("parameter " + path + " lists no wheel joint");
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i].empty()) throw ControllerConfigError("parameter " + path + "[" + std::to_string(i) + "] is empty");
    if (std::count(names.begin(), names.end(), names[i]) > 1) {
      throw ControllerConfigError("parameter " + path + ": joint '" + names[i] + "' is listed twice");
    }
  }
  return names;
}

DiffDriveConfig read_diff_drive_config(const Params& params) {
  DiffDriveConfig c;
  c.left_wheels = read_wheel_list(params, "left_wheel");
  c.right_wheels = read_wheel_list(params, "right_wheel");
  for (const std::string& l : c.left_wheels) {
    if (std::find(c.right_wheels.begin(), c.right_wheels.end(), l) != c.right_wheels.end()) {
      throw ControllerConfigError("joint '" + l + "' is in both " + path_of(params, "left_wheel") + " and " +
                                  path_of(params, "right_wheel"));
    }
  }
  for (const char* key : {"wheel_separation", "wheel_radius"}) {
    if (!params.has(key)) {
      throw ControllerConfigError("parameter " + path_of(params, key) +
                                  " not found, and the robot description did not give it (fill_diff_drive_geometry)");
    }
  }
  c.wheel_separation = positive_param(params, "wheel_separation", 0.0);
  c.wheel_radius = positive_param(params, "wheel_radius", 0.0);
  c.wheel_separation_multiplier = positive_param(params, "wheel_separation_multiplier", 1.0);
  // wheel_radius_multiplier, when given, sets both sides (ros_controllers' rule).
  if (params.has("wheel_radius_multiplier")) {
    c.left_wheel_radius_multiplier = c.right_wheel_radius_multiplier = positive_param(params, "wheel_radius_multiplier", 1.0);
  } else {
    c.left_wheel_radius_multiplier = positive_param(params, "left_wheel_radius_multiplier", 1.0);
    c.right_wheel_radius_multiplier = positive_param(params, "right_wheel_radius_multiplier", 1.0);
  }
  c.cmd_vel_timeout = params.get<double>("cmd_vel_timeout", 0.5);
  if (!std::isfinite(c.cmd_vel_timeout)) throw ControllerConfigError("parameter " + path_of(params, "cmd_vel_timeout") + " is not finite");
  c.publish_rate = params.get<double>("publish_rate", 50.0);
  if (!std::isfinite(c.publish_rate)) throw ControllerConfigError("parameter " + path_of(params, "publish_rate") + " is not finite");
  c.base_frame_id = params.get<std::string>("base_frame_id", "base_link");
  c.odom_frame_id = params.get<std::string>("odom_frame_id", "odom");
  c.enable_odom_tf = params.get<bool>("enable_odom_tf", true);
  c.pose_covariance_diagonal = diagonal(params, "pose_covariance_diagonal");
  c.twist_covariance_diagonal = diagonal(params, "twist_covariance_diagonal");
  c.open_loop = params.get<bool>("open_loop", false);
  c.velocity_rolling_window_size = params.get<int>("velocity_rolling_window_size", 10);
  if (c.velocity_rolling_window_size < 1) {
    throw ControllerConfigError("parameter " + path_of(params, "velocity_rolling_window_size") + " must be >= 1 (got " +
                                std::to_string(c.velocity_rolling_window_size) + ")");
  }
  c.publish_cmd = params.get<bool>("publish_cmd", false);
  c.allow_multiple_cmd_vel_publishers = params.get<bool>("allow_multiple_cmd_vel_publishers", true);
  if (auto linear = params.find("linear/x")) c.linear = read_speed_limiter(*linear);
  if (auto angular = params.find("angular/z")) c.angular = read_speed_limiter(*angular);
  return c;
}

int fill_diff_drive_geometry(const Params& params, const description::RobotModel& model) {
  const bool need_separation = !params.has("wheel_separation");
  const bool need_radius = !params.has("wheel_radius");
  if (!need_separation && !need_radius) return 0;
  const std::vector<std::string> left = read_wheel_list(params, "left_wheel");
  const std::vector<std::string> right = read_wheel_list(params, "right_wheel");
  description::RoverGeometry g;
  try {
    g = description::rover_geometry(model, {left.front(), right.front()}, {}, model.root_link);
  } catch (const description::RoverGeometryError& e) {
    throw ControllerConfigError("parameter " + path_of(params, need_separation ? "wheel_separation" : "wheel_radius") +
                                " not given and not found in the robot description: " + e.what());
  }
  int set = 0;
  Params writable = params;
  if (need_separation) {
    const description::Vec3 a = g.wheels[0].joint_position, b = g.wheels[1].joint_position;
    const double separation = std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
    if (!(separation > 0.0)) {
      throw ControllerConfigError("parameter " + path_of(params, "wheel_separation") + " not given, and joints '" + left.front() +
                                  "' and '" + right.front() + "' are at the same place in the robot description");
    }
    writable.set("wheel_separation", separation);
    ++set;
  }
  if (need_radius) {
    if (!g.wheel_radius) {
      throw ControllerConfigError("parameter " + path_of(params, "wheel_radius") + " not given, and the links of wheel joints '" +
                                  left.front() + "' and '" + right.front() +
                                  "' have no collision cylinder or sphere in the robot description to take it from");
    }
    writable.set("wheel_radius", *g.wheel_radius);
    ++set;
  }
  return set;
}

int fill_diff_drive_geometry_all(const Params& ns, const description::RobotModel& model) {
  int filled = 0;
  for (const std::string& key : ns.keys()) {
    const Params controller = ns.child(key);
    if (!controller.is_map() || !controller.has("type")) continue;
    const Params type = controller.child("type");
    if (!type.is_scalar() || type.as<std::string>() != kDiffDriveControllerType) continue;
    try {
      filled += fill_diff_drive_geometry(controller, model) > 0 ? 1 : 0;
    } catch (const std::exception&) {
      // Reported when the controller is loaded (Simulation::load_controller fills it again).
    }
  }
  return filled;
}

}  // namespace mechsim::control
