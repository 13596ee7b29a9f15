#include "mechanism/build_mechanism.hpp"

#include "mechanism/ros2_control_joints.hpp"
#include "mechanism/simple_transmission.hpp"
#include "mechanism/transmission_builder.hpp"
#include "mechanism/transmission_factory.hpp"

namespace mechsim::mechanism {

MechanismModel build_mechanism(const description::RobotModel& robot) {
  MechanismModel model;
  model.source = robot.source;
  for (const description::Transmission& spec : robot.transmissions) {
    TransmissionBuilder builder(robot, model, spec, static_cast<int>(model.transmissions.size()));
    if (spec.name.empty()) builder.fail("the transmission has no name");
    // A repeated name is no error (ros_control keys transmissions by joint; description validation
    // warns, naming both lines).
    if (add_to_driven_joint(builder, robot, model)) continue;
    model.transmissions.push_back(build_transmission(builder));
  }
  // ros2_control robots: the joints of their <ros2_control> tags, with the tags' interfaces.
  add_ros2_control_joints(model, robot);
  return model;
}

}  // namespace mechsim::mechanism
