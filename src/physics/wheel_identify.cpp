#include "physics/wheel_identify.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "physics/transform.hpp"

namespace mechsim::physics {
namespace {

using description::GeometryType;
using description::JointType;

const description::Joint* turning_joint(const description::RobotModel& robot, const description::Link& link) {
  const description::Joint* j = link.parent_joint.empty() ? nullptr : robot.joint(link.parent_joint);
  if (j == nullptr || (j->type != JointType::Continuous && j->type != JointType::Revolute)) return nullptr;
  return j;
}

// Cosine of the angle between the cylinder's axis (its z, in the link frame, which is the joint
// frame) and the joint's axis.
double alignment(const description::Joint& j, const description::Collision& c) {
  const Vec3 cylinder_axis = rotate(c.origin.orientation, Vec3{0.0, 0.0, 1.0});
  return std::abs(cylinder_axis.x * j.axis.x + cylinder_axis.y * j.axis.y + cylinder_axis.z * j.axis.z);
}

const char* shape_name(GeometryType t) {
  switch (t) {
    case GeometryType::Box: return "a box";
    case GeometryType::Cylinder: return "a cylinder";
    case GeometryType::Sphere: return "a sphere";
    case GeometryType::Mesh: return "a mesh";
  }
  return "a shape";
}

}  // namespace

bool is_wheel_collision(const description::RobotModel& robot, const description::Link& link, const description::Collision& c) {
  if (c.geometry.type != GeometryType::Cylinder) return false;
  const description::Joint* j = turning_joint(robot, link);
  return j != nullptr && alignment(*j, c) > 0.999;  // within ~2.6 degrees
}

bool is_narrow_wheel_collision(const description::RobotModel& robot, const description::Link& link,
                               const description::Collision& c) {
  return is_wheel_collision(robot, link, c) && c.geometry.length <= c.geometry.radius;
}

std::vector<WheelCandidate> identify_wheels(const description::RobotModel& robot) {
  std::vector<WheelCandidate> out;
  for (const description::Link& link : robot.links) {
    const description::Joint* j = turning_joint(robot, link);
    if (j == nullptr || link.collisions.empty()) continue;
    WheelCandidate c;
    c.link = link.name;
    c.joint = j->name;
    const description::Collision* across = nullptr;
    for (const description::Collision& col : link.collisions) {
      if (is_wheel_collision(robot, link, col)) {
        c.wheel = true;
        c.radius = col.geometry.radius;
        c.width = col.geometry.length;
        break;
      }
      if (col.geometry.type == GeometryType::Cylinder && across == nullptr) across = &col;
    }
    if (!c.wheel) {
      char text[256];
      if (across != nullptr) {
        const double deg = std::acos(std::min(1.0, alignment(*j, *across))) * 180.0 / M_PI;
        std::snprintf(text, sizeof text, "its collision cylinder's axis is %.1f deg off the joint's axis (a wheel's is within 2.6)", deg);
        c.reason = text;
      } else if (j->type == JointType::Continuous) {
        c.reason = std::string("its collision is ") + shape_name(link.collisions.front().geometry.type) +
                   ", not a cylinder about the joint's axis";
      } else {
        continue;  // a revolute joint without a cylinder: an arm, a flap, not a wheel anyone meant
      }
      c.reason += " (world.wheels can make it one: radius and width)";
    }
    out.push_back(std::move(c));
  }
  return out;
}

std::string describe(const WheelCandidate& c) {
  char text[512];
  if (c.wheel) {
    std::snprintf(text, sizeof text, "wheel '%s' on joint '%s': r %.4g m, b %.4g m%s", c.link.c_str(), c.joint.c_str(), c.radius,
                  c.width, c.width <= c.radius ? " (narrow: b <= r)" : "");
  } else {
    std::snprintf(text, sizeof text, "'%s' on joint '%s' is not a wheel: %s", c.link.c_str(), c.joint.c_str(), c.reason.c_str());
  }
  return text;
}

}  // namespace mechsim::physics
