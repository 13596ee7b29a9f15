// A ros2_control robot through the bridge (what the ROS 2 wire layer binds to): the ROS 2
// parameter files given as BridgeOptions::ros2_parameters, the controller manager's node and the
// plugin's namespace and remappings in ros2_control(), each controller's type and ports, claims
// named by interface, and a twist through the diff drive's port moving the robot, its odometry
// following.
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <thread>

#include "bridge/sim_bridge.hpp"
#include "description/robot_loader.hpp"

namespace mechsim::bridge {
namespace {

namespace fs = std::filesystem;
const fs::path kBots = fs::path(MECHSIM_SOURCE_DIR) / "robots/ros2bots";

std::unique_ptr<SimBridge> diffbot(const std::string& ns) {
  description::LoadOptions load;
  load.packages["mechsim_ros2bots"] = kBots.string();
  load.xacro_args["ns"] = ns;
  BridgeOptions options;
  options.robot = description::load_robot((kBots / "urdf/diffbot.urdf.xacro").string(), load).model;
  options.ros2_parameters = control::Ros2ParameterSet::from_files({(kBots / "config/diffbot_controllers.yaml").string()});
  options.z = 0.001;
  return std::make_unique<SimBridge>(std::move(options));
}

// Switches with a ticker thread standing in for the node's loop.
BridgeResult start(SimBridge& bridge, const std::vector<std::string>& names) {
  for (const std::string& n : names) {
    const BridgeResult r = bridge.load_controller(n);
    if (!r.ok) return r;
  }
  std::atomic<bool> done{false};
  std::thread ticker([&] {
    std::string e;
    while (!done.load()) bridge.run_for(0.001, &e);
  });
  const BridgeResult r = bridge.switch_controllers(names, {}, true, 5.0);
  done.store(true);
  ticker.join();
  return r;
}

TEST(Ros2ControlBridge, TellsTheWireLayerTheManagerPluginControllersAndPorts) {
  auto bridge = diffbot("robot1");
  const Ros2ControlSummary* r = bridge->ros2_control();
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->controller_manager, "/robot1/controller_manager");
  EXPECT_EQ(r->node_namespace, "/robot1");
  EXPECT_EQ(r->update_rate, 100.0);
  EXPECT_EQ(r->declared_controllers,
            (std::vector<std::string>{"joint_state_broadcaster", "diff_drive_base_controller", "imu_sensor_broadcaster"}));
  ASSERT_TRUE(r->plugin);
  EXPECT_EQ(r->plugin->filename, "libgazebo_ros2_control.so");
  ASSERT_EQ(r->plugin->remappings.size(), 2u);
  EXPECT_EQ(r->plugin->remappings[0].from, "/tf");
  ASSERT_NE(bridge->ros2_parameters(), nullptr);
  // The controllers' own parameters, for the topics' names and types.
  EXPECT_FALSE(bridge->controller_params().get<bool>("diff_drive_base_controller/use_stamped_vel"));

  ASSERT_TRUE(start(*bridge, {"joint_state_broadcaster", "diff_drive_base_controller", "imu_sensor_broadcaster"}).ok);
  std::map<std::string, PortType> ports;
  for (const PortRef& p : bridge->ports("diff_drive_base_controller")) {
    EXPECT_EQ(p.controller_type, "diff_drive_controller/DiffDriveController");
    ports[p.name] = p.type;
  }
  EXPECT_EQ(ports.at("cmd_vel"), PortType::TwistCommand);
  EXPECT_EQ(ports.at("odom"), PortType::Odometry);
  EXPECT_EQ(bridge->ports("joint_state_broadcaster").at(0).type, PortType::JointStates);
  EXPECT_EQ(bridge->ports("imu_sensor_broadcaster").at(0).type, PortType::ImuState);
  for (const ControllerSummary& c : bridge->list_controllers()) {
    if (c.name != "diff_drive_base_controller") continue;
    ASSERT_EQ(c.claims.size(), 1u);
    EXPECT_EQ(c.claims[0].hardware_interface, "velocity");  // ros2_control: "left_wheel_joint/velocity"
    EXPECT_EQ(c.claims[0].resources, (std::vector<std::string>{"left_wheel_joint", "right_wheel_joint"}));
  }
  // A twist through the port moves the robot; the odometry port reports it.
  PortRef cmd, odom;
  for (const PortRef& p : bridge->ports("diff_drive_base_controller")) {
    if (p.name == "cmd_vel") cmd = p;
    if (p.name == "odom") odom = p;
  }
  // As a teleop node would: the command again every 0.1 s (cmd_vel_timeout is 0.5 s).
  std::string error;
  for (int i = 0; i < 10; ++i) {
    ASSERT_TRUE(write_twist(cmd, 0.4, 0, 0, 0, 0, 0, &error)) << error;
    ASSERT_TRUE(bridge->run_for(0.1, &error)) << error;
  }
  OdometryData o;
  std::uint64_t seq = 0;
  ASSERT_TRUE(read_odometry(odom, o, &seq));
  EXPECT_GT(o.x, 0.2);
  EXPECT_NEAR(bridge->base_pose().position.x, o.x, 0.02);
  EXPECT_EQ(o.frame_id, "odom");
  EXPECT_EQ(o.child_frame_id, "base_footprint");
}

TEST(Ros2ControlBridge, WithoutParametersForItsNamespaceTheManagerHasNoControllers) {
  description::LoadOptions load;
  load.packages["mechsim_ros2bots"] = kBots.string();
  load.xacro_args["ns"] = "robot2";
  BridgeOptions options;
  options.robot = description::load_robot((kBots / "urdf/rrbot.urdf.xacro").string(), load).model;
  // The arm's file names its nodes without a namespace: they are in "/", the manager in "/robot2".
  options.ros2_parameters = control::Ros2ParameterSet::from_files({(kBots / "config/rrbot_controllers.yaml").string()});
  SimBridge bridge(std::move(options));
  ASSERT_NE(bridge.ros2_control(), nullptr);
  EXPECT_TRUE(bridge.ros2_control()->declared_controllers.empty());
  ASSERT_FALSE(bridge.ros2_control()->notes.empty());
  EXPECT_NE(bridge.ros2_control()->notes[0].find("no parameters for the controller manager /robot2/controller_manager"),
            std::string::npos);
  EXPECT_FALSE(bridge.load_controller("forward_position_controller").ok);
}

}  // namespace
}  // namespace mechsim::bridge
