// Effort, position and velocity command modes, mimic equalities and the differential law.
#include <gtest/gtest.h>

#include <cmath>

#include "physics_test_util.hpp"

namespace mechsim::physics {
namespace {

constexpr double kG = 9.81;

std::string arm_urdf(double effort_limit, double damping = 0.0) {
  // 2 kg at 1 m from a horizontal hinge: gravity torque 19.62 N m when horizontal.
  return test::pendulum_urdf(1.0, 2.0, 1e-3,
                             "<limit lower=\"-3\" upper=\"3\" effort=\"" + std::to_string(effort_limit) +
                                 "\" velocity=\"5\"/><dynamics damping=\"" + std::to_string(damping) + "\"/>",
                             "revolute");
}

TEST(PhysicsServo, PositionServoHoldsAgainstGravityWithinTheEffortLimit) {
  Physics p(test::build(arm_urdf(30.0)));
  p.set_mode(0, JointMode::Position);
  const double target = M_PI / 2;  // horizontal: the largest gravity torque
  double peak_effort = 0.0;
  while (p.time() < 4.0) {
    p.set_position_command(0, target);
    ASSERT_TRUE(p.step().ok());
    peak_effort = std::max(peak_effort, std::fabs(p.actuator_effort(0)));
  }
  EXPECT_NEAR(p.position(0), target, 0.01);
  EXPECT_NEAR(std::fabs(p.velocity(0)), 0.0, 1e-3);
  EXPECT_LE(peak_effort, 30.0 + 1e-9);
  EXPECT_NEAR(std::fabs(p.actuator_effort(0)), 2.0 * kG * 1.0, 0.2);  // holding gravity
}

TEST(PhysicsServo, PositionServoSaturatesAtTheEffortLimitAndSags) {
  // Below the 19.62 N m gravity torque; joint damping lets the saturated swing settle.
  Physics p(test::build(arm_urdf(10.0, 2.0)));
  p.set_mode(0, JointMode::Position, {5000.0, 200.0});
  double peak_effort = 0.0;
  while (p.time() < 12.0) {
    p.set_position_command(0, M_PI / 2);
    ASSERT_TRUE(p.step().ok());
    peak_effort = std::max(peak_effort, std::fabs(p.actuator_effort(0)));
  }
  EXPECT_LE(peak_effort, 10.0 + 1e-9);
  EXPECT_NEAR(peak_effort, 10.0, 1e-6);
  // Where the limited torque balances gravity: 2 g sin(q) = 10.
  EXPECT_NEAR(p.position(0), std::asin(10.0 / (2.0 * kG)), 0.02);
}

TEST(PhysicsServo, EffortIsClampedToTheLimitToo) {
  Physics p(test::build(arm_urdf(10.0)));
  p.set_effort(0, 500.0);
  ASSERT_TRUE(p.step().ok());
  EXPECT_DOUBLE_EQ(p.actuator_effort(0), 10.0);
}

TEST(PhysicsServo, VelocityServoTracksAWheelSpeed) {
  const std::string urdf = R"(<robot name="wheel">
  <link name="world"/>
  <link name="wheel"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.02" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="axle" type="continuous"><parent link="world"/><child link="wheel"/><origin xyz="0 0 1"/><axis xyz="0 1 0"/>
    <limit effort="5" velocity="10"/><dynamics damping="0.01"/></joint>
</robot>)";
  Physics p(test::build(urdf));
  p.set_mode(0, JointMode::Velocity, {0.0, 2.0});
  while (p.time() < 2.0) {
    p.set_velocity_command(0, 3.0);
    ASSERT_TRUE(p.step().ok());
  }
  // Steady state: kv (3 - w) = b w  ->  w = 3 kv / (kv + b).
  EXPECT_NEAR(p.velocity(0), 3.0 * 2.0 / 2.01, 1e-3);
  EXPECT_GT(p.position(0), 4.0);  // it turned: a servo, not a teleport
}

TEST(PhysicsServo, ModesSwitchAtRunTimeWithoutJumping) {
  Physics p(test::build(arm_urdf(30.0)));
  p.set_joint_state(0, 0.3);
  p.set_mode(0, JointMode::Position);
  EXPECT_EQ(p.mode(0), JointMode::Position);
  EXPECT_GT(p.gains(0).kp, 0.0);
  for (int i = 0; i < 2000; ++i) ASSERT_TRUE(p.step().ok());
  EXPECT_NEAR(p.position(0), 0.3, 0.01);  // held where it was when switched
  p.set_mode(0, JointMode::Effort);
  for (int i = 0; i < 200; ++i) ASSERT_TRUE(p.step().ok());
  EXPECT_LT(p.position(0), 0.28);  // released: gravity pulls it back down
  p.reset();
  EXPECT_EQ(p.mode(0), JointMode::Effort);
}

TEST(PhysicsServo, MimicEqualityHolds) {
  const std::string urdf = R"(<robot name="mimic">
  <link name="world"/>
  <link name="a"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="b"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="leader" type="continuous"><parent link="world"/><child link="a"/><origin xyz="0 0 1"/><axis xyz="0 0 1"/></joint>
  <joint name="follower" type="continuous"><parent link="world"/><child link="b"/><origin xyz="1 0 1"/><axis xyz="0 0 1"/>
    <mimic joint="leader" multiplier="-2" offset="0.1"/></joint>
</robot>)";
  auto model = test::build(urdf);
  Physics p(model);
  const std::size_t lead = *model->joint_index("leader"), follow = *model->joint_index("follower");
  double worst = 0.0;
  while (p.time() < 3.0) {
    p.set_effort(lead, 0.05 * std::sin(3.0 * p.time()));
    ASSERT_TRUE(p.step().ok());
    if (p.time() > 0.5) worst = std::max(worst, std::fabs(p.position(follow) - (-2.0 * p.position(lead) + 0.1)));
  }
  EXPECT_GT(std::fabs(p.position(lead)), 0.01);  // it moved
  EXPECT_LT(worst, 2e-3);                        // rad
}

std::string rocker_urdf() {
  return R"(<robot name="rockers">
  <link name="world"/>
  <link name="left"><inertial><mass value="1"/><inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="right"><inertial><mass value="1"/><inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="rocker_L" type="continuous"><parent link="world"/><child link="left"/><origin xyz="0 0.3 1"/><axis xyz="0 1 0"/></joint>
  <joint name="rocker_R" type="continuous"><parent link="world"/><child link="right"/><origin xyz="0 -0.3 1"/><axis xyz="0 -1 0"/>
    <mimic joint="rocker_L"/></joint>
  <gazebo>
    <plugin filename="libleo_gazebo_differential_plugin.so" name="rocker_differential">
      <jointA>rocker_L</jointA><jointB>rocker_R</jointB><forceConstant>1000.0</forceConstant>
    </plugin>
  </gazebo>
</robot>)";
}

TEST(PhysicsServo, DifferentialPluginLawAppliesTheSpringTorques) {
  BuildOptions o;
  o.differential = DifferentialMode::PluginLaw;
  o.world.gravity = 0.0;
  auto model = test::build(rocker_urdf(), o);
  ASSERT_TRUE(model->differential().has_value());
  EXPECT_TRUE(model->differential()->active);
  EXPECT_DOUBLE_EQ(model->differential()->force_constant, 1000.0);
  EXPECT_EQ(model->mjcf().find("<equality>"), std::string::npos);  // the plugin replaces the mimic
  Physics p(model);
  const std::size_t a = *model->joint_index("rocker_L"), b = *model->joint_index("rocker_R");
  p.set_joint_state(a, 0.02);
  p.set_joint_state(b, -0.01);
  ASSERT_TRUE(p.step().ok());
  EXPECT_DOUBLE_EQ(p.differential_torque_a(), -1000.0 * 0.03);
  EXPECT_DOUBLE_EQ(p.differential_torque_b(), 1000.0 * 0.03);
  EXPECT_DOUBLE_EQ(p.applied_effort(a), -30.0);
  EXPECT_DOUBLE_EQ(p.effort(b), 30.0);  // nothing else acts on the rocker
  // The torques act: after one step, qdot = tau / I dt for each rocker (I = 0.1 kg m^2).
  EXPECT_NEAR(p.velocity(a), -30.0 / 0.1 * 0.001, 1e-9);
  EXPECT_NEAR(p.velocity(b), 30.0 / 0.1 * 0.001, 1e-9);
  // Over time the spring pulls the two together (no damping: they oscillate about the mean).
  double worst = 0.0;
  while (p.time() < 1.0) {
    ASSERT_TRUE(p.step().ok());
    worst = std::max(worst, std::fabs(p.position(a) - p.position(b)));
  }
  EXPECT_LE(worst, 0.03 * 1.05);  // symplectic Euler: bounded amplitude ripple (omega h = 0.14)
  EXPECT_NEAR(p.position(a) + p.position(b), 0.01, 1e-9);  // internal forces: the sum is conserved
}

TEST(PhysicsServo, DifferentialMimicModeUsesTheConstraintInstead) {
  BuildOptions o;
  o.world.gravity = 0.0;
  auto model = test::build(rocker_urdf(), o);
  ASSERT_TRUE(model->differential().has_value());
  EXPECT_FALSE(model->differential()->active);
  Physics p(model);
  const std::size_t a = *model->joint_index("rocker_L"), b = *model->joint_index("rocker_R");
  while (p.time() < 1.0) {
    p.set_effort(a, 1.0);
    ASSERT_TRUE(p.step().ok());
  }
  EXPECT_EQ(p.differential_torque_a(), 0.0);
  EXPECT_GT(p.position(a), 0.5);
  EXPECT_NEAR(p.position(b), p.position(a), 2e-3);
}

}  // namespace
}  // namespace mechsim::physics
