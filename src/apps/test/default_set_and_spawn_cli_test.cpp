// `mechsim bench` without --start runs the robot's usual controller set (the widest conflict-free
// one) and says which; `mechsim run` warns at spawn when the robot stands outside the usable
// ground, and the run does not complete.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

#include "run_process.hpp"

namespace mechsim::apps::test {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

const fs::path kSource = MECHSIM_SOURCE_DIR;

ProcessResult mechsim(std::vector<std::string> args, double timeout = 120.0) {
  args.insert(args.begin(), MECHSIM_EXE);
  return run_process(args, timeout);
}

// The line listing the controllers that ran.
std::string running_line(const std::string& out) {
  const auto at = out.find("controllers running");
  return at == std::string::npos ? "" : out.substr(at, out.find('\n', at) - at);
}

TEST(DefaultControllerSet, BenchRunsTheCc8sRoverDriveNotItsPerJointControllers) {
  const ProcessResult r = mechsim({"bench", (kSource / "robots/cc8/urdf/cc8.urdf.xacro").string(), "--package",
                                   "mechsim_cc8=" + (kSource / "robots/cc8").string(), "--controllers",
                                   (kSource / "robots/cc8/config/controllers.yaml").string(), "--namespace", "cc8",
                                   "--seconds", "0.05"});
  ASSERT_TRUE(r.started);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(running_line(r.out),
            "controllers running (default: the widest conflict-free set): joint_state_controller rover_drive_controller");
  EXPECT_THAT(r.err, Not(HasSubstr("warning")));
  EXPECT_THAT(r.out, HasSubstr("2 controllers running"));
}

TEST(DefaultControllerSet, BenchRunsThePr2DefaultSetAndStartReplacesIt) {
  const std::vector<std::string> robot = {(kSource / "robots/pr2/urdf/pr2.urdf.xacro").string(), "--package",
                                          "mechsim_pr2=" + (kSource / "robots/pr2").string(), "--controllers",
                                          (kSource / "robots/pr2/config/controllers.yaml").string(), "--namespace", "pr2",
                                          "--seconds", "0.02"};
  std::vector<std::string> args = {"bench"};
  args.insert(args.end(), robot.begin(), robot.end());
  const ProcessResult r = mechsim(args);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const std::string line = running_line(r.out);
  // pr2_gazebo's default set (robots/pr2/launch/pr2_default_controllers.launch), in YAML order.
  for (const char* name : {"base_controller", "base_odometry", "head_traj_controller", "laser_tilt_controller", "torso_controller",
                           "r_gripper_controller", "l_gripper_controller", "r_arm_controller", "l_arm_controller"}) {
    EXPECT_THAT(line, HasSubstr(std::string(" ") + name));
  }
  EXPECT_THAT(line, Not(HasSubstr("position_controller")));
  EXPECT_THAT(r.out, HasSubstr("9 controllers running"));

  args.insert(args.end(), {"--start", "r_shoulder_pan_position_controller"});
  const ProcessResult chosen = mechsim(args);
  ASSERT_EQ(chosen.exit_code, 0) << chosen.out << chosen.err;
  EXPECT_EQ(running_line(chosen.out), "controllers running (--start): r_shoulder_pan_position_controller");
}

TEST(SpawnOutsideTheTerrain, RunWarnsAtSpawnAndDoesNotComplete) {
  const fs::path dir = fs::temp_directory_path() / ("mechsim_spawn_border_cli_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  write_file((dir / "s.yaml").string(),
             "name: border\nrobot: {description: " + (kSource / "robots/cc8/urdf/cc8.urdf.xacro").string() +
                 ", packages: {mechsim_cc8: " + (kSource / "robots/cc8").string() + "}}\n"
                 "world: {name: mars_yard_2024}\nspawn: {x: -19.6, y: 0, z: 0.05}\n"
                 "controllers: {file: " + (kSource / "robots/cc8/config/controllers.yaml").string() +
                 ", namespace: cc8, start: [joint_state_controller, rover_drive_controller]}\nduration: 1\n");
  const ProcessResult r = mechsim({"run", (dir / "s.yaml").string(), "--no-plots", "-o", (dir / "out").string()});
  fs::remove_all(dir);
  ASSERT_TRUE(r.started);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("warning: at spawn, the robot's footprint"));
  EXPECT_THAT(r.err, HasSubstr("mars_yard_2024's usable ground (inside its 1.5 m border)"));
  EXPECT_THAT(r.out, HasSubstr("did not complete: t=0.001 s: left the usable ground"));
  // Printed once, at spawn (before the run's own lines), not again at the end.
  EXPECT_EQ(r.err.find("warning: at spawn"), r.err.rfind("warning: at spawn"));
}

}  // namespace
}  // namespace mechsim::apps::test
