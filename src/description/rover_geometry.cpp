#include "description/rover_geometry.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace mechsim::description {
namespace {

Eigen::Isometry3d to_eigen(const Pose& pose) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = Eigen::Quaterniond(pose.orientation.w, pose.orientation.x, pose.orientation.y, pose.orientation.z)
                   .normalized()
                   .toRotationMatrix();
  X.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  return X;
}

Pose from_eigen(const Eigen::Isometry3d& X) {
  const Eigen::Quaterniond q(X.rotation());
  const Eigen::Vector3d p = X.translation();
  return {{p.x(), p.y(), p.z()}, {q.w(), q.x(), q.y(), q.z()}};
}

Vec3 to_vec(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

std::string in_file(const RobotModel& model) { return model.source.empty() ? std::string() : " in " + model.source; }

const Joint& find_joint(const RobotModel& model, const std::string& name, const char* what) {
  const Joint* joint = model.joint(name);
  if (joint == nullptr) {
    throw RoverGeometryError(std::string(what) + " '" + name + "' is not a joint of robot '" + model.name + "'" +
                             in_file(model));
  }
  return *joint;
}

// The joints from `base_link` down to `joint` (inclusive), top first.
std::vector<const Joint*> chain_from(const RobotModel& model, const Joint& joint, const std::string& base_link) {
  std::vector<const Joint*> chain{&joint};
  std::string link = joint.parent_link;
  while (link != base_link) {
    const Link* l = model.link(link);
    if (l == nullptr || l->parent_joint.empty() || chain.size() > model.joints.size()) {
      throw RoverGeometryError("joint '" + joint.name + "' is not below link '" + base_link + "'" + in_file(model));
    }
    const Joint& parent = find_joint(model, l->parent_joint, "joint");
    chain.push_back(&parent);
    link = parent.parent_link;
  }
  std::reverse(chain.begin(), chain.end());
  return chain;
}

Eigen::Isometry3d pose_at_zero(const std::vector<const Joint*>& chain) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  for (const Joint* j : chain) X = X * to_eigen(j->origin);
  return X;
}

Eigen::Vector3d axis_in_base(const Eigen::Isometry3d& X_BJ, const Joint& joint) {
  return X_BJ.rotation() * Eigen::Vector3d(joint.axis.x, joint.axis.y, joint.axis.z).normalized();
}

std::string format_axis(const Eigen::Vector3d& a) {
  return "(" + std::to_string(a.x()) + ", " + std::to_string(a.y()) + ", " + std::to_string(a.z()) + ")";
}

// A tilt up to ~25 deg (camber, toe, caster) still counts as lateral / vertical.
constexpr double kAxisAlignment = 0.9;

}  // namespace

Pose joint_pose_at_zero(const RobotModel& model, const std::string& joint, const std::string& base_link) {
  if (model.link(base_link) == nullptr) {
    throw RoverGeometryError("base link '" + base_link + "' is not a link of robot '" + model.name + "'" +
                             in_file(model));
  }
  return from_eigen(pose_at_zero(chain_from(model, find_joint(model, joint, "joint"), base_link)));
}

RoverGeometry rover_geometry(const RobotModel& model, const std::vector<std::string>& wheel_joints,
                             const std::vector<std::string>& steering_joints, const std::string& base_link) {
  if (model.link(base_link) == nullptr) {
    throw RoverGeometryError("base link '" + base_link + "' is not a link of robot '" + model.name + "'" +
                             in_file(model));
  }
  RoverGeometry out;
  out.base_link = base_link;

  for (const std::string& name : steering_joints) {
    const Joint& joint = find_joint(model, name, "steering joint");
    const Eigen::Isometry3d X_BJ = pose_at_zero(chain_from(model, joint, base_link));
    const Eigen::Vector3d axis = axis_in_base(X_BJ, joint);
    if (std::abs(axis.z()) < kAxisAlignment) {
      throw RoverGeometryError("steering joint '" + name + "'" + in_file(model) + " (line " +
                               std::to_string(joint.line) + "): its axis in " + base_link + " is " + format_axis(axis) +
                               ", not vertical (+-z)");
    }
    out.steering.push_back({name, to_vec(X_BJ.translation()), axis.z() > 0.0 ? 1.0 : -1.0});
  }

  std::vector<int> wheels_per_steering(steering_joints.size(), 0);
  for (const std::string& name : wheel_joints) {
    const Joint& joint = find_joint(model, name, "wheel joint");
    const std::vector<const Joint*> chain = chain_from(model, joint, base_link);
    const Eigen::Isometry3d X_BJ = pose_at_zero(chain);
    const Eigen::Vector3d axis = axis_in_base(X_BJ, joint);
    if (std::abs(axis.y()) < kAxisAlignment) {
      throw RoverGeometryError("wheel joint '" + name + "'" + in_file(model) + " (line " + std::to_string(joint.line) +
                               "): its axis in " + base_link + " is " + format_axis(axis) + ", not lateral (+-y)");
    }
    RoverWheelGeometry wheel;
    wheel.joint = name;
    wheel.joint_position = to_vec(X_BJ.translation());
    wheel.tyre_position = wheel.joint_position;
    wheel.axis_sign = axis.y() > 0.0 ? 1.0 : -1.0;
    for (const Joint* above : chain) {
      auto it = std::find(steering_joints.begin(), steering_joints.end(), above->name);
      if (it == steering_joints.end()) continue;
      wheel.steering_joint = above->name;
      ++wheels_per_steering[static_cast<std::size_t>(it - steering_joints.begin())];
    }
    if (const Link* link = model.link(joint.child_link)) {
      for (const Collision& c : link->collisions) {
        if (c.geometry.type != GeometryType::Cylinder && c.geometry.type != GeometryType::Sphere) continue;
        wheel.tyre_position = to_vec(X_BJ * Eigen::Vector3d(c.origin.position.x, c.origin.position.y, c.origin.position.z));
        wheel.radius = c.geometry.radius;
        break;
      }
    }
    out.wheels.push_back(wheel);
  }

  for (std::size_t s = 0; s < steering_joints.size(); ++s) {
    if (wheels_per_steering[s] != 1) {
      throw RoverGeometryError("steering joint '" + steering_joints[s] + "'" + in_file(model) + " carries " +
                               std::to_string(wheels_per_steering[s]) +
                               " of the wheel joints; a steering joint must carry exactly one");
    }
  }

  for (const RoverWheelGeometry& w : out.wheels) {
    if (!w.radius) continue;
    if (!out.wheel_radius) {
      out.wheel_radius = w.radius;
    } else if (std::abs(*out.wheel_radius - *w.radius) > 1e-3) {
      throw RoverGeometryError("wheel joints' tyres have different radii (" + std::to_string(*out.wheel_radius) +
                               " m and " + std::to_string(*w.radius) + " m at '" + w.joint + "')" + in_file(model));
    }
  }
  return out;
}

}  // namespace mechsim::description
