#include "mechanism/build_mechanism.hpp"

#include "mechanism/transmission_builder.hpp"
#include "mechanism/transmission_factory.hpp"

namespace mechsim::mechanism {

MechanismModel build_mechanism(const description::RobotModel& robot) {
  MechanismModel model;
  model.source = robot.source;
  for (const description::Transmission& spec : robot.transmissions) {
    TransmissionBuilder builder(robot, model, spec, static_cast<int>(model.transmissions.size()));
    std::unique_ptr<Transmission> t = build_transmission(builder);
    if (spec.name.empty()) builder.fail("the transmission has no name");
    for (const auto& other : model.transmissions)
      if (other->name() == spec.name) builder.fail("a transmission of this name already exists");
    model.transmissions.push_back(std::move(t));
  }
  return model;
}

}  // namespace mechsim::mechanism
