// ROS 2 parameter files: node names (plain, namespaced, nested, wildcards), dotted names, the
// order files and entries apply in, the controller manager's setup, and the errors malformed
// files get (file and line named).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "control/params_edit.hpp"
#include "control/ros2_params.hpp"

namespace mechsim::control {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

class Ros2Params : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(::testing::TempDir()) / ("mechsim_ros2_params_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string write(const std::string& name, const std::string& content) {
    const fs::path p = dir_ / name;
    std::ofstream(p) << content;
    return p.string();
  }
  fs::path dir_;
};

TEST(Ros2NodeNames, MatchAsRclcppMatchesThem) {
  EXPECT_TRUE(ros2_node_name_matches("/controller_manager", "/controller_manager"));
  EXPECT_FALSE(ros2_node_name_matches("/controller_manager", "/r1/controller_manager"));
  EXPECT_TRUE(ros2_node_name_matches("/**", "/r1/controller_manager"));
  EXPECT_TRUE(ros2_node_name_matches("/**", "/controller_manager"));
  EXPECT_TRUE(ros2_node_name_matches("/**/controller_manager", "/controller_manager"));
  EXPECT_TRUE(ros2_node_name_matches("/**/controller_manager", "/a/b/controller_manager"));
  EXPECT_FALSE(ros2_node_name_matches("/**/controller_manager", "/a/controller_manager2"));
  EXPECT_TRUE(ros2_node_name_matches("/*/arm_controller", "/r1/arm_controller"));
  EXPECT_FALSE(ros2_node_name_matches("/*/arm_controller", "/arm_controller"));
  EXPECT_TRUE(ros2_node_name_matches("/r1/*", "/r1/arm_controller"));
}

TEST_F(Ros2Params, MergesMatchingEntriesInOrderWithDottedNamesExpanded) {
  const std::string a = write("a.yaml", R"(/**:
  ros__parameters:
    use_sim_time: true
    gains.j1.p: 1.0
controller_manager:
  ros__parameters:
    update_rate: 250
    arm:
      type: joint_trajectory_controller/JointTrajectoryController
arm:
  ros__parameters:
    joints: [j1, j2]
    gains:
      j1: {p: 5.0, d: 0.1}
    linear.x.max_velocity: 2.0
)");
  const std::string b = write("b.yaml", R"(r1:
  arm:
    ros__parameters:
      joints: [j3]
/arm:
  ros__parameters:
    gains.j1.i: 0.5
)");
  const Ros2ParameterSet set = Ros2ParameterSet::from_files({a, b});
  ASSERT_EQ(set.entries().size(), 5u);
  EXPECT_EQ(set.entries()[3].pattern, "/r1/arm");
  const Params arm = set.parameters_for("/arm");
  EXPECT_TRUE(arm.get<bool>("use_sim_time"));
  EXPECT_EQ(arm.get<std::vector<std::string>>("joints"), (std::vector<std::string>{"j1", "j2"}));
  EXPECT_EQ(arm.get<double>("gains/j1/p"), 5.0);  // the node's own entry comes after /**
  EXPECT_EQ(arm.get<double>("gains/j1/d"), 0.1);
  EXPECT_EQ(arm.get<double>("gains/j1/i"), 0.5);  // the second file adds to the map
  EXPECT_EQ(arm.get<double>("linear/x/max_velocity"), 2.0);
  // Values keep the file and line they came from.
  EXPECT_EQ(arm.child("gains/j1/i").location(), b + ":7");
  EXPECT_EQ(arm.child("joints").location(), a + ":12");
  const Params r1 = set.parameters_for("/r1/arm");
  EXPECT_EQ(r1.get<std::vector<std::string>>("joints"), (std::vector<std::string>{"j3"}));
  EXPECT_FALSE(set.has_node("/r2/arm") && set.parameters_for("/r2/arm").has("joints"));
}

TEST_F(Ros2Params, TheControllerManagerSetupDeclaresTypedControllersWithTheirOwnParameters) {
  const std::string f = write("c.yaml", R"(/**/controller_manager:
  ros__parameters:
    update_rate: 50
    joint_state_broadcaster:
      type: joint_state_broadcaster/JointStateBroadcaster
    arm_controller:
      type: forward_command_controller/ForwardCommandController
/**/arm_controller:
  ros__parameters:
    joints: [j1]
    interface_name: position
/r1/typo_controller:
  ros__parameters:
    joints: [j1]
/r1/own_type_controller:
  ros__parameters:
    type: position_controllers/JointGroupPositionController
    joints: [j2]
)");
  const Ros2ParameterSet set = Ros2ParameterSet::from_files({f});
  const Ros2ControlSetup setup = ros2_control_setup(set, "/r1/controller_manager");
  EXPECT_EQ(setup.node_namespace, "/r1");
  EXPECT_EQ(setup.update_rate, 50.0);
  EXPECT_TRUE(setup.update_rate_given);
  EXPECT_EQ(setup.controller_names,
            (std::vector<std::string>{"joint_state_broadcaster", "arm_controller", "own_type_controller"}));
  EXPECT_EQ(setup.controllers.get<std::string>("own_type_controller/type"), "position_controllers/JointGroupPositionController");
  EXPECT_EQ(setup.controllers.get<std::string>("arm_controller/type"), "forward_command_controller/ForwardCommandController");
  EXPECT_EQ(setup.controllers.get<std::string>("arm_controller/interface_name"), "position");
  EXPECT_EQ(setup.controllers.child("arm_controller/type").location(), f + ":7");
  EXPECT_EQ(setup.controllers.child("arm_controller").path(), "/arm_controller");
  ASSERT_EQ(setup.notes.size(), 1u);
  EXPECT_THAT(setup.notes[0], HasSubstr("parameters of node /r1/typo_controller, which controller manager /r1/controller_manager does not declare"));
  // A manager the files do not mention: ros2_control's default rate, no controllers, a note.
  const Ros2ControlSetup other = ros2_control_setup(Ros2ParameterSet::from_files({write("d.yaml", "x:\n  ros__parameters: {a: 1}\n")}),
                                                    "/controller_manager");
  EXPECT_EQ(other.update_rate, 100.0);
  EXPECT_FALSE(other.update_rate_given);
  EXPECT_TRUE(other.controller_names.empty());
  EXPECT_THAT(other.notes.front(), HasSubstr("no parameters for the controller manager /controller_manager"));
}

TEST_F(Ros2Params, MalformedFilesAreErrorsNamingFileAndLine) {
  const auto error_of = [&](const std::string& name, const std::string& yaml) -> std::string {
    try {
      Ros2ParameterSet::from_files({write(name, yaml)});
    } catch (const ParamsError& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_THAT(error_of("v.yaml", "controller_manager:\n  update_rate: 100\n"),
              HasSubstr("v.yaml:2:"));
  EXPECT_THAT(error_of("v.yaml", "controller_manager:\n  update_rate: 100\n"),
              HasSubstr("'update_rate' under node name 'controller_manager' is not a map"));
  EXPECT_THAT(error_of("l.yaml", "arm:\n  ros__parameters: [1, 2]\n"), HasSubstr("ros__parameters of node 'arm' is not a map"));
  EXPECT_THAT(error_of("n.yaml", "arm:\n  joints:\n    sub: {}\n"), HasSubstr("no ros__parameters in the file"));
  EXPECT_THAT(error_of("t.yaml", "ros__parameters: {a: 1}\n"), HasSubstr("ros__parameters at the top level"));
  EXPECT_THAT(error_of("y.yaml", "arm:\n  ros__parameters:\n    joints: [a\n"), HasSubstr("y.yaml"));
  EXPECT_THAT(error_of("d.yaml", "arm:\n  ros__parameters:\n    gains..p: 1\n"), HasSubstr("empty part between dots"));
  // A bad update_rate names its line.
  const std::string bad_rate = write("r.yaml", "controller_manager:\n  ros__parameters:\n    update_rate: fast\n");
  try {
    ros2_control_setup(Ros2ParameterSet::from_files({bad_rate}), "/controller_manager");
    ADD_FAILURE() << "no error";
  } catch (const ParamsError& e) {
    EXPECT_THAT(e.what(), HasSubstr(bad_rate + ":3"));
    EXPECT_THAT(e.what(), HasSubstr("update_rate of /controller_manager is not a number"));
  }
}

TEST_F(Ros2Params, TellsRos2FilesFromRos1Ones) {
  EXPECT_TRUE(is_ros2_parameter_file(write("a.yaml", "/**/controller_manager:\n  ros__parameters: {update_rate: 10}\n")));
  EXPECT_TRUE(is_ros2_parameter_file(write("b.yaml", "ns:\n  cm:\n    ros__parameters: {}\n")));
  EXPECT_FALSE(is_ros2_parameter_file(write("c.yaml", "cc8:\n  ctrl: {type: x}\n")));
  EXPECT_FALSE(is_ros2_parameter_file((dir_ / "missing.yaml").string()));
}

}  // namespace
}  // namespace mechsim::control
