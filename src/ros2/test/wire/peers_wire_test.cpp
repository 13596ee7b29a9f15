// The same topics as the Cyclone peer decodes them (cyclone_wire_test.cpp), received and decoded
// by two more peers written by others: Fast DDS's own DynamicData (rmw_fastrtps_cpp's library)
// and @foxglove/ros2 (an independent TypeScript ROS 2, foxglove's copies of the definitions); and
// commands from the Fast DDS peer. Humble and Jazzy layouts.
#include "topic_checks.hpp"
#include "wire_fixture.hpp"

namespace mechsim::ros2::test {
namespace {

class PeerWire : public WireTest, public ::testing::WithParamInterface<std::string> {
 protected:
  void start_ros2bot() {
    auto args = ros2bot_args();
    args.insert(args.end(), {"--ros-distro", GetParam(), "--real-time-factor", "1"});
    start_mechsim(args);
  }
};

bool has_node(const nlohmann::json& graph, const std::string& ns, const std::string& name) {
  for (const auto& n : graph["nodes"])
    if (n["namespace"] == ns && n["name"] == name) return true;
  return false;
}

TEST_P(PeerWire, FastDdsDecodesEveryTopic) {
  start_ros2bot();
  auto subs = ros2bot_subscriptions();
  subs.insert(subs.end(), {"--seconds", "6", "--sub", "ros_discovery_info=graph"});  // as CycloneWire
  const auto lines = run_fastdds(GetParam(), subs);
  stop_mechsim();
  expect_ros2bot_topics(lines);
  const auto graph = summary(lines, "ros_discovery_info");
  ASSERT_FALSE(graph.is_null());
  EXPECT_EQ(graph["last"]["gid_size"], GetParam() == "humble" ? 24 : 16);
  EXPECT_TRUE(has_node(graph["last"], "/ros2bot", "diff_drive_controller")) << graph;
}

TEST_P(PeerWire, FoxgloveDecodesEveryTopic) {
  start_ros2bot();
  auto subs = ros2bot_subscriptions();
  subs.insert(subs.end(), {"--seconds", "6", "--sub", "ros_discovery_info=graph", "--save-png", dir_ + "/front_camera.png"});
  std::string skip;
  const auto lines = run_foxglove(GetParam(), subs, &skip);
  if (!skip.empty()) GTEST_SKIP() << skip;
  stop_mechsim();
  expect_ros2bot_topics(lines);
  const auto graph = summary(lines, "ros_discovery_info");
  ASSERT_FALSE(graph.is_null());
  EXPECT_EQ(graph["last"]["gid_size"], GetParam() == "humble" ? 24 : 16);
  EXPECT_TRUE(has_node(graph["last"], "/", "robot_state_publisher")) << graph;
  EXPECT_TRUE(std::filesystem::exists(dir_ + "/front_camera.png"));
}

TEST_P(PeerWire, FastDdsCommandsMoveTheRobot) {
  start_ros2bot();
  const auto lines = run_fastdds(GetParam(), {"--seconds", "4", "--rate", "20", "--pub",
                                              "/ros2bot/diff_drive_controller/cmd_vel=twist_stamped:0,0,0,0,0,0.8",
                                              "--pub", "/ros2bot/mast_controller/commands=float64_array:-0.7", "--sub",
                                              "/ros2bot/diff_drive_controller/odom=odometry", "--sub",
                                              "/ros2bot/joint_states=joint_state"});
  stop_mechsim();
  const auto odom = summary(lines, "/ros2bot/diff_drive_controller/odom");
  ASSERT_FALSE(odom.is_null());
  EXPECT_NEAR(odom["last"]["angular"][2].get<double>(), 0.8, 0.1) << odom;
  const auto js = summary(lines, "/ros2bot/joint_states")["last"];
  const auto names = js["name"].get<std::vector<std::string>>();
  const auto it = std::find(names.begin(), names.end(), "pan_joint");
  ASSERT_NE(it, names.end());
  EXPECT_NEAR(js["position"][it - names.begin()].get<double>(), -0.7, 0.03);
}

INSTANTIATE_TEST_SUITE_P(Distros, PeerWire, ::testing::Values("humble", "jazzy"),
                         [](const ::testing::TestParamInfo<std::string>& i) { return i.param; });

}  // namespace
}  // namespace mechsim::ros2::test
