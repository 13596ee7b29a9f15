// The abuse test's last phase (issue 19, item 3): the rosmaster killed and restarted once while
// the PR2 runs its controllers and takes a stream of malformed commands (NaN/Inf Twists on the
// base, trajectories naming a joint twice at 100 Hz, from Debian's rostopic). The node must behave
// as src/ros/README.md "Master restarts" documents: wait while the master is away, then exit with
// status 2 (not a crash: no signal, no sanitizer report) once a new master answers. The node
// talks to a master of its own on a second loopback port (__master:=), as master_restart_test.cpp.
#include <gmock/gmock.h>

#include <filesystem>

#include "ros_fixture.hpp"

namespace mechsim::ros::test {
namespace {

using ::testing::HasSubstr;

const std::string kPr2Urdf = std::string(MECHSIM_SHARED_DIR) + "/robots/reference/pr2.urdf";

// `argv` against the master at `uri` (Debian's Python tools read ROS_MASTER_URI).
std::vector<std::string> with_master(const std::string& uri, const std::vector<std::string>& argv) {
  std::vector<std::string> out{"/usr/bin/env", "ROS_MASTER_URI=" + uri, "/usr/bin/python3"};
  out.insert(out.end(), argv.begin(), argv.end());
  return out;
}

TEST(Pr2AbuseMasterRestart, NodeUnderMalformedCommandsExitsWithStatus2WhenTheMasterRestarts) {
  if (!std::filesystem::exists(kPr2Urdf)) GTEST_SKIP() << "the shared data folder has no PR2 (" << kPr2Urdf << ")";
  const int port = free_loopback_port();
  const std::string uri = "http://127.0.0.1:" + std::to_string(port);
  auto master = start_master_on(port, log_dir() + "/abuse_master_1.log");
  ChildProcess params(with_master(uri, {"/usr/bin/rosparam", "load",
                                        std::string(MECHSIM_SOURCE_DIR) + "/robots/pr2/config/controllers.yaml"}),
                      log_dir() + "/abuse_restart_rosparam.log");
  ASSERT_EQ(params.wait(30.0), 0) << params.log();
  ChildProcess node({MECHSIM_NODE_EXE, "__name:=abuse_restart_sim", "__master:=" + uri, "_model:=" + kPr2Urdf,
                     "_lenient:=true", "_robot_namespace:=/pr2", "_real_time_factor:=1.0"},
                    log_dir() + "/node_abuse_restart.log");
  ChildProcess spawner({MECHSIM_SPAWNER_EXE, "__master:=" + uri, "__ns:=/pr2", "__name:=abuse_restart_spawner",
                        "base_controller", "r_arm_controller"},
                       log_dir() + "/spawner_abuse_restart.log");
  ASSERT_TRUE(wait_until([&] { return spawner.log().find("started 2 controllers") != std::string::npos || !node.running(); },
                         60.0))
      << spawner.log() << "\n" << node.log();
  ASSERT_TRUE(node.running()) << node.log();

  // The streams, until the node exits.
  ChildProcess twist(with_master(uri, {"/usr/bin/rostopic", "pub", "-r", "100", "/pr2/base_controller/command",
                                       "geometry_msgs/Twist", "{linear: {x: .nan, y: 1.0e+300}, angular: {z: .inf}}"}),
                     log_dir() + "/abuse_restart_twist.log");
  ChildProcess trajectory(
      with_master(uri, {"/usr/bin/rostopic", "pub", "-r", "100", "/pr2/r_arm_controller/command",
                        "trajectory_msgs/JointTrajectory",
                        "{joint_names: [r_shoulder_pan_joint, r_shoulder_pan_joint], points: [{positions: [.nan, 1.0], "
                        "time_from_start: {secs: -1, nsecs: 0}}]}"}),
      log_dir() + "/abuse_restart_trajectory.log");
  // Both arrive and are refused (the node says so, throttled).
  ASSERT_TRUE(wait_until(
      [&] {
        const std::string log = node.log();
        return log.find("base_controller: cmd_vel rejected") != std::string::npos &&
               log.find("r_arm_controller: trajectory rejected") != std::string::npos;
      },
      30.0))
      << node.log() << "\n" << twist.log() << "\n" << trajectory.log();

  master->stop();
  master.reset();
  std::this_thread::sleep_for(std::chrono::seconds(2));
  EXPECT_TRUE(node.running()) << "a master away for a while is waited for:\n" << node.log();
  master = start_master_on(port, log_dir() + "/abuse_master_2.log");
  EXPECT_EQ(node.wait(15.0), 2) << "expected exit status 2 (README \"Master restarts\"); -1 is a signal:\n" << node.log();
  EXPECT_EQ(spawner.wait(10.0), 2) << spawner.log();
  const std::string log = node.log();
  EXPECT_THAT(log, HasSubstr("restarted"));
  for (const char* bad : {"AddressSanitizer", "runtime error", "terminate called", "Segmentation"}) {
    EXPECT_EQ(log.find(bad), std::string::npos) << "the node's log says '" << bad << "':\n" << log;
  }
  twist.stop();
  trajectory.stop();
}

}  // namespace
}  // namespace mechsim::ros::test
