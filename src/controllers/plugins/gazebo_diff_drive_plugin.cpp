#include "controllers/plugins/gazebo_diff_drive_plugin.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "controllers/drive/diff_drive_kinematics.hpp"
#include "controllers/plugins/plugin_params.hpp"
#include "description/rover_geometry.hpp"  // joint_pose_at_zero

namespace mechsim::control {
namespace {

using description::Pose;
using description::Quat;
using description::Vec3;
using Matrix = std::array<std::array<double, 3>, 3>;

Matrix rotation(const Quat& q) {
  const double w = q.w, x = q.x, y = q.y, z = q.z;
  return {{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
           {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
           {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}}};
}

Vec3 apply(const Pose& X, const Vec3& p) {
  const Matrix R = rotation(X.orientation);
  return {X.position.x + R[0][0] * p.x + R[0][1] * p.y + R[0][2] * p.z,
          X.position.y + R[1][0] * p.x + R[1][1] * p.y + R[1][2] * p.z,
          X.position.z + R[2][0] * p.x + R[2][1] * p.y + R[2][2] * p.z};
}

Quat multiply(const Quat& a, const Quat& b) {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

// The axis-aligned box of a shape at pose X (in X's parent frame): its centre and half extents.
struct Box {
  std::array<double, 3> low{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                            std::numeric_limits<double>::infinity()};
  std::array<double, 3> high{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity()};
  void add(const Vec3& centre, const std::array<double, 3>& half) {
    const double c[3] = {centre.x, centre.y, centre.z};
    for (std::size_t i = 0; i < 3; ++i) {
      low[i] = std::min(low[i], c[i] - half[i]);
      high[i] = std::max(high[i], c[i] + half[i]);
    }
  }
  double largest_edge() const { return std::max({high[0] - low[0], high[1] - low[1], high[2] - low[2]}); }
};

std::array<double, 3> half_extents(const description::Geometry& g, const Matrix& R) {
  using description::GeometryType;
  std::array<double, 3> half{};
  switch (g.type) {
    case GeometryType::Box:
      for (std::size_t i = 0; i < 3; ++i) {
        half[i] = (std::abs(R[i][0]) * g.size.x + std::abs(R[i][1]) * g.size.y + std::abs(R[i][2]) * g.size.z) / 2.0;
      }
      break;
    case GeometryType::Cylinder:
      // Along its own z: a disc of the radius at each end of the length.
      for (std::size_t i = 0; i < 3; ++i) {
        const double a = R[i][2];
        half[i] = std::abs(a) * g.length / 2.0 + g.radius * std::sqrt(std::max(0.0, 1.0 - a * a));
      }
      break;
    case GeometryType::Sphere:
      half = {g.radius, g.radius, g.radius};
      break;
    case GeometryType::Mesh:
      break;
  }
  return half;
}

}  // namespace

GazeboDiffDriveGeometry gazebo_diff_drive_geometry(const description::RobotModel& robot, const std::string& left_joint,
                                                   const std::string& right_joint) {
  Pose X_BL, X_BR;
  try {
    X_BL = description::joint_pose_at_zero(robot, left_joint, robot.root_link);
    X_BR = description::joint_pose_at_zero(robot, right_joint, robot.root_link);
  } catch (const std::exception& e) {
    throw ControllerConfigError(std::string("cannot measure the wheels as Gazebo does: ") + e.what());
  }
  GazeboDiffDriveGeometry g;
  g.separation = std::hypot(X_BL.position.x - X_BR.position.x, X_BL.position.y - X_BR.position.y,
                            X_BL.position.z - X_BR.position.z);
  if (!(g.separation > 1e-9)) {
    throw ControllerConfigError("joints '" + left_joint + "' and '" + right_joint +
                                "' have the same anchor: Gazebo's wheel separation (the distance between them) would be 0");
  }
  // The child link's frame is its joint's frame at zero angle.
  const description::Joint* joint = robot.joint(left_joint);
  const description::Link* wheel = joint != nullptr ? robot.link(joint->child_link) : nullptr;
  if (wheel == nullptr || wheel->collisions.empty()) {
    throw ControllerConfigError("wheel link '" + (joint != nullptr ? joint->child_link : left_joint) +
                                "' has no collision shape: Gazebo sizes the wheel radius by its bounding box");
  }
  Box box;
  for (const description::Collision& c : wheel->collisions) {
    if (c.geometry.type == description::GeometryType::Mesh) {
      throw ControllerConfigError("wheel link '" + wheel->name + "' has a mesh collision ('" + c.geometry.mesh_uri +
                                  "'): mechsim sizes libDiffDrivePlugin's wheel radius from boxes, cylinders and spheres only");
    }
    const Pose X_BG{apply(X_BL, c.origin.position), multiply(X_BL.orientation, c.origin.orientation)};
    box.add(X_BG.position, half_extents(c.geometry, rotation(X_BG.orientation)));
  }
  g.radius = box.largest_edge() / 2.0;
  if (!(g.radius > 1e-9)) throw ControllerConfigError("wheel link '" + wheel->name + "' has a bounding box of size 0");
  return g;
}

std::string gazebo_vel_cmd_topic(const std::string& model_name) { return "/" + model_name + "/vel_cmd"; }

std::vector<std::string> GazeboDiffDrivePlugin::joints(const Params& params) {
  const PluginParams p(params);
  return {p.required("left_joint"), p.required("right_joint")};
}

bool GazeboDiffDrivePlugin::init(RobotHardware& hardware, const Params& params, std::string& /*error*/) {
  const PluginParams p(params);
  torque_ = p.has("torque") ? p.positive("torque", 5.0) : 0.0;
  const std::string left = p.required("left_joint"), right = p.required("right_joint");
  if (left == right) p.fail("right_joint", "names the same joint as <left_joint> ('" + left + "')");
  left_ = hardware.claim_joint(left, HardwareInterface::Velocity, p.location("left_joint"));
  right_ = hardware.claim_joint(right, HardwareInterface::Velocity, p.location("right_joint"));
  ros_.robot_namespace = "";
  ros_.topics.push_back({"vel_cmd", gazebo_vel_cmd_topic(model_name_), "geometry_msgs/Pose"});
  return true;
}

void GazeboDiffDrivePlugin::starting(double /*time*/) {
  command_.reset_from_rt(Twist{});
  left_.set_effort_limit(torque_);
  right_.set_effort_limit(torque_);
  left_.set_command(0.0);
  right_.set_command(0.0);
}

UpdateStatus GazeboDiffDrivePlugin::update(double /*time*/, double /*period*/) {
  const Twist& command = command_.read_from_rt();
  // Gazebo's va turns clockwise: the ROS convention's w is -va.
  const WheelRimSpeeds rim = diff_drive_rim_speeds(command.linear.x, -command.angular.z, geometry_.separation);
  left_.set_command(rim.left / geometry_.radius);
  right_.set_command(rim.right / geometry_.radius);
  return UpdateStatus::Ok();
}

}  // namespace mechsim::control
