// The PR2 controllers' update() allocates nothing: the base controller and odometry driving
// the 12-joint test base, the gripper with an active goal that stalls, the laser sweeping;
// commands and goals written between ticks. The counting operator new is allocation_test.cpp's.

#include <gtest/gtest.h>

#include "control/controller_manager.hpp"
#include "controllers/builtin_controllers.hpp"
#include "controllers/pr2/laser_scanner_traj_controller.hpp"
#include "controllers/drive/pr2_base_controller.hpp"
#include "controllers/gripper/pr2_gripper_controller.hpp"
#include "controllers/drive/test/pr2_base_test_util.hpp"
#include "mechanism/propagation.hpp"
#include "controllers/test/allocation_counter.hpp"

namespace mechsim::control {
namespace {

TEST(Pr2Allocation, BaseOdometryGripperAndLaserUpdatesAllocateNothing) {
  std::vector<testing::JointSpec> joints;
  {
    auto base = testing::make_pr2_base_robot();
    for (const auto& j : base->model.joints) {
      joints.push_back({j.name, description::JointType::Continuous, description::JointLimits{0.0, 0.0, 100.0, 15.0}});
    }
  }
  joints.push_back({"r_gripper_joint", description::JointType::Prismatic, description::JointLimits{0.0, 0.09, 1000.0, 0.2}});
  joints.push_back({"laser_tilt_mount_joint"});
  auto robot = testing::make_robot(joints);
  robot->joint("r_gripper_joint").position = 0.08;
  mechanism::propagate_joint_to_actuator_position(robot->model, robot->state);
  const std::string yaml = testing::pr2_base_yaml() +
                           "  gripper:\n    type: pr2_mechanism_controllers/Pr2GripperController\n"
                           "    joint: r_gripper_joint\n    pid: {p: 100.0, d: 20.0}\n"
                           "  laser:\n    type: pr2_mechanism_controllers/LaserScannerTrajController\n"
                           "    joint: laser_tilt_mount_joint\n    pid: {p: 8.0, d: 0.4}\n";
  ControllerManager manager(robot->model, robot->state, Params::from_yaml_string(yaml).child("base"),
                            builtin_controller_registry());
  const std::vector<std::string> names{"base_controller", "odometry", "gripper", "laser"};
  for (const auto& n : names) ASSERT_TRUE(manager.load_controller(n).ok) << n;
  ASSERT_TRUE(manager.switch_controllers(names, {}, SwitchStrictness::Strict).ok);
  double time = testing::run(manager, *robot, 0.0, 2);

  auto* base = dynamic_cast<Pr2BaseController*>(manager.controller("base_controller"));
  auto* gripper = dynamic_cast<Pr2GripperController*>(manager.controller("gripper"));
  auto* laser = dynamic_cast<LaserScannerTrajController*>(manager.controller("laser"));
  ASSERT_TRUE(base->command_port().write({{0.2, 0.1, 0.3}, {}}));
  ASSERT_TRUE(laser->command_port().write("linear", 0.5, 0.4, 0.2));
  const GripperSubmission goal = gripper->goal_port().submit({0.0, 5.0});
  ASSERT_TRUE(goal.accepted);

  testing::start_counting_allocations();
  for (int i = 0; i < 1000; ++i) {
    if (i % 100 == 0) {
      // Commands from "outside" between ticks: the port writes copy into preallocated slots.
      base->command_port().write({{0.2, 0.1, 0.3 - 0.0001 * i}, {}});
    }
    time = testing::run(manager, *robot, time, 1);
  }
  const long allocations = testing::stop_counting_allocations();
  EXPECT_EQ(allocations, 0);
  for (const auto& n : names) EXPECT_EQ(manager.controller_info(n)->statistics.failures, 0u) << n;
  EXPECT_TRUE(base->status_port().read().applied.vx > 0.0);
}

}  // namespace
}  // namespace mechsim::control
