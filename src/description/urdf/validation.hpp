#pragma once
// Checks of a RobotModel that urdfdom does not make. Every problem is one line
// "SOURCE:LINE: link 'x': what is wrong" (LINE omitted when unknown), so that a user finds it.

#include <string>
#include <vector>

#include "description/robot_model.hpp"

namespace mechsim::description {

struct ValidationReport {
  std::vector<std::string> errors;
  std::vector<std::string> warnings;
  bool ok() const { return errors.empty(); }
};

struct ValidationOptions {
  // Physical-plausibility problems (mass, inertia, joint limits) are reported as warnings.
  bool lenient = false;
};

// The tree: duplicate link/joint names (repeated transmission names, a <hardwareInterface> only in
// the <actuator>, and one joint given several actuators are warnings: ros_control accepts them), joints naming missing links, a joint whose
// parent is its child, a link with two parent joints, kinematic cycles, no root or several roots.
void validate_structure(const RobotModel& model, ValidationReport& report);

// Numbers: non-finite values anywhere; negative mass; inertia not positive definite or breaking
// the triangle inequality; lower > upper; negative effort or velocity limits; a zero axis.
void validate_physics(const RobotModel& model, const ValidationOptions& options,
                      ValidationReport& report);

// Names used by reference: mimic joints, transmission joints, gazebo references.
void validate_references(const RobotModel& model, ValidationReport& report);

// All of the above.
ValidationReport validate_robot(const RobotModel& model, const ValidationOptions& options);

// "SOURCE:LINE: " (or "SOURCE: " when line is 0).
std::string location(const std::string& source, int line);

}  // namespace mechsim::description
