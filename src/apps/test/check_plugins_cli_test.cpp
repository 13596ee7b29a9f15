// `mechsim check` lists a description's Gazebo model plugins, simulated or not (an unknown one is
// named once and is not an error), and reports a simulated plugin's bad elements as errors naming
// the file, the line and the plugin.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

#include "run_process.hpp"

namespace mechsim::apps::test {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

// A two-wheel robot with `plugins` inside its <gazebo> block, in this program's scratch folder.
std::string robot_file(const std::string& name, const std::string& plugins) {
  std::string joints;
  for (const char* side : {"left", "right"}) {
    joints += std::string("<joint name='") + side + "_wheel' type='continuous'><parent link='base'/><child link='" + side +
              "_link'/><axis xyz='0 1 0'/></joint><link name='" + side +
              "_link'><inertial><mass value='0.5'/><inertia ixx='1e-3' ixy='0' ixz='0' iyy='1e-3' iyz='0' izz='1e-3'/>"
              "</inertial></link>\n";
  }
  const fs::path dir = fs::path(::testing::TempDir()) / ("mechsim_check_plugins_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const std::string path = (dir / name).string();
  write_file(path, "<?xml version='1.0'?>\n<robot name='wheels'>\n<link name='base'><inertial><mass value='2'/>"
                   "<inertia ixx='0.1' ixy='0' ixz='0' iyy='0.1' iyz='0' izz='0.1'/></inertial></link>\n" +
                       joints + "<gazebo>\n" + plugins + "</gazebo>\n</robot>\n");
  return path;
}

struct Cleanup {
  ~Cleanup() {
    std::error_code ignored;
    fs::remove_all(fs::path(::testing::TempDir()) / ("mechsim_check_plugins_" + std::to_string(getpid())), ignored);
  }
} cleanup;

constexpr const char* kDiffDrive =
    "<plugin name='drive' filename='libgazebo_ros_diff_drive.so'><leftJoint>left_wheel</leftJoint>"
    "<rightJoint>right_wheel</rightJoint><wheelDiameter>DIAMETER</wheelDiameter><updateRate>RATE</updateRate></plugin>\n";

std::string diff_drive(const std::string& diameter, const std::string& rate) {
  std::string s = kDiffDrive;
  s.replace(s.find("DIAMETER"), 8, diameter);
  s.replace(s.find("RATE"), 4, rate);
  return s;
}

TEST(CheckPluginsCli, ListsEveryPluginAndNamesAnUnknownOneOnce) {
  const std::string file = robot_file("good.urdf", diff_drive("0.1", "50") +
                                                       "<plugin name='lights' filename='libdisco_lights.so'><hz>2</hz></plugin>\n");
  const ProcessResult r = run_process({MECHSIM_EXE, "check", file}, 60.0);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("drive (libgazebo_ros_diff_drive.so), line 7: simulated: differential drive"));
  EXPECT_THAT(r.out, HasSubstr("lights (libdisco_lights.so), line 8: NOT SIMULATED"));
  EXPECT_THAT(r.out, HasSubstr("NOT SIMULATED: mechsim does not know this plugin"));
  // Said once (the summary above lists every plugin with its elements, simulated or not).
  const std::string all = r.out + r.err;
  const std::size_t first = all.find("NOT SIMULATED");
  EXPECT_EQ(all.find("NOT SIMULATED", first + 1), std::string::npos) << "said twice:\n" << all;
}

TEST(CheckPluginsCli, BadElementsAreErrorsNamingFileLineAndPlugin) {
  for (const auto& [diameter, rate, what] : std::vector<std::tuple<std::string, std::string, std::string>>{
           {"0", "50", "<wheelDiameter> must be > 0 (got 0)"}, {"0.1", "-10", "<updateRate> is a rate in Hz and must be >= 0"}}) {
    const std::string file = robot_file("bad.urdf", diff_drive(diameter, rate));
    const ProcessResult r = run_process({MECHSIM_EXE, "check", file}, 60.0);
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_THAT(r.err, HasSubstr("Gazebo model plugin 'drive' (libgazebo_ros_diff_drive.so, " + file + ":"));
    EXPECT_THAT(r.err, HasSubstr(what));
  }
  const std::string missing = robot_file("missing.urdf", "<plugin name='drive' filename='libgazebo_ros_diff_drive.so'>"
                                                         "<leftJoint>left_wheel</leftJoint><rightJoint>back_wheel</rightJoint>"
                                                         "</plugin>\n");
  const ProcessResult r = run_process({MECHSIM_EXE, "check", missing}, 60.0);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr(missing + ":"));
  EXPECT_THAT(r.err, HasSubstr("gazebo plugin 'drive' (libgazebo_ros_diff_drive.so): <rightJoint> ("));
  EXPECT_THAT(r.err, HasSubstr("names joint 'back_wheel', which robot 'wheels' does not have"));
}

// A gazebo_ros_control pid_gains block beside the controllers (gazebo's usual file) is no
// namespace; the turntable's three same-name transmissions load with warnings.
TEST(CheckPluginsCli, PidGainsBesideTheControllersAndRepeatedTransmissionNames) {
  const fs::path testbots = fs::path(MECHSIM_SOURCE_DIR) / "robots/testbots";
  const ProcessResult r = run_process({MECHSIM_EXE, "check", (testbots / "urdf/turntable.urdf").string(), "--controllers",
                                       (testbots / "config/turntable_controllers.yaml").string()},
                                      60.0);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_THAT(r.out, HasSubstr("3 of 3 controllers load"));
  EXPECT_THAT(r.out + r.err, HasSubstr("turntable.urdf:28: transmission 'hinge_trans' is defined twice (first at line 22)"));
}

TEST(CheckPluginsCli, NamesARobotSimTypeItCannotLoad) {
  const std::string file = robot_file("hwsim.urdf", "<plugin name='gazebo_ros_control' filename='libgazebo_ros_control.so'>"
                                                    "<robotSimType>my_hw/MyRobotHWSim</robotSimType></plugin>\n");
  const ProcessResult r = run_process({MECHSIM_EXE, "check", file}, 60.0);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("robotSimType 'my_hw/MyRobotHWSim' is NOT SIMULATED"));
}

// Gazebo's own libDiffDrivePlugin.so listens on a Gazebo-transport topic mechsim lacks: the listing
// says which ROS topic stands in for it. It measures its wheels from their joints and collision
// shapes: wheels it cannot measure are an error naming them.
TEST(CheckPluginsCli, SaysHowGazebosOwnDiffDriveIsCommanded) {
  const std::string plugin = "<plugin name='diff_drive' filename='libDiffDrivePlugin.so'><left_joint>left_wheel</left_joint>"
                             "<right_joint>right_wheel</right_joint></plugin>\n";
  const fs::path dir = fs::path(::testing::TempDir()) / ("mechsim_check_plugins_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const std::string tyres = (dir / "tyres.urdf").string();
  std::string joints;
  for (const char* side : {"left", "right"}) {
    joints += std::string("<joint name='") + side + "_wheel' type='continuous'><parent link='base'/><child link='" + side +
              "_link'/><origin xyz='0 " + (side[0] == 'l' ? "0.2" : "-0.2") + " 0'/><axis xyz='0 1 0'/></joint><link name='" +
              side + "_link'><inertial><mass value='0.5'/><inertia ixx='1e-3' ixy='0' ixz='0' iyy='1e-3' iyz='0' izz='1e-3'/>"
              "</inertial><collision><origin rpy='1.5707963 0 0'/><geometry><cylinder radius='0.06' length='0.03'/>"
              "</geometry></collision></link>\n";
  }
  write_file(tyres, "<?xml version='1.0'?>\n<robot name='wheels'>\n<link name='base'><inertial><mass value='2'/>"
                        "<inertia ixx='0.1' ixy='0' ixz='0' iyy='0.1' iyz='0' izz='0.1'/></inertial></link>\n" + joints + "<gazebo>\n" + plugin +
                        "</gazebo>\n</robot>\n");
  const ProcessResult r = run_process({MECHSIM_EXE, "check", tyres}, 60.0);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_THAT(r.out, HasSubstr("diff_drive (libDiffDrivePlugin.so), line 7: simulated: Gazebo's own differential drive"));
  EXPECT_THAT(r.out, HasSubstr("mechsim has no Gazebo transport: its ~/wheels/vel_cmd is the ROS topic /wheels/vel_cmd "
                               "(geometry_msgs/Pose"));
  const ProcessResult bare = run_process({MECHSIM_EXE, "check", robot_file("bare.urdf", plugin)}, 60.0);
  EXPECT_EQ(bare.exit_code, 1) << bare.out;
  // robot_file's wheels share one anchor (no joint origins): Gazebo's separation would be 0.
  EXPECT_THAT(bare.err, HasSubstr("bare.urdf:7: gazebo plugin 'diff_drive' (libDiffDrivePlugin.so): joints 'left_wheel' and "
                                  "'right_wheel' have the same anchor"));
}

}  // namespace
}  // namespace mechsim::apps::test
