// mechsim's ROS 2 topics as a Cyclone DDS peer (rmw_cyclonedds_cpp's library, types from idlc on
// the official definitions) receives and decodes them, and commands it publishes moving the test
// robot, in the Humble and the Jazzy layout.
#include <cmath>

#include <mechsim_ros2_msgs/rosgraph_msgs.hpp>

#include "topic_checks.hpp"
#include "wire_fixture.hpp"

namespace mechsim::ros2::test {
namespace {

class CycloneWire : public WireTest, public ::testing::WithParamInterface<std::string> {};

double seconds_of(const nlohmann::json& t) { return t["sec"].get<double>() + 1e-9 * t["nanosec"].get<double>(); }

bool has_node(const nlohmann::json& graph, const std::string& ns, const std::string& name) {
  for (const auto& n : graph["nodes"])
    if (n["namespace"] == ns && n["name"] == name) return true;
  return false;
}

TEST_P(CycloneWire, GraphClockAndTypeHashes) {
  const std::string distro = GetParam();
  // Humble at a rate set, Jazzy at the default (every tick: 1 kHz at real time).
  const double expected = distro == "humble" ? 200.0 : 1000.0;
  auto args = ros2bot_args();
  args.insert(args.end(), {"--ros-distro", distro, "--real-time-factor", "1"});
  if (distro == "humble") args.insert(args.end(), {"--clock-rate", "200"});
  start_mechsim(args);
  // A reliable, deep subscription counts every sample sent (ClockQoS' depth 1 keeps the newest).
  const auto lines = run_cyclone(distro, {"--seconds", "3", "--sub", "/clock=clock:deep", "--sub",
                                          "ros_discovery_info=graph", "--endpoints"});
  stop_mechsim();

  // /clock at the rate set, in simulated time.
  const auto clock = summary(lines, "/clock");
  ASSERT_FALSE(clock.is_null());
  const double first = seconds_of(first_sample(lines, "/clock")["clock"]);
  const double last = seconds_of(clock["last"]["clock"]);
  const double count = clock["count"].get<double>();
  ASSERT_GT(last - first, 1.0);
  const double rate = (count - 1) / (last - first);
  EXPECT_NEAR(rate, expected, 0.02 * expected) << count << " messages over " << last - first << " s of simulated time";
  // Real time: about 1 s of simulated time a wall second (the peer's span is wall time).
  EXPECT_NEAR((last - first) / clock["span"].get<double>(), 1.0, 0.15);

  // The graph message in this distro's layout, listing gzserver's, robot_state_publisher's,
  // the controller manager's, each controller's and each sensor plugin's node.
  const auto graph = summary(lines, "ros_discovery_info");
  ASSERT_FALSE(graph.is_null());
  const auto& g = graph["last"];
  EXPECT_EQ(g["gid_size"], distro == "humble" ? 24 : 16);
  EXPECT_TRUE(has_node(g, "/", "gazebo")) << g;
  EXPECT_TRUE(has_node(g, "/", "robot_state_publisher")) << g;
  for (const char* n : {"controller_manager", "joint_state_controller", "diff_drive_controller", "mast_controller",
                        "laser_plugin", "camera_plugin", "imu_plugin"}) {
    EXPECT_TRUE(has_node(g, "/ros2bot", n)) << n << ": " << g;
  }

  // Jazzy's writers carry their type hash; Humble's none.
  bool seen = false;
  for (const auto& l : lines) {
    if (l.value("endpoint", "") != "writer" || l["topic"] != "rt/clock") continue;
    seen = true;
    EXPECT_EQ(l["type"], "rosgraph_msgs::msg::dds_::Clock_");
    if (distro == "jazzy") {
      EXPECT_EQ(l["user_data"], std::string("typehash=") + MessageTraits<rosgraph_msgs::msg::Clock>::type_hash + ";");
    } else {
      EXPECT_EQ(l["user_data"], "");
    }
  }
  EXPECT_TRUE(seen);
}

TEST_P(CycloneWire, TopicsAreDecoded) {
  const std::string distro = GetParam();
  auto args = ros2bot_args();
  args.insert(args.end(), {"--ros-distro", distro, "--real-time-factor", "1"});
  start_mechsim(args);
  auto subs = ros2bot_subscriptions();
  // 6 s of listening for the counts of 4 s (topic_checks.hpp): discovery under a loaded machine
  // took 1.5 s of them once.
  subs.insert(subs.end(), {"--seconds", "6", "--save-image", dir_ + "/front_camera.ppm"});
  const auto lines = run_cyclone(distro, subs);
  stop_mechsim();
  expect_ros2bot_topics(lines);
}

TEST_P(CycloneWire, CommandsMoveTheRobot) {
  const std::string distro = GetParam();
  auto args = ros2bot_args();
  args.insert(args.end(), {"--ros-distro", distro, "--real-time-factor", "1"});
  start_mechsim(args);
  // diff_drive_controller takes TwistStamped on ~/cmd_vel (Jazzy; Humble's use_stamped_vel
  // default); the forward command controller Float64MultiArray on ~/commands.
  const auto lines = run_cyclone(
      distro, {"--seconds", "4", "--rate", "20", "--pub", "/ros2bot/diff_drive_controller/cmd_vel=twist_stamped:0.3,0,0,0,0,0",
               "--pub", "/ros2bot/mast_controller/commands=float64_array:0.6", "--sub",
               "/ros2bot/diff_drive_controller/odom=odometry", "--sub", "/ros2bot/joint_states=joint_state"});
  const std::string log = stop_mechsim();
  const auto odom = summary(lines, "/ros2bot/diff_drive_controller/odom");
  ASSERT_FALSE(odom.is_null());
  EXPECT_GT(odom["last"]["position"][0].get<double>(), 0.4) << odom;  // 0.3 m/s for ~3 s, after discovery
  EXPECT_NEAR(odom["last"]["linear"][0].get<double>(), 0.3, 0.05);
  const auto js = summary(lines, "/ros2bot/joint_states")["last"];
  const auto names = js["name"].get<std::vector<std::string>>();
  const auto it = std::find(names.begin(), names.end(), "pan_joint");
  ASSERT_NE(it, names.end());
  EXPECT_NEAR(js["position"][it - names.begin()].get<double>(), 0.6, 0.03);
}

TEST_F(WireTest, HumbleUnstampedCmdVel) {
  // Humble with use_stamped_vel false: geometry_msgs/msg/Twist on ~/cmd_vel_unstamped.
  auto args = ros2bot_args();
  args.insert(args.end(), {"--ros-distro", "humble", "--use-stamped-vel", "false", "--real-time-factor", "1"});
  start_mechsim(args);
  const auto lines = run_cyclone("humble", {"--seconds", "3", "--pub", "/ros2bot/diff_drive_controller/cmd_vel_unstamped=twist:0.3,0,0,0,0,0.5",
                                            "--sub", "/ros2bot/diff_drive_controller/odom=odometry"});
  stop_mechsim();
  const auto odom = summary(lines, "/ros2bot/diff_drive_controller/odom");
  ASSERT_FALSE(odom.is_null());
  EXPECT_NEAR(odom["last"]["angular"][2].get<double>(), 0.5, 0.1);
  EXPECT_GT(odom["last"]["position"][0].get<double>(), 0.2);
}

INSTANTIATE_TEST_SUITE_P(Distros, CycloneWire, ::testing::Values("humble", "jazzy"),
                         [](const ::testing::TestParamInfo<std::string>& i) { return i.param; });

}  // namespace
}  // namespace mechsim::ros2::test
