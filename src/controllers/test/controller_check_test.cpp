#include "control/controller_check.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "control/controller_manager.hpp"
#include "controllers/builtin_controllers.hpp"
#include "controllers/test/test_robot.hpp"
#include "description/urdf/urdf_parser.hpp"
#include "mechanism/build_mechanism.hpp"

namespace mechsim::control {
namespace {

using ::testing::HasSubstr;

TEST(ControllerCheck, FindsControllersInNamespacesAndAtTopLevel) {
  auto robot = testing::make_robot(3);
  Params root = Params::from_yaml_string(R"(
top_level:
  type: effort_controllers/JointEffortController
  joint: j0
robot:
  pos:
    type: effort_controllers/JointPositionController
    joint: j1
    pid: {p: 1}
  bad_joint:
    type: effort_controllers/JointEffortController
    joint: wheel_X
  bad_type:
    type: fancy_controllers/Magic
  arm:
    group:
      type: velocity_controllers/JointGroupVelocityController
      joints: [j1, j2]
  gazebo_gains: {j1: {p: 3, i: 0}}
scalar: 4
)", "ctrl.yaml");
  auto checks = check_controllers(robot->model, root, builtin_controller_registry());
  ASSERT_EQ(checks.size(), 5u);
  EXPECT_EQ(checks[0].name, "top_level");
  EXPECT_EQ(checks[0].ns, "/");
  EXPECT_TRUE(checks[0].ok()) << checks[0].error;
  EXPECT_EQ(checks[0].claims[0].joints, (std::vector<std::string>{"j0"}));

  EXPECT_EQ(checks[1].path, "/robot/pos");
  EXPECT_EQ(checks[1].type, "effort_controllers/JointPositionController");
  EXPECT_TRUE(checks[1].ok()) << checks[1].error;

  EXPECT_FALSE(checks[2].ok());
  EXPECT_THAT(checks[2].error, HasSubstr("'bad_joint'"));
  EXPECT_THAT(checks[2].error, HasSubstr("unknown joint 'wheel_X' (parameter /robot/bad_joint/joint)"));

  EXPECT_THAT(checks[3].error, HasSubstr("unknown type 'fancy_controllers/Magic' (parameter /robot/bad_type/type)"));

  EXPECT_EQ(checks[4].path, "/robot/arm/group");
  EXPECT_EQ(checks[4].ns, "/robot/arm");
  EXPECT_TRUE(checks[4].ok()) << checks[4].error;
  EXPECT_EQ(checks[4].claims[0].interface, HardwareInterface::Velocity);

  EXPECT_EQ(describe(checks[4]), "/robot/arm/group (velocity_controllers/JointGroupVelocityController): velocity [j1, j2]");
  EXPECT_THAT(describe(checks[2]), HasSubstr("/robot/bad_joint (effort_controllers/JointEffortController): ERROR "));
}

TEST(ControllerCheck, MalformedFileNamesFileAndLine) {
  auto robot = testing::make_robot(1);
  auto path = std::filesystem::temp_directory_path() / ("mechsim_check_bad_" + std::to_string(::getpid()) + ".yaml");
  {
    std::ofstream out(path);
    out << "cc8:\n  c:\n    type: [unclosed\n";
  }
  try {
    (void)check_controllers_file(robot->model, path.string(), builtin_controller_registry());
    FAIL() << "expected a ParamsError";
  } catch (const ParamsError& e) {
    EXPECT_THAT(e.what(), HasSubstr(path.string() + ":"));
  }
  std::filesystem::remove(path);
}

TEST(ControllerCheck, AllCc8ControllersLoadAgainstTheCc8Mechanism) {
  const std::filesystem::path shared = MECHSIM_SHARED_DIR;
  const auto urdf = shared / "robots/reference/cc8.urdf";
  const auto yaml = shared / "robots/cc8_description/config/controller.yaml";
  if (!std::filesystem::exists(urdf) || !std::filesystem::exists(yaml)) {
    GTEST_SKIP() << "shared data not found at " << shared << " (needs robots/reference/cc8.urdf and "
                 << "robots/cc8_description/config/controller.yaml)";
  }
  const description::RobotModel robot = description::parse_urdf_file(urdf.string(), description::UrdfOptions{});
  const mechanism::MechanismModel model = mechanism::build_mechanism(robot);
  auto checks = check_controllers_file(model, yaml.string(), builtin_controller_registry());
  ASSERT_EQ(checks.size(), 11u);
  int position_controllers = 0;
  for (const auto& c : checks) {
    EXPECT_TRUE(c.ok()) << c.path << ": " << c.error;
    EXPECT_EQ(c.ns, "/cc8");
    if (c.type == "effort_controllers/JointPositionController") {
      ++position_controllers;
      ASSERT_EQ(c.claims.size(), 1u);
      EXPECT_EQ(c.claims[0].interface, HardwareInterface::Effort);
      ASSERT_EQ(c.claims[0].joints.size(), 1u);
      EXPECT_EQ(c.name, c.claims[0].joints[0] + "_position_controller");
    }
  }
  EXPECT_EQ(position_controllers, 10);
  EXPECT_EQ(checks[0].name, "joint_state_controller");
  EXPECT_TRUE(checks[0].claims.empty());
}

TEST(ControllerCheck, Cc8ControllersAllStartTogetherUnderStrictSwitching) {
  const std::filesystem::path shared = MECHSIM_SHARED_DIR;
  const auto urdf = shared / "robots/reference/cc8.urdf";
  const auto yaml = shared / "robots/cc8_description/config/controller.yaml";
  if (!std::filesystem::exists(urdf) || !std::filesystem::exists(yaml)) {
    GTEST_SKIP() << "shared data not found at " << shared;
  }
  testing::TestRobot robot;
  robot.model = mechanism::build_mechanism(description::parse_urdf_file(urdf.string(), description::UrdfOptions{}));
  robot.state = mechanism::make_state(robot.model);
  ControllerManager manager(robot.model, robot.state, Params::from_yaml_file(yaml.string()).child("cc8"),
                            builtin_controller_registry());
  std::vector<std::string> names = manager.params().keys();
  ASSERT_EQ(names.size(), 11u);
  for (const auto& n : names) ASSERT_TRUE(manager.load_controller(n).ok) << n;
  auto s = manager.switch_controllers(names, {}, SwitchStrictness::Strict);
  ASSERT_TRUE(s.ok) << s.error;
  auto* steering = manager.controller("steering_FL_position_controller")->port_as<ScalarCommandPort>("command");
  double time = testing::run(manager, robot, 0.0, 1);
  ASSERT_TRUE(steering->write(0.3));
  time = testing::run(manager, robot, time, 99);
  for (const auto& info : manager.list_controllers()) {
    EXPECT_EQ(info.state, ControllerLifecycle::Running) << info.name << " " << info.failure;
  }
  EXPECT_GT(robot.joint("steering_FL").position, 0.0);  // pushed towards +0.3 rad
  auto* js = manager.controller("joint_state_controller")->port_as<StatePort<JointStateSnapshot>>("joint_states");
  EXPECT_EQ(js->sequence(), 4u);  // 0.1 s at 50 Hz, the first one 20 ms after starting
  EXPECT_EQ(js->read().names.size(), robot.model.joints.size());
}

}  // namespace
}  // namespace mechsim::control
