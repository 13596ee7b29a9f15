#pragma once
// The drive geometry of a wheeled rover read from its description: where its wheels and
// steering axes are in the body frame, which way each joint turns, and the wheel radius. The
// sim and apps layers use it to fill a rover drive controller's geometry parameters when the
// controller YAML leaves them out (controllers/drive/rover_drive_params.hpp), the way a diff_drive user
// would otherwise measure wheel_separation by hand.
//
// Everything is taken at zero joint angles: the pose of each joint frame in the base frame is
// the product of the joint origins from the base link down to that joint.

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "description/robot_model.hpp"

namespace mechsim::description {

// A description that does not fit what a rover drive needs (unknown joint, wheel axis not
// lateral, steering axis not vertical, a joint not below the base link). The message names
// the joint and the description's file.
class RoverGeometryError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// X_BJ: the pose of joint `joint`'s frame in the frame of link `base_link`, all joints at zero.
// Throws RoverGeometryError when the joint is unknown or not below `base_link`.
Pose joint_pose_at_zero(const RobotModel& model, const std::string& joint, const std::string& base_link);

struct RoverWheelGeometry {
  std::string joint;           // the wheel joint
  std::string steering_joint;  // the steering joint above it, "" for a fixed (unsteered) wheel
  Vec3 joint_position;         // m, base frame: the wheel joint's origin
  // m, base frame: the centre of the tyre, i.e. the wheel link's first collision cylinder or
  // sphere where it has one (the contact is there, not at the joint origin when the tyre is
  // offset along the axle), else the joint origin.
  Vec3 tyre_position;
  // +1 when a positive joint velocity rolls the wheel forward (+x of its steering frame at
  // zero steering, i.e. the joint axis points to +y), -1 when the axis points to -y.
  double axis_sign = 1.0;
  std::optional<double> radius;  // m, the tyre's collision cylinder/sphere radius, if any
};

struct RoverSteeringGeometry {
  std::string joint;
  Vec3 position;  // m, base frame: the joint's origin (a point on the steering axis)
  // +1 when the joint axis points up (+z: a positive angle turns the wheel counter-clockwise
  // seen from above), -1 when it points down (the CC8).
  double axis_sign = 1.0;
};

struct RoverGeometry {
  std::string base_link;
  std::vector<RoverWheelGeometry> wheels;       // in the order asked for
  std::vector<RoverSteeringGeometry> steering;  // in the order asked for
  // m: the radius shared by all wheels that have a collision cylinder or sphere; empty when
  // none has one. Throws if they disagree by more than 1 mm.
  std::optional<double> wheel_radius;
};

// Reads the geometry of `wheel_joints` and `steering_joints` (each steering joint must carry
// exactly one of the wheels: its wheel joint lies below it in the tree). Throws
// RoverGeometryError naming the joint for an unknown joint, a wheel axis that is not along
// +-y of the base frame, a steering axis that is not along +-z, a steering joint with no or
// several wheels below it.
RoverGeometry rover_geometry(const RobotModel& model, const std::vector<std::string>& wheel_joints,
                             const std::vector<std::string>& steering_joints,
                             const std::string& base_link = "base_link");

}  // namespace mechsim::description
