// The bookkeeping behind pr2_controller_manager's joint_states and mechanism_statistics, through
// the bridge on a small inline robot: which joints, the per-period window (min/max position,
// max |velocity|, violated_limits), the odometer, actuators and controller statistics.
#include <gtest/gtest.h>

#include <cmath>

#include "description/urdf/urdf_parser.hpp"
#include "bridge/sim_bridge.hpp"
#include "bridge/test/pendulum_robot.hpp"

namespace mechsim::bridge {
namespace {

const std::string kPendulum = test::pendulum_urdf(10);

const JointStatisticsData& joint(const MechanismStatisticsData& s, const std::string& name) {
  for (const JointStatisticsData& j : s.joints) {
    if (j.name == name) return j;
  }
  throw std::runtime_error("no joint " + name);
}

TEST(MechanismStatistics, WindowOdometerActuatorsControllersAndViolatedLimits) {
  BridgeOptions options;
  options.robot = description::parse_urdf_string(kPendulum, "pendulum", {});
  options.controller_params =
      control::Params::from_yaml_string("push: {type: effort_controllers/JointEffortController, joint: hinge}", "c");
  options.paused = true;  // the switch below is applied by the first tick
  SimBridge bridge(options);
  bridge.enable_mechanism_statistics();
  ASSERT_TRUE(bridge.load_controller("push").ok);
  ASSERT_TRUE(bridge.switch_controllers({"push"}, {}, true, 1.0).ok);
  bridge.unpause();
  std::string error;
  ASSERT_TRUE(bridge.run_for(0.2, &error)) << error;

  MechanismStatisticsData s;
  bridge.take_mechanism_statistics(s);
  EXPECT_NEAR(s.stamp, 0.2, 1e-9);
  ASSERT_EQ(s.joints.size(), 1u);  // the fixed joint is left out
  const JointStatisticsData& swing = joint(s, "hinge");
  // The bob falls from level: the hinge turns one way (about +y, a level bob at +x falls down).
  EXPECT_GT(swing.max_position - swing.min_position, 0.1);
  EXPECT_NEAR(swing.odometer, swing.max_position - swing.min_position, 1e-9);  // one way so far
  EXPECT_GT(swing.max_abs_velocity, 1.0);
  EXPECT_GE(swing.position, swing.min_position);
  EXPECT_LE(swing.position, swing.max_position);
  EXPECT_FALSE(swing.violated_limits);
  ASSERT_EQ(s.actuators.size(), 1u);
  EXPECT_EQ(s.actuators[0].name, "m");
  EXPECT_NEAR(s.actuators[0].position, 10.0 * swing.position, 1e-9);
  ASSERT_EQ(s.controllers.size(), 1u);
  EXPECT_EQ(s.controllers[0].name, "push");
  EXPECT_TRUE(s.controllers[0].running);
  EXPECT_GT(s.controllers[0].mean_time, 0.0);
  EXPECT_GE(s.controllers[0].max_time, s.controllers[0].mean_time);

  // joint_states: the same joints, the same tick.
  JointStatesData js;
  bridge.mechanism_joint_states(js);
  ASSERT_EQ(js.names, std::vector<std::string>{"hinge"});
  ASSERT_EQ(js.position.size(), 1u);
  EXPECT_EQ(js.position[0], swing.position);
  EXPECT_EQ(js.velocity[0], swing.velocity);

  // A new window with no tick in it: min = max = now, nothing violated, the odometer kept.
  const double odometer = swing.odometer;
  bridge.take_mechanism_statistics(s);
  EXPECT_EQ(joint(s, "hinge").min_position, joint(s, "hinge").position);
  EXPECT_EQ(joint(s, "hinge").max_position, joint(s, "hinge").position);
  EXPECT_EQ(joint(s, "hinge").odometer, odometer);

  // An effort beyond the limit is clamped to it by the safety limits: a violated limit.
  PortRef command;
  for (const PortRef& p : bridge.ports("push")) {
    if (p.name == "command") command = p;
  }
  ASSERT_EQ(command.type, PortType::ScalarCommand);
  EXPECT_EQ(command.controller_type, "effort_controllers/JointEffortController");
  ASSERT_TRUE(write_scalar(command, 100.0, &error)) << error;
  ASSERT_TRUE(bridge.run_for(0.01, &error)) << error;
  bridge.take_mechanism_statistics(s);
  EXPECT_TRUE(joint(s, "hinge").violated_limits);
  EXPECT_NEAR(joint(s, "hinge").commanded_effort, 50.0, 1e-9);
  // ... and that window is over once taken.
  bridge.take_mechanism_statistics(s);
  EXPECT_FALSE(joint(s, "hinge").violated_limits);
}

TEST(MechanismStatistics, ReadsNeedEnabling) {
  BridgeOptions options;
  options.robot = description::parse_urdf_string(kPendulum, "pendulum", {});
  options.paused = true;
  SimBridge bridge(options);
  MechanismStatisticsData s;
  EXPECT_THROW(bridge.take_mechanism_statistics(s), std::logic_error);
  JointStatesData js;
  EXPECT_THROW(bridge.mechanism_joint_states(js), std::logic_error);
}

}  // namespace
}  // namespace mechsim::bridge
