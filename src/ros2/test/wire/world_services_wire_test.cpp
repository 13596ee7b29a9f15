// Issue 37's services called by a Fast DDS client in rmw_fastrtps_cpp's form (the peer builds
// every message from the official field lists; Fast DDS serializes them): gazebo_ros' world
// services mapped onto bridge::World, ros2_control's controller manager with its lifecycle, a
// controller's parameters, and 200 concurrent calls from 4 clients with the world's real-time
// factor measured on /clock before and during them. Humble and Jazzy layouts.
#include "wire_fixture.hpp"

namespace mechsim::ros2::test {
namespace {

class WorldServicesWire : public WireTest, public ::testing::WithParamInterface<std::string> {
 protected:
  // One --request argument pair.
  static void request(std::vector<std::string>& args, const std::string& service, const std::string& type,
                      const nlohmann::json& body, int count = 1) {
    args.push_back("--request");
    args.push_back(service + "=" + type + "=" + body.dump() + (count > 1 ? "@" + std::to_string(count) : ""));
  }
  // The reply lines, in order.
  static std::vector<nlohmann::json> replies(const std::vector<nlohmann::json>& lines) {
    std::vector<nlohmann::json> out;
    for (const auto& l : lines)
      if (l.contains("replies")) out.push_back(l);
    return out;
  }
};

nlohmann::json pose(double x, double y, double z) {
  return {{"position", {{"x", x}, {"y", y}, {"z", z}}}, {"orientation", {{"x", 0}, {"y", 0}, {"z", 0}, {"w", 1}}}};
}

const char* kBox =
    "<robot name='crate'><link name='body'><inertial><mass value='2'/><inertia ixx='0.02' iyy='0.02' izz='0.02' "
    "ixy='0' ixz='0' iyz='0'/></inertial><collision><geometry><box size='0.2 0.2 0.2'/></geometry></collision>"
    "</link></robot>";

TEST_P(WorldServicesWire, GazeboServicesMapOntoTheWorld) {
  const std::string distro = GetParam();
  auto args = ros2bot_args();
  args.insert(args.end(), {"--ros-distro", distro, "--real-time-factor", "1"});
  start_mechsim(args);
  std::vector<std::string> a{"--seconds", "0.1"};
  request(a, "/get_model_list", "gazebo_msgs/srv/GetModelList", {});
  request(a, "/get_entity_state", "gazebo_msgs/srv/GetEntityState", {{"name", "ros2bot"}, {"reference_frame", "world"}});
  request(a, "/set_entity_state", "gazebo_msgs/srv/SetEntityState",
          {{"state", {{"name", "ros2bot"}, {"pose", pose(2.0, -1.0, 0.2)}, {"reference_frame", ""}}}});
  request(a, "/get_entity_state", "gazebo_msgs/srv/GetEntityState", {{"name", "ros2bot"}, {"reference_frame", ""}});
  // A URDF with no name given: the description's (gazebo_ros' factory), 1 m above ros2bot.
  request(a, "/spawn_entity", "gazebo_msgs/srv/SpawnEntity",
          {{"name", ""}, {"xml", kBox}, {"initial_pose", pose(0.0, 0.0, 1.0)}, {"reference_frame", "ros2bot"}});
  request(a, "/spawn_entity", "gazebo_msgs/srv/SpawnEntity", {{"name", "crate"}, {"xml", kBox}, {"initial_pose", pose(0, 0, 1)}});
  request(a, "/spawn_entity", "gazebo_msgs/srv/SpawnEntity", {{"name", "broken"}, {"xml", "<robot name='x'><link"}});
  request(a, "/spawn_entity", "gazebo_msgs/srv/SpawnEntity",
          {{"name", "lost"}, {"xml", kBox}, {"initial_pose", pose(0, 0, 1)}, {"reference_frame", "nowhere"}});
  request(a, "/get_entity_state", "gazebo_msgs/srv/GetEntityState", {{"name", "crate::body"}, {"reference_frame", "ros2bot"}});
  request(a, "/get_model_list", "gazebo_msgs/srv/GetModelList", {});
  request(a, "/delete_entity", "gazebo_msgs/srv/DeleteEntity", {{"name", "crate"}});
  request(a, "/delete_entity", "gazebo_msgs/srv/DeleteEntity", {{"name", "crate"}});
  request(a, "/get_entity_state", "gazebo_msgs/srv/GetEntityState", {{"name", "nobody"}, {"reference_frame", ""}});
  request(a, "/get_model_list", "gazebo_msgs/srv/GetModelList", {});
  const auto r = replies(run_fastdds(distro, a, "client"));
  const std::string log = stop_mechsim();
  ASSERT_EQ(r.size(), 14u) << log;
  for (const auto& l : r) EXPECT_EQ(l["replies"], 1) << l << "\n" << log;
  auto models = [](const nlohmann::json& l) { return l["response"]["model_names"].get<std::vector<std::string>>(); };
  EXPECT_EQ(models(r[0]), (std::vector<std::string>{"ground_plane", "ros2bot"}));
  EXPECT_TRUE(r[1]["response"]["success"].get<bool>());
  EXPECT_TRUE(r[2]["response"]["success"].get<bool>()) << log;
  const auto& moved = r[3]["response"]["state"]["pose"]["position"];
  EXPECT_NEAR(moved["x"].get<double>(), 2.0, 0.05) << r[3];
  EXPECT_NEAR(moved["y"].get<double>(), -1.0, 0.05) << r[3];
  EXPECT_TRUE(r[4]["response"]["success"].get<bool>()) << r[4] << "\n" << log;
  EXPECT_EQ(r[4]["response"]["status_message"], "SpawnEntity: Successfully spawned entity [crate]");
  EXPECT_FALSE(r[5]["response"]["success"].get<bool>()) << r[5];  // the name is taken now
  EXPECT_FALSE(r[6]["response"]["success"].get<bool>()) << r[6];  // malformed XML
  EXPECT_FALSE(r[7]["response"]["success"].get<bool>()) << r[7];  // unknown reference frame
  EXPECT_TRUE(r[8]["response"]["success"].get<bool>()) << r[8];
  EXPECT_EQ(r[8]["response"]["header"]["frame_id"], "ros2bot");
  EXPECT_EQ(models(r[9]), (std::vector<std::string>{"ground_plane", "ros2bot", "crate"}));
  EXPECT_TRUE(r[10]["response"]["success"].get<bool>()) << r[10];
  EXPECT_EQ(r[10]["response"]["status_message"], "Successfully deleted entity [crate]");
  EXPECT_FALSE(r[11]["response"]["success"].get<bool>());
  EXPECT_EQ(r[11]["response"]["status_message"], "Entity [crate] does not exist");
  EXPECT_FALSE(r[12]["response"]["success"].get<bool>());
  EXPECT_EQ(models(r[13]), (std::vector<std::string>{"ground_plane", "ros2bot"}));
}

TEST_P(WorldServicesWire, ControllerManagerLifecycleAndParameters) {
  const std::string distro = GetParam();
  auto args = ros2bot_args();
  args.insert(args.end(), {"--ros-distro", distro, "--real-time-factor", "1"});
  start_mechsim(args);
  const std::string cm = "/ros2bot/controller_manager";
  const std::string srv = "controller_manager_msgs/srv/";
  const nlohmann::json none = nlohmann::json::object();
  const nlohmann::json strict = {{"activate_controllers", nlohmann::json::array()}, {"deactivate_controllers", {"mast_controller"}},
                                 {"strictness", 2}, {"activate_asap", false}, {"timeout", {{"sec", 5}, {"nanosec", 0}}}};
  nlohmann::json activate = strict;
  activate["activate_controllers"] = {"mast_controller"};
  activate["deactivate_controllers"] = nlohmann::json::array();
  std::vector<std::string> a{"--seconds", "0.1"};
  request(a, cm + "/list_controllers", srv + "ListControllers", none);                           // 0
  request(a, cm + "/list_controller_types", srv + "ListControllerTypes", none);                  // 1
  request(a, cm + "/list_hardware_interfaces", srv + "ListHardwareInterfaces", none);            // 2
  request(a, cm + "/list_hardware_components", srv + "ListHardwareComponents", none);            // 3
  request(a, cm + "/unload_controller", srv + "UnloadController", {{"name", "mast_controller"}});  // 4 active: refused
  request(a, cm + "/switch_controller", srv + "SwitchController", strict);                       // 5 deactivate
  request(a, cm + "/unload_controller", srv + "UnloadController", {{"name", "mast_controller"}});  // 6
  request(a, cm + "/load_controller", srv + "LoadController", {{"name", "mast_controller"}});      // 7 unconfigured
  request(a, cm + "/switch_controller", srv + "SwitchController", activate);                     // 8 not configured: refused
  request(a, "/ros2bot/mast_controller/get_parameters", "rcl_interfaces/srv/GetParameters", {{"names", {"joints", "use_sim_time", "nope"}}});  // 9
  request(a, cm + "/configure_controller", srv + "ConfigureController", {{"name", "mast_controller"}});  // 10 inactive
  request(a, cm + "/list_controllers", srv + "ListControllers", none);                           // 11
  request(a, cm + "/switch_controller", srv + "SwitchController", activate);                     // 12 active
  request(a, cm + "/load_controller", srv + "LoadController", {{"name", "no_such_controller"}});  // 13 undeclared: refused
  request(a, cm + "/set_hardware_component_state", srv + "SetHardwareComponentState",
          {{"name", "ros2bot"}, {"target_state", {{"id", 2}, {"label", "inactive"}}}});          // 14 refused
  request(a, cm + "/reload_controller_libraries", srv + "ReloadControllerLibraries", {{"force_kill", false}});  // 15 refused
  request(a, "/ros2bot/mast_controller/list_parameters", "rcl_interfaces/srv/ListParameters", {{"prefixes", nlohmann::json::array()}, {"depth", 0}});  // 16
  request(a, "/ros2bot/mast_controller/set_parameters", "rcl_interfaces/srv/SetParameters",
          {{"parameters", {{{"name", "use_sim_time"}, {"value", {{"type", 4}, {"string_value", "yes"}}}}}}});  // 17 wrong type
  request(a, cm + "/list_controllers", srv + "ListControllers", none);                           // 18
  const auto r = replies(run_fastdds(distro, a, "client"));
  const std::string log = stop_mechsim();
  ASSERT_EQ(r.size(), 19u) << log;
  for (const auto& l : r) ASSERT_EQ(l["replies"], 1) << l << "\n" << log;
  auto state_of = [](const nlohmann::json& l, const std::string& name) {
    for (const auto& c : l["response"]["controller"])
      if (c["name"] == name) return c;
    return nlohmann::json();
  };
  EXPECT_EQ(state_of(r[0], "mast_controller")["state"], "active") << r[0];
  EXPECT_EQ(state_of(r[0], "diff_drive_controller")["state"], "active") << r[0];
  EXPECT_EQ(state_of(r[0], "mast_controller")["claimed_interfaces"], nlohmann::json::array({"pan_joint/position"})) << r[0];
  const auto types = r[1]["response"]["types"].get<std::vector<std::string>>();
  EXPECT_NE(std::find(types.begin(), types.end(), "diff_drive_controller/DiffDriveController"), types.end());
  bool pan_claimed = false;
  for (const auto& i : r[2]["response"]["command_interfaces"])
    if (i["name"] == "pan_joint/position") pan_claimed = i["is_claimed"].get<bool>();
  EXPECT_TRUE(pan_claimed) << r[2];
  EXPECT_EQ(r[3]["response"]["component"][0]["name"], "ros2bot");
  EXPECT_EQ(r[3]["response"]["component"][0]["state"]["label"], "active");
  EXPECT_FALSE(r[4]["response"]["ok"].get<bool>());
  EXPECT_TRUE(r[5]["response"]["ok"].get<bool>()) << log;
  EXPECT_TRUE(r[6]["response"]["ok"].get<bool>()) << log;
  EXPECT_TRUE(r[7]["response"]["ok"].get<bool>()) << log;
  EXPECT_FALSE(r[8]["response"]["ok"].get<bool>());
  const auto& values = r[9]["response"]["values"];
  ASSERT_EQ(values.size(), 3u) << r[9];
  EXPECT_EQ(values[0]["type"], 9);  // string array
  EXPECT_EQ(values[0]["string_array_value"], nlohmann::json::array({"pan_joint"}));
  EXPECT_EQ(values[1]["type"], 1);
  EXPECT_EQ(values[2]["type"], 0);
  EXPECT_TRUE(r[10]["response"]["ok"].get<bool>()) << log;
  EXPECT_EQ(state_of(r[11], "mast_controller")["state"], "inactive") << r[11];
  EXPECT_TRUE(r[12]["response"]["ok"].get<bool>()) << log;
  EXPECT_FALSE(r[13]["response"]["ok"].get<bool>());
  EXPECT_FALSE(r[14]["response"]["ok"].get<bool>());
  EXPECT_EQ(r[14]["response"]["state"]["label"], "active");
  EXPECT_FALSE(r[15]["response"]["ok"].get<bool>());
  const auto names = r[16]["response"]["result"]["names"].get<std::vector<std::string>>();
  EXPECT_NE(std::find(names.begin(), names.end(), "joints"), names.end()) << r[16];
  EXPECT_FALSE(r[17]["response"]["results"][0]["successful"].get<bool>()) << r[17];
  EXPECT_EQ(state_of(r[18], "mast_controller")["state"], "active") << r[18];
}

// 200 calls from 4 clients at once (two Fast DDS and two Cyclone DDS clients, 50 each in bursts
// of 10 written back to back), every reply matched to its request; /clock's simulated time per
// wall second while they run and before.
TEST_P(WorldServicesWire, TwoHundredConcurrentCallsFromFourClients) {
  const std::string distro = GetParam();
  auto args = ros2bot_args();
  args.insert(args.end(), {"--ros-distro", distro, "--real-time-factor", "1"});
  start_mechsim(args);
  const auto before = run_fastdds(distro, {"--sub", "/clock=clock:rel", "--seconds", "1.6"}, "clock_before");
  // /clock from the moment the clients start: the calls span most of its 1.6 s (each client
  // writes its 50 requests in 5 bursts of 10, 0.3 s apart, after ~0.2 s of discovery).
  peers_.push_back(std::make_unique<Process>(
      std::vector<std::string>{std::string(MECHSIM_BINARY_DIR) + "/bin/fastdds_peer", "--domain", kDomain, "--distro", distro,
                               "--sub", "/clock=clock:rel", "--seconds", "1.6"},
      dir_ + "/clock_during.log"));
  Process& clock_during = *peers_.back();
  // Two Fast DDS clients (rmw_fastrtps' form) and two Cyclone DDS clients (rmw_cyclonedds' form).
  std::vector<Process*> clients;
  for (int i = 0; i < 4; ++i) {
    const std::string name = i < 2 ? "ros2bot" : "ros2bot::base_link";
    const nlohmann::json steps = {{{"op", "call"}, {"service", "/get_entity_state"}, {"type", "gazebo_msgs/srv/GetEntityState"},
                                   {"request", {{"name", name}, {"reference_frame", ""}}}, {"count", 50}, {"burst", 10},
                                   {"interval", 0.3}}};
    const std::string log = "client" + std::to_string(i);
    clients.push_back(i % 2 == 0 ? &start_fastdds_script(distro, steps, log) : &start_cyclone_script(distro, steps, log));
  }
  const auto clock_status = clock_during.wait(std::chrono::seconds(30));
  EXPECT_TRUE(clock_status && *clock_status == 0) << clock_during.output();
  const auto during = json_lines(clock_during.output());
  int correct = 0;
  for (Process* c : clients) {
    const auto status = c->wait(std::chrono::seconds(60));
    ASSERT_TRUE(status && *status == 0) << c->output();
    for (const auto& l : replies(json_lines(c->output()))) {
      // Every reply goes to every client's reply reader (Fast DDS has no directed write); each
      // client keeps its own: rmw_fastrtps' by related_sample_identity, rmw_cyclonedds' by the
      // client id in the 16-byte header.
      EXPECT_EQ(l["sent"], 50) << l;
      EXPECT_EQ(l["replies"], 50) << l;
      if (l["response"]["success"].get<bool>()) correct += l["replies"].get<int>();
    }
  }
  const std::string log = stop_mechsim();
  EXPECT_EQ(correct, 200) << log;
  std::printf("%d of 200 calls from 4 clients answered correctly\n", correct);
  auto rtf = [](const std::vector<nlohmann::json>& lines) {
    const auto s = summary(lines, "/clock");
    const auto f = first_sample(lines, "/clock");
    if (s.is_null() || f.is_null() || s["span"].get<double>() <= 0.0) return 0.0;
    auto secs = [](const nlohmann::json& t) { return t["sec"].get<double>() + 1e-9 * t["nanosec"].get<double>(); };
    return (secs(s["last"]["clock"]) - secs(f["clock"])) / s["span"].get<double>();
  };
  const double r0 = rtf(before), r1 = rtf(during);
  std::printf("real-time factor from /clock: %.3f before, %.3f during 200 calls\n", r0, r1);
  EXPECT_GT(r0, 0.5);
  EXPECT_GT(r1, 0.9 * r0) << r0 << " before, " << r1 << " during";
}

// gazebo_msgs/srv/GetModelList from a Cyclone DDS client (rmw_cyclonedds' in-payload header,
// types compiled by idlc) and a Fast DDS client (rmw_fastrtps' related sample identity) at once.
TEST_P(WorldServicesWire, ModelListFromBothMiddlewaresAtOnce) {
  const std::string distro = GetParam();
  auto args = ros2bot_args();
  args.insert(args.end(), {"--ros-distro", distro, "--real-time-factor", "1"});
  start_mechsim(args);
  Process& cyclone = start_cyclone(distro, {"--call", "/get_model_list=model_list", "--seconds", "0.1"});
  std::vector<std::string> a{"--seconds", "0.1"};
  request(a, "/get_model_list", "gazebo_msgs/srv/GetModelList", {}, 5);
  const auto fast = replies(run_fastdds(distro, a, "client"));
  const auto status = cyclone.wait(std::chrono::seconds(30));
  ASSERT_TRUE(status && *status == 0) << cyclone.output();
  const std::string log = stop_mechsim();
  nlohmann::json c;
  for (const auto& l : json_lines(cyclone.output()))
    if (l.contains("service")) c = l;
  ASSERT_FALSE(c.is_null()) << cyclone.output();
  EXPECT_EQ(c["form"], "rmw_cyclonedds");
  EXPECT_TRUE(c["reply"].get<bool>()) << c << "\n" << log;
  EXPECT_TRUE(c["success"].get<bool>()) << c;
  EXPECT_EQ(c["model_names"], nlohmann::json::array({"ground_plane", "ros2bot"})) << c;
  ASSERT_EQ(fast.size(), 1u);
  EXPECT_EQ(fast[0]["replies"], 5) << fast[0];
  EXPECT_EQ(fast[0]["response"]["model_names"], nlohmann::json::array({"ground_plane", "ros2bot"}));
}

INSTANTIATE_TEST_SUITE_P(Distros, WorldServicesWire, ::testing::Values("humble", "jazzy"),
                         [](const ::testing::TestParamInfo<std::string>& i) { return i.param; });

}  // namespace
}  // namespace mechsim::ros2::test
