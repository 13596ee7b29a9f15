// gazebo_ros' gzserver, gazebo and debug over mechsim (packages/gazebo_ros): Gazebo 11's command
// line into mechsim_node's gzserver-mode parameters, without a ROS master: the scripts run from a
// copy of the package beside a stand-in mechsim_node that prints the arguments it gets.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace mechsim::ros {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

struct Package {
  fs::path root = fs::temp_directory_path() / ("mechsim_gzserver_" + std::to_string(::getpid()));
  Package() {
    fs::create_directories(root / "mechsim");
    fs::copy(fs::path(MECHSIM_SOURCE_DIR) / "src/ros/packages/gazebo_ros", root / "gazebo_ros", fs::copy_options::recursive);
    const fs::path node = root / "mechsim" / "mechsim_node";
    std::ofstream(node) << "#!/bin/sh\nfor a in \"$@\"; do echo \"ARG[$a]\"; done\n";
    fs::permissions(node, fs::perms::owner_all);
  }
  ~Package() { fs::remove_all(root); }
  // Runs `script args` (with `env` before it) and returns its output (stdout and stderr) and status.
  std::string run(const std::string& script, const std::string& args, int* status = nullptr, const std::string& env = "") {
    const std::string command = "cd '" + root.string() + "' && " + env + " '" + (root / "gazebo_ros" / script).string() +
                                "' " + args + " 2>&1";
    std::string out;
    FILE* pipe = ::popen(command.c_str(), "r");
    if (pipe == nullptr) return out;
    std::array<char, 512> buffer{};
    while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) out += buffer.data();
    const int s = ::pclose(pipe);
    if (status != nullptr) *status = WIFEXITED(s) ? WEXITSTATUS(s) : -1;
    return out;
  }
};

TEST(GzserverScript, TakesGazebosCommandLineAndStartsTheNodeInGzserverMode) {
  Package p;
  const std::string out = p.run("gzserver", "-u --verbose -e ode -s libgazebo_ros_api_plugin.so -s libmy.so --seed 3 "
                                            "worlds/shapes.world __name:=gazebo __log:=/tmp/x.log");
  EXPECT_THAT(out, HasSubstr("ARG[__name:=gazebo]"));
  EXPECT_THAT(out, HasSubstr("ARG[__log:=/tmp/x.log]"));
  EXPECT_THAT(out, HasSubstr("ARG[_gazebo:=true]"));
  EXPECT_THAT(out, HasSubstr("ARG[_world:=" + (p.root / "gazebo_ros/worlds/shapes.world").string() + "]"));
  EXPECT_THAT(out, HasSubstr("ARG[_paused:=true]"));
  EXPECT_THAT(out, HasSubstr("accepted without effect (no GUI; MuJoCo, not ODE): --verbose; -e ode; -s libmy.so; --seed 3"));
  EXPECT_THAT(out, Not(HasSubstr("libgazebo_ros_api_plugin.so;")));
}

TEST(GzserverScript, FindsWorldsAsGazeboDoesAndFallsBackOnTheEmptyWorld) {
  Package p;
  // No world: Gazebo's worlds/empty.world, which the node takes as mechsim's `empty`.
  EXPECT_THAT(p.run("gzserver", ""), HasSubstr("ARG[_world:=worlds/empty.world]"));
  // Under GAZEBO_RESOURCE_PATH (and its worlds/), before this package's.
  fs::create_directories(p.root / "resources/worlds");
  std::ofstream(p.root / "resources/worlds/shapes.world") << "<sdf version='1.6'><world name='w'/></sdf>\n";
  EXPECT_THAT(p.run("gzserver", "shapes.world", nullptr, "GAZEBO_RESOURCE_PATH=/nowhere:" + (p.root / "resources").string()),
              HasSubstr("ARG[_world:=" + (p.root / "resources/worlds/shapes.world").string() + "]"));
  // A world it cannot find: a message saying why, and the empty world.
  const std::string out = p.run("gzserver", "worlds/willowgarage.world");
  EXPECT_THAT(out, HasSubstr("could not open world file [worlds/willowgarage.world]: the Willow Garage office is a mesh"));
  EXPECT_THAT(out, HasSubstr("ARG[_world:=worlds/empty.world]"));
  EXPECT_THAT(p.run("gzserver", "no_such.world"), HasSubstr("could not open world file [no_such.world]: no such file"));
}

TEST(GzserverScript, RefusesLogPlaybackAndAnswersHelpAndVersion) {
  Package p;
  int status = 0;
  EXPECT_THAT(p.run("gzserver", "-p state.log", &status), HasSubstr("mechsim does not play Gazebo state logs"));
  EXPECT_EQ(status, 2);
  EXPECT_THAT(p.run("gzserver", "-e", &status), HasSubstr("-e needs a value"));
  EXPECT_EQ(status, 2);
  EXPECT_THAT(p.run("gzserver", "--help", &status), HasSubstr("Usage: gzserver [options] [world_file]"));
  EXPECT_EQ(status, 0);
  EXPECT_THAT(p.run("gzserver", "-v", &status), HasSubstr("mechsim gzserver"));
}

TEST(GzserverScript, GazeboIsTheServerAloneAndGzclientSaysThereIsNoGui) {
  Package p;
  const std::string out = p.run("gazebo", "-u worlds/mud.world");
  EXPECT_THAT(out, HasSubstr("gazebo: mechsim has no GUI"));
  EXPECT_THAT(out, HasSubstr("ARG[_world:=" + (p.root / "gazebo_ros/worlds/mud.world").string() + "]"));
  EXPECT_THAT(out, HasSubstr("ARG[_paused:=true]"));
  // gzclient stays until shut down (here SIGTERM: a shell's background job ignores SIGINT), then
  // ends cleanly, its sleep with it.
  const std::string command = "'" + (p.root / "gazebo_ros/gzclient").string() + "' > '" + (p.root / "gui.log").string() +
                              "' 2>&1 & pid=$!; sleep 0.5; kill -0 $pid && echo alive; kill -TERM $pid; wait $pid; echo status=$?";
  FILE* pipe = ::popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string gui;
  std::array<char, 256> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) gui += buffer.data();
  ::pclose(pipe);
  EXPECT_THAT(gui, HasSubstr("alive"));
  EXPECT_THAT(gui, HasSubstr("status=0"));
  std::ifstream log(p.root / "gui.log");
  EXPECT_THAT(std::string(std::istreambuf_iterator<char>(log), {}), HasSubstr("gzclient: mechsim has no GUI"));
}

}  // namespace
}  // namespace mechsim::ros
