// Users' Gazebo launch files, unmodified from ../shared, through mechsim's gazebo_ros,
// controller_manager, pr2_controller_manager and xacro packages (src/ros/packages), with only
// ROS_PACKAGE_PATH set to <build>/ros_package and ../shared/robots (and xacro on PATH, as a ROS
// install has it): cc8_description's cc8_gazebo.launch (its 11 controllers running,
// robot_state_publisher's TF), pr2_gazebo's pr2_empty_world.launch (pr2_gazebo's default
// controllers; the base follows a Twist; robot_pose_ekf's odom_combined follows the odometry;
// pr2_head_action's point_head_action turns the head) and pr2_gazebo's own rostests hztest_pr2_scan.launch and
// (with MECHSIM_SLOW_TESTS=1) hztest_pr2_image.launch.
// Skipped without roslaunch or the shared robots. Each test stops roslaunch (its process group)
// also on failure; waits are bounded (at most 90 s of wall time each).
#include <gmock/gmock.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <set>

#include <actionlib/client/simple_action_client.h>
#include <controller_manager_msgs/ListControllers.h>
#include <gazebo_msgs/GetModelState.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <geometry_msgs/Twist.h>
#include <pr2_controllers_msgs/PointHeadAction.h>
#include <nav_msgs/Odometry.h>
#include <pr2_mechanism_msgs/ListControllers.h>
#include <sensor_msgs/JointState.h>
#include <tf2_msgs/TFMessage.h>

#include "param_snapshot.hpp"
#include "ros_fixture.hpp"

namespace mechsim::ros::test {
namespace {

const std::string kShared = MECHSIM_SHARED_DIR;
const char* const kRoslaunch = "/usr/bin/roslaunch";

// `argv` run with the environment the acceptance names: ROS_PACKAGE_PATH = mechsim's packages and
// the shared robots, xacro and Debian's tools first on PATH.
std::vector<std::string> in_gazebo_env(const std::vector<std::string>& argv,
                                       const std::vector<std::string>& extra_env = {}) {
  const char* path = std::getenv("PATH");
  std::vector<std::string> out = {
      "/usr/bin/env",
      "ROS_PACKAGE_PATH=" + std::string(MECHSIM_BINARY_DIR) + "/ros_package:" + kShared + "/robots",
      "PATH=" + std::string(MECHSIM_BINARY_DIR) + "/ros_bin:/usr/bin:" + (path != nullptr ? path : "")};
  out.insert(out.end(), extra_env.begin(), extra_env.end());
  out.insert(out.end(), argv.begin(), argv.end());
  return out;
}

std::vector<std::string> running(const std::vector<std::string>& names, const std::vector<std::string>& states) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < names.size() && i < states.size(); ++i)
    if (states[i] == "running") out.push_back(names[i]);
  std::sort(out.begin(), out.end());
  return out;
}

class GazeboLaunch : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(kRoslaunch)) GTEST_SKIP() << kRoslaunch << " is missing (Debian's python3-roslaunch)";
    if (!std::filesystem::exists(kShared + "/robots/cc8_description")) GTEST_SKIP() << "no " << kShared << "/robots";
    ASSERT_TRUE(::ros::master::check()) << "no ROS master";
  }
  void launch(const std::vector<std::string>& args) {
    std::vector<std::string> argv = {"/usr/bin/python3", kRoslaunch};
    argv.insert(argv.end(), args.begin(), args.end());
    const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    launch_ = std::make_unique<ChildProcess>(in_gazebo_env(argv), log_dir() + "/roslaunch_" + name + ".log");
  }
  void TearDown() override {
    if (launch_) {
      EXPECT_NE(launch_->stop(15.0), -1) << "roslaunch did not stop on SIGINT within 15 s";
    }
    params_.forget_new();  // the PR2's controllers were loaded at the root namespace
  }
  std::string tail() const {
    const std::string log = launch_->log();
    return log.substr(log.size() > 6000 ? log.size() - 6000 : 0);
  }
  std::unique_ptr<ChildProcess> launch_;
  ParamSnapshot params_;
};

TEST_F(GazeboLaunch, Cc8DescriptionsGazeboLaunchRunsUnchanged) {
  launch({"cc8_description", "cc8_gazebo.launch", "paused:=false"});
  const std::vector<std::string> expected = {
      "joint_state_controller",           "steering_FL_position_controller",    "steering_FR_position_controller",
      "steering_RL_position_controller",  "steering_RR_position_controller",    "wheel_joint_FL_position_controller",
      "wheel_joint_FR_position_controller", "wheel_joint_ML_position_controller", "wheel_joint_MR_position_controller",
      "wheel_joint_RL_position_controller", "wheel_joint_RR_position_controller"};
  std::vector<std::string> now;
  ASSERT_TRUE(wait_until(
      [&] {
        controller_manager_msgs::ListControllers list;
        if (!::ros::service::exists("/cc8/controller_manager/list_controllers", false) ||
            !::ros::service::call("/cc8/controller_manager/list_controllers", list)) {
          return false;
        }
        std::vector<std::string> names, states;
        for (const auto& c : list.response.controller) names.push_back(c.name), states.push_back(c.state);
        now = running(names, states);
        return now == expected;
      },
      60.0))
      << "running: " << ::testing::PrintToString(now) << "\n" << tail();

  // TF of the moving joints comes from robot_state_publisher (over /cc8/joint_states), as in Gazebo.
  ::ros::NodeHandle nh;
  std::mutex m;
  std::set<std::string> publishers, children;
  int joint_states = 0;
  ::ros::Subscriber tf = nh.subscribe<tf2_msgs::TFMessage>(
      "/tf", 10, boost::function<void(const ::ros::MessageEvent<tf2_msgs::TFMessage const>&)>(
                     [&](const ::ros::MessageEvent<tf2_msgs::TFMessage const>& e) {
                       std::lock_guard<std::mutex> l(m);
                       publishers.insert(e.getPublisherName());
                       for (const auto& t : e.getMessage()->transforms) children.insert(t.child_frame_id);
                     }));
  ::ros::Subscriber js = nh.subscribe<sensor_msgs::JointState>(
      "/cc8/joint_states", 10, [&](const sensor_msgs::JointState::ConstPtr&) {
        std::lock_guard<std::mutex> l(m);
        ++joint_states;
      });
  ASSERT_TRUE(wait_until([&] { std::lock_guard<std::mutex> l(m); return joint_states > 5 && children.size() > 5; }, 20.0))
      << tail();
  {
    std::lock_guard<std::mutex> l(m);
    EXPECT_THAT(publishers, ::testing::ElementsAre("/robot_state_publisher"));
    EXPECT_THAT(children, ::testing::Contains("bogie_L_1"));
  }
  gazebo_msgs::GetModelState state;
  state.request.model_name = "cc8";
  ASSERT_TRUE(call("/gazebo/get_model_state", state));
  EXPECT_TRUE(state.response.success) << state.response.status_message;
  EXPECT_NEAR(state.response.pose.position.x, 0.0, 0.05) << "the rover stands where spawn_model put it";
}

TEST_F(GazeboLaunch, Pr2GazebosEmptyWorldLaunchRunsUnchanged) {
  launch({"pr2_gazebo", "pr2_empty_world.launch"});
  const std::vector<std::string> expected = {"base_controller",      "base_odometry",        "head_traj_controller",
                                             "l_arm_controller",     "l_gripper_controller", "laser_tilt_controller",
                                             "r_arm_controller",     "r_gripper_controller", "torso_controller"};
  std::vector<std::string> now;
  ASSERT_TRUE(wait_until(
      [&] {
        pr2_mechanism_msgs::ListControllers list;
        if (!::ros::service::exists("/pr2_controller_manager/list_controllers", false) ||
            !::ros::service::call("/pr2_controller_manager/list_controllers", list)) {
          return false;
        }
        now = running(list.response.controllers, list.response.state);
        return now == expected;
      },
      90.0))
      << "running: " << ::testing::PrintToString(now) << "\n" << tail();
  // pr2_gazebo's names: the controllers at the root namespace.
  ::ros::NodeHandle nh;
  std::mutex m;
  double x0 = std::numeric_limits<double>::quiet_NaN(), x = 0.0;
  ::ros::Subscriber odom =
      nh.subscribe<nav_msgs::Odometry>("/base_odometry/odom", 10, [&](const nav_msgs::Odometry::ConstPtr& msg) {
        std::lock_guard<std::mutex> l(m);
        x = msg->pose.pose.position.x;
        if (std::isnan(x0)) x0 = x;
      });
  ASSERT_TRUE(wait_until([&] { std::lock_guard<std::mutex> l(m); return !std::isnan(x0); }, 10.0)) << tail();
  ::ros::Publisher cmd = nh.advertise<geometry_msgs::Twist>("/base_controller/command", 1);
  ASSERT_TRUE(wait_until([&] { return cmd.getNumSubscribers() > 0; }, 5.0));
  geometry_msgs::Twist twist;
  twist.linear.x = 0.2;
  const bool moved = wait_until(
      [&] {
        cmd.publish(twist);
        std::lock_guard<std::mutex> l(m);
        return x - x0 > 0.15;
      },
      20.0);
  EXPECT_TRUE(moved) << "base_odometry x " << x0 << " -> " << x << "\n" << tail();

  // pr2_bringup's robot_pose_ekf: odom_combined follows the base odometry (it started with it),
  // and its transform odom_combined -> base_footprint is on /tf.
  double fused = std::numeric_limits<double>::quiet_NaN();
  std::set<std::string> fused_tf;
  ::ros::Subscriber ekf = nh.subscribe<geometry_msgs::PoseWithCovarianceStamped>(
      "/robot_pose_ekf/odom_combined", 10, [&](const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& msg) {
        std::lock_guard<std::mutex> l(m);
        if (msg->header.frame_id == "odom_combined") fused = msg->pose.pose.position.x;
      });
  ::ros::Subscriber tf = nh.subscribe<tf2_msgs::TFMessage>("/tf", 100, [&](const tf2_msgs::TFMessage::ConstPtr& msg) {
    std::lock_guard<std::mutex> l(m);
    for (const auto& t : msg->transforms)
      if (t.header.frame_id == "odom_combined") fused_tf.insert(t.child_frame_id);
  });
  EXPECT_TRUE(wait_until([&] {
    std::lock_guard<std::mutex> l(m);
    return std::abs(fused - x) < 0.05 && fused_tf.count("base_footprint") > 0;
  }, 15.0)) << "odom_combined x " << fused << ", base_odometry x " << x << "\n" << tail();

  // pr2_head_action's point_head_action: the head turns to a point ahead and to the left.
  actionlib::SimpleActionClient<pr2_controllers_msgs::PointHeadAction> head("/head_traj_controller/point_head_action", true);
  ASSERT_TRUE(head.waitForServer(::ros::Duration(30.0))) << tail();
  double pan = std::numeric_limits<double>::quiet_NaN();
  ::ros::Subscriber js = nh.subscribe<sensor_msgs::JointState>("/joint_states", 10, [&](const sensor_msgs::JointState::ConstPtr& msg) {
    std::lock_guard<std::mutex> l(m);
    for (std::size_t i = 0; i < msg->name.size() && i < msg->position.size(); ++i)
      if (msg->name[i] == "head_pan_joint") pan = msg->position[i];
  });
  pr2_controllers_msgs::PointHeadGoal goal;
  goal.target.header.frame_id = "base_link";
  goal.target.point.x = 2.0;
  goal.target.point.y = 2.0;
  goal.target.point.z = 1.2;
  goal.min_duration = ::ros::Duration(0.5);
  head.sendGoal(goal);
  ASSERT_TRUE(head.waitForResult(::ros::Duration(30.0))) << tail();
  EXPECT_EQ(head.getState(), actionlib::SimpleClientGoalState::SUCCEEDED) << head.getState().getText() << "\n" << tail();
  {
    std::lock_guard<std::mutex> l(m);
    // The pan axis stands 6.7 cm behind base_link's origin: the target is 0.77 rad to the left.
    EXPECT_NEAR(pan, std::atan2(2.0, 2.0 + 0.067), 0.15);
  }
}

// pr2_gazebo's own rostests, through its launch files and gazebo_ros' (rostest --reuse-master on
// the test's master; hztest's Python from Debian). Rates are in simulated time (/use_sim_time).
class Pr2GazeboHztest : public GazeboLaunch {
 protected:
  void run(const std::string& launch_file, int tests, double limit, const std::vector<std::string>& extra_env = {},
           const std::string& package = "pr2_gazebo") {
    const char* const rostest = "/usr/bin/rostest";
    if (!std::filesystem::exists(rostest)) GTEST_SKIP() << rostest << " is missing (Debian's python3-rostest)";
    ::ros::param::set("/run_id", std::string("mechsim_gazebo_hztest"));
    launch_ = std::make_unique<ChildProcess>(
        in_gazebo_env({"/usr/bin/python3", rostest, "--reuse-master", package, launch_file}, extra_env),
        log_dir() + "/rostest_gazebo_" + launch_file + ".log");
    const int status = launch_->wait(limit);
    const std::string log = tail();
    EXPECT_EQ(status, 0) << log;
    EXPECT_THAT(log, ::testing::HasSubstr("* TESTS: " + std::to_string(tests)));
    EXPECT_THAT(log, ::testing::HasSubstr("RESULT: SUCCESS"));
  }
};

// Both Hokuyos at their rates.
TEST_F(Pr2GazeboHztest, ScanPasses) { run("hztest_pr2_scan.launch", 2, 200.0); }

// Six cameras at 20 Hz (+-10): the stereo pairs' and forearm cameras' images, and the forearm
// cameras' camera_info alone (published at the camera's rate without rendering).
// rostest brings the launch file up afresh for each of its 8 tests, and each renders six cameras
// for 12 s of simulated time: about 1.5 minutes here, too long for every CI run.
TEST_F(Pr2GazeboHztest, ImagePasses) {
  if (std::getenv("MECHSIM_SLOW_TESTS") == nullptr) {
    GTEST_SKIP() << "about 1.5 minutes (rostest relaunches the PR2 for each of its 8 rate tests): run with MECHSIM_SLOW_TESTS=1";
  }
  run("hztest_pr2_image.launch", 8, 420.0);
}

// Both stereo pairs' point clouds (stereo_image_proc's nodelets on the wide and narrow stereo
// cameras, 640x480 at 20 Hz) at 20 +- 15 Hz of simulated time, at the launch file's default
// real-time factor (1.0; the world runs slower when the cameras and the block matching need more
// than the machine has: hztest counts simulated time). Two tests, each with the PR2 brought up
// afresh: about 30 s.
TEST_F(Pr2GazeboHztest, StereoPasses) {
  if (std::getenv("MECHSIM_SLOW_TESTS") == nullptr) {
    GTEST_SKIP() << "about 30 s (two rate tests, each with the PR2 brought up afresh): run with MECHSIM_SLOW_TESTS=1";
  }
  run("hztest_pr2_stereo.launch", 2, 600.0);
}

// pr2_gazebo's bring-up rates (robots/pr2/test/hztest_pr2_gazebo_bringup.test): the bounds of
// pr2_gazebo's mechanism rate test, /tf with robot_pose_ekf's transform among its publishers, and
// robot_pose_ekf's odom_combined. Five tests, each with the PR2 brought up afresh.
TEST_F(Pr2GazeboHztest, BringupRatesPass) {
  if (std::getenv("MECHSIM_SLOW_TESTS") == nullptr) {
    GTEST_SKIP() << "about 2 minutes (five rate tests, each with the PR2 brought up afresh): run with MECHSIM_SLOW_TESTS=1";
  }
  run("hztest_pr2_gazebo_bringup.test", 5, 600.0,
      {"ROS_PACKAGE_PATH=" + std::string(MECHSIM_BINARY_DIR) + "/ros_package:" + MECHSIM_SOURCE_DIR + "/robots:" + kShared + "/robots"},
      "mechsim_pr2");
}

}  // namespace
}  // namespace mechsim::ros::test
