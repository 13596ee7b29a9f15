// The PR2 launch files end to end: `roslaunch mechsim_pr2 pr2_empty_world.launch paused:=false`
// on the test's master brings up mechsim_node, uploads mechsim's own PR2 description
// (robots/pr2/urdf, expanded by `mechsim xacro`) and starts the default controllers that
// pr2_gazebo starts; pr2_controller_manager lists them running, and a Twist on
// /pr2/base_controller/command moves /pr2/base_odometry/odom. paused:=true holds them until
// /gazebo/unpause_physics; the variant arg picks the description and the controller set
// (pr2_no_arms: no arm or gripper controllers). Skipped without roslaunch.
// Each test's waits add up to at most 50 s (wall); it stops roslaunch (its process group:
// the node and the spawner with it) also on failure.
#include <gmock/gmock.h>

#include <filesystem>
#include <mutex>

#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <pr2_mechanism_msgs/ListControllers.h>
#include <std_srvs/Empty.h>

#include "ros_fixture.hpp"

namespace mechsim::ros::test {
namespace {

const char* const kRoslaunch = "/usr/bin/roslaunch";
const char* const kList = "/pr2_controller_manager/list_controllers";

// The controllers pr2_controller_manager lists in `state` (sorted); empty when it is not up (yet).
std::vector<std::string> controllers_in(const std::string& state) {
  if (!::ros::service::exists(kList, false)) return {};
  pr2_mechanism_msgs::ListControllers list;
  if (!::ros::service::call(kList, list)) return {};
  std::vector<std::string> running;
  for (std::size_t i = 0; i < list.response.controllers.size() && i < list.response.state.size(); ++i) {
    if (list.response.state[i] == state) running.push_back(list.response.controllers[i]);
  }
  std::sort(running.begin(), running.end());
  return running;
}

std::vector<std::string> running_controllers() { return controllers_in("running"); }

class Pr2Launch : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(kRoslaunch)) GTEST_SKIP() << kRoslaunch << " is missing (Debian's python3-roslaunch)";
    ASSERT_TRUE(::ros::master::check()) << "no ROS master";
  }

  void launch(const std::vector<std::string>& args) {
    std::vector<std::string> argv = {"/usr/bin/python3", kRoslaunch, "mechsim_pr2", "pr2_empty_world.launch"};
    argv.insert(argv.end(), args.begin(), args.end());
    launch_ = std::make_unique<ChildProcess>(argv, log_dir() + "/roslaunch_" + name() + ".log");
  }

  // Waits (at most 20 s wall) until exactly `expected` (sorted) run.
  bool wait_for_controllers(const std::vector<std::string>& expected) {
    return wait_until([&] { return running_controllers() == expected; }, 20.0);
  }

  // Stops roslaunch and everything it started; true when all went and the services are gone.
  void stop() {
    ASSERT_NE(launch_->stop(10.0), -1) << "roslaunch did not stop on SIGINT within 10 s\n" << launch_->log();
    EXPECT_FALSE(::ros::service::exists(kList, false)) << "pr2_controller_manager still up after roslaunch stopped";
  }

  void expect_variant(const std::vector<std::string>& expected, const std::string& has, const std::string& lacks) {
    ASSERT_TRUE(wait_for_controllers(expected))
        << "running: " << ::testing::PrintToString(running_controllers()) << "\n"
        << launch_->log();
    std::string description;
    ASSERT_TRUE(::ros::param::get("/robot_description", description));
    EXPECT_THAT(description, ::testing::HasSubstr("\"" + has + "\""));
    EXPECT_THAT(description, ::testing::Not(::testing::HasSubstr("\"" + lacks + "\"")));
  }

  static std::string name() { return ::testing::UnitTest::GetInstance()->current_test_info()->name(); }

  std::unique_ptr<ChildProcess> launch_;
};

TEST_F(Pr2Launch, EmptyWorldStartsDefaultControllersAndBaseFollowsTwist) {
  const auto t0 = std::chrono::steady_clock::now();
  launch({"paused:=false"});
  // pr2_gazebo's default set (pr2_controller_configuration_gazebo), sorted.
  const std::vector<std::string> expected = {"base_controller",      "base_odometry",      "head_traj_controller",
                                             "l_arm_controller",     "l_gripper_controller", "laser_tilt_controller",
                                             "r_arm_controller",     "r_gripper_controller", "torso_controller"};
  ASSERT_TRUE(wait_for_controllers(expected))
      << "running: " << ::testing::PrintToString(running_controllers()) << "\n"
      << launch_->log();
  const double up = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  ::ros::NodeHandle nh;
  std::mutex m;
  nav_msgs::Odometry last;
  int count = 0;
  ::ros::Subscriber odom =
      nh.subscribe<nav_msgs::Odometry>("/pr2/base_odometry/odom", 10, [&](const nav_msgs::Odometry::ConstPtr& msg) {
        std::lock_guard<std::mutex> l(m);
        last = *msg;
        ++count;
      });
  ASSERT_TRUE(wait_until([&] { std::lock_guard<std::mutex> l(m); return count > 0; }, 5.0)) << launch_->log();
  double x0 = 0.0;
  {
    std::lock_guard<std::mutex> l(m);
    x0 = last.pose.pose.position.x;
  }
  ::ros::Publisher cmd = nh.advertise<geometry_msgs::Twist>("/pr2/base_controller/command", 1);
  ASSERT_TRUE(wait_until([&] { return cmd.getNumSubscribers() > 0; }, 5.0));
  geometry_msgs::Twist twist;
  twist.linear.x = 0.2;
  // Keep commanding (the base controller stops on a stale command) until the base has gone 0.15 m
  // (about 1 s of sim time at 0.2 m/s; the launch runs at real time).
  double x = x0;
  const bool moved = wait_until(
      [&] {
        cmd.publish(twist);
        std::lock_guard<std::mutex> l(m);
        x = last.pose.pose.position.x;
        return x - x0 > 0.15;
      },
      10.0);
  EXPECT_TRUE(moved) << "base_odometry x " << x0 << " -> " << x << " m\n" << launch_->log();
  {
    std::lock_guard<std::mutex> l(m);
    EXPECT_EQ(last.header.frame_id, "odom");
    EXPECT_NEAR(last.twist.twist.linear.x, 0.2, 0.05);
  }
  std::printf("pr2_empty_world.launch: 9 controllers running after %.1f s (wall); base_odometry x %.3f -> %.3f m\n",
              up, x0, x);
  stop();
}

// paused:=true: the spawner loads the set, whose start waits for the first tick; unpausing the
// world (gazebo's service) starts them.
TEST_F(Pr2Launch, PausedWorldStartsTheControllersOnUnpause) {
  launch({"paused:=true"});
  ASSERT_TRUE(wait_until([] { return controllers_in("stopped").size() == 9; }, 20.0))
      << "stopped: " << ::testing::PrintToString(controllers_in("stopped")) << "\n"
      << launch_->log();
  ::ros::WallDuration(0.5).sleep();
  EXPECT_THAT(running_controllers(), ::testing::IsEmpty()) << "started while paused";
  std_srvs::Empty unpause;
  ASSERT_TRUE(call("/gazebo/unpause_physics", unpause, 5.0));
  EXPECT_TRUE(wait_until([] { return running_controllers().size() == 9; }, 10.0))
      << "running: " << ::testing::PrintToString(running_controllers()) << "\n"
      << launch_->log();
  stop();
}

// The variant's description is the one uploaded (`has`/`lacks`: a joint it has, one it has not),
// and pr2_default_controllers.launch starts only the controllers it has joints for.
TEST_F(Pr2Launch, NoArmsVariantStartsTheControllersItHasJointsFor) {
  launch({"paused:=false", "variant:=pr2_no_arms"});
  expect_variant({"base_controller", "base_odometry", "head_traj_controller", "laser_tilt_controller",
                  "torso_controller"},
                 "torso_lift_joint", "r_shoulder_pan_joint");
  stop();
}

TEST_F(Pr2Launch, OneArmVariantStartsTheRightArmAndGripperOnly) {
  launch({"paused:=false", "variant:=pr2_one_arm"});
  expect_variant({"base_controller", "base_odometry", "head_traj_controller", "laser_tilt_controller",
                  "r_arm_controller", "r_gripper_controller", "torso_controller"},
                 "r_shoulder_pan_joint", "l_shoulder_pan_joint");
  stop();
}

}  // namespace
}  // namespace mechsim::ros::test
