#include "mechanism/direct_joints.hpp"

#include "mechanism/mechanism_error.hpp"

namespace mechsim::mechanism {

void add_direct_joints(MechanismModel& model, const description::RobotModel& robot, const std::vector<std::string>& joints) {
  using description::JointType;
  for (const std::string& name : joints) {
    if (model.joint_index(name) >= 0) continue;
    const description::Joint* joint = robot.joint(name);
    if (joint == nullptr) throw MechanismError(robot.source + ": no joint '" + name + "' in the robot", "", name, 0);
    if (joint->type != JointType::Revolute && joint->type != JointType::Continuous && joint->type != JointType::Prismatic) {
      throw MechanismError(robot.source + ":" + std::to_string(joint->line) + ": joint '" + name +
                               "' is not revolute, continuous or prismatic", "", name, joint->line);
    }
    JointInfo info;
    info.name = name;
    info.type = joint->type;
    info.continuous = joint->type == JointType::Continuous;
    info.limits = joint->limits;
    info.safety = joint->safety;
    info.mimic = joint->mimic;
    info.role = JointRole::Direct;
    info.line = joint->line;
    model.joints.push_back(std::move(info));
  }
}

}  // namespace mechsim::mechanism
