// mechsim's own robots driven from ROS 2 topics by a Cyclone DDS peer: the CC8's rover drive by a
// TwistStamped (its odometry moves), a PR2 arm by a JointTrajectory on its trajectory controller
// (its joint moves, seen on /tf as robot_state_publisher publishes it). Humble and Jazzy.
#include <cmath>

#include "wire_fixture.hpp"

namespace mechsim::ros2::test {
namespace {

class RobotWire : public WireTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(RobotWire, Cc8RoverDriveFollowsTwistStamped) {
  const std::string src = MECHSIM_SOURCE_DIR;
  start_mechsim({src + "/robots/cc8/urdf/cc8.urdf.xacro", "--package", "mechsim_cc8=" + src + "/robots/cc8",
                 "--controllers", src + "/robots/cc8/config/controllers.yaml", "--real-time-factor", "1",
                 "--ros-distro", GetParam()});
  const auto lines = run_cyclone(GetParam(), {"--seconds", "5", "--rate", "20", "--pub",
                                           "/cc8/rover_drive_controller/cmd_vel=twist_stamped:0.3,0,0,0,0,0", "--sub",
                                           "/cc8/rover_drive_controller/odom=odometry", "--sub", "/cc8/joint_states=joint_state"});
  const std::string log = stop_mechsim();
  const auto odom = summary(lines, "/cc8/rover_drive_controller/odom");
  ASSERT_FALSE(odom.is_null()) << log;
  EXPECT_GT(odom["last"]["position"][0].get<double>(), 0.4) << odom;
  EXPECT_NEAR(odom["last"]["linear"][0].get<double>(), 0.3, 0.05) << odom;
  const auto js = summary(lines, "/cc8/joint_states");
  ASSERT_FALSE(js.is_null());
  EXPECT_THAT(js["last"]["name"].get<std::vector<std::string>>(), ::testing::Contains("wheel_joint_FL"));
}

TEST_P(RobotWire, Pr2ArmFollowsJointTrajectory) {
  const std::string src = MECHSIM_SOURCE_DIR;
  start_mechsim({src + "/robots/pr2/urdf/pr2.urdf.xacro", "--package", "mechsim_pr2=" + src + "/robots/pr2",
                 "--controllers", src + "/robots/pr2/config/controllers.yaml", "--start", "r_arm_controller",
                 "--real-time-factor", "1", "--ros-distro", GetParam()});
  const std::string joints = "r_shoulder_pan_joint,r_shoulder_lift_joint,r_upper_arm_roll_joint,r_elbow_flex_joint,"
                             "r_forearm_roll_joint,r_wrist_flex_joint,r_wrist_roll_joint";
  const auto lines = run_cyclone(GetParam(), {"--seconds", "5", "--rate", "2", "--pub",
                                           "/pr2/r_arm_controller/joint_trajectory=trajectory:" + joints +
                                               ":0.4,0,0,-0.3,0,-0.3,0:1.0",
                                           "--sub", "/tf=tf"});
  const std::string log = stop_mechsim();
  const auto tf = summary(lines, "/tf");
  ASSERT_FALSE(tf.is_null()) << log;
  double pan = NAN;
  for (const auto& t : tf["last"]["transforms"]) {
    if (t["child"] == "r_shoulder_pan_link") {
      EXPECT_EQ(t["frame_id"], "torso_lift_link");
      pan = 2.0 * std::atan2(t["q"][2].get<double>(), t["q"][3].get<double>());
    }
  }
  EXPECT_NEAR(pan, 0.4, 0.03) << tf << "\n" << log;
}

INSTANTIATE_TEST_SUITE_P(Distros, RobotWire, ::testing::Values("humble", "jazzy"),
                         [](const ::testing::TestParamInfo<std::string>& i) { return i.param; });

}  // namespace
}  // namespace mechsim::ros2::test
