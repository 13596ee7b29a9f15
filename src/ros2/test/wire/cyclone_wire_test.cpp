// mechsim's ROS 2 topics as a Cyclone DDS peer (rmw_cyclonedds_cpp's library, types from idlc on
// the official definitions) receives and decodes them, and commands it publishes moving the test
// robot, in the Humble and the Jazzy layout.
#include <cmath>

#include <mechsim_ros2_msgs/rosgraph_msgs.hpp>

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
  auto args = ros2bot_args();
  args.insert(args.end(), {"--ros-distro", distro, "--clock-rate", "200", "--real-time-factor", "1"});
  start_mechsim(args);
  const auto lines =
      run_cyclone(distro, {"--seconds", "3", "--sub", "/clock=clock", "--sub", "ros_discovery_info=graph", "--endpoints"});
  stop_mechsim();

  // /clock at the rate set: 200 Hz of simulated time (best effort on loopback loses nothing here).
  const auto clock = summary(lines, "/clock");
  ASSERT_FALSE(clock.is_null());
  const double first = seconds_of(first_sample(lines, "/clock")["clock"]);
  const double last = seconds_of(clock["last"]["clock"]);
  const double count = clock["count"].get<double>();
  ASSERT_GT(last - first, 1.0);
  const double rate = (count - 1) / (last - first);
  EXPECT_NEAR(rate, 200.0, 10.0) << count << " messages over " << last - first << " s of simulated time";
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
  const auto lines = run_cyclone(
      distro, {"--seconds", "4", "--sub", "/tf=tf", "--sub", "/tf_static=tf_static", "--sub",
               "/ros2bot/joint_states=joint_state", "--sub", "/ros2bot/scan=laser", "--sub",
               "/ros2bot/front_camera/image_raw=image", "--sub", "/ros2bot/front_camera/camera_info=camera_info",
               "--sub", "/robot_description=string", "--sub", "/ros2bot/diff_drive_controller/odom=odometry", "--sub",
               "/ros2bot/imu=imu", "--save-image", dir_ + "/front_camera.ppm"});
  stop_mechsim();

  // /tf_static: every fixed joint in one message (transient local: the peer came after it).
  const auto tf_static = summary(lines, "/tf_static");
  ASSERT_FALSE(tf_static.is_null());
  EXPECT_EQ(tf_static["count"], 1);
  std::vector<std::string> children;
  for (const auto& t : tf_static["last"]["transforms"]) children.push_back(t["child"]);
  EXPECT_THAT(children, ::testing::UnorderedElementsAre("base_link", "front_caster_link", "rear_caster_link",
                                                        "laser_link", "camera_link"));
  // /tf: the moving joints (20 Hz), and the diff drive's odom -> base_footprint.
  const auto tf = summary(lines, "/tf");
  ASSERT_FALSE(tf.is_null());
  EXPECT_GT(tf["count"].get<int>(), 40);
  bool joints = false, odom = false;
  for (const auto& l : lines) {
    if (l.value("topic", "") != "/tf" || !l.contains("sample")) continue;
    for (const auto& t : l["sample"]["transforms"]) {
      if (t["child"] == "mast_link") joints = t["frame_id"] == "base_link";
      if (t["child"] == "base_footprint") odom = t["frame_id"] == "odom";
    }
  }
  for (const auto& t : tf["last"]["transforms"]) {
    if (t["child"] == "mast_link") joints = true;
    if (t["child"] == "base_footprint") odom = true;
  }
  EXPECT_TRUE(joints) << tf;
  EXPECT_TRUE(odom) << tf;

  const auto js = summary(lines, "/ros2bot/joint_states");
  ASSERT_FALSE(js.is_null());
  EXPECT_THAT(js["last"]["name"].get<std::vector<std::string>>(),
              ::testing::IsSupersetOf({"left_wheel_joint", "right_wheel_joint", "pan_joint"}));
  EXPECT_GT(js["count"].get<int>(), 100);  // 50 Hz for 4 s

  // The laser looks 0.35 rad down from ~0.30 m: the ground ~0.87 m ahead, farther to the sides.
  const auto scan = summary(lines, "/ros2bot/scan");
  ASSERT_FALSE(scan.is_null());
  const auto& s = scan["last"];
  EXPECT_EQ(s["frame_id"], "laser_link");
  EXPECT_EQ(s["ranges"], 181);
  EXPECT_NEAR(s["angle_min"].get<double>(), -1.5708, 1e-4);
  EXPECT_GT(s["finite"].get<int>(), 100);
  EXPECT_NEAR(s["nearest"].get<double>(), 0.87, 0.1);
  EXPECT_GT(scan["count"].get<int>(), 40);  // 20 Hz

  const auto image = summary(lines, "/ros2bot/front_camera/image_raw");
  ASSERT_FALSE(image.is_null());
  EXPECT_EQ(image["last"]["width"], 64);
  EXPECT_EQ(image["last"]["height"], 48);
  EXPECT_EQ(image["last"]["encoding"], "rgb8");
  EXPECT_EQ(image["last"]["bytes"], 64 * 48 * 3);
  EXPECT_GT(image["last"]["mean"].get<double>(), 5.0);  // something was rendered
  EXPECT_EQ(image["last"]["frame_id"], "camera_link");
  const auto info = summary(lines, "/ros2bot/front_camera/camera_info");
  ASSERT_FALSE(info.is_null());
  EXPECT_EQ(info["last"]["width"], 64);
  EXPECT_NEAR(info["last"]["k"][0].get<double>(), 32.0 / std::tan(0.6), 0.5);  // fx from the 1.2 rad FOV

  const auto description = summary(lines, "/robot_description");
  ASSERT_FALSE(description.is_null());
  EXPECT_GT(description["last"]["length"].get<int>(), 2000);
  EXPECT_NE(description["last"]["head"].get<std::string>().find("<"), std::string::npos);

  const auto odometry = summary(lines, "/ros2bot/diff_drive_controller/odom");
  ASSERT_FALSE(odometry.is_null());
  EXPECT_EQ(odometry["last"]["frame_id"], "odom");
  EXPECT_EQ(odometry["last"]["child_frame_id"], "base_footprint");

  const auto imu = summary(lines, "/ros2bot/imu");
  ASSERT_FALSE(imu.is_null());
  EXPECT_EQ(imu["last"]["frame_id"], "base_link");
  EXPECT_NEAR(imu["last"]["linear_acceleration"][2].get<double>(), 9.81, 0.3);
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
