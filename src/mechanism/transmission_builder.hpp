#pragma once
// What a transmission type's builder uses to wire itself into a MechanismModel while
// build_mechanism runs: resolves joint and actuator names to indices (adding them to the model),
// reads parameters and reports bad input as MechanismError naming the transmission, the joint,
// actuator or parameter, and the URDF line. Build time only: allocates and throws.

#include <optional>
#include <string>

#include "description/robot_model.hpp"
#include "mechanism/mechanism_error.hpp"
#include "mechanism/mechanism_model.hpp"

namespace mechsim::mechanism {

class TransmissionBuilder {
 public:
  // `index` is the position the transmission will take in model.transmissions.
  TransmissionBuilder(const description::RobotModel& robot, MechanismModel& model,
                      const description::Transmission& spec, int index);

  const description::Transmission& spec() const { return spec_; }
  // The transmission uses the ros_control format (type "transmission_interface/...").
  bool ros_control_format() const;

  // Adds the joint as a mechanism joint of this transmission and returns its index. Errors:
  // the joint is not in the robot, is fixed/floating/planar, or another transmission drives it.
  // Actuated joints get the hardware interfaces the entry names (Effort when a PR2 transmission
  // names none; a ros_control transmission must name one, in its <joint> or, as gazebo_ros_control
  // also reads it, in its <actuator>).
  int joint(const description::TransmissionJoint& entry, JointRole role);
  // Adds the interfaces `entry` names (as joint() does) to the mechanism joint `index`, which an
  // earlier transmission made: several ros_control transmissions may name one joint, each adding
  // an interface (transmission_interface and gazebo_ros_control register one handle per interface).
  void add_interfaces(int index, const description::TransmissionJoint& entry);
  int joint(const std::string& name, JointRole role, int line);
  // Adds the actuator and returns its index; an actuator belongs to one transmission only.
  // Its <hardwareInterface> names must be known ones.
  int actuator(const description::TransmissionActuator& entry);
  bool has_robot_joint(const std::string& name) const { return robot_.joint(name) != nullptr; }

  // The entries with a role (exactly one / all of them).
  const description::TransmissionJoint& joint_entry(const std::string& role) const;
  const description::TransmissionActuator& actuator_entry(const std::string& role) const;
  std::vector<const description::TransmissionJoint*> joint_entries(const std::string& role) const;

  // A reduction: finite and nonzero. `value` absent -> `fallback`, or an error when none.
  double reduction(std::optional<double> value, std::optional<double> fallback, const std::string& what,
                   const std::string& element, int line) const;
  // A finite number from an attribute of `node`; `fallback` when absent, error when none.
  double number_attribute(const description::XmlNode& node, const std::string& attribute,
                          std::optional<double> fallback, const std::string& element) const;
  // The text of the child element `child` of `node` as a finite number, or nullopt when absent.
  std::optional<double> number_child(const description::XmlNode& node, const std::string& child,
                                     const std::string& element) const;

  // The first direct child of the <transmission> element called `element` with name="name",
  // or the first called `element` when `name` is empty; null when none.
  const description::XmlNode* xml_child(const std::string& element, const std::string& name = "") const;
  // The line of the entry named `name` in the transmission, or the transmission's line.
  int line_of(const std::string& name) const;

  [[noreturn]] void fail(const std::string& what, const std::string& element = "", int line = 0) const;

 private:
  const description::RobotModel& robot_;
  MechanismModel& model_;
  const description::Transmission& spec_;
  int index_;
};

// "<source>:<line>: " (or "<source>: " when the line is unknown).
std::string where(const std::string& source, int line);

}  // namespace mechsim::mechanism
