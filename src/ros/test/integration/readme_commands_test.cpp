// The documentation's ROS commands, run as printed (bash in the repository's root, the command
// text taken from the test's table only after checking that the page holds it verbatim), against
// the test's own master on loopback; and scripts/install-deps.sh --with-ros checked against what
// the node exchanges and the tools import. Commands that never end by themselves (roslaunch,
// rostopic pub -r, rostopic echo without -n) run in the background and are stopped (their
// process group) at the end of the test, also on failure. Each test's waits add up to at most
// about 90 s (wall).
#include <gmock/gmock.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <regex>
#include <set>
#include <sstream>

#include <controller_manager_msgs/ListControllers.h>
#include <nav_msgs/Odometry.h>
#include <pr2_mechanism_msgs/ListControllers.h>
#include <rosgraph_msgs/Clock.h>

#include "ros_fixture.hpp"

namespace mechsim::ros::test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

namespace fs = std::filesystem;

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// A shell in the repository's root that runs README lines one after the other; `export` and
// `. script` lines carry over to the later ones (as in one terminal per line of a session).
class ReadmeShell {
 public:
  explicit ReadmeShell(std::string readme) : readme_path_(std::move(readme)) {
    text_ = read_text(fs::path(MECHSIM_SOURCE_DIR) / readme_path_);
  }

  // The environment line `line` (export / source) for every later command.
  void setup(const std::string& line) {
    require_printed(line);
    prefix_ += line + " && ";
  }
  // Runs `line` to its end (at most `timeout` s); its exit status (-1 killed) and output.
  int run(const std::string& line, std::string& output, double timeout = 30.0) {
    require_printed(line);
    ChildProcess p(argv(line), log_path());
    int status = p.wait(timeout);
    if (status == -2) status = p.stop();
    output = p.log();
    return status;
  }
  // Starts `line` in the background; it stays until the shell goes away.
  ChildProcess& start(const std::string& line) {
    require_printed(line);
    background_.push_back(std::make_unique<ChildProcess>(argv(line), log_path()));
    return *background_.back();
  }
  bool printed(const std::string& line) const { return text_.find(line) != std::string::npos; }

  ~ReadmeShell() {
    for (auto it = background_.rbegin(); it != background_.rend(); ++it) (*it)->stop(10.0);
  }

 private:
  void require_printed(const std::string& line) {
    if (!printed(line)) throw std::runtime_error(readme_path_ + " does not print `" + line + "`");
  }
  std::vector<std::string> argv(const std::string& line) const {
    return {"/bin/bash", "-c", "cd '" + std::string(MECHSIM_SOURCE_DIR) + "' && " + prefix_ + line};
  }
  std::string log_path() { return log_dir() + "/readme_" + std::to_string(++count_) + ".log"; }

  std::string readme_path_, text_, prefix_;
  std::vector<std::unique_ptr<ChildProcess>> background_;
  int count_ = 0;
};

// The READMEs name the build folder build/release; another build folder cannot run them as printed.
bool build_is_build_release() {
  std::error_code ec;
  return fs::equivalent(fs::path(MECHSIM_SOURCE_DIR) / "build/release", fs::path(MECHSIM_BINARY_DIR), ec);
}

// The last `position: x:` of rostopic echo's YAML for an Odometry; NaN when there is none.
double last_position_x(const std::string& echo) {
  static const std::regex x(R"(position:\s*\n\s*x: ([-+0-9.eE]+))");
  double last = std::nan("");
  for (auto it = std::sregex_iterator(echo.begin(), echo.end(), x); it != std::sregex_iterator(); ++it) {
    last = std::stod((*it)[1]);
  }
  return last;
}

int running_cc8_controllers() {
  if (!::ros::service::exists("/cc8/controller_manager/list_controllers", false)) return 0;
  controller_manager_msgs::ListControllers list;
  if (!::ros::service::call("/cc8/controller_manager/list_controllers", list)) return 0;
  int running = 0;
  for (const auto& c : list.response.controller) running += c.state == "running" ? 1 : 0;
  return running;
}

// Every Debian message package whose types mechsim_node or the spawner include (src/ros, not
// the packages the build generates) needs its Python module for rostopic/rosservice/rospy.
TEST(RosDeps, InstallDepsListsThePythonModuleOfEveryRosPackageTheNodeExchanges) {
  const fs::path ros_dir = fs::path(MECHSIM_SOURCE_DIR) / "src/ros";
  std::set<std::string> generated;
  for (const auto& entry : fs::directory_iterator(ros_dir / "msgs")) generated.insert(entry.path().filename());
  std::set<std::string> used;
  static const std::regex include(R"(#include <([a-z0-9_]+_(msgs|srvs))/[A-Za-z0-9_]+\.h>)");
  for (const auto& entry : fs::recursive_directory_iterator(ros_dir)) {
    if (entry.path().extension() != ".cpp" && entry.path().extension() != ".hpp") continue;
    if (entry.path().string().find("/test/") != std::string::npos) continue;
    const std::string text = read_text(entry.path());
    for (auto it = std::sregex_iterator(text.begin(), text.end(), include); it != std::sregex_iterator(); ++it) {
      if (!generated.count((*it)[1])) used.insert((*it)[1]);
    }
  }
  ASSERT_TRUE(used.count("nav_msgs") && used.count("std_srvs")) << "the include scan found too little";
  const std::string deps = read_text(fs::path(MECHSIM_SOURCE_DIR) / "scripts/install-deps.sh");
  std::string imports;
  for (const std::string& pkg : used) {
    std::string debian = "python3-" + pkg;
    std::replace(debian.begin(), debian.end(), '_', '-');
    EXPECT_THAT(deps, HasSubstr(" " + debian)) << "install-deps.sh --with-ros lacks " << debian;
    const bool services = pkg.compare(pkg.size() - 5, 5, "_srvs") == 0;
    imports += (imports.empty() ? "import " : ", ") + pkg + (services ? ".srv" : ".msg");
  }
  // Installed here (the test command runs install-deps.sh --with-ros): the modules and the tools load.
  for (const char* pkg : {"rosbash", "python3-actionlib", "python3-rostest"}) {
    EXPECT_THAT(deps, HasSubstr(std::string(" ") + pkg)) << "install-deps.sh --with-ros lacks " << pkg;
  }
  ChildProcess python({"/usr/bin/python3", "-c",
                       imports + "; import roslaunch, rostopic, rosservice, rosparam, rosnode, rosmsg, rostest, "
                                 "actionlib; print('imported')"},
                      log_dir() + "/python_imports.log");
  EXPECT_EQ(python.wait(60.0), 0) << python.log();
  EXPECT_THAT(python.log(), HasSubstr("imported"));
  EXPECT_TRUE(fs::exists("/usr/bin/rosrun")) << "rosrun (rosbash) is not installed";
}

// docs/gazebo-ros1.md's "The ROS way" (its block marked `<!-- runnable: ros_integration_test
// ReadmeCommands -->`: test/docs/docs_check.py checks that this test runs each of its lines) and
// src/ros/README.md's "Python tools" block, on the CC8.
TEST(ReadmeCommands, Cc8SessionOfTheReadmesRunsAsPrinted) {
  if (!build_is_build_release()) GTEST_SKIP() << "the READMEs' commands name build/release; this build is " << MECHSIM_BINARY_DIR;
  ASSERT_TRUE(::ros::master::check());
  ReadmeShell top("docs/gazebo-ros1.md");
  top.setup("export ROS_PACKAGE_PATH=$PWD/robots:$PWD/build/release/ros_package");
  ChildProcess& launch = top.start("PATH=/usr/bin:$PATH roslaunch mechsim_cc8 cc8_mechsim.launch paused:=false");
  ASSERT_TRUE(wait_until([] { return running_cc8_controllers() == 2; }, 60.0)) << launch.log();

  top.start("rostopic pub -r 10 /cc8/cmd_vel geometry_msgs/Twist '{linear: {x: 0.4}}'");
  ChildProcess& echo = top.start("rostopic echo /cc8/odom");
  ASSERT_TRUE(wait_until([&] { return last_position_x(echo.log()) > 0.3 || !echo.running(); }, 20.0))
      << "rostopic echo /cc8/odom:\n" << echo.log();
  EXPECT_THAT(echo.log(), Not(HasSubstr("Cannot load message class")));
  std::printf("rostopic echo /cc8/odom: x %.3f m\n", last_position_x(echo.log()));

  std::string out;
  ASSERT_EQ(top.run("rostopic echo -n 1 /cc8/joint_states", out), 0) << out;
  EXPECT_THAT(out, HasSubstr("  - wheel_joint_FL"));
  EXPECT_THAT(out, HasSubstr("position: ["));

  ::ros::NodeHandle nh;
  std::mutex m;
  double clock = -1.0;
  ::ros::Subscriber clock_sub = nh.subscribe<rosgraph_msgs::Clock>("/clock", 10, [&](const rosgraph_msgs::Clock::ConstPtr& c) {
    std::lock_guard<std::mutex> l(m);
    clock = c->clock.toSec();
  });
  auto clock_now = [&] {
    std::lock_guard<std::mutex> l(m);
    return clock;
  };
  ASSERT_EQ(top.run("rosservice call /gazebo/pause_physics", out), 0) << out;
  ASSERT_TRUE(wait_until([&] { return clock_now() >= 0.0; }, 5.0));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // a /clock in flight at the pause
  const double paused_at = clock_now();
  std::this_thread::sleep_for(std::chrono::seconds(1));
  EXPECT_EQ(clock_now(), paused_at) << "/clock moved while paused";
  ASSERT_EQ(top.run("rosservice call /gazebo/unpause_physics", out), 0) << out;
  EXPECT_TRUE(wait_until([&] { return clock_now() > paused_at + 0.2; }, 5.0)) << "/clock did not move on unpause";

  // src/ros/README.md, "Python tools" (after the roslaunch above, in another terminal).
  ReadmeShell tools("src/ros/README.md");
  ASSERT_TRUE(tools.printed("PATH=/usr/bin:$PATH roslaunch mechsim_cc8 cc8_mechsim.launch paused:=false"));
  tools.setup(". scripts/ros_env.sh build/release");
  ASSERT_EQ(tools.run("rosservice call /cc8/controller_manager/list_controllers", out), 0) << out;
  EXPECT_THAT(out, HasSubstr("name: \"rover_drive_controller\""));
  EXPECT_THAT(out, HasSubstr("state: \"running\""));
  ASSERT_EQ(tools.run("rostopic echo -n 1 /cc8/joint_states", out), 0) << out;
  EXPECT_THAT(out, HasSubstr("velocity: ["));
  ASSERT_EQ(tools.run("rosmsg show control_msgs/FollowJointTrajectoryGoal", out), 0) << out;
  EXPECT_THAT(out, HasSubstr("trajectory_msgs/JointTrajectory trajectory"));
  ASSERT_EQ(tools.run("python3 -c \"from controller_manager_msgs.srv import ListControllers; "
                      "print(ListControllers._md5sum)\"",
                      out),
            0)
      << out;
  EXPECT_TRUE(std::regex_search(out, std::regex("[0-9a-f]{32}"))) << out;
  EXPECT_TRUE(launch.running()) << launch.log();
}

// robots/pr2/README.md's launch block: the PR2 comes up with its 9 controllers and the printed
// Twist moves the base odometry.
TEST(ReadmeCommands, Pr2LaunchBlockRunsAsPrinted) {
  if (!build_is_build_release()) GTEST_SKIP() << "the READMEs' commands name build/release; this build is " << MECHSIM_BINARY_DIR;
  ASSERT_TRUE(::ros::master::check());
  ReadmeShell pr2("robots/pr2/README.md");
  pr2.setup(". scripts/ros_env.sh build/release");
  ChildProcess& launch = pr2.start("roslaunch mechsim_pr2 pr2_empty_world.launch");
  const char* const list_service = "/pr2_controller_manager/list_controllers";
  auto running = [&] {
    if (!::ros::service::exists(list_service, false)) return 0;
    pr2_mechanism_msgs::ListControllers list;
    if (!::ros::service::call(list_service, list)) return 0;
    int n = 0;
    for (const auto& s : list.response.state) n += s == "running" ? 1 : 0;
    return n;
  };
  ASSERT_TRUE(wait_until([&] { return running() == 9; }, 60.0)) << "running: " << running() << "\n" << launch.log();

  ::ros::NodeHandle nh;
  std::mutex m;
  double x = std::nan("");
  ::ros::Subscriber odom = nh.subscribe<nav_msgs::Odometry>(
      "/pr2/base_odometry/odom", 10, [&](const nav_msgs::Odometry::ConstPtr& msg) {
        std::lock_guard<std::mutex> l(m);
        x = msg->pose.pose.position.x;
      });
  auto odom_x = [&] {
    std::lock_guard<std::mutex> l(m);
    return x;
  };
  ASSERT_TRUE(wait_until([&] { return !std::isnan(odom_x()); }, 10.0)) << launch.log();
  const double x0 = odom_x();
  ChildProcess& pub = pr2.start("rostopic pub -r 10 /pr2/base_controller/command geometry_msgs/Twist '{linear: {x: 0.2}}'");
  EXPECT_TRUE(wait_until([&] { return odom_x() > x0 + 0.2 || !pub.running(); }, 20.0))
      << "base_odometry x " << x0 << " -> " << odom_x() << "\n" << pub.log();
  std::printf("rostopic pub on /pr2/base_controller/command: base_odometry x %.3f -> %.3f m\n", x0, odom_x());
  EXPECT_TRUE(launch.running()) << launch.log();
}

}  // namespace
}  // namespace mechsim::ros::test
