#include "controllers/drive/pr2_base_params.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "controllers/drive/rover_drive_params.hpp"  // read_rover_joint_list
#include "controllers/param_checks.hpp"
#include "description/rover_geometry.hpp"  // joint_pose_at_zero

namespace mechsim::control {
namespace {

std::string path_of(const Params& params, std::string_view key) { return join_param_path(params.path(), key); }

// A map parameter keyed by joint name, every key one of `joints`; nullopt when absent.
std::optional<Params> joint_map(const Params& params, const char* key, const std::vector<std::string>& joints,
                                bool required) {
  const std::string path = path_of(params, key);
  if (!params.has(key)) {
    if (!required) return std::nullopt;
    throw ControllerConfigError("parameter " + path +
                                " not found (give it, or let the simulation fill the base geometry from the robot "
                                "description: control::fill_pr2_base_geometry)");
  }
  Params map = params.child(key);
  if (!map.is_map()) throw ControllerConfigError("parameter " + path + " must be a map keyed by joint name");
  for (const std::string& k : map.keys()) {
    if (std::find(joints.begin(), joints.end(), k) == joints.end()) {
      throw ControllerConfigError("parameter " + join_param_path(path, k) + ": '" + k + "' is not one of the controller's joints");
    }
  }
  return map;
}

double read_sign(const std::optional<Params>& map, const std::string& joint) {
  if (!map || !map->has(joint)) return 1.0;
  const double v = map->get<double>(joint);
  if (v != 1.0 && v != -1.0) {
    throw ControllerConfigError("parameter " + join_param_path(map->path(), joint) + " must be 1 or -1 (got " + std::to_string(v) + ")");
  }
  return v;
}

double finite_at(const Params& map, const std::string& joint) {
  const double v = map.get<double>(joint);  // throws naming <map>/<joint> when absent
  if (!std::isfinite(v)) throw ControllerConfigError("parameter " + join_param_path(map.path(), joint) + " is not finite");
  return v;
}

}  // namespace

Pr2BaseGeometry read_pr2_base_geometry(const Params& params) {
  Pr2BaseGeometry g;
  if (!params.has("caster_joints") && params.has("caster_names")) {
    throw ControllerConfigError("parameter " + path_of(params, "caster_joints") + " not found; " +
                                path_of(params, "caster_names") +
                                " (caster links) needs the robot description: let the simulation fill the base "
                                "geometry (control::fill_pr2_base_geometry)");
  }
  SteeredJointLists lists = read_steered_joint_lists(params, "caster_joints", 1, "wheel_joints", 1);
  g.caster_joints = std::move(lists.steering);
  g.wheel_joints = std::move(lists.wheels);
  Pr2BaseKinematics& k = g.kinematics;
  if (!params.has("wheel_radius")) {
    throw ControllerConfigError("parameter " + path_of(params, "wheel_radius") +
                                " not found (m; or let the simulation fill it from the robot description)");
  }
  k.wheel_radius = positive_param(params, "wheel_radius", 0.0) * positive_param(params, "wheel_radius_multiplier", 1.0);

  const Params positions = *joint_map(params, "caster_positions", g.caster_joints, true);
  const auto caster_signs = joint_map(params, "caster_axis_signs", g.caster_joints, false);
  for (const std::string& c : g.caster_joints) {
    const auto v = positions.get<std::vector<double>>(c);
    const std::string path = join_param_path(positions.path(), c);
    if (v.size() != 2 && v.size() != 3) throw ControllerConfigError("parameter " + path + " must be [x, y] or [x, y, z] (m)");
    if (!std::isfinite(v[0]) || !std::isfinite(v[1])) throw ControllerConfigError("parameter " + path + " is not finite");
    k.casters.push_back({v[0], v[1], read_sign(caster_signs, c)});
  }
  const Params casters_of = *joint_map(params, "wheel_casters", g.wheel_joints, true);
  const Params offsets = *joint_map(params, "wheel_offsets", g.wheel_joints, true);
  const auto wheel_signs = joint_map(params, "wheel_axis_signs", g.wheel_joints, false);
  std::vector<int> carried(g.caster_joints.size(), 0);
  for (const std::string& w : g.wheel_joints) {
    const std::string caster = casters_of.get<std::string>(w);
    auto it = std::find(g.caster_joints.begin(), g.caster_joints.end(), caster);
    if (it == g.caster_joints.end()) {
      throw ControllerConfigError("parameter " + join_param_path(casters_of.path(), w) + ": '" + caster +
                                  "' is not one of " + path_of(params, "caster_joints"));
    }
    Pr2Wheel wheel;
    wheel.caster = static_cast<std::size_t>(it - g.caster_joints.begin());
    wheel.offset = finite_at(offsets, w);
    wheel.axis_sign = read_sign(wheel_signs, w);
    ++carried[wheel.caster];
    k.wheels.push_back(wheel);
  }
  for (std::size_t c = 0; c < g.caster_joints.size(); ++c) {
    if (carried[c] == 0) {
      throw ControllerConfigError("parameter " + path_of(params, "wheel_casters") + ": no wheel is carried by caster '" +
                                  g.caster_joints[c] + "'");
    }
  }
  return g;
}

Pr2BaseConfig read_pr2_base_config(const Params& params) {
  Pr2BaseConfig c;
  c.geometry = read_pr2_base_geometry(params);
  c.max_translational_velocity = positive_param(params, "max_translational_velocity", 0.5);
  c.max_rotational_velocity = positive_param(params, "max_rotational_velocity", 10.0);
  c.max_translational_acceleration_x = positive_param(params, "max_translational_acceleration/x", 0.2);
  c.max_translational_acceleration_y = positive_param(params, "max_translational_acceleration/y", 0.2);
  c.max_rotational_acceleration = positive_param(params, "max_rotational_acceleration", 10.0);
  c.timeout = params.get<double>("timeout", 0.2);
  if (!std::isfinite(c.timeout)) throw ControllerConfigError("parameter " + path_of(params, "timeout") + " is not finite");
  c.caster_hold_speed = positive_param(params, "caster_hold_speed", 1e-5);
  return c;
}

// ---------------------------------------------------------------- filling from the description

namespace {

using description::Pose;
using description::Vec3;

// v rotated by the unit quaternion q.
Vec3 rotate(const description::Quat& q, const Vec3& v) {
  // t = 2 q_v x v; v' = v + w t + q_v x t
  const double tx = 2.0 * (q.y * v.z - q.z * v.y), ty = 2.0 * (q.z * v.x - q.x * v.z), tz = 2.0 * (q.x * v.y - q.y * v.x);
  return {v.x + q.w * tx + (q.y * tz - q.z * ty), v.y + q.w * ty + (q.z * tx - q.x * tz),
          v.z + q.w * tz + (q.x * ty - q.y * tx)};
}

description::Quat conjugate(const description::Quat& q) { return {q.w, -q.x, -q.y, -q.z}; }

std::vector<std::string> names_list(const Params& params, const char* key) {
  const Params node = params.child(key);
  if (node.is_list()) return node.as<std::vector<std::string>>();
  std::istringstream in(node.as<std::string>());  // the PR2 writes "fl_caster_rotation_link fr_..."
  std::vector<std::string> out;
  for (std::string s; in >> s;) out.push_back(s);
  return out;
}

}  // namespace

int fill_pr2_base_geometry(const Params& params, const description::RobotModel& model) {
  Params p = params;  // a handle: sets go to the shared tree
  int set = 0;
  const std::string base = params.get<std::string>("base_link_frame", "base_link");
  const auto where = [&](const std::string& key, std::size_t i) { return path_of(params, key) + "[" + std::to_string(i) + "]"; };

  // The wheels of a caster: the joints below its rotation link whose axis is lateral.
  const auto wheels_below = [&](const description::Link& link, std::vector<std::string>& wheels) {
    for (const std::string& j : link.child_joints) {
      const description::Joint* joint = model.joint(j);
      if (joint != nullptr && std::abs(joint->axis.y) > 0.9) wheels.push_back(j);
    }
  };
  std::vector<std::string> derived_wheels;
  if (!p.has("caster_joints")) {
    if (!p.has("caster_names")) {
      throw ControllerConfigError("parameter " + path_of(params, "caster_joints") + " not found (nor caster_names)");
    }
    const auto links = names_list(params, "caster_names");
    std::vector<std::string> casters;
    for (std::size_t i = 0; i < links.size(); ++i) {
      const description::Link* link = model.link(links[i]);
      if (link == nullptr || link->parent_joint.empty()) {
        throw ControllerConfigError("unknown caster link '" + links[i] + "' (parameter " + where("caster_names", i) +
                                    ") in robot '" + model.name + "'");
      }
      casters.push_back(link->parent_joint);
      wheels_below(*link, derived_wheels);
    }
    p.set("caster_joints", casters);
    ++set;
  } else if (!p.has("wheel_joints")) {
    const auto casters = read_rover_joint_list(params, "caster_joints", 1);
    for (std::size_t i = 0; i < casters.size(); ++i) {
      const description::Joint* joint = model.joint(casters[i]);
      const description::Link* link = joint != nullptr ? model.link(joint->child_link) : nullptr;
      if (link == nullptr) {
        throw ControllerConfigError("unknown joint '" + casters[i] + "' (parameter " + where("caster_joints", i) +
                                    ") in robot '" + model.name + "'");
      }
      wheels_below(*link, derived_wheels);
    }
  }
  if (!p.has("wheel_joints")) {
    p.set("wheel_joints", derived_wheels);
    ++set;
  }
  const auto casters = read_rover_joint_list(params, "caster_joints", 1);
  const auto wheels = read_rover_joint_list(params, "wheel_joints", 1);
  const auto pose = [&](const std::vector<std::string>& list, const char* key, std::size_t i) {
    if (model.joint(list[i]) == nullptr) {
      throw ControllerConfigError("unknown joint '" + list[i] + "' (parameter " + where(key, i) + ") in robot '" + model.name + "'");
    }
    try {
      return description::joint_pose_at_zero(model, list[i], base);
    } catch (const description::RoverGeometryError& e) {
      throw ControllerConfigError("controller " + params.path() + ": " + e.what());
    }
  };
  const auto set_if_absent = [&](const std::string& key, const auto& value) {
    if (p.has(key)) return;
    p.set(key, value);
    ++set;
  };

  std::vector<Pose> caster_poses;
  for (std::size_t i = 0; i < casters.size(); ++i) {
    caster_poses.push_back(pose(casters, "caster_joints", i));
    const Vec3 axis = rotate(caster_poses.back().orientation, model.joint(casters[i])->axis);
    if (std::abs(axis.z) < 0.9) {
      throw ControllerConfigError("caster joint '" + casters[i] + "' (parameter " + where("caster_joints", i) +
                                  "): its axis is not vertical in " + base);
    }
    const Vec3& x = caster_poses.back().position;
    set_if_absent("caster_positions/" + casters[i], std::vector<double>{x.x, x.y, x.z});
    set_if_absent("caster_axis_signs/" + casters[i], axis.z > 0.0 ? 1.0 : -1.0);
  }
  std::optional<double> radius;
  for (std::size_t i = 0; i < wheels.size(); ++i) {
    const Pose X_BW = pose(wheels, "wheel_joints", i);
    // The caster above the wheel: the nearest listed caster joint up the tree.
    std::size_t caster = casters.size();
    for (std::string link = model.joint(wheels[i])->parent_link; caster == casters.size();) {
      const description::Link* l = model.link(link);
      if (l == nullptr || l->parent_joint.empty()) break;
      auto it = std::find(casters.begin(), casters.end(), l->parent_joint);
      if (it != casters.end()) caster = static_cast<std::size_t>(it - casters.begin());
      link = model.joint(l->parent_joint)->parent_link;
    }
    if (caster == casters.size()) {
      throw ControllerConfigError("wheel joint '" + wheels[i] + "' (parameter " + where("wheel_joints", i) +
                                  ") is not below any of " + path_of(params, "caster_joints"));
    }
    const Pose& X_BC = caster_poses[caster];
    const description::Quat to_caster = conjugate(X_BC.orientation);
    const Vec3 d = rotate(to_caster, {X_BW.position.x - X_BC.position.x, X_BW.position.y - X_BC.position.y,
                                      X_BW.position.z - X_BC.position.z});
    const Vec3 axis = rotate(to_caster, rotate(X_BW.orientation, model.joint(wheels[i])->axis));
    if (std::abs(axis.y) < 0.9) {
      throw ControllerConfigError("wheel joint '" + wheels[i] + "' (parameter " + where("wheel_joints", i) +
                                  "): its axis is not along its caster's y axis");
    }
    if (std::abs(d.x) > 0.005) {
      throw ControllerConfigError("wheel joint '" + wheels[i] + "' (parameter " + where("wheel_joints", i) + ") is " +
                                  std::to_string(d.x) + " m ahead of its caster's pivot; the kinematics handle offsets "
                                  "along the axle only");
    }
    set_if_absent("wheel_casters/" + wheels[i], casters[caster]);
    set_if_absent("wheel_offsets/" + wheels[i], d.y);
    set_if_absent("wheel_axis_signs/" + wheels[i], axis.y > 0.0 ? 1.0 : -1.0);
    if (const description::Link* link = model.link(model.joint(wheels[i])->child_link)) {
      for (const auto& c : link->collisions) {
        if (c.geometry.type == description::GeometryType::Cylinder || c.geometry.type == description::GeometryType::Sphere) {
          if (!radius) radius = c.geometry.radius;
          break;
        }
      }
    }
  }
  if (!p.has("wheel_radius")) {
    if (!radius) {
      throw ControllerConfigError("parameter " + path_of(params, "wheel_radius") + " not found and the wheels of '" +
                                  model.name + "' have no collision cylinder to read it from");
    }
    set_if_absent("wheel_radius", *radius);
  }
  return set;
}

int fill_pr2_base_geometry_all(const Params& ns, const description::RobotModel& model) {
  int filled = 0;
  for (const std::string& key : ns.keys()) {
    const Params controller = ns.child(key);
    if (!controller.is_map() || !controller.has("type")) continue;
    const Params type = controller.child("type");
    if (!type.is_scalar()) continue;
    const std::string t = type.as<std::string>();
    if (t != kPr2BaseController2Type && t != kPr2BaseControllerType && t != kPr2OdometryType) continue;
    fill_pr2_base_geometry(controller, model);
    ++filled;
  }
  return filled;
}

}  // namespace mechsim::control
