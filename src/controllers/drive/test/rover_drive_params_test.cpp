// Filling the rover drive's geometry parameters from a robot description, and loading the
// controller on the real CC8's mechanism (shared/robots/reference/cc8.urdf).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "control/controller_manager.hpp"
#include "controllers/builtin_controllers.hpp"
#include "controllers/drive/rover_drive_controller.hpp"
#include "controllers/drive/rover_drive_params.hpp"
#include "description/robot_loader.hpp"
#include "description/urdf/urdf_parser.hpp"
#include "mechanism/build_mechanism.hpp"

namespace mechsim::control {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

constexpr const char* kYaml = R"(cc8:
  rover:
    type: mechsim/RoverDriveController
    steering_joints: [steering_FL, steering_FR, steering_RL, steering_RR]
    wheel_joints: [wheel_joint_FL, wheel_joint_FR, wheel_joint_ML, wheel_joint_MR, wheel_joint_RL, wheel_joint_RR]
    steering_pid: {p: 60.0, i: 5.0, d: 3.0, i_clamp: 5.0}
    wheel_pid: {p: 8.0, i: 20.0, i_clamp: 15.0}
  joint_state_controller:
    type: joint_state_controller/JointStateController
)";

std::optional<description::RobotModel> reference_cc8() {
  const fs::path path = fs::path(MECHSIM_SHARED_DIR) / "robots" / "reference" / "cc8.urdf";
  if (!fs::exists(path)) return std::nullopt;
  description::UrdfOptions options;
  options.lenient = true;
  return description::parse_urdf_file(path.string(), options);
}

TEST(RoverDriveParams, FillsTheGeometryOfTheReferenceCc8AndLoads) {
  const auto robot = reference_cc8();
  if (!robot) GTEST_SKIP() << "shared data not found at " << MECHSIM_SHARED_DIR << "/robots/reference/cc8.urdf";
  const Params root = Params::from_yaml_string(kYaml);
  const Params ns = root.child("cc8");
  EXPECT_EQ(fill_rover_drive_geometry_all(ns, *robot), 1);
  const Params p = ns.child("rover");
  EXPECT_DOUBLE_EQ(p.get<double>("wheel_radius"), 0.09);
  EXPECT_EQ(p.get<double>("wheel_axis_signs/wheel_joint_ML"), -1.0);
  EXPECT_EQ(p.get<double>("wheel_axis_signs/wheel_joint_RL"), 1.0);
  EXPECT_EQ(p.get<double>("steering_axis_signs/steering_FR"), -1.0);
  EXPECT_EQ(p.get<std::string>("wheel_steering/wheel_joint_RR"), "steering_RR");
  EXPECT_FALSE(p.has("wheel_steering/wheel_joint_MR"));
  EXPECT_EQ(fill_rover_drive_geometry(p, *robot), 0);  // everything is there now

  const mechanism::MechanismModel model = mechanism::build_mechanism(*robot);
  mechanism::MechanismState state = mechanism::make_state(model);
  ControllerManager manager(model, state, ns, builtin_controller_registry());
  const ControlResult r = manager.load_controller("rover");
  ASSERT_TRUE(r.ok) << r.error;
  auto* c = dynamic_cast<RoverDriveController*>(manager.controller("rover"));
  ASSERT_NE(c, nullptr);
  const RoverKinematics& k = c->config().kinematics;
  ASSERT_EQ(k.wheels.size(), 6u);
  // FL pivots at (0.496003, 0.275 + 0.0215 + 0.094); its tyre is 0.059 m out on the wheel joint
  // and 0.06 m back in on the collision cylinder.
  EXPECT_NEAR(k.wheels[0].x, 0.496003, 1e-9);
  EXPECT_NEAR(k.wheels[0].y, 0.3905, 1e-9);
  EXPECT_NEAR(k.wheels[0].offset, 0.059 - 0.06, 1e-9);
  EXPECT_NEAR(k.wheels[1].offset, -(0.059 - 0.06), 1e-9);
  EXPECT_NEAR(k.wheels[2].y, 0.275 + 0.0215 + 0.086631 + 0.121437 - 0.06, 1e-9);  // ML tyre
  EXPECT_NEAR(k.axle_x, -0.211097 + 0.211047, 1e-9);  // the middle axle, 0.05 mm behind base_link
  EXPECT_EQ(k.wheels[4].steering, 2);
  EXPECT_EQ(k.wheels[2].steering, -1);
  EXPECT_EQ(k.wheels[3].axis_sign, -1.0);
}

TEST(RoverDriveParams, DrivesMechsimsOwnCc8Xacro) {
  const fs::path dir = fs::path(MECHSIM_SOURCE_DIR) / "robots" / "cc8";
  description::LoadOptions options;
  options.packages["mechsim_cc8"] = dir.string();
  const description::LoadedRobot robot = description::load_robot((dir / "urdf" / "cc8.urdf.xacro").string(), options);
  const Params ns = Params::from_yaml_string(kYaml).child("cc8");
  EXPECT_EQ(fill_rover_drive_geometry_all(ns, robot.model), 1);
  const mechanism::MechanismModel model = mechanism::build_mechanism(robot.model);
  mechanism::MechanismState state = mechanism::make_state(model);
  ControllerManager manager(model, state, ns, builtin_controller_registry());
  const ControlResult r = manager.load_controller("rover");
  ASSERT_TRUE(r.ok) << r.error;
  auto* c = dynamic_cast<RoverDriveController*>(manager.controller("rover"));
  ASSERT_NE(c, nullptr);
  const RoverKinematics& k = c->config().kinematics;
  EXPECT_DOUBLE_EQ(k.wheel_radius, 0.09);
  EXPECT_NEAR(k.wheels[0].offset, 0.059 - 0.045, 1e-9);  // mechsim's tyres sit 0.045 m inboard
  EXPECT_DOUBLE_EQ(c->config().max_steering_rate, 3.0);  // the steering joints' URDF limit
  EXPECT_DOUBLE_EQ(c->config().max_wheel_speed, 20.0);
  ASSERT_TRUE(manager.switch_controllers({"rover"}, {}, SwitchStrictness::Strict).ok);
  manager.update(0.0, 0.001);
  ASSERT_TRUE(c->command_port().write(Twist{{0.5, 0.0, 0.0}, {}}));
  manager.update(0.001, 0.001);
  // Straight ahead: 0.5 / 0.09 rad/s on every wheel, signed by its axis (FL +y, ML -y).
  const auto s = c->state_port().read();
  EXPECT_NEAR(s.joints[4].set_point, 0.5 / 0.09, 1e-9);
  EXPECT_NEAR(s.joints[6].set_point, -0.5 / 0.09, 1e-9);
}

TEST(RoverDriveParams, KeepsWhatTheYamlGives) {
  const auto robot = reference_cc8();
  if (!robot) GTEST_SKIP() << "shared data not found at " << MECHSIM_SHARED_DIR << "/robots/reference/cc8.urdf";
  Params root = Params::from_yaml_string(kYaml);
  Params p = root.child("cc8/rover");
  p.set("wheel_radius", 0.1);
  p.set("wheel_positions/wheel_joint_FL", std::vector<double>{0.5, 0.45});
  const int set = fill_rover_drive_geometry(p, *robot);
  EXPECT_EQ(set, 6 * 2 + 4 + 4 * 2 - 1);  // all but the radius and one position
  EXPECT_DOUBLE_EQ(p.get<double>("wheel_radius"), 0.1);
  EXPECT_EQ(p.get<std::vector<double>>("wheel_positions/wheel_joint_FL"), (std::vector<double>{0.5, 0.45}));
}

TEST(RoverDriveParams, UnknownJointInTheDescriptionNamesTheParameter) {
  const auto robot = reference_cc8();
  if (!robot) GTEST_SKIP() << "shared data not found at " << MECHSIM_SHARED_DIR << "/robots/reference/cc8.urdf";
  std::string yaml = kYaml;
  yaml.replace(yaml.find("steering_RL,"), 12, "steering_XX,");
  const Params p = Params::from_yaml_string(yaml).child("cc8/rover");
  try {
    fill_rover_drive_geometry(p, *robot);
    FAIL() << "no error";
  } catch (const ControllerConfigError& e) {
    EXPECT_THAT(e.what(), HasSubstr("steering_XX"));
    EXPECT_THAT(e.what(), HasSubstr("/cc8/rover/steering_joints[2]"));
  }
}

TEST(RoverDriveParams, MissingJointListsNameTheParameter) {
  const Params p = Params::from_yaml_string("rover: {type: mechsim/RoverDriveController, wheel_radius: 0.1}").child("rover");
  description::RobotModel empty;
  try {
    fill_rover_drive_geometry(p, empty);
    FAIL() << "no error";
  } catch (const ControllerConfigError& e) {
    EXPECT_THAT(e.what(), HasSubstr("/rover/steering_joints"));
  }
}

TEST(RoverDriveParams, AJointInBothListsNamesBothParameters) {
  const Params p = Params::from_yaml_string("base: {casters: [c0, c1], wheels: [w0, c1, w1]}").child("base");
  try {
    read_steered_joint_lists(p, "casters", 1, "wheels", 1);
    FAIL() << "no error";
  } catch (const ControllerConfigError& e) {
    EXPECT_THAT(e.what(), HasSubstr("joint 'c1' is in both /base/casters and /base/wheels"));
  }
  const Params ok = Params::from_yaml_string("base: {casters: [c0], wheels: [w0, w1]}").child("base");
  const SteeredJointLists lists = read_steered_joint_lists(ok, "casters", 1, "wheels", 2);
  EXPECT_THAT(lists.steering, ::testing::ElementsAre("c0"));
  EXPECT_THAT(lists.wheels, ::testing::ElementsAre("w0", "w1"));
}

}  // namespace
}  // namespace mechsim::control
