// Debian's Python ROS tools (rosservice, rostopic, and any rospy script) against mechsim_node,
// decoding mechsim's own types through the genpy modules the build writes to <build>/ros_python,
// with the environment that scripts/ros_env.sh sets up.
#include <gmock/gmock.h>

#include <fstream>
#include <sstream>

#include <controller_manager_msgs/ListControllers.h>

#include "ros_fixture.hpp"

namespace mechsim::ros::test {
namespace {

using ::testing::HasSubstr;

// Runs `command` in bash after sourcing scripts/ros_env.sh for this build; waits at most
// `timeout` s (then stops it) and returns the exit status, with the output in `output`.
int run_with_ros_env(const std::string& command, const std::string& log_name, std::string& output,
                     double timeout = 60.0) {
  const std::string script = std::string(". '") + MECHSIM_SOURCE_DIR + "/scripts/ros_env.sh' '" +
                             MECHSIM_BINARY_DIR + "' && " + command;
  ChildProcess p({"/bin/bash", "-c", script}, log_dir() + "/" + log_name + ".log");
  int status = p.wait(timeout);
  if (status == -2) status = p.stop();
  output = p.log();
  return status;
}

// The MD5 column of md5sums.tsv for `type`; empty when absent.
std::string table_md5(const std::string& type) {
  std::ifstream in(std::string(MECHSIM_SHARED_DIR) + "/msgs/md5sums.tsv");
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string name, kind, md5;
    if (std::getline(fields, name, '\t') && std::getline(fields, kind, '\t') &&
        std::getline(fields, md5, '\t') && name == type) {
      return md5;
    }
  }
  return "";
}

bool running(const std::string& controller) {
  controller_manager_msgs::ListControllers srv;
  if (!call("/cc8/controller_manager/list_controllers", srv, 1.0)) return false;
  for (const auto& c : srv.response.controller) {
    if (c.name == controller && c.state == "running") return true;
  }
  return false;
}

// A shell set up by ros_env.sh is a Noetic shell as launch and CMake files test it (ROS_DISTRO),
// and finds pr2_gazebo's test dependency pr2_machine with its sim.machine.
TEST(RosPython, RosEnvIsANoeticShellWithPr2Machine) {
  const std::string script = std::string("unset ROS_DISTRO ROS_VERSION; . '") + MECHSIM_SOURCE_DIR + "/scripts/ros_env.sh' '" +
                             MECHSIM_BINARY_DIR + "' && echo \"distro=$ROS_DISTRO version=$ROS_VERSION\" && ls \"$(rospack find pr2_machine)\"";
  ChildProcess p({"/bin/bash", "-c", script}, log_dir() + "/ros_env_noetic.log");
  EXPECT_EQ(p.wait(60.0), 0) << p.log();
  EXPECT_THAT(p.log(), HasSubstr("distro=noetic version=1"));
  EXPECT_THAT(p.log(), HasSubstr("sim.machine"));
}

TEST(RosPython, GeneratedModulesHaveTheTableMd5s) {
  const std::string table = std::string(MECHSIM_SHARED_DIR) + "/msgs/md5sums.tsv";
  if (!std::ifstream(table)) GTEST_SKIP() << "no " << table << " (the shared data folder is absent)";
  std::string out;
  ASSERT_EQ(run_with_ros_env("python3 -c 'from controller_manager_msgs.srv import ListControllers; "
                             "from control_msgs.msg import JointControllerState, FollowJointTrajectoryActionGoal; "
                             "print(ListControllers._md5sum); print(JointControllerState._md5sum); "
                             "print(FollowJointTrajectoryActionGoal._md5sum)'",
                             "python_md5", out),
            0)
      << out;
  for (const char* type : {"controller_manager_msgs/ListControllers", "control_msgs/JointControllerState",
                           "control_msgs/FollowJointTrajectoryActionGoal"}) {
    const std::string md5 = table_md5(type);
    ASSERT_EQ(md5.size(), 32u) << type << " missing from " << table;
    EXPECT_THAT(out, HasSubstr(md5)) << type;
  }
}

TEST_F(CC8Node, RosserviceAndRostopicDecodeMechsimTypes) {
  rosparam_load(std::string(MECHSIM_SOURCE_DIR) + "/robots/cc8/config/controllers.yaml");
  ChildProcess& sp = spawner({"joint_state_controller", "steering_FL_position_controller"}, "spawner");
  ASSERT_TRUE(wait_until([] { return running("steering_FL_position_controller"); }, 20.0))
      << "spawner log:\n" << sp.log();

  std::string out;
  ASSERT_EQ(run_with_ros_env("rosservice call /cc8/controller_manager/list_controllers", "rosservice", out), 0)
      << out;
  EXPECT_THAT(out, HasSubstr("name: \"steering_FL_position_controller\""));
  EXPECT_THAT(out, HasSubstr("type: \"effort_controllers/JointPositionController\""));
  EXPECT_THAT(out, HasSubstr("hardware_interface: \"hardware_interface::EffortJointInterface\""));

  ASSERT_EQ(run_with_ros_env("rostopic type /cc8/steering_FL_position_controller/state", "rostopic_type", out), 0)
      << out;
  EXPECT_THAT(out, HasSubstr("control_msgs/JointControllerState"));
  ASSERT_EQ(run_with_ros_env("rostopic echo -n 1 /cc8/steering_FL_position_controller/state", "rostopic_echo", out),
            0)
      << out;
  for (const char* field : {"set_point:", "process_value:", "process_value_dot:", "error:", "command:", "p:"}) {
    EXPECT_THAT(out, HasSubstr(field));
  }
}

}  // namespace
}  // namespace mechsim::ros::test
