// The CC8 launch files end to end: `roslaunch mechsim_cc8 cc8_mechsim.launch` on the test's
// master brings up mechsim_node, the CC8 and its default controllers (joint_state_controller and
// the rover drive from robots/cc8/config/controllers.yaml); a Twist on /cc8/cmd_vel moves
// /cc8/odom forward (the launch file's remapping of the rover drive's topics).
#include <gmock/gmock.h>

#include <mutex>

#include <controller_manager_msgs/ListControllers.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>

#include "ros_fixture.hpp"

namespace mechsim::ros::test {
namespace {

TEST(Cc8Launch, Cc8MechsimLaunchDrivesOnCmdVelAndReportsOdom) {
  ASSERT_TRUE(::ros::master::check());
  ChildProcess launch({"/usr/bin/python3", "/usr/bin/roslaunch", "mechsim_cc8", "cc8_mechsim.launch", "paused:=false"},
                      log_dir() + "/roslaunch.log");
  ASSERT_TRUE(wait_until(
      [&] {
        controller_manager_msgs::ListControllers list;
        if (!::ros::service::exists("/cc8/controller_manager/list_controllers", false)) return false;
        if (!::ros::service::call("/cc8/controller_manager/list_controllers", list)) return false;
        int running = 0;
        for (const auto& c : list.response.controller) running += c.state == "running" ? 1 : 0;
        return running == 2;
      },
      60.0))
      << launch.log();

  ::ros::NodeHandle nh;
  std::mutex m;
  double x = 0.0;
  int odom_count = 0;
  ::ros::Subscriber odom = nh.subscribe<nav_msgs::Odometry>("/cc8/odom", 10, [&](const nav_msgs::Odometry::ConstPtr& msg) {
    std::lock_guard<std::mutex> l(m);
    x = msg->pose.pose.position.x;
    ++odom_count;
  });
  ASSERT_TRUE(wait_until([&] { std::lock_guard<std::mutex> l(m); return odom_count > 0; }, 10.0)) << launch.log();
  ::ros::Publisher cmd = nh.advertise<geometry_msgs::Twist>("/cc8/cmd_vel", 1);
  ASSERT_TRUE(wait_until([&] { return cmd.getNumSubscribers() > 0; }, 10.0));
  double x0 = 0.0;
  {
    std::lock_guard<std::mutex> l(m);
    x0 = x;
  }
  geometry_msgs::Twist twist;
  twist.linear.x = 0.4;
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(4);
  while (std::chrono::steady_clock::now() < until) {
    cmd.publish(twist);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  std::lock_guard<std::mutex> l(m);
  std::printf("cc8_mechsim.launch: /cc8/odom x %.3f -> %.3f m\n", x0, x);
  EXPECT_GT(x - x0, 0.4);
  EXPECT_NE(launch.stop(30.0), -1) << "roslaunch did not stop on SIGINT";
}

}  // namespace
}  // namespace mechsim::ros::test
