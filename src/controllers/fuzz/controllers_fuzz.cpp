// Fuzz target: a controller YAML (as users load it with rosparam) read into parameters; every
// controller in it is loaded into a controller manager over a small robot's mechanism, started
// and ticked. An input may fail only with ParamsError (malformed YAML); a controller that does
// not load is refused by the manager with a message, and running ones must tick without
// crashing whatever their gains or limits are (NaN, Inf, huge, negative).

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "control/controller_manager.hpp"
#include "control/params.hpp"
#include "controllers/builtin_controllers.hpp"
#include "description/urdf/urdf_parser.hpp"
#include "mechanism/build_mechanism.hpp"

namespace {

// Joints of each kind, each transmission offering effort, velocity and position.
constexpr const char* kRobot = R"(<robot name="fuzzbot">
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

const mechsim::mechanism::MechanismModel& model() {
  static const mechsim::mechanism::MechanismModel m =
      mechsim::mechanism::build_mechanism(mechsim::description::parse_urdf_string(kRobot, "fuzzbot", {}));
  return m;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace c = mechsim::control;
  c::Params params;
  try {
    params = c::Params::from_yaml_string(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.yaml");
  } catch (const c::ParamsError&) {
    return 0;
  }
  mechsim::mechanism::MechanismState state = mechsim::mechanism::make_state(model());
  c::ControllerManager manager(model(), state, params, c::builtin_controller_registry());
  std::vector<std::string> loaded;
  for (const std::string& name : params.keys()) {
    if (manager.load_controller(name)) loaded.push_back(name);
  }
  (void)manager.switch_controllers(loaded, {}, c::SwitchStrictness::SkipConflicts);
  for (int tick = 0; tick < 20; ++tick) manager.update(0.001 * tick, 0.001);
  for (const std::string& name : loaded) (void)manager.unload_controller(name);
  return 0;
}
