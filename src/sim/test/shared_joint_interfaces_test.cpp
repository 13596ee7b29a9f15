// A joint given three same-name transmissions, one per hardware interface (as ros_control
// descriptions do): the description loads, and position, velocity and effort controllers each
// run on the joint in turn through the controller manager, with MuJoCo moving it.

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "control/ports.hpp"
#include "description/urdf/urdf_parser.hpp"
#include "sim/simulation.hpp"

namespace mechsim::sim {
namespace {

// A 1 kg bob 0.5 m out on a hinge about z (gravity does not load it): I = 0.001 + 1 * 0.5^2 =
// 0.251 kg m^2. The three transmissions share name, actuator and reduction (10).
constexpr const char* kRobot = R"(<robot name="turntable">
  <link name="world"/>
  <joint name="fix" type="fixed"><parent link="world"/><child link="post"/><origin xyz="0 0 1"/></joint>
  <link name="post"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="hinge" type="continuous">
    <parent link="post"/><child link="bob"/><axis xyz="0 0 1"/>
    <limit effort="20" velocity="10"/>
  </joint>
  <link name="bob"><inertial><origin xyz="0.5 0 0"/><mass value="1"/>
    <inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <transmission name="hinge_trans"><type>transmission_interface/SimpleTransmission</type>
    <joint name="hinge"><hardwareInterface>hardware_interface/PositionJointInterface</hardwareInterface></joint>
    <actuator name="hinge_motor"><hardwareInterface>hardware_interface/PositionJointInterface</hardwareInterface>
      <mechanicalReduction>10</mechanicalReduction></actuator></transmission>
  <transmission name="hinge_trans"><type>transmission_interface/SimpleTransmission</type>
    <joint name="hinge"><hardwareInterface>hardware_interface/VelocityJointInterface</hardwareInterface></joint>
    <actuator name="hinge_motor"><hardwareInterface>hardware_interface/VelocityJointInterface</hardwareInterface>
      <mechanicalReduction>10</mechanicalReduction></actuator></transmission>
  <transmission name="hinge_trans"><type>transmission_interface/SimpleTransmission</type>
    <joint name="hinge"><hardwareInterface>hardware_interface/EffortJointInterface</hardwareInterface></joint>
    <actuator name="hinge_motor"><hardwareInterface>hardware_interface/EffortJointInterface</hardwareInterface>
      <mechanicalReduction>10</mechanicalReduction></actuator></transmission>
</robot>)";

constexpr const char* kControllers = R"(
pos: {type: position_controllers/JointPositionController, joint: hinge}
vel: {type: velocity_controllers/JointVelocityController, joint: hinge}
eff: {type: effort_controllers/JointEffortController, joint: hinge}
)";

constexpr double kInertia = 0.251;  // kg m^2 about the hinge

control::ScalarCommandPort& command(Simulation& sim, const std::string& controller) {
  auto* port = dynamic_cast<control::ScalarCommandPort*>(sim.controllers().controller(controller)->port("command"));
  if (port == nullptr) throw std::runtime_error(controller + " has no scalar command port");
  return *port;
}

void switch_to(Simulation& sim, const std::string& start, const std::string& stop) {
  const std::vector<std::string> stopping = stop.empty() ? std::vector<std::string>{} : std::vector<std::string>{stop};
  const control::SwitchResult r = sim.controllers().switch_controllers({start}, stopping, control::SwitchStrictness::Strict);
  ASSERT_TRUE(r) << r.error;
  ASSERT_TRUE(sim.step());  // the switch happens in this tick
}

TEST(SharedJointInterfaces, ThreeSameNameTransmissionsLoadAndEachInterfaceMovesTheJoint) {
  std::vector<std::string> warnings;
  description::RobotModel robot = description::parse_urdf_string(kRobot, "turntable.urdf", {}, &warnings);
  ASSERT_EQ(warnings.size(), 2u);  // the repeated name, twice
  EXPECT_NE(warnings[0].find("turntable.urdf:15: transmission 'hinge_trans' is defined twice (first at line 11)"),
            std::string::npos)
      << warnings[0];
  Simulation sim(std::move(robot), make_world({}), control::Params::from_yaml_string(kControllers, "controllers"));
  ASSERT_EQ(sim.mechanism().transmissions.size(), 1u);
  ASSERT_EQ(sim.mechanism().actuators.size(), 1u);
  for (const char* name : {"pos", "vel", "eff"}) ASSERT_TRUE(sim.load_controller(name)) << name;
  const std::size_t j = *sim.physics().model().joint_index("hinge");
  const physics::Physics& physics = sim.physics();

  // Position: the servo takes the joint to 0.8 rad.
  switch_to(sim, "pos", "");
  ASSERT_TRUE(command(sim, "pos").write(0.8));
  ASSERT_TRUE(sim.run_for(2.0));
  EXPECT_NEAR(physics.position(j), 0.8, 0.01);
  EXPECT_NEAR(physics.velocity(j), 0.0, 0.01);
  // The actuator reads the joint through the one transmission's reduction.
  EXPECT_NEAR(sim.mechanism_state().actuators[0].position, 10.0 * physics.position(j), 1e-9);

  // Velocity: 1.5 rad/s, held.
  switch_to(sim, "vel", "pos");
  ASSERT_TRUE(command(sim, "vel").write(1.5));
  ASSERT_TRUE(sim.run_for(0.5));
  const double q0 = physics.position(j);
  ASSERT_TRUE(sim.run_for(1.0));
  EXPECT_NEAR(physics.velocity(j), 1.5, 0.02);
  EXPECT_NEAR(physics.position(j) - q0, 1.5, 0.03);

  // Effort: 0.5 N m accelerates the bob at tau / I from where the velocity controller left it.
  switch_to(sim, "eff", "vel");
  ASSERT_TRUE(command(sim, "eff").write(0.5));
  ASSERT_TRUE(sim.step());
  const double v0 = physics.velocity(j);
  ASSERT_TRUE(sim.run_for(0.5));
  EXPECT_NEAR(physics.velocity(j) - v0, 0.5 / kInertia * 0.5, 0.03);
  EXPECT_NEAR(physics.actuator_effort(j), 0.5, 1e-9);
}

}  // namespace
}  // namespace mechsim::sim
