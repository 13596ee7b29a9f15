// Simulation::add_reflected_inertia_for_safety_limits: a joint whose safety controller's
// velocity gain is too stiff for the tick (the PR2 torso's k_velocity 2e6 N s/m on ~50 kg)
// gets the rotor inertia that keeps the explicitly applied law stable; other joints do not.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "description/urdf/urdf_parser.hpp"
#include "sim/simulation.hpp"

namespace mechsim::sim {
namespace {

// A 50 kg lift on a prismatic joint like the PR2 torso (limit 0..0.33 m, 0.013 m/s, 10 kN, damping
// 2e4 N s/m, safety soft limits 0.0115..0.325 m, k_position 100), with safety k_velocity `kv`;
// beside it a light 1 kg pendulum with the PR2 arms' k_velocity 10 N m s/rad. It starts at
// q = 0, below the soft lower limit, so the safety law pushes it up from the first tick.
std::string lift_urdf(double kv) {
  return R"(<robot name="lift">
  <link name="world"/>
  <link name="deck"><inertial><mass value="50"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="lift" type="prismatic"><parent link="world"/><child link="deck"/><axis xyz="0 0 1"/>
    <limit lower="0" upper="0.33" effort="10000" velocity="0.013"/><dynamics damping="20000"/>
    <safety_controller k_position="100" k_velocity=")" +
         std::to_string(kv) + R"(" soft_lower_limit="0.0115" soft_upper_limit="0.325"/></joint>
  <link name="arm"><inertial><origin xyz="0 0 -0.3"/><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="swing" type="revolute"><parent link="deck"/><child link="arm"/><axis xyz="0 1 0"/>
    <limit lower="-2" upper="2" effort="30" velocity="3"/>
    <safety_controller k_position="100" k_velocity="10" soft_lower_limit="-1.9" soft_upper_limit="1.9"/></joint>
  <transmission name="t_lift"><type>transmission_interface/SimpleTransmission</type>
    <joint name="lift"><hardwareInterface>hardware_interface/EffortJointInterface</hardwareInterface></joint>
    <actuator name="lift_motor"><mechanicalReduction>1</mechanicalReduction></actuator></transmission>
  <transmission name="t_swing"><type>transmission_interface/SimpleTransmission</type>
    <joint name="swing"><hardwareInterface>hardware_interface/EffortJointInterface</hardwareInterface></joint>
    <actuator name="swing_motor"><mechanicalReduction>1</mechanicalReduction></actuator></transmission>
</robot>)";
}

std::unique_ptr<Simulation> make(double kv) {
  description::RobotModel robot = description::parse_urdf_string(lift_urdf(kv), "lift", {});
  return std::make_unique<Simulation>(std::move(robot), make_world({}), control::Params::from_yaml_string("{}", "none"));
}

TEST(SafetyInertia, AStiffSafetyVelocityGainGetsRotorInertiaAndTheJointRisesWithoutChatter) {
  auto sim = make(2e6);
  ASSERT_EQ(sim->reflected_inertia().size(), 1u);  // the lift, not the pendulum
  EXPECT_EQ(sim->reflected_inertia()[0].joint, "lift");
  // 2 k dt - (I + c dt): I is the 51 kg moving on the lift, c dt = 20 kg.
  EXPECT_NEAR(sim->reflected_inertia()[0].armature, 2.0 * 2e6 * 0.001 - 51.0 - 20.0, 0.5);
  const std::size_t lift = *sim->physics().model().joint_index("lift");
  const std::size_t swing = *sim->physics().model().joint_index("swing");
  EXPECT_DOUBLE_EQ(sim->physics().armature(swing), 0.0);
  // The velocity bound is +k_position (soft_lower - q) = 1.15 m/s clamped to 0.013 m/s: the lift
  // creeps up at <= 0.013 m/s, never reversing from one tick to the next (unstable, the law
  // would swing the velocity by metres per second each tick at the 10 kN effort limit).
  double previous = 0.0;
  int reversals = 0;
  for (int k = 0; k < 2000; ++k) {
    ASSERT_TRUE(sim->step());
    const double v = sim->physics().velocity(lift);
    if (k > 10 && v * previous < 0.0 && std::abs(v) > 1e-3 && std::abs(previous) > 1e-3) ++reversals;  // chatter
    EXPECT_LT(v, 0.0135) << "tick " << k;
    previous = v;
  }
  EXPECT_EQ(reversals, 0);
  EXPECT_GT(sim->physics().position(lift), 0.0115 - 0.001);  // up to its soft lower limit
}

TEST(SafetyInertia, ASoftSafetyVelocityGainNeedsNone) {
  // k_velocity 2e4: k dt = 20 kg is below half of I + c dt = 71 kg, stable as it is.
  auto sim = make(2e4);
  EXPECT_TRUE(sim->reflected_inertia().empty());
  const std::size_t lift = *sim->physics().model().joint_index("lift");
  EXPECT_DOUBLE_EQ(sim->physics().armature(lift), 0.0);
}

}  // namespace
}  // namespace mechsim::sim
