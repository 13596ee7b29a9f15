// Every service of issue 37 called by two clients of different middlewares at once: the Fast DDS
// peer (rmw_fastrtps_cpp's related sample identity) and the Cyclone DDS client (rmw_cyclonedds'
// in-payload request header), each running the same script on ros2bot: gazebo_ros' world
// services, every controller_manager service (each client takes its own controller through
// the lifecycle, so the two never race for one), the parameter services and /parameter_events.
// Every call gets exactly one reply, the one its request asks for. Humble and Jazzy layouts.
#include "wire_fixture.hpp"

namespace mechsim::ros2::test {
namespace {

using nlohmann::json;

const std::string kCm = "/ros2bot/controller_manager/";
const std::string kSrv = "controller_manager_msgs/srv/";
const std::string kBox =
    "<robot name='crate'><link name='body'><inertial><mass value='2'/><inertia ixx='0.02' iyy='0.02' izz='0.02' "
    "ixy='0' ixz='0' iyz='0'/></inertial><collision><geometry><box size='0.2 0.2 0.2'/></geometry></collision>"
    "</link></robot>";

json call(const std::string& service, const std::string& type, const json& request = json::object()) {
  return {{"op", "call"}, {"service", service}, {"type", type}, {"request", request}};
}
json pose(double x, double y, double z) {
  return {{"position", {{"x", x}, {"y", y}, {"z", z}}}, {"orientation", {{"x", 0}, {"y", 0}, {"z", 0}, {"w", 1}}}};
}
json switch_request(const std::vector<std::string>& activate, const std::vector<std::string>& deactivate) {
  return {{"activate_controllers", activate}, {"deactivate_controllers", deactivate}, {"strictness", 2},
          {"activate_asap", false}, {"timeout", {{"sec", 5}, {"nanosec", 0}}}};
}
const json kUpdateRate = {{"names", {"update_rate"}}};

// What both clients run; `tag` names what is theirs alone (a model, a parameter), `controller`
// the controller they take through the lifecycle.
json script(const std::string& tag, const std::string& controller, double y) {
  const json none = json::object();
  return {
      {{"op", "listen"}, {"topic", "/parameter_events"}, {"type", "rcl_interfaces/ParameterEvent"}, {"as", "events"}},  // 0
      call("/get_model_list", "gazebo_msgs/srv/GetModelList"),                                                       // 1
      call("/get_entity_state", "gazebo_msgs/srv/GetEntityState", {{"name", "ros2bot"}, {"reference_frame", "world"}}),  // 2
      call("/set_entity_state", "gazebo_msgs/srv/SetEntityState",
           {{"state", {{"name", "ros2bot"}, {"pose", pose(1.0, 0.5, 0.2)}, {"reference_frame", "world"}}}}),  // 3
      call("/spawn_entity", "gazebo_msgs/srv/SpawnEntity",
           {{"name", "crate_" + tag}, {"xml", kBox}, {"initial_pose", pose(0.0, y, 0.5)}, {"reference_frame", "world"}}),  // 4
      call("/delete_entity", "gazebo_msgs/srv/DeleteEntity", {{"name", "crate_" + tag}}),  // 5
      call("/pause_physics", "std_srvs/srv/Empty"),                                         // 6
      call("/unpause_physics", "std_srvs/srv/Empty"),                                       // 7
      call("/reset_world", "std_srvs/srv/Empty"),                                           // 8
      call("/reset_simulation", "std_srvs/srv/Empty"),                                      // 9
      call(kCm + "list_controllers", kSrv + "ListControllers"),                             // 10
      call(kCm + "list_controller_types", kSrv + "ListControllerTypes"),                    // 11
      call(kCm + "list_hardware_interfaces", kSrv + "ListHardwareInterfaces"),              // 12
      call(kCm + "list_hardware_components", kSrv + "ListHardwareComponents"),              // 13
      call(kCm + "load_controller", kSrv + "LoadController", {{"name", "no_such_" + tag}}),  // 14 refused
      call(kCm + "configure_controller", kSrv + "ConfigureController", {{"name", "no_such_" + tag}}),  // 15 refused
      call(kCm + "switch_controller", kSrv + "SwitchController", switch_request({}, {"no_such_" + tag})),  // 16 refused
      call(kCm + "unload_controller", kSrv + "UnloadController", {{"name", "no_such_" + tag}}),  // 17 refused
      call(kCm + "reload_controller_libraries", kSrv + "ReloadControllerLibraries", {{"force_kill", false}}),  // 18 refused
      call(kCm + "set_hardware_component_state", kSrv + "SetHardwareComponentState",
           {{"name", "ros2bot"}, {"target_state", {{"id", 3}, {"label", "active"}}}}),  // 19
      call(kCm + "switch_controller", kSrv + "SwitchController", switch_request({}, {controller})),  // 20 deactivate
      call(kCm + "unload_controller", kSrv + "UnloadController", {{"name", controller}}),            // 21
      call(kCm + "load_controller", kSrv + "LoadController", {{"name", controller}}),                // 22 unconfigured
      call(kCm + "configure_controller", kSrv + "ConfigureController", {{"name", controller}}),      // 23 inactive
      call(kCm + "switch_controller", kSrv + "SwitchController", switch_request({controller}, {})),  // 24 active
      call(kCm + "list_controllers", kSrv + "ListControllers"),                                      // 25
      call(kCm + "list_parameters", "rcl_interfaces/srv/ListParameters", {{"prefixes", json::array()}, {"depth", 0}}),  // 26
      call(kCm + "get_parameters", "rcl_interfaces/srv/GetParameters", kUpdateRate),            // 27
      call(kCm + "describe_parameters", "rcl_interfaces/srv/DescribeParameters", kUpdateRate),  // 28
      call(kCm + "get_parameter_types", "rcl_interfaces/srv/GetParameterTypes", kUpdateRate),   // 29
      call(kCm + "set_parameters", "rcl_interfaces/srv/SetParameters",
           {{"parameters", {{{"name", "probe_" + tag}, {"value", {{"type", 2}, {"integer_value", 7}}}}}}}),  // 30
      call("/ros2bot/" + controller + "/get_parameters", "rcl_interfaces/srv/GetParameters", {{"names", {"type"}}}),  // 31
      {{"op", "take"}, {"reader", "events"}, {"all", true}, {"timeout", 0.5}},  // 32
  };
}

class EveryServiceWire : public WireTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(EveryServiceWire, EveryServiceFromBothMiddlewaresAtOnce) {
  const std::string distro = GetParam();
  auto args = ros2bot_args();
  args.insert(args.end(), {"--ros-distro", distro, "--real-time-factor", "1"});
  start_mechsim(args);
  struct Client {
    std::string tag, form, controller, type;
    Process* process;
    std::vector<json> steps;
  };
  const json fast_script = script("fast", "mast_controller", 2.0);
  const json cyclone_script = script("cyclone", "diff_drive_controller", -2.0);
  std::vector<Client> clients = {
      {"fast", "rmw_fastrtps", "mast_controller", "position_controllers/JointGroupPositionController",
       &start_fastdds_script(distro, fast_script, "fastdds"), {}},
      {"cyclone", "rmw_cyclonedds", "diff_drive_controller", "diff_drive_controller/DiffDriveController",
       &start_cyclone_script(distro, cyclone_script, "cyclone"), {}},
  };
  for (Client& c : clients) c.steps = steps_of(*c.process);
  const std::string log = stop_mechsim();
  int calls = 0;
  for (const Client& c : clients) {
    const auto& r = c.steps;
    ASSERT_EQ(r.size(), fast_script.size()) << c.process->output() << log;
    SCOPED_TRACE(c.form);
    for (const auto& s : r) {
      EXPECT_EQ(s["form"], c.form) << s;
      EXPECT_FALSE(s.contains("error")) << s;
      if (s["op"] != "call") continue;
      // One reply, to this request: none of the other client's.
      EXPECT_EQ(s["replies"], 1) << s << "\n" << log;
      calls += s["replies"] == 1 ? 1 : 0;
    }
    auto ok = [&](int i, const char* field) { return r[i]["response"][field] == true; };
    EXPECT_TRUE(ok(1, "success")) << r[1];
    EXPECT_TRUE(ok(2, "success")) << r[2];
    EXPECT_TRUE(ok(3, "success")) << r[3];
    EXPECT_TRUE(ok(4, "success")) << r[4] << log;
    EXPECT_EQ(r[4]["response"]["status_message"], "SpawnEntity: Successfully spawned entity [crate_" + c.tag + "]");
    EXPECT_TRUE(ok(5, "success")) << r[5];
    EXPECT_EQ(r[5]["response"]["status_message"], "Successfully deleted entity [crate_" + c.tag + "]");
    EXPECT_FALSE(r[10]["response"]["controller"].empty()) << r[10];
    EXPECT_FALSE(r[11]["response"]["types"].empty()) << r[11];
    EXPECT_FALSE(r[12]["response"]["command_interfaces"].empty()) << r[12];
    EXPECT_EQ(r[13]["response"]["component"][0]["name"], "ros2bot") << r[13];
    for (const int i : {14, 15, 16, 17, 18}) EXPECT_FALSE(ok(i, "ok")) << r[i];
    EXPECT_TRUE(ok(19, "ok")) << r[19];
    for (const int i : {20, 21, 22, 23, 24}) EXPECT_TRUE(ok(i, "ok")) << r[i] << log;
    bool active = false;
    for (const auto& ctl : r[25]["response"]["controller"])
      if (ctl["name"] == c.controller) active = ctl["state"] == "active";
    EXPECT_TRUE(active) << r[25];
    const auto names = r[26]["response"]["result"]["names"];
    EXPECT_NE(std::find(names.begin(), names.end(), "update_rate"), names.end()) << r[26];
    EXPECT_EQ(r[27]["response"]["values"][0]["type"], 2) << r[27];
    EXPECT_EQ(r[27]["response"]["values"][0]["integer_value"], 1000) << r[27];
    EXPECT_EQ(r[28]["response"]["descriptors"][0]["name"], "update_rate") << r[28];
    EXPECT_TRUE(r[28]["response"]["descriptors"][0]["read_only"].get<bool>()) << r[28];
    EXPECT_EQ(r[29]["response"]["types"], json::array({2})) << r[29];
    EXPECT_TRUE(r[30]["response"]["results"][0]["successful"].get<bool>()) << r[30];
    EXPECT_EQ(r[31]["response"]["values"][0]["string_value"], c.type) << r[31];
    // /parameter_events: the controller manager's event for this client's new parameter.
    bool event = false;
    for (const auto& e : r[32]["values"])
      if (e["node"] == "/ros2bot/controller_manager")
        for (const auto& p : e["new_parameters"])
          if (p["name"] == "probe_" + c.tag) event = p["value"]["integer_value"] == 7;
    EXPECT_TRUE(event) << r[32];
  }
  std::printf("%s: %d of %zu calls answered, from rmw_fastrtps and rmw_cyclonedds clients at once\n", distro.c_str(), calls,
              2 * static_cast<std::size_t>(std::count_if(fast_script.begin(), fast_script.end(),
                                                          [](const json& s) { return s["op"] == "call"; })));
}

INSTANTIATE_TEST_SUITE_P(Distros, EveryServiceWire, ::testing::Values("humble", "jazzy"),
                         [](const ::testing::TestParamInfo<std::string>& i) { return i.param; });

}  // namespace
}  // namespace mechsim::ros2::test
