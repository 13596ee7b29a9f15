#include "mechanism/safety_limits.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "mechanism/propagation.hpp"

namespace mechsim::mechanism {
namespace {

using description::JointLimits;
using description::JointType;
using description::SafetyController;

// The PR2's r_wrist_flex_joint: <limit effort="10" lower="-2.18" upper="0.0" velocity="3.078"/>
// <safety_controller k_position="20" k_velocity="4" soft_lower_limit="-2.0" soft_upper_limit="-0.1"/>
JointInfo wrist_flex() {
  JointInfo j;
  j.name = "r_wrist_flex_joint";
  j.type = JointType::Revolute;
  j.limits = JointLimits{-2.18, 0.0, 10.0, 3.078};
  j.safety = SafetyController{-2.0, -0.1, 20.0, 4.0};
  j.interfaces = {HardwareInterface::Effort};
  return j;
}

JointState at(double q, double v) {
  JointState s;
  s.position = q;
  s.velocity = v;
  return s;
}

TEST(SafetyLimits, EffortBoundsInTheMiddleOfTheRangeAreTheEffortLimit) {
  // v_high = clamp(-20 (-1 + 0.1), +-3.078) = 3.078; tau_high = clamp(-4 (0 - 3.078), +-10) = 10
  const EffortBounds b = effort_bounds(wrist_flex(), at(-1.0, 0.0));
  EXPECT_DOUBLE_EQ(b.high, 10.0);
  EXPECT_DOUBLE_EQ(b.low, -10.0);
}

TEST(SafetyLimits, PastTheSoftLimitTheJointIsPushedBack) {
  // q = -0.05: v_high = clamp(-20 (-0.05 + 0.1), +-3.078) = -1; tau_high = -4 (0.5 - (-1)) = -6
  //            v_low = clamp(-20 (-0.05 + 2), ...) = -3.078; tau_low = clamp(-4 (0.5 + 3.078)) = -10
  const EffortBounds b = effort_bounds(wrist_flex(), at(-0.05, 0.5));
  EXPECT_NEAR(b.high, -6.0, 1e-12);
  EXPECT_DOUBLE_EQ(b.low, -10.0);
  JointState s = at(-0.05, 0.5);
  s.commanded_effort = 5.0;
  enforce_joint_limits(wrist_flex(), s, 0.001);
  EXPECT_NEAR(s.commanded_effort, -6.0, 1e-12);
}

TEST(SafetyLimits, NearTheVelocityLimitEffortIsReduced) {
  // v = 3.0: tau_high = -4 (3.0 - 3.078) = 0.312
  JointState s = at(-1.0, 3.0);
  s.commanded_effort = 5.0;
  enforce_joint_limits(wrist_flex(), s, 0.001);
  EXPECT_NEAR(s.commanded_effort, 0.312, 1e-12);
  s.commanded_effort = -15.0;
  enforce_joint_limits(wrist_flex(), s, 0.001);
  EXPECT_DOUBLE_EQ(s.commanded_effort, -10.0);
}

TEST(SafetyLimits, ContinuousJointsHaveNoPositionBound) {
  // The PR2's r_wrist_roll_joint: <limit effort="10" velocity="3.6"/> <safety_controller k_velocity="2"/>
  JointInfo roll;
  roll.type = JointType::Continuous;
  roll.continuous = true;
  roll.limits = JointLimits{0.0, 0.0, 10.0, 3.6};
  roll.safety = SafetyController{0.0, 0.0, 0.0, 2.0};
  // v_high = 3.6 whatever q; tau_high = -2 (3 - 3.6) = 1.2; tau_low = clamp(-2 (3 + 3.6)) = -10
  const EffortBounds b = effort_bounds(roll, at(100.0, 3.0));
  EXPECT_NEAR(b.high, 1.2, 1e-12);
  EXPECT_DOUBLE_EQ(b.low, -10.0);
  // The same joint read as revolute would be held at the soft limits 0: v_high = -0 -> tau_high = -6.
  roll.type = JointType::Revolute;
  roll.continuous = false;
  EXPECT_NEAR(effort_bounds(roll, at(100.0, 3.0)).high, -6.0, 1e-12);
}

TEST(SafetyLimits, WithoutSafetyControllerOnlyTheEffortLimit) {
  JointInfo j;
  j.type = JointType::Revolute;
  j.limits = JointLimits{-1.0, 1.0, 7.5, 2.0};
  JointState s = at(5.0, 100.0);  // far outside: no position/velocity law without <safety_controller>
  s.commanded_effort = 20.0;
  enforce_joint_limits(j, s, 0.001);
  EXPECT_DOUBLE_EQ(s.commanded_effort, 7.5);
  s.commanded_effort = -3.0;
  enforce_joint_limits(j, s, 0.001);
  EXPECT_DOUBLE_EQ(s.commanded_effort, -3.0);
}

TEST(SafetyLimits, NoLimitsNoClamp) {
  JointInfo j;
  j.type = JointType::Continuous;
  j.continuous = true;
  JointState s = at(0.0, 0.0);
  s.commanded_effort = 1e6;
  s.commanded_velocity = -1e3;
  enforce_joint_limits(j, s, 0.001);
  EXPECT_DOUBLE_EQ(s.commanded_effort, 1e6);
  EXPECT_DOUBLE_EQ(s.commanded_velocity, -1e3);
}

JointInfo position_joint(bool soft) {
  JointInfo j;
  j.type = JointType::Revolute;
  j.limits = JointLimits{-1.0, 1.0, 10.0, 2.0};
  if (soft) j.safety = SafetyController{-0.8, 0.8, 10.0, 1.0};
  return j;
}

TEST(SafetyLimits, PositionCommandIsReachableWithinOnePeriod) {
  const JointInfo j = position_joint(false);
  JointState s = at(0.5, 0.0);
  s.command_mode = HardwareInterface::Position;
  s.commanded_position = 0.9;
  enforce_joint_limits(j, s, 0.001);  // from the measured 0.5: at most 2 rad/s * 1 ms
  EXPECT_NEAR(s.commanded_position, 0.502, 1e-15);
  s.commanded_position = 0.9;
  enforce_joint_limits(j, s, 0.001);  // from the previous command 0.502
  EXPECT_NEAR(s.commanded_position, 0.504, 1e-15);
  s.commanded_position = 0.0;
  enforce_joint_limits(j, s, 0.01);
  EXPECT_NEAR(s.commanded_position, 0.484, 1e-15);
}

TEST(SafetyLimits, PositionCommandStaysInsideTheLimits) {
  JointInfo j = position_joint(false);
  JointState s = at(0.9995, 0.0);
  s.command_mode = HardwareInterface::Position;
  s.commanded_position = 5.0;
  enforce_joint_limits(j, s, 0.001);
  EXPECT_DOUBLE_EQ(s.commanded_position, 1.0);
  // With a safety controller the soft limits bound it.
  j = position_joint(true);
  s = at(0.0, 0.0);
  s.command_mode = HardwareInterface::Position;
  s.commanded_position = 5.0;
  enforce_joint_limits(j, s, 1.0);
  EXPECT_DOUBLE_EQ(s.commanded_position, 0.8);
  // Continuous joints: no position bound, only reachability.
  j.type = JointType::Continuous;
  j.continuous = true;
  s = at(10.0, 0.0);
  s.command_mode = HardwareInterface::Position;
  s.commanded_position = 12.0;
  enforce_joint_limits(j, s, 0.5);
  EXPECT_DOUBLE_EQ(s.commanded_position, 11.0);
}

TEST(SafetyLimits, VelocityCommandClampedToTheVelocityLimit) {
  const JointInfo j = position_joint(false);
  JointState s = at(0.0, 0.0);
  s.command_mode = HardwareInterface::Velocity;
  s.commanded_velocity = 5.0;
  enforce_joint_limits(j, s, 0.001);
  EXPECT_DOUBLE_EQ(s.commanded_velocity, 2.0);
  s.commanded_velocity = -5.0;
  enforce_joint_limits(j, s, 0.001);
  EXPECT_DOUBLE_EQ(s.commanded_velocity, -2.0);
  EXPECT_TRUE(std::isnan(s.last_position_command));
}

TEST(SafetyLimits, NonFiniteCommandsNeverReachAnActuator) {
  MechanismModel m;
  m.joints.push_back(position_joint(false));
  m.joints.push_back(position_joint(false));
  m.joints[1].role = JointRole::Passive;
  m.actuators.push_back(ActuatorInfo{"a", 0});
  MechanismState s = make_state(m);
  s.joints[0].position = 0.3;
  s.joints[0].command_mode = HardwareInterface::Position;
  s.joints[0].commanded_effort = std::numeric_limits<double>::quiet_NaN();
  s.joints[0].commanded_position = std::numeric_limits<double>::infinity();
  s.joints[0].commanded_velocity = -std::numeric_limits<double>::infinity();
  s.joints[1].commanded_effort = 1e9;  // passive: not a command, left alone
  enforce_safety_limits(m, s);
  EXPECT_EQ(s.joints[0].commanded_effort, 0.0);
  EXPECT_DOUBLE_EQ(s.joints[0].commanded_position, 0.3);  // holds the measured position
  EXPECT_EQ(s.joints[0].commanded_velocity, 0.0);
  EXPECT_EQ(s.rejected_commands, 3u);
  EXPECT_EQ(s.joints[1].commanded_effort, 1e9);
  // A later NaN position holds the previous good command.
  s.joints[0].position = 0.35;
  s.joints[0].commanded_position = std::numeric_limits<double>::quiet_NaN();
  enforce_safety_limits(m, s, 0.001);
  EXPECT_DOUBLE_EQ(s.joints[0].commanded_position, 0.3);
  EXPECT_EQ(s.rejected_commands, 4u);
}

TEST(SafetyLimits, BadLimitsDoNotMisbehave) {
  // Soft limits outside the hard ones, lower > upper after intersecting: still a finite clamp.
  JointInfo j = position_joint(true);
  j.safety->soft_lower_limit = 0.9;
  j.safety->soft_upper_limit = 0.95;
  j.limits->upper = 0.5;
  JointState s = at(0.0, 0.0);
  s.command_mode = HardwareInterface::Position;
  s.commanded_position = 0.7;
  enforce_joint_limits(j, s, 1.0);
  EXPECT_TRUE(std::isfinite(s.commanded_position));
  EXPECT_LE(s.commanded_position, 0.9);
}

}  // namespace
}  // namespace mechsim::mechanism
