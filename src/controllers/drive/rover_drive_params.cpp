#include "controllers/drive/rover_drive_params.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

#include "controllers/param_checks.hpp"
#include "description/rover_geometry.hpp"

namespace mechsim::control {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::string path_of(const Params& params, std::string_view key) { return join_param_path(params.path(), key); }

}  // namespace

std::vector<std::string> read_rover_joint_list(const Params& params, const char* key, std::size_t min_count) {
  const std::string path = path_of(params, key);
  if (!params.has(key)) throw ControllerConfigError("no joints given: parameter " + path + " not found");
  auto names = params.get<std::vector<std::string>>(key);
  if (names.size() < min_count) {
    throw ControllerConfigError("parameter " + path + " lists " + std::to_string(names.size()) +
                                " joints; at least " + std::to_string(min_count) + " needed");
  }
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i].empty()) throw ControllerConfigError("parameter " + path + "[" + std::to_string(i) + "] is empty");
    if (std::count(names.begin(), names.end(), names[i]) > 1) {
      throw ControllerConfigError("parameter " + path + ": joint '" + names[i] + "' is listed twice");
    }
  }
  return names;
}

SteeredJointLists read_steered_joint_lists(const Params& params, const char* steering_key, std::size_t min_steering,
                                           const char* wheel_key, std::size_t min_wheels) {
  SteeredJointLists lists{read_rover_joint_list(params, steering_key, min_steering),
                          read_rover_joint_list(params, wheel_key, min_wheels)};
  for (const std::string& s : lists.steering) {
    if (std::find(lists.wheels.begin(), lists.wheels.end(), s) != lists.wheels.end()) {
      throw ControllerConfigError("joint '" + s + "' is in both " + path_of(params, steering_key) + " and " +
                                  path_of(params, wheel_key));
    }
  }
  return lists;
}

namespace {

// A map parameter keyed by joint name: every key must be one of `joints`.
Params joint_map(const Params& params, const char* key, const std::vector<std::string>& joints) {
  const std::string path = path_of(params, key);
  if (!params.has(key)) {
    throw ControllerConfigError("parameter " + path +
                                " not found (give it, or let the simulation fill the geometry from the robot "
                                "description: control::fill_rover_drive_geometry)");
  }
  Params map = params.child(key);
  if (!map.is_map()) throw ControllerConfigError("parameter " + path + " must be a map keyed by joint name");
  for (const std::string& k : map.keys()) {
    if (std::find(joints.begin(), joints.end(), k) == joints.end()) {
      throw ControllerConfigError("parameter " + join_param_path(path, k) + ": '" + k +
                                  "' is not one of the controller's joints");
    }
  }
  return map;
}

std::array<double, 2> read_xy(const Params& map, const std::string& joint) {
  const auto v = map.get<std::vector<double>>(joint);  // throws naming <map>/<joint> when absent
  if (v.size() != 2 && v.size() != 3) {
    throw ControllerConfigError("parameter " + join_param_path(map.path(), joint) + " must be [x, y] or [x, y, z] (m)");
  }
  for (double c : v) {
    if (!std::isfinite(c)) throw ControllerConfigError("parameter " + join_param_path(map.path(), joint) + " is not finite");
  }
  return {v[0], v[1]};
}

double read_sign(const Params& map, const std::string& joint) {
  const double v = map.get<double>(joint);
  if (v != 1.0 && v != -1.0) {
    throw ControllerConfigError("parameter " + join_param_path(map.path(), joint) + " must be 1 or -1 (got " +
                                std::to_string(v) + ")");
  }
  return v;
}

std::array<double, 6> covariance(const Params& params, const char* key) {
  std::array<double, 6> out{};
  if (!params.has(key)) return out;
  const auto v = params.get<std::vector<double>>(key);
  if (v.size() != 6) throw ControllerConfigError("parameter " + path_of(params, key) + " must list 6 values");
  for (std::size_t i = 0; i < 6; ++i) {
    if (!(v[i] >= 0.0) || !std::isfinite(v[i])) {
      throw ControllerConfigError("parameter " + path_of(params, key) + "[" + std::to_string(i) + "] must be finite and >= 0");
    }
    out[i] = v[i];
  }
  return out;
}

// The smallest URDF velocity limit of `joints`, inf when none has one.
double velocity_limit(const RobotHardware& hardware, const std::vector<std::string>& joints) {
  double limit = kInf;
  for (const std::string& j : joints) {
    const int index = hardware.find_joint(j);
    if (index < 0) continue;
    const auto& info = hardware.model().joints[static_cast<std::size_t>(index)];
    if (info.limits && info.limits->velocity > 0.0) limit = std::fmin(limit, info.limits->velocity);
  }
  return limit;
}

}  // namespace

RoverDriveConfig read_rover_drive_config(const Params& params, const RobotHardware& hardware) {
  RoverDriveConfig c;
  SteeredJointLists lists = read_steered_joint_lists(params, "steering_joints", 0, "wheel_joints", 2);
  c.steering_joints = std::move(lists.steering);
  c.wheel_joints = std::move(lists.wheels);

  RoverKinematics& k = c.kinematics;
  if (!params.has("wheel_radius")) {
    throw ControllerConfigError("parameter " + path_of(params, "wheel_radius") +
                                " not found (m; or let the simulation fill it from the robot description)");
  }
  k.wheel_radius = positive_param(params, "wheel_radius", 0.0);
  if (!std::isfinite(k.wheel_radius)) throw ControllerConfigError("parameter " + path_of(params, "wheel_radius") + " is not finite");
  // Default: +-90 deg, narrowed to the steering joints' URDF limits where they have them.
  double feasible = std::numbers::pi / 2.0;
  for (const std::string& s : c.steering_joints) {
    const int index = hardware.find_joint(s);
    if (index < 0) continue;
    const auto& info = hardware.model().joints[static_cast<std::size_t>(index)];
    if (info.continuous || !info.limits || info.limits->lower >= info.limits->upper) continue;
    const double both_ways = std::fmin(std::abs(info.limits->lower), std::abs(info.limits->upper));
    if (both_ways > 0.0) feasible = std::fmin(feasible, both_ways);
  }
  k.max_steering_angle = positive_param(params, "max_steering_angle", feasible);
  if (k.max_steering_angle > std::numbers::pi) {
    throw ControllerConfigError("parameter " + path_of(params, "max_steering_angle") + " must be <= pi");
  }

  const Params wheel_positions = joint_map(params, "wheel_positions", c.wheel_joints);
  const Params wheel_signs = joint_map(params, "wheel_axis_signs", c.wheel_joints);
  std::map<std::string, std::string> wheel_steering;
  std::vector<std::array<double, 2>> pivots;
  if (!c.steering_joints.empty()) {
    const Params steering_positions = joint_map(params, "steering_positions", c.steering_joints);
    const Params steering_signs = joint_map(params, "steering_axis_signs", c.steering_joints);
    wheel_steering = joint_map(params, "wheel_steering", c.wheel_joints).as<std::map<std::string, std::string>>();
    for (const std::string& s : c.steering_joints) {
      pivots.push_back(read_xy(steering_positions, s));
      k.steering_axis_signs.push_back(read_sign(steering_signs, s));
    }
  }
  std::vector<int> carried(c.steering_joints.size(), 0);
  for (const std::string& w : c.wheel_joints) {
    RoverWheel wheel;
    const auto xy = read_xy(wheel_positions, w);
    wheel.axis_sign = read_sign(wheel_signs, w);
    wheel.x = xy[0];
    wheel.y = xy[1];
    auto it = wheel_steering.find(w);
    if (it != wheel_steering.end()) {
      const std::string path = join_param_path(join_param_path(params.path(), "wheel_steering"), w);
      auto s = std::find(c.steering_joints.begin(), c.steering_joints.end(), it->second);
      if (s == c.steering_joints.end()) {
        throw ControllerConfigError("parameter " + path + ": '" + it->second + "' is not one of " +
                                    path_of(params, "steering_joints"));
      }
      const auto index = static_cast<std::size_t>(s - c.steering_joints.begin());
      if (++carried[index] > 1) {
        throw ControllerConfigError("parameter " + path + ": steering joint '" + it->second + "' carries two wheels");
      }
      wheel.steering = static_cast<int>(index);
      // The tyre's offset from the steering axis, in the fork frame at zero steering (= B).
      const double along = xy[0] - pivots[index][0];
      wheel.offset = xy[1] - pivots[index][1];
      if (std::abs(along) > 0.005) {
        throw ControllerConfigError("parameter " + join_param_path(wheel_positions.path(), w) + ": the tyre is " +
                                    std::to_string(along) + " m ahead of steering joint '" + it->second +
                                    "' axis; the kinematics handle offsets along the axle only (<= 5 mm ahead)");
      }
      wheel.x = pivots[index][0];
      wheel.y = pivots[index][1];
    }
    k.wheels.push_back(wheel);
  }
  for (std::size_t s = 0; s < c.steering_joints.size(); ++s) {
    if (carried[s] != 1) {
      throw ControllerConfigError("parameter " + path_of(params, "wheel_steering") + ": no wheel is carried by steering joint '" +
                                  c.steering_joints[s] + "'");
    }
  }
  finish_rover_kinematics(k);

  c.max_steering_rate = positive_param(params, "max_steering_rate", velocity_limit(hardware, c.steering_joints));
  c.max_wheel_speed = positive_param(params, "max_wheel_speed", velocity_limit(hardware, c.wheel_joints));
  c.max_linear_velocity = positive_param(params, "max_linear_velocity", kInf);
  c.max_angular_velocity = positive_param(params, "max_angular_velocity", kInf);
  c.max_linear_acceleration = positive_param(params, "max_linear_acceleration", kInf);
  c.max_angular_acceleration = positive_param(params, "max_angular_acceleration", kInf);
  c.cmd_vel_timeout = params.get<double>("cmd_vel_timeout", 0.5);
  c.steering_tolerance = non_negative_param(params, "steering_tolerance", 0.05);
  c.steering_stop_error = non_negative_param(params, "steering_stop_error", 0.35);
  if (!(c.steering_stop_error > c.steering_tolerance)) {
    throw ControllerConfigError("parameter " + path_of(params, "steering_stop_error") + " must exceed " +
                                path_of(params, "steering_tolerance"));
  }
  c.crab_sensing.assign(c.wheel_joints.size(), 0);
  if (params.has("crab_sensing_wheels")) {
    const std::string path = path_of(params, "crab_sensing_wheels");
    const Params node = params.child("crab_sensing_wheels");
    if (node.is_scalar()) {
      const auto text = node.as<std::string>();
      if (text == "trailing_side") {
        c.crab_sensing_mode = RoverDriveConfig::CrabSensing::TrailingSide;
      } else if (text != "none") {
        throw ControllerConfigError("parameter " + path + " must be a list of wheel joints, 'trailing_side' or 'none' (got '" +
                                    text + "')");
      }
    } else {
      const auto sensing = params.get<std::vector<std::string>>("crab_sensing_wheels");
      for (std::size_t j = 0; j < sensing.size(); ++j) {
        auto it = std::find(c.wheel_joints.begin(), c.wheel_joints.end(), sensing[j]);
        if (it == c.wheel_joints.end()) {
          throw ControllerConfigError("parameter " + path + "[" + std::to_string(j) + "]: '" + sensing[j] +
                                      "' is not one of " + path_of(params, "wheel_joints"));
        }
        c.crab_sensing[static_cast<std::size_t>(it - c.wheel_joints.begin())] = 1;
      }
      if (std::count(c.crab_sensing.begin(), c.crab_sensing.end(), 1) ==
          static_cast<std::ptrdiff_t>(c.wheel_joints.size())) {
        throw ControllerConfigError("parameter " + path + " lists every wheel: at least one must drive");
      }
      if (!sensing.empty()) c.crab_sensing_mode = RoverDriveConfig::CrabSensing::Listed;
    }
  }
  c.crab_driven_rolling_weight = non_negative_param(params, "crab_driven_rolling_weight", 0.01);
  c.crab_lateral_weight = non_negative_param(params, "crab_lateral_weight", 0.1);
  c.crab_heading_p = non_negative_param(params, "crab_heading_p", 0.0);
  c.crab_heading_i = non_negative_param(params, "crab_heading_i", 0.0);
  c.crab_heading_max_rate = positive_param(params, "crab_heading_max_rate", 0.2);
  if (!std::isfinite(c.crab_heading_max_rate)) {
    throw ControllerConfigError("parameter " + path_of(params, "crab_heading_max_rate") + " is not finite");
  }
  if (params.has("crab_heading_source")) {
    const std::string path = path_of(params, "crab_heading_source");
    const auto source = params.get<std::string>("crab_heading_source");
    if (source == "imu") {
      c.crab_heading_source = RoverDriveConfig::HeadingSource::Imu;
    } else if (source != "wheels") {
      throw ControllerConfigError("parameter " + path + " must be 'wheels' or 'imu' (got '" + source + "')");
    }
  }
  if (c.crab_heading_source == RoverDriveConfig::HeadingSource::Imu) {
    if (params.has("crab_heading_imu")) {
      c.crab_heading_imu = params.get<std::string>("crab_heading_imu");
    } else {
      const std::vector<std::string> imus = hardware.imu_sensor_names();
      if (imus.size() != 1) {
        std::string names;
        for (const std::string& n : imus) names += (names.empty() ? "" : ", ") + n;
        throw ControllerConfigError("parameter " + path_of(params, "crab_heading_source") + " is 'imu': name the IMU in " +
                                    path_of(params, "crab_heading_imu") + " (the robot's IMUs: " +
                                    (names.empty() ? std::string("none") : names) + ")");
      }
      c.crab_heading_imu = imus[0];
    }
  }
  c.odometry_robust.scale = non_negative_param(params, "odometry_robust_scale", 0.05);
  c.odometry_robust.iterations = params.get<int>("odometry_robust_iterations", 3);
  if (c.odometry_robust.iterations < 0 || c.odometry_robust.iterations > 20) {
    throw ControllerConfigError("parameter " + path_of(params, "odometry_robust_iterations") + " must be in [0, 20] (got " +
                                std::to_string(c.odometry_robust.iterations) + ")");
  }
  c.odom_frame_id = params.get<std::string>("odom_frame_id", "odom");
  c.base_frame_id = params.get<std::string>("base_frame_id", "base_link");
  c.pose_covariance_diagonal = covariance(params, "pose_covariance_diagonal");
  c.twist_covariance_diagonal = covariance(params, "twist_covariance_diagonal");
  return c;
}

int fill_rover_drive_geometry(const Params& params, const description::RobotModel& model) {
  const auto steering = read_rover_joint_list(params, "steering_joints", 0);
  const auto wheels = read_rover_joint_list(params, "wheel_joints", 2);
  const std::string base = params.get<std::string>("base_frame_id", "base_link");
  for (const auto* list : {&steering, &wheels}) {
    const char* key = list == &steering ? "steering_joints" : "wheel_joints";
    for (std::size_t i = 0; i < list->size(); ++i) {
      if (model.joint((*list)[i]) == nullptr) {
        throw ControllerConfigError("unknown joint '" + (*list)[i] + "' (parameter " + path_of(params, key) + "[" +
                                    std::to_string(i) + "]) in robot '" + model.name + "'");
      }
    }
  }
  description::RoverGeometry g;
  try {
    g = description::rover_geometry(model, wheels, steering, base);
  } catch (const description::RoverGeometryError& e) {
    throw ControllerConfigError("controller " + params.path() + ": " + e.what());
  }
  Params p = params;  // a handle: sets go to the shared tree
  int set = 0;
  const auto set_if_absent = [&](const std::string& key, const auto& value) {
    if (p.has(key)) return;
    p.set(key, value);
    ++set;
  };
  if (!p.has("wheel_radius")) {
    if (!g.wheel_radius) {
      throw ControllerConfigError("parameter " + path_of(params, "wheel_radius") +
                                  " not found and the wheels of '" + model.name + "' have no collision cylinder to read it from");
    }
    set_if_absent("wheel_radius", *g.wheel_radius);
  }
  for (const auto& w : g.wheels) {
    set_if_absent("wheel_positions/" + w.joint, std::vector<double>{w.tyre_position.x, w.tyre_position.y, w.tyre_position.z});
    set_if_absent("wheel_axis_signs/" + w.joint, w.axis_sign);
    if (!w.steering_joint.empty()) set_if_absent("wheel_steering/" + w.joint, w.steering_joint);
  }
  for (const auto& s : g.steering) {
    set_if_absent("steering_positions/" + s.joint, std::vector<double>{s.position.x, s.position.y, s.position.z});
    set_if_absent("steering_axis_signs/" + s.joint, s.axis_sign);
  }
  return set;
}

int fill_rover_drive_geometry_all(const Params& ns, const description::RobotModel& model) {
  int filled = 0;
  for (const std::string& key : ns.keys()) {
    const Params controller = ns.child(key);
    if (!controller.is_map() || !controller.has("type")) continue;
    const Params type = controller.child("type");
    if (!type.is_scalar() || type.as<std::string>() != kRoverDriveControllerType) continue;
    fill_rover_drive_geometry(controller, model);
    ++filled;
  }
  return filled;
}

}  // namespace mechsim::control
