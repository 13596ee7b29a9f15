// A restarted ROS master: mechsim_node (and mechsim_spawner) notices that the new master does not know it (roscpp
// never registers again, so it would run on unseen) and exits with status 2 and a message saying
// why; a master that is merely away is waited for. The test runs its own rosmaster on a second
// free loopback port (the node is pointed at it with __master:=), kills it, checks that the node
// waits, starts a master again on the same port and waits at most 15 s for the node to exit.
#include <gmock/gmock.h>

#include <xmlrpcpp/XmlRpcClient.h>

#include "ros_fixture.hpp"

namespace mechsim::ros::test {
namespace {

using ::testing::HasSubstr;

TEST(MasterRestart, NodeExitsWithAClearMessageWhenTheMasterRestartedAndWaitsWhileItIsAway) {
  const int port = free_loopback_port();
  const std::string uri = "http://127.0.0.1:" + std::to_string(port);
  auto master = start_master_on(port, log_dir() + "/restart_master_1.log");
  ChildProcess node({MECHSIM_NODE_EXE, "__name:=restart_sim", "__master:=" + uri,
                     "_model:=" + std::string(MECHSIM_SOURCE_DIR) + "/robots/cc8/urdf/cc8.urdf.xacro",
                     "_real_time_factor:=1.0"},
                    log_dir() + "/node_restart.log");
  // Up: the controller manager's services (advertised last) are registered.
  ASSERT_TRUE(wait_until([&] { return node.log().find("controller manager at") != std::string::npos || !node.running(); },
                         60.0))
      << node.log();
  EXPECT_EQ(lookup_node(port, "/restart_sim"), 1);
  // A spawner too, with joint_state_controller's parameters on that master.
  for (const auto& [key, value] : std::vector<std::pair<std::string, XmlRpc::XmlRpcValue>>{
           {"type", XmlRpc::XmlRpcValue("joint_state_controller/JointStateController")},
           {"publish_rate", XmlRpc::XmlRpcValue(50.0)}}) {
    XmlRpc::XmlRpcClient client("127.0.0.1", port, "/");
    XmlRpc::XmlRpcValue args, result;
    args[0] = "/master_restart_test";
    args[1] = "/cc8/joint_state_controller/" + key;
    args[2] = value;
    ASSERT_TRUE(client.execute("setParam", args, result));
  }
  ChildProcess spawner({MECHSIM_SPAWNER_EXE, "__master:=" + uri, "__ns:=/cc8", "__name:=restart_spawner",
                        "joint_state_controller"},
                       log_dir() + "/spawner_restart.log");
  ASSERT_TRUE(wait_until([&] { return spawner.log().find("started 1 controllers") != std::string::npos; }, 30.0))
      << spawner.log();
  ASSERT_TRUE(node.running()) << node.log();

  master->stop();
  master.reset();
  std::this_thread::sleep_for(std::chrono::seconds(3));
  EXPECT_TRUE(node.running()) << "a master away for a while is waited for:\n" << node.log();
  EXPECT_THAT(node.log(), HasSubstr("does not answer; waiting for it"));

  master = start_master_on(port, log_dir() + "/restart_master_2.log");
  EXPECT_EQ(node.wait(15.0), 2) << node.log();
  EXPECT_EQ(spawner.wait(5.0), 2) << spawner.log();
  EXPECT_THAT(spawner.log(), HasSubstr("restarted"));
  EXPECT_THAT(node.log(), HasSubstr("restarted"));
  EXPECT_THAT(node.log(), HasSubstr("exiting"));
  EXPECT_EQ(lookup_node(port, "/restart_sim"), -1) << "the node registered nothing with the new master";
}

}  // namespace
}  // namespace mechsim::ros::test
