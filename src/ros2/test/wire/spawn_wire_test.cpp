// A robot from spawn to moving through services alone, as a ROS 2 user's launch file does it:
// a Cyclone DDS node publishes the description on /robot_description (robot_state_publisher's
// transient local); a Fast DDS client does what spawn_entity.py -topic robot_description, the
// spawner and MoveIt do (spawn, declare the controller's type, load, set its parameters,
// configure, activate, a FollowJointTrajectory goal); a client vanishes with a goal running;
// a Cyclone DDS client deletes the robot and spawns it again under the same name and namespace,
// which finds nothing of the first one left. mechsim starts with an empty world. Humble and Jazzy.
#include <cmath>
#include <fstream>
#include <sstream>

#include "wire_fixture.hpp"

namespace mechsim::ros2::test {
namespace {

using nlohmann::json;

json call(const std::string& service, const std::string& type, const json& request = json::object()) {
  return {{"op", "call"}, {"service", service}, {"type", type}, {"request", request}};
}
json parameter(const std::string& name, const json& value) { return {{"name", name}, {"value", value}}; }
json string_value(const std::string& s) { return {{"type", 4}, {"string_value", s}}; }
json strings_value(const std::vector<std::string>& s) { return {{"type", 9}, {"string_array_value", s}}; }
json identity_pose() {
  return {{"position", {{"x", 0}, {"y", 0}, {"z", 0}}}, {"orientation", {{"x", 0}, {"y", 0}, {"z", 0}, {"w", 1}}}};
}
// /spawn_entity as spawn_entity.py -topic robot_description -entity turntable -robot_namespace /turntable.
json spawn() {
  return call("/spawn_entity", "gazebo_msgs/srv/SpawnEntity",
              {{"name", "turntable"}, {"xml", "$description"}, {"robot_namespace", "/turntable"},
               {"initial_pose", identity_pose()}, {"reference_frame", "world"}});
}
json take_description() {
  return {{"op", "take"}, {"topic", "/robot_description"}, {"type", "std_msgs/String"}, {"qos", "tl"},
          {"field", "data"}, {"as", "description"}, {"timeout", 10.0}};
}
// One point: the hinge at `position` after `seconds`.
json hinge_goal(double position, double seconds) {
  return {{"trajectory",
           {{"joint_names", {"hinge"}},
            {"points", {{{"positions", {position}}, {"time_from_start", {{"sec", static_cast<int>(seconds)},
                                                                         {"nanosec", static_cast<unsigned>(std::lround((seconds - std::floor(seconds)) * 1e9))}}}}}}}},
          {"goal_tolerance", {{{"name", "hinge"}, {"position", 0.05}, {"velocity", 0.0}, {"acceleration", 0.0}}}},
          {"goal_time_tolerance", {{"sec", 1}, {"nanosec", 0}}}};
}
const std::string kCm = "/turntable/controller_manager/";
const std::string kSrv = "controller_manager_msgs/srv/";
const std::string kAction = "/turntable/arm_controller/follow_joint_trajectory";

// The yaw of a GetEntityState reply's orientation.
double yaw_of(const json& reply) {
  const json& q = reply["response"]["state"]["pose"]["orientation"];
  return 2.0 * std::atan2(q["z"].get<double>(), q["w"].get<double>());
}

class SpawnWire : public WireTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(SpawnWire, SpawnToMovingThroughServicesAlone) {
  const std::string distro = GetParam();
  std::ifstream file(std::string(MECHSIM_SOURCE_DIR) + "/robots/testbots/urdf/turntable.urdf");
  ASSERT_TRUE(file) << "robots/testbots/urdf/turntable.urdf";
  std::stringstream urdf;
  urdf << file.rdbuf();
  start_mechsim({"--real-time-factor", "1", "--ros-distro", distro});

  // robot_state_publisher's part: the description, transient local, kept while the node lives.
  const json publisher = {{{"op", "publish"}, {"topic", "/robot_description"}, {"type", "std_msgs/String"}, {"qos", "tl"},
                           {"message", {{"data", urdf.str()}}}},
                          {{"op", "sleep"}, {"seconds", 30.0}}};
  start_cyclone_script(distro, publisher, "robot_state_publisher");

  const json activate = {{"activate_controllers", {"arm_controller"}}, {"deactivate_controllers", json::array()},
                         {"strictness", 2}, {"activate_asap", false}, {"timeout", {{"sec", 5}, {"nanosec", 0}}}};
  const json user = {
      take_description(),                                                                                    // 0
      spawn(),                                                                                               // 1
      call("/get_model_list", "gazebo_msgs/srv/GetModelList"),                                               // 2
      call(kCm + "set_parameters", "rcl_interfaces/srv/SetParameters",
           {{"parameters", {parameter("arm_controller.type", string_value("joint_trajectory_controller/JointTrajectoryController"))}}}),  // 3
      call(kCm + "load_controller", kSrv + "LoadController", {{"name", "arm_controller"}}),                 // 4
      call("/turntable/arm_controller/set_parameters", "rcl_interfaces/srv/SetParameters",
           {{"parameters", {parameter("joints", strings_value({"hinge"})), parameter("command_interfaces", strings_value({"position"})),
                            parameter("state_interfaces", strings_value({"position", "velocity"}))}}}),  // 5
      call(kCm + "configure_controller", kSrv + "ConfigureController", {{"name", "arm_controller"}}),       // 6
      call(kCm + "switch_controller", kSrv + "SwitchController", activate),                                 // 7
      call(kCm + "list_controllers", kSrv + "ListControllers"),                                             // 8
      {{"op", "send_goal"}, {"action", kAction}, {"type", "control_msgs/action/FollowJointTrajectory"},
       {"goal", hinge_goal(0.8, 1.0)}, {"as", "turn"}},                                                     // 9
      {{"op", "result"}, {"goal", "turn"}, {"timeout", 20.0}},                                              // 10 SUCCEEDED
      call("/get_entity_state", "gazebo_msgs/srv/GetEntityState", {{"name", "turntable::bob"}, {"reference_frame", "world"}}),  // 11
  };
  const auto u = steps_of(start_fastdds_script(distro, user, "spawner"));
  ASSERT_EQ(u.size(), user.size()) << mechsim_->output();
  for (const auto& s : u) EXPECT_FALSE(s.contains("error")) << s;
  EXPECT_TRUE(u[0]["got"].get<bool>()) << u[0];
  EXPECT_EQ(u[0]["length"], urdf.str().size());
  for (const int i : {1, 2, 3, 4, 5, 6, 7, 8, 11}) ASSERT_EQ(u[i]["replies"], 1) << u[i] << mechsim_->output();
  EXPECT_TRUE(u[1]["response"]["success"].get<bool>()) << u[1] << mechsim_->output();
  EXPECT_EQ(u[2]["response"]["model_names"], json::array({"ground_plane", "turntable"})) << u[2];
  EXPECT_TRUE(u[3]["response"]["results"][0]["successful"].get<bool>()) << u[3];
  EXPECT_TRUE(u[4]["response"]["ok"].get<bool>()) << u[4] << mechsim_->output();
  for (const auto& r : u[5]["response"]["results"]) EXPECT_TRUE(r["successful"].get<bool>()) << u[5];
  EXPECT_TRUE(u[6]["response"]["ok"].get<bool>()) << u[6] << mechsim_->output();
  EXPECT_TRUE(u[7]["response"]["ok"].get<bool>()) << u[7] << mechsim_->output();
  ASSERT_EQ(u[8]["response"]["controller"].size(), 1u) << u[8];
  EXPECT_EQ(u[8]["response"]["controller"][0]["name"], "arm_controller");
  EXPECT_EQ(u[8]["response"]["controller"][0]["state"], "active");
  EXPECT_EQ(u[8]["response"]["controller"][0]["claimed_interfaces"], json::array({"hinge/position"})) << u[8];
  EXPECT_TRUE(u[9]["accepted"].get<bool>()) << u[9] << mechsim_->output();
  EXPECT_EQ(u[10]["status"], 4) << u[10] << mechsim_->output();
  EXPECT_EQ(u[10]["result"]["error_code"], 0) << u[10];
  // The bob turned with the hinge (its link frame is on the hinge axis).
  EXPECT_TRUE(u[11]["response"]["success"].get<bool>()) << u[11];
  const double turned = yaw_of(u[11]);
  EXPECT_NEAR(turned, 0.8, 0.05) << u[11];

  // A client sends a long goal and vanishes (a crash: nothing said; its lease 1 s).
  const json vanishing = {{{"op", "send_goal"}, {"action", kAction}, {"type", "control_msgs/action/FollowJointTrajectory"},
                           {"goal", hinge_goal(-0.8, 5.0)}, {"as", "long"}},
                          {{"op", "sleep"}, {"seconds", 0.2}},
                          {{"op", "vanish"}}};
  const auto v = steps_of(start_fastdds_script(distro, vanishing, "vanishing", {"--lease", "1"}));
  ASSERT_EQ(v.size(), 2u);
  EXPECT_TRUE(v[0]["accepted"].get<bool>()) << v[0];
  EXPECT_TRUE(mechsim_->wait_for_output("get_result request(s) dropped: the client is gone", std::chrono::seconds(4)))
      << mechsim_->output();

  // Delete while that goal runs, from Cyclone DDS; then the same name and namespace again.
  const json again = {
      call("/delete_entity", "gazebo_msgs/srv/DeleteEntity", {{"name", "turntable"}}),  // 0
      call("/get_model_list", "gazebo_msgs/srv/GetModelList"),                          // 1
      take_description(),                                                               // 2
      spawn(),                                                                          // 3
      call(kCm + "list_controllers", kSrv + "ListControllers"),                         // 4
      call("/get_entity_state", "gazebo_msgs/srv/GetEntityState", {{"name", "turntable::bob"}, {"reference_frame", "world"}}),  // 5
      call("/delete_entity", "gazebo_msgs/srv/DeleteEntity", {{"name", "turntable"}}),  // 6
      call("/get_model_list", "gazebo_msgs/srv/GetModelList"),                          // 7
  };
  const auto a = steps_of(start_cyclone_script(distro, again, "delete_and_again"));
  const std::string log = stop_mechsim();
  ASSERT_EQ(a.size(), again.size()) << log;
  for (const int i : {0, 1, 3, 4, 5, 6, 7}) ASSERT_EQ(a[i]["replies"], 1) << a[i] << log;
  EXPECT_EQ(a[0]["form"], "rmw_cyclonedds");
  EXPECT_TRUE(a[0]["response"]["success"].get<bool>()) << a[0];
  EXPECT_EQ(a[1]["response"]["model_names"], json::array({"ground_plane"})) << a[1];
  EXPECT_TRUE(a[3]["response"]["success"].get<bool>()) << a[3] << log;
  // Nothing of the first one: no controller, the hinge at rest where the description puts it.
  EXPECT_EQ(a[4]["response"]["controller"], json::array()) << a[4];
  EXPECT_NEAR(yaw_of(a[5]), 0.0, 0.01) << a[5];
  EXPECT_TRUE(a[6]["response"]["success"].get<bool>()) << a[6];
  EXPECT_EQ(a[7]["response"]["model_names"], json::array({"ground_plane"})) << a[7];
  // The vanished client's goal ended with its robot; its controller went with it.
  EXPECT_NE(log.find(kAction + ": goals canceled: the model is being deleted"), std::string::npos) << log;
  EXPECT_NE(log.find("deleting 'turntable': 1 controllers stopped and unloaded"), std::string::npos) << log;
  std::printf("%s: spawned from /robot_description, controller loaded, configured, activated; goal SUCCEEDED, hinge at "
              "%.3f rad (goal 0.8, tolerance 0.05); deleted and spawned again clean\n",
              distro.c_str(), turned);
}

INSTANTIATE_TEST_SUITE_P(Distros, SpawnWire, ::testing::Values("humble", "jazzy"),
                         [](const ::testing::TestParamInfo<std::string>& i) { return i.param; });

}  // namespace
}  // namespace mechsim::ros2::test
