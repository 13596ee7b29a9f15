// A ros2_control robot simulated (robots/ros2bots): the description's <parameters> found through
// its gazebo_ros2_control plugin, initial_value honoured, hold_joints against gravity, the
// controller manager at its update_rate, a command past the interface's max clamped, the mimic
// finger following, and the configuration errors a scenario reports.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "control/ports.hpp"
#include "description/robot_loader.hpp"
#include "sim/ros2_control_config.hpp"
#include "sim/scenario.hpp"
#include "sim/scenario_build.hpp"
#include "sim/simulation.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

const fs::path kBots = fs::path(MECHSIM_SOURCE_DIR) / "robots/ros2bots";

description::RobotModel load(const std::string& file, std::map<std::string, std::string> args = {}) {
  description::LoadOptions o;
  o.packages["mechsim_ros2bots"] = kBots.string();
  o.xacro_args = std::move(args);
  return description::load_robot((kBots / "urdf" / file).string(), o).model;
}

std::unique_ptr<Simulation> simulate(const description::RobotModel& robot, Ros2ControlConfig* out = nullptr) {
  const Ros2ControlConfig config = load_ros2_control_config(robot, {});
  SimulationOptions options;
  apply_ros2_control(options, config);
  auto sim = std::make_unique<Simulation>(robot, World{}, config.setup.controllers, options);
  if (out != nullptr) *out = config;
  return sim;
}

double position(const Simulation& sim, const std::string& joint) {
  return sim.mechanism_state().joints[static_cast<std::size_t>(sim.mechanism().joint_index(joint))].position;
}

TEST(Ros2ControlSimulation, ReadsThePluginsParametersAndRunsAtTheUpdateRate) {
  Ros2ControlConfig config;
  auto sim = simulate(load("rrbot.urdf.xacro"), &config);
  EXPECT_EQ(config.setup.controller_manager, "/controller_manager");
  EXPECT_EQ(config.files, (std::vector<std::string>{(kBots / "config/rrbot_controllers.yaml").string()}));
  EXPECT_EQ(config.setup.update_rate, 100.0);
  EXPECT_DOUBLE_EQ(sim->control_period(), 0.01);
  EXPECT_EQ(config.setup.controller_names,
            (std::vector<std::string>{"joint_state_broadcaster", "forward_position_controller", "joint_trajectory_controller",
                                      "gripper_controller"}));
  sim->load_and_start({"joint_state_broadcaster"});
  sim->run_for(0.1);
  // 100 Hz: 10 updates in 0.1 s, each a joint state snapshot.
  auto* port = sim->controllers().controller("joint_state_broadcaster")->port("joint_states");
  EXPECT_EQ(dynamic_cast<control::StatePort<control::JointStateSnapshot>*>(port)->sequence(), 10u);
}

TEST(Ros2ControlSimulation, InitialValueSetsTheJointAndHoldJointsHoldsItAgainstGravity) {
  auto held = simulate(load("rrbot.urdf.xacro"));
  EXPECT_NEAR(position(*held, "joint2"), 0.3, 1e-9);  // initial_value, before any tick
  held->run_for(1.0);
  const double drift_held = std::abs(position(*held, "joint2") - 0.3);
  // The same arm with hold_joints false: gravity takes joint2 (0.5 kg, 0.2 m out, 0.3 rad off).
  description::RobotModel loose = load("rrbot.urdf.xacro");
  for (description::GazeboPlugin& p : loose.plugins) {
    if (p.filename != "libgazebo_ros2_control.so") continue;
    description::XmlNode hold;
    hold.name = "hold_joints";
    hold.text = "false";
    p.xml.children.push_back(hold);
  }
  auto falling = simulate(loose);
  falling->run_for(1.0);
  const double drift_loose = std::abs(position(*falling, "joint2") - 0.3);
  std::cout << "[ figures  ] joint2 after 1 s: held " << drift_held << " rad from 0.3, loose " << drift_loose << " rad\n";
  EXPECT_LT(drift_held, 0.01);
  EXPECT_GT(drift_loose, 0.2);
}

TEST(Ros2ControlSimulation, ForwardCommandPastTheInterfaceMaxStopsAtIt) {
  auto sim = simulate(load("rrbot.urdf.xacro"));
  sim->load_and_start({"forward_position_controller"});
  auto* command = dynamic_cast<control::ArrayCommandPort*>(sim->controllers().controller("forward_position_controller")->port("command"));
  ASSERT_NE(command, nullptr);
  ASSERT_TRUE(command->write(std::vector<double>{1.6, -0.3}));
  sim->run_for(3.0);
  EXPECT_NEAR(position(*sim, "joint1"), 1.0, 0.01);  // its command interface's max
  EXPECT_NEAR(position(*sim, "joint2"), -0.3, 0.01);
}

TEST(Ros2ControlSimulation, TheMimicFingerFollowsInBothDescriptionStyles) {
  for (const char* style : {"param", "urdf"}) {
    auto sim = simulate(load("rrbot.urdf.xacro", {{"mimic", style}}));
    sim->load_and_start({"gripper_controller"});
    auto* command = dynamic_cast<control::ArrayCommandPort*>(sim->controllers().controller("gripper_controller")->port("command"));
    ASSERT_TRUE(command->write(std::vector<double>{0.025}));
    sim->run_for(1.0);
    EXPECT_NEAR(position(*sim, "left_finger_joint"), 0.025, 0.001) << style;
    EXPECT_NEAR(position(*sim, "right_finger_joint"), 0.025, 0.001) << style;
    // No controller may claim the mimic joint.
    EXPECT_TRUE(sim->mechanism().joints[static_cast<std::size_t>(sim->mechanism().joint_index("right_finger_joint"))].interfaces.empty());
  }
}

TEST(Ros2ControlSimulation, ANamespacedRobotFindsItsWildcardParameters) {
  Ros2ControlConfig config;
  auto sim = simulate(load("diffbot.urdf.xacro", {{"ns", "r1"}}), &config);
  EXPECT_EQ(config.setup.controller_manager, "/r1/controller_manager");
  EXPECT_EQ(config.setup.controller_names.size(), 3u);
  EXPECT_TRUE(config.plugin->hold_joints);
  ASSERT_EQ(config.plugin->remappings.size(), 2u);
  sim->load_and_start({"joint_state_broadcaster", "diff_drive_base_controller", "imu_sensor_broadcaster"});
  EXPECT_EQ(sim->controllers().controller_info("diff_drive_base_controller")->claims[0].joints,
            (std::vector<std::string>{"left_wheel_joint", "right_wheel_joint"}));
}

class Ros2ControlScenario : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(::testing::TempDir()) / ("mechsim_ros2_scenario_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string write(const std::string& name, const std::string& content) {
    std::ofstream(dir_ / name) << content;
    return (dir_ / name).string();
  }
  std::string build_error(const std::string& controllers) {
    const std::string file = write("s.yaml", "name: s\nrobot:\n  description: " + (kBots / "urdf/rrbot.urdf.xacro").string() +
                                                 "\n  packages: {mechsim_ros2bots: " + kBots.string() + "}\n" + controllers +
                                                 "duration: 0.1\n");
    try {
      std::string urdf;
      build_simulation(load_scenario(file), urdf);
    } catch (const std::exception& e) {
      return e.what();
    }
    return "built";
  }
  fs::path dir_;
};

TEST_F(Ros2ControlScenario, ConfigurationErrorsNameTheFileAndTheParameter) {
  const std::string bad = write("bad.yaml", R"(controller_manager:
  ros__parameters:
    update_rate: 100
    arm: {type: forward_command_controller/ForwardCommandController}
arm:
  ros__parameters:
    joints: [joint1, elbow]
    interface_name: position
)");
  EXPECT_THAT(build_error("controllers: {file: " + bad + ", start: [arm]}\n"), HasSubstr("elbow"));
  EXPECT_THAT(build_error("controllers: {file: " + bad + ", start: [arm]}\n"), HasSubstr("/arm/joints[1]"));
  const std::string malformed = write("malformed.yaml", "controller_manager:\n  ros__parameters:\n    update_rate: 100\narm:\n  joints: [a]\n  ros__parameters: {x: 1}\n");
  EXPECT_THAT(build_error("controllers: {file: " + malformed + "}\n"), HasSubstr("malformed.yaml:5"));
  EXPECT_THAT(build_error("controllers: {file: " + malformed + "}\n"), HasSubstr("'joints' under node name 'arm' is not a map"));
  EXPECT_THAT(build_error("controllers: {file: " + bad + ", start: [nobody]}\n"), HasSubstr("nobody"));
  EXPECT_EQ(build_error("controllers: {start: [joint_state_broadcaster]}\n"), "built");
  // A controllers.params overlay names parameters the ROS 2 file has.
  const std::string files = "controllers:\n  file: " + (kBots / "config/rrbot_controllers.yaml").string() + "\n";
  EXPECT_EQ(build_error(files + "  params: {forward_position_controller: {interface_name: velocity}}\n"), "built");
  try {
    load_scenario(write("o.yaml", "name: s\nrobot:\n  description: " + (kBots / "urdf/rrbot.urdf.xacro").string() + "\n" + files +
                                      "  params: {forward_position_controller: {interface: velocity}}\nduration: 0.1\n"));
    ADD_FAILURE() << "no error";
  } catch (const ScenarioError& e) {
    EXPECT_THAT(e.what(), HasSubstr("interface"));
  }
}

}  // namespace
}  // namespace mechsim::sim
