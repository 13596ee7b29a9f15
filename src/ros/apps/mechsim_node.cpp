// mechsim_node: the simulation as a ROS 1 node (drop-in for gazebo_ros + gazebo_ros_control).
//
// Private parameters (~): ros/node_params.cpp lists them (`mechsim_node --params` prints the
// list); the node reports at start which it took from the parameter server.
// Exit status: 0 after SIGINT/SIGTERM, 1 on an error at start (the message names it), 2 when the
// ROS master restarted under it (ros/master_watch.hpp).
// When ~model is used, the expanded URDF is also set as robot_description (for RViz).
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include <ros/ros.h>

#include "description/robot_loader.hpp"
#include "description/urdf/urdf_parser.hpp"
#include "ros/gazebo_world.hpp"
#include "ros/master_watch.hpp"
#include "ros/node_params.hpp"
#include "bridge/robot_plugins.hpp"
#include "ros/sim_node.hpp"

namespace {

// The first signal asks ROS to shut down (the clean path); a second one ends the process at once,
// for a node stuck contacting an unreachable master (roslaunch follows SIGINT with SIGTERM).
volatile std::sig_atomic_t g_signals = 0;
extern "C" void request_shutdown(int) {
  if (g_signals++ > 0) std::_Exit(130);
  ::ros::requestShutdown();
}

// Waits for a signal or a restarted master (status 2), one loop for both modes.
int serve(mechsim::ros::MasterWatch& master) {
  for (int tick = 1; ::ros::ok(); ++tick) {  // until a signal or rosnode kill
    ::ros::WallDuration(0.1).sleep();
    if (tick % 10 == 0 && master.poll() == mechsim::ros::MasterWatch::State::Restarted) return 2;
  }
  return 0;
}

// Hz (sim time) of /clock: ~pub_clock_frequency as gazebo_ros reads it (0, every step, when
// unset), or mechsim's earlier name ~clock_publish_rate.
double clock_frequency(const ::ros::NodeHandle& pnh) {
  double hz = 0.0;
  if (pnh.getParam("pub_clock_frequency", hz)) return hz;
  return pnh.param("clock_publish_rate", 0.0);
}

// ~gazebo:=true: gazebo_ros' gzserver, an empty world that robots are spawned into.
int run_gazebo_world(::ros::NodeHandle& pnh, mechsim::ros::MasterWatch& master) {
  mechsim::ros::GazeboWorldOptions options;
  options.world.world = pnh.param<std::string>("world", "empty");
  options.world.paused = pnh.param("paused", false);
  options.world.real_time_factor = pnh.param("real_time_factor", 1.0);
  options.world.lenient = pnh.param("lenient", true);
  options.model_states_rate = pnh.param("model_states_rate", 0.0);
  options.node.publish_tf = pnh.param("publish_tf", false);
  options.node.publish_odom_tf = pnh.param("publish_odom_tf", false);
  options.node.odom_frame = pnh.param<std::string>("odom_frame", "odom");
  options.node.tf_rate = pnh.param("tf_rate", 50.0);
  options.node.state_publish_rate = pnh.param("state_publish_rate", 50.0);
  options.node.clock_publish_rate = clock_frequency(pnh);
  options.enable_ros_network = pnh.param("enable_ros_network", true);
  options.step_service = pnh.param("step_service", true);
  if (bool pr2 = false; pnh.getParam("pr2", pr2)) options.node.pr2 = pr2;
  if (std::string ignored; pnh.getParam("gazebo_ignored", ignored) && !ignored.empty()) {
    ROS_INFO_STREAM("mechsim: gazebo_ros arguments accepted without effect (no GUI; MuJoCo, not ODE): " << ignored);
  }
  mechsim::ros::GazeboWorld world(pnh, options);
  ROS_INFO_STREAM("mechsim: world '" << options.world.world << "' up" << (options.world.paused ? " (paused)" : "")
                                     << "; robots come in through /gazebo/spawn_urdf_model");
  // Spawning (a robot's physics built) holds a spinner thread for a while: others keep serving.
  ::ros::AsyncSpinner spinner(4);
  // The world first: its services are advertised already, and a request that comes before it runs
  // waits in the queue rather than being refused ("the world is not running").
  world.start();
  spinner.start();
  const int status = serve(master);
  world.stop();
  spinner.stop();
  ::ros::shutdown();
  return status;
}

int run(int argc, char** argv) {
  // SIGINT/SIGTERM request a ROS shutdown (what roscpp's own SIGINT handler does), so that every
  // wait (for the master, for robot_description) ends and the loop thread stops cleanly.
  std::signal(SIGINT, request_shutdown);
  std::signal(SIGTERM, request_shutdown);
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--params") {
      std::cout << mechsim::ros::describe_private_params();
      return 0;
    }
  }
  ::ros::init(argc, argv, "mechsim", ::ros::init_options::NoSigintHandler);
  mechsim::ros::MasterWatch master;
  ::ros::NodeHandle pnh("~");
  ::ros::NodeHandle nh;
  mechsim::ros::report_private_params(pnh);
  if (pnh.param("gazebo", false)) return run_gazebo_world(pnh, master);

  mechsim::ros::BridgeOptions bridge;
  std::string urdf, source = "robot_description";
  std::string model_path;
  // Description errors that Gazebo tolerates (the PR2's sensor mounts break the inertia triangle
  // inequality) become warnings.
  const bool lenient = pnh.param("lenient", false);
  // An empty ~model is no model: a launch file that waits for robot_description sets it so.
  if (pnh.getParam("model", model_path) && !model_path.empty()) {
    mechsim::description::LoadOptions load;
    pnh.getParam("xacro_args", load.xacro_args);
    load.lenient = lenient;
    mechsim::description::LoadedRobot loaded = mechsim::description::load_robot(model_path, load);
    for (const std::string& w : loaded.warnings) ROS_WARN_STREAM("mechsim: " << model_path << ": " << w);
    urdf = loaded.urdf;
    bridge.robot = std::move(loaded.model);
    nh.setParam("robot_description", urdf);
  } else {
    std::string param_name = pnh.param<std::string>("robot_description", "robot_description");
    std::string found;
    // Like gazebo waiting for spawn_model: the description may be set after the node starts.
    const ::ros::WallTime deadline = ::ros::WallTime::now() + ::ros::WallDuration(pnh.param("spawn_timeout", 60.0));
    auto have = [&] { return nh.searchParam(param_name, found) && nh.getParam(found, urdf); };
    bool waited = false;
    while (!have() && ::ros::WallTime::now() < deadline && ::ros::ok()) {
      if (!waited) ROS_INFO_STREAM("mechsim: waiting for the parameter '" << param_name << "' (the robot to spawn)");
      waited = true;
      ::ros::WallDuration(0.1).sleep();
    }
    if (urdf.empty() && !have()) {
      throw std::runtime_error("no robot: set ~model to a xacro/URDF file or the parameter '" + param_name +
                               "' to a URDF (searched upwards from '" + nh.getNamespace() + "')");
    }
    source = found;
    std::vector<std::string> warnings;
    mechsim::description::UrdfOptions urdf_options;
    urdf_options.lenient = lenient;
    bridge.robot = mechsim::description::parse_urdf_string(urdf, source, urdf_options, &warnings);
    for (const std::string& w : warnings) ROS_WARN_STREAM("mechsim: " << source << ": " << w);
  }

  mechsim::ros::apply_camera_overrides_param(pnh, bridge.robot);

  bool pr2 = false;
  mechsim::ros::NodeOptions options;
  options.robot_namespace = mechsim::ros::plugin_namespace(bridge.robot, &pr2);
  if (std::string ns; pnh.getParam("robot_namespace", ns) && !ns.empty()) options.robot_namespace = ns;
  if (options.robot_namespace.empty()) options.robot_namespace = "/";
  options.pr2 = pnh.param("pr2", pr2);
  options.publish_tf = pnh.param("publish_tf", true);
  options.publish_odom_tf = pnh.param("publish_odom_tf", false);
  options.odom_frame = pnh.param<std::string>("odom_frame", "odom");
  options.tf_rate = pnh.param("tf_rate", 50.0);
  options.state_publish_rate = pnh.param("state_publish_rate", 50.0);
  options.clock_publish_rate = clock_frequency(pnh);
  options.foxglove_port = pnh.param("foxglove_port", -1);
  options.foxglove_address = pnh.param<std::string>("foxglove_address", "127.0.0.1");
  options.foxglove_rate = pnh.param("foxglove_rate", 30.0);
  options.robot_description = urdf;

  bridge.world = pnh.param<std::string>("world", "empty");
  bridge.x = pnh.param("x", 0.0);
  bridge.y = pnh.param("y", 0.0);
  bridge.z = pnh.param("z", 0.0);
  bridge.roll = pnh.param("R", 0.0);
  bridge.pitch = pnh.param("P", 0.0);
  bridge.yaw = pnh.param("Y", 0.0);
  bridge.paused = pnh.param("paused", false);
  bridge.real_time_factor = pnh.param("real_time_factor", 0.0);
  // The controllers' namespace in the Params tree carries its ROS path (errors name it).
  const std::string ns = options.robot_namespace;
  const std::string key = ns.find_first_not_of('/') == std::string::npos ? "" : ns.substr(ns.find_first_not_of('/'));
  mechsim::control::Params root;
  bridge.controller_params = key.empty() ? root : root.child_or_create(key);
  bridge.parameter_root = root;

  mechsim::ros::SimNode node(pnh, std::move(bridge), options);
  for (const std::string& w : node.bridge().physics_warnings()) ROS_WARN_STREAM("mechsim: physics: " << w);
  ROS_INFO_STREAM("mechsim: " << node.bridge().robot().name << " in world '" << pnh.param<std::string>("world", "empty")
                              << "', controller manager at " << ns << (ns.back() == '/' ? "" : "/")
                              << "controller_manager" << (node.bridge().paused() ? " (paused)" : ""));

  ::ros::AsyncSpinner spinner(2);
  spinner.start();
  node.start();
  // SIGINT/SIGTERM: a clean stop (loop thread joined before ROS shuts down). A restarted master
  // (master_watch.hpp) ends the node with status 2.
  const int status = serve(master);
  node.stop();
  spinner.stop();
  ::ros::shutdown();
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  // Line by line into a log file too (roslaunch's output="log", a test's capture): INFO goes to
  // stdout, which is otherwise block-buffered when it is not a terminal.
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "mechsim_node: error: " << e.what() << "\n";
    return 1;
  }
}
