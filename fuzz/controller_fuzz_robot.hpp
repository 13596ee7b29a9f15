#pragma once
// What the fuzz targets that end in controllers share (controllers_fuzz: a controller YAML;
// xmlrpc_fuzz: the parameter server's values): a small robot with one joint of each kind, each
// transmission offering effort, velocity and position, and the manager's whole life of every
// controller the parameters name: loaded, started, ticked, unloaded. A controller that does not
// load is refused with a message; running ones must tick whatever their gains or limits are.

#include <string>
#include <vector>

#include "control/controller_manager.hpp"
#include "control/params.hpp"
#include "controllers/builtin_controllers.hpp"
#include "description/urdf/urdf_parser.hpp"
#include "mechanism/build_mechanism.hpp"

namespace mechsim::fuzz {

// Joints of each kind, each transmission offering effort, velocity and position.
inline constexpr const char* kRobot = R"(<robot name="fuzzbot">
  <link name="base"><inertial><mass value="5"/><inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="l0"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="l1"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="l2"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="l3"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="j0" type="revolute"><parent link="base"/><child link="l0"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="10" velocity="2"/></joint>
  <joint name="j1" type="revolute"><parent link="l0"/><child link="l1"/><axis xyz="0 1 0"/><limit lower="-2" upper="0" effort="10" velocity="2"/></joint>
  <joint name="wheel" type="continuous"><parent link="base"/><child link="l2"/><axis xyz="0 1 0"/><limit effort="10" velocity="20"/></joint>
  <joint name="slider" type="prismatic"><parent link="base"/><child link="l3"/><axis xyz="0 0 1"/><limit lower="0" upper="0.3" effort="100" velocity="0.1"/></joint>
  <transmission name="t0"><type>transmission_interface/SimpleTransmission</type><joint name="j0"><hardwareInterface>hardware_interface/EffortJointInterface</hardwareInterface><hardwareInterface>hardware_interface/VelocityJointInterface</hardwareInterface><hardwareInterface>hardware_interface/PositionJointInterface</hardwareInterface></joint><actuator name="m0"><mechanicalReduction>1</mechanicalReduction></actuator></transmission>
  <transmission name="t1"><type>transmission_interface/SimpleTransmission</type><joint name="j1"><hardwareInterface>hardware_interface/EffortJointInterface</hardwareInterface><hardwareInterface>hardware_interface/VelocityJointInterface</hardwareInterface><hardwareInterface>hardware_interface/PositionJointInterface</hardwareInterface></joint><actuator name="m1"><mechanicalReduction>2</mechanicalReduction></actuator></transmission>
  <transmission name="t2"><type>transmission_interface/SimpleTransmission</type><joint name="wheel"><hardwareInterface>hardware_interface/EffortJointInterface</hardwareInterface><hardwareInterface>hardware_interface/VelocityJointInterface</hardwareInterface><hardwareInterface>hardware_interface/PositionJointInterface</hardwareInterface></joint><actuator name="m2"><mechanicalReduction>1</mechanicalReduction></actuator></transmission>
  <transmission name="t3"><type>transmission_interface/SimpleTransmission</type><joint name="slider"><hardwareInterface>hardware_interface/EffortJointInterface</hardwareInterface><hardwareInterface>hardware_interface/VelocityJointInterface</hardwareInterface><hardwareInterface>hardware_interface/PositionJointInterface</hardwareInterface></joint><actuator name="m3"><mechanicalReduction>1</mechanicalReduction></actuator></transmission>
</robot>)";

inline const mechsim::mechanism::MechanismModel& controller_fuzz_model() {
  static const mechsim::mechanism::MechanismModel m =
      mechsim::mechanism::build_mechanism(mechsim::description::parse_urdf_string(kRobot, "fuzzbot", {}));
  return m;
}

// Loads every controller `params` names at its top level, starts those that loaded, ticks them
// 20 times and unloads them.
inline void run_controllers(const mechsim::control::Params& params) {
  namespace c = mechsim::control;
  mechsim::mechanism::MechanismState state = mechsim::mechanism::make_state(controller_fuzz_model());
  c::ControllerManager manager(controller_fuzz_model(), state, params, c::builtin_controller_registry());
  std::vector<std::string> loaded;
  for (const std::string& name : params.keys()) {
    if (manager.load_controller(name)) loaded.push_back(name);
  }
  (void)manager.switch_controllers(loaded, {}, c::SwitchStrictness::SkipConflicts);
  for (int tick = 0; tick < 20; ++tick) manager.update(0.001 * tick, 0.001);
  for (const std::string& name : loaded) (void)manager.unload_controller(name);
}

}  // namespace mechsim::fuzz
