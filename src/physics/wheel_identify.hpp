#pragma once
// Which links of a robot are wheels for the wheel-soil model (physics/terramechanics.hpp), from
// the description alone: a wheel is a link that turns on a revolute or continuous joint and has a
// collision cylinder whose axis is the joint's (within about 2.6 degrees). Its radius and width
// are the cylinder's, whatever its proportions: a narrow one (width <= radius, most small rover
// and caster wheels) is as much a soil wheel as a wide one; on rigid ground MuJoCo gets it as an
// ellipsoid with the same rolling circle (ContactDefaults::point_contact_wheels).
//
// What looks like a wheel but is not one is named with the reason, for `mechsim check` and the
// run report: a link on a continuous joint without such a cylinder (a sphere, a mesh, a cylinder
// across the axis), or a cylinder on a revolute joint that does not turn about the cylinder's axis.
// A world or scenario can make any link a wheel, or none (sim/wheel_config.hpp,
// physics::WheelOverride).

#include <string>
#include <vector>

#include "description/robot_model.hpp"

namespace mechsim::physics {

// The collision `c` of `link` is a wheel: a cylinder coaxial with the link's revolute or
// continuous joint.
bool is_wheel_collision(const description::RobotModel& robot, const description::Link& link,
                        const description::Collision& c);
// ... and no wider than its radius.
bool is_narrow_wheel_collision(const description::RobotModel& robot, const description::Link& link,
                               const description::Collision& c);

struct WheelCandidate {
  std::string link, joint;
  bool wheel = false;
  double radius = 0.0, width = 0.0;  // m, a wheel's (its first wheel collision)
  std::string reason;                // why it is not a wheel ("" for a wheel)
};

// Every wheel of the robot and every link that looks like one but is not (see above), in
// document order.
std::vector<WheelCandidate> identify_wheels(const description::RobotModel& robot);

// One line each: "wheel 'l' on joint 'j': r 0.058 m, b 0.05 m (narrow: b <= r)" or "'l' on joint
// 'j' is not a wheel: <reason>".
std::string describe(const WheelCandidate& candidate);

}  // namespace mechsim::physics
