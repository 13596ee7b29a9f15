// mechsim's gazebo_ros package as Gazebo users' launch files use it (src/ros/packages/README.md),
// with a real rosmaster and Debian's roslaunch, mechsim's packages first on ROS_PACKAGE_PATH:
//   - a launch file of our own with gazebo_ros' test form <node pkg="gazebo_ros" type="gzserver"
//     args="--verbose WORLD"/>: the server starts the world (mechsim's shapes.world, found by its
//     Gazebo resource name worlds/shapes.world), names the arguments it does not apply, and its
//     clock runs;
//   - gazebo_ros' range_world.launch (gui on: gzclient stays up, as launch files that require it
//     need): the server runs gazebo_plugins' test world, its two sonar boxes where the file puts
//     them;
//   - a world gzserver cannot find falls back on the empty world with a message, as gzserver does.
// Skipped without roslaunch. Each test stops roslaunch (its process group) also on failure; waits
// are bounded.
#include <gmock/gmock.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>

#include <gazebo_msgs/GetModelState.h>
#include <gazebo_msgs/GetWorldProperties.h>
#include <rosgraph_msgs/Clock.h>

#include "ros_fixture.hpp"

namespace mechsim::ros::test {
namespace {

using ::testing::HasSubstr;
const char* const kRoslaunch = "/usr/bin/roslaunch";

class GazeboRosPackage : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(kRoslaunch)) GTEST_SKIP() << kRoslaunch << " is missing (Debian's python3-roslaunch)";
    ASSERT_TRUE(::ros::master::check()) << "no ROS master";
    clock_sub_ = nh_.subscribe<rosgraph_msgs::Clock>("/clock", 10, [this](const rosgraph_msgs::Clock::ConstPtr& c) {
      std::lock_guard<std::mutex> l(mutex_);
      clock_ = c->clock.toSec();
    });
  }
  void TearDown() override {
    if (launch_) {
      EXPECT_NE(launch_->stop(15.0), -1) << "roslaunch did not stop on SIGINT within 15 s";
    }
  }
  void launch(const std::vector<std::string>& args) {
    const char* path = std::getenv("PATH");
    std::vector<std::string> argv = {
        "/usr/bin/env", "ROS_PACKAGE_PATH=" + std::string(MECHSIM_BINARY_DIR) + "/ros_package",
        "PATH=" + std::string(MECHSIM_BINARY_DIR) + "/ros_bin:/usr/bin:" + (path != nullptr ? path : ""), "/usr/bin/python3",
        kRoslaunch};
    argv.insert(argv.end(), args.begin(), args.end());
    const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    launch_ = std::make_unique<ChildProcess>(argv, log_dir() + "/roslaunch_" + name + ".log");
  }
  std::string tail() const {
    const std::string log = launch_->log();
    return log.substr(log.size() > 6000 ? log.size() - 6000 : 0);
  }
  double clock() {
    std::lock_guard<std::mutex> l(mutex_);
    return clock_;
  }
  std::vector<std::string> world_models() {
    gazebo_msgs::GetWorldProperties w;
    if (!call("/gazebo/get_world_properties", w, 60.0)) return {};
    return w.response.model_names;
  }

  std::unique_ptr<ChildProcess> launch_;
  ::ros::NodeHandle nh_;
  ::ros::Subscriber clock_sub_;
  std::mutex mutex_;
  double clock_ = -1.0;
};

TEST_F(GazeboRosPackage, AGzserverNodeWithAWorldArgumentStartsThatWorld) {
  const std::string file = log_dir() + "/gzserver_node.launch";
  std::ofstream(file) << R"(<launch>
  <param name="/use_sim_time" value="true"/>
  <node name="gazebo" pkg="gazebo_ros" type="gzserver" respawn="false" output="screen"
        args="--verbose -e ode -s libgazebo_ros_api_plugin.so -s libmy_world_plugin.so worlds/shapes.world"/>
</launch>
)";
  launch({file});
  std::vector<std::string> models;
  ASSERT_TRUE(wait_until([&] { models = world_models(); return !models.empty(); }, 60.0)) << tail();
  EXPECT_THAT(models, ::testing::IsSupersetOf({"ground_plane", "box", "sphere", "cylinder"}));
  gazebo_msgs::GetModelState sphere;
  sphere.request.model_name = "sphere";
  ASSERT_TRUE(call("/gazebo/get_model_state", sphere));
  EXPECT_TRUE(sphere.response.success) << sphere.response.status_message;
  EXPECT_NEAR(sphere.response.pose.position.y, 1.5, 0.01);
  const double t0 = clock();
  EXPECT_TRUE(wait_until([&] { return clock() > t0 + 0.5; }, 10.0)) << "the world's clock does not run\n" << tail();
  // One line names what gzserver took without effect; the API plugin is what the node is.
  EXPECT_THAT(tail(), HasSubstr("accepted without effect (no GUI; MuJoCo, not ODE): --verbose; -e ode; -s libmy_world_plugin.so"));
}

TEST_F(GazeboRosPackage, GazeboRosRangeWorldLaunchRunsGazeboPluginsTestWorld) {
  launch({"gazebo_ros", "range_world.launch"});
  std::vector<std::string> models;
  ASSERT_TRUE(wait_until([&] { models = world_models(); return !models.empty(); }, 60.0)) << tail();
  EXPECT_THAT(models, ::testing::IsSupersetOf({"model_1", "model_2"}));
  gazebo_msgs::GetModelState box;
  box.request.model_name = "model_2";
  ASSERT_TRUE(call("/gazebo/get_model_state", box));
  EXPECT_TRUE(box.response.success) << box.response.status_message;
  EXPECT_NEAR(box.response.pose.position.x, 0.5, 0.01);
  // gui defaults to true: gzclient says there is no GUI and stays, as a GUI would.
  EXPECT_TRUE(wait_until([&] { return tail().find("gzclient: mechsim has no GUI") != std::string::npos; }, 20.0)) << tail();
  ::ros::WallDuration(2.0).sleep();
  // roslaunch reports a process that ended ("[gazebo_gui-2] process has finished cleanly").
  EXPECT_THAT(tail(), ::testing::Not(HasSubstr("] process has"))) << tail();
}

TEST_F(GazeboRosPackage, AWorldGzserverCannotFindFallsBackOnTheEmptyWorldWithAMessage) {
  launch({"gazebo_ros", "willowgarage_world.launch"});
  std::vector<std::string> models;
  ASSERT_TRUE(wait_until([&] { models = world_models(); return !models.empty(); }, 60.0)) << tail();
  EXPECT_THAT(models, ::testing::ElementsAre("ground_plane"));
  EXPECT_THAT(tail(), HasSubstr("could not open world file [worlds/willowgarage.world]: the Willow Garage office is a mesh"));
  EXPECT_THAT(tail(), HasSubstr("falling back on worlds/empty.world"));
}

}  // namespace
}  // namespace mechsim::ros::test
