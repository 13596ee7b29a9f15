// SimNode: construction, the loop thread, /clock and gazebo's simulation services.
#include "ros/sim_node.hpp"

#include <rosgraph_msgs/Clock.h>
#include <std_msgs/Bool.h>
#include <std_srvs/Empty.h>

#include <time.h>

#include <cstdio>

#include "description/ros_control_plugin.hpp"
#include "ros/xmlrpc_params.hpp"

namespace mechsim::ros {

void SimNode::load_parameters(const std::string& robot_namespace, BridgeOptions& bridge) {
  ::ros::NodeHandle robot_nh(robot_namespace);
  // The controllers' parameters as they are now; each load re-reads its own namespace.
  XmlRpc::XmlRpcValue all;
  if (robot_nh.getParam(robot_nh.getNamespace(), all) && all.getType() == XmlRpc::XmlRpcValue::TypeStruct) {
    std::string warning;
    fill_params_from_xmlrpc(bridge.controller_params, all, &warning);
    if (!warning.empty()) ROS_WARN_STREAM("mechsim: parameters not taken: " << warning);
  }
  // gazebo_ros_control's legacy pid_gains live at the absolute /gazebo_ros_control (outside a
  // robot namespace other than /).
  XmlRpc::XmlRpcValue gains;
  if (bridge.parameter_root && robot_nh.getNamespace() != "/" && ::ros::NodeHandle("/").getParam("/gazebo_ros_control", gains) &&
      gains.getType() == XmlRpc::XmlRpcValue::TypeStruct) {
    std::string warning;
    set_param_from_xmlrpc(*bridge.parameter_root, "gazebo_ros_control", gains, &warning);
    if (!warning.empty()) ROS_WARN_STREAM("mechsim: parameters not taken: " << warning);
  }
}

SimNode::SimNode(::ros::NodeHandle nh, BridgeOptions bridge, NodeOptions options)
    : private_nh_(std::move(nh)), root_nh_("/"), robot_nh_(options.robot_namespace), options_(std::move(options)) {
  load_parameters(options_.robot_namespace, bridge);
  owned_bridge_ = std::make_unique<SimBridge>(std::move(bridge));
  bridge_ = owned_bridge_.get();
  clock_pub_ = root_nh_.advertise<rosgraph_msgs::Clock>("/clock", 10);
  set_up();
}

SimNode::SimNode(::ros::NodeHandle nh, SimBridge& model, NodeOptions options)
    : private_nh_(std::move(nh)), root_nh_("/"), robot_nh_(options.robot_namespace), options_(std::move(options)),
      bridge_(&model), other_robot_(true) {
  options_.gazebo_services = false;  // the world offers them
  set_up();
}

void SimNode::set_up() {
  for (const std::string& note : bridge_->joint_drive_notes()) ROS_INFO_STREAM("mechsim: " << note);
  if (const auto plugin = description::find_ros_control_plugin(bridge_->robot()); plugin && !plugin->default_hw()) {
    ROS_WARN_STREAM("mechsim: " << plugin->origin << ": gazebo_ros_control robotSimType '" << plugin->robot_sim_type
                                << "' is not simulated (mechsim cannot load a RobotHWSim plugin): the transmissions' "
                                   "joints get gazebo_ros_control/DefaultRobotHWSim's behaviour instead");
  }
  if (!bridge_->e_stop_topic().empty()) {
    // gazebo_ros_control subscribes to its <eStopTopic> in the robot's namespace, queue 1.
    SimBridge* sim = bridge_;
    e_stop_sub_ = robot_nh_.subscribe<std_msgs::Bool>(
        bridge_->e_stop_topic(), 1, [sim](const std_msgs::Bool::ConstPtr& msg) {
          if (msg->data != sim->e_stop_active()) {
            ROS_INFO_STREAM("mechsim: e-stop " << (msg->data ? "active: joints hold, no effort" : "released: controllers restart"));
          }
          sim->set_e_stop(msg->data);
        });
    ROS_INFO_STREAM("mechsim: gazebo_ros_control e-stop on " << e_stop_sub_.getTopic());
  }
  if (options_.publish_tf) {
    tf_ = std::make_unique<TfPublisher>(root_nh_, bridge_->robot(), options_.publish_odom_tf ? options_.odom_frame : "");
    tf_->publish_static(bridge_->time());
  }
  if (options_.foxglove_port >= 0 && other_robot_) {
    ROS_WARN_STREAM("mechsim: model '" << bridge_->robot().name << "': ~foxglove_port: no live view of a model spawned into a world (gzserver mode); mechsim_node with ~model has one");
  } else if (options_.foxglove_port >= 0) {
    const std::string url = bridge_->start_live_view(options_.foxglove_address, options_.foxglove_port,
                                                     options_.robot_description, options_.foxglove_rate);
    ROS_INFO_STREAM("mechsim: live view on " << url << " (Foxglove WebSocket protocol: Foxglove Studio, Lichtblick)");
  }
  // The statistics observer runs before on_tick, so that a tick's statistics include it.
  if (options_.pr2) bridge_->enable_mechanism_statistics();
  sensors_ = std::make_unique<SensorPublishers>(root_nh_, *bridge_);
  plugins_ = std::make_unique<ModelPluginTopics>(root_nh_, *bridge_);
  // Another robot's bridge outlives this node (the world takes it out of the physics after the
  // node has gone): its observer asks the shared flag before it touches the node.
  bridge_->add_observer([this, other = other_robot_, on = outputs_on_](double time) {
    if (!other || on->load(std::memory_order_acquire)) on_tick(time);
  });
  if (options_.gazebo_services) advertise_sim_services();
  if (options_.controller_manager) advertise_controller_manager();
  if (options_.pr2) {
    advertise_pr2_controller_manager();
    advertise_pr2_outputs();
  }
}

SimNode::~SimNode() { stop(); }

void SimNode::start() {
  if (other_robot_) {
    outputs_on_->store(true, std::memory_order_release);
    return;
  }
  stop_.store(false);
  loop_thread_ = std::thread([this] { loop(); });
}

void SimNode::stop() {
  if (other_robot_) {
    outputs_on_->store(false, std::memory_order_release);
    bridge_->wait_for_loop();
    return;
  }
  stop_.store(true);
  if (!loop_thread_.joinable()) return;
  loop_thread_.join();
  if (const std::string live = bridge_->live_view_summary(); !live.empty()) std::printf("mechsim: live view: %s\n", live.c_str());
  // What publishing the sensors cost (the figures in README.md, "Sensors", come from here).
  // printf: after a SIGINT, roscpp has shut rosconsole down by now.
  const SensorPublishStats s = sensors_->stats();
  if (s.calls > 0) {
    const double ticks = static_cast<double>(s.calls);
    std::printf("mechsim: sensor publishing: %llu ticks; per tick %.3f us wall in the tick's publisher, %.3f us CPU "
                "filling %llu messages (%llu dropped), of %.3f us CPU in all (loop thread); sender thread %.3f us CPU "
                "per tick; %llu camera frames, %.3f ms CPU each to fill\n",
                static_cast<unsigned long long>(s.calls), 1e6 * s.wall_seconds / ticks,
                1e6 * s.publish_cpu_seconds / ticks, static_cast<unsigned long long>(s.messages),
                static_cast<unsigned long long>(s.dropped), 1e6 * loop_cpu_seconds_ / ticks,
                1e6 * s.sender_cpu_seconds / ticks, static_cast<unsigned long long>(s.camera_frames),
                s.camera_frames > 0 ? 1e3 * s.camera_seconds / static_cast<double>(s.camera_frames) : 0.0);
  }
}

void SimNode::loop() {
  // Chunks of 10 ms of simulation time keep stop() and pause() responsive at any pace.
  while (!stop_.load() && ::ros::ok()) {
    if (bridge_->paused()) {
      bridge_->run_for(bridge_->period(), nullptr);  // applies a pending reset, sleeps 1 ms
      // Time stands still but /clock keeps coming, as gazebo does while paused.
      const auto now = std::chrono::steady_clock::now();
      if (now - last_clock_ > std::chrono::milliseconds(100)) {
        rosgraph_msgs::Clock clock;
        clock.clock = ::ros::Time(bridge_->time());
        clock_pub_.publish(clock);
        last_clock_ = now;
      }
      // The frames at the paused time, once (a world started paused has never ticked).
      if (tf_ && last_tf_ != bridge_->time()) publish_tf(bridge_->time());
      continue;
    }
    std::string error;
    if (!bridge_->run_for(0.01, &error)) {
      if (error != divergence_) ROS_ERROR_STREAM("mechsim: " << error);
      divergence_ = error;
    }
  }
  timespec cpu{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &cpu);
  loop_cpu_seconds_ = static_cast<double>(cpu.tv_sec) + 1e-9 * static_cast<double>(cpu.tv_nsec);
}

void SimNode::on_tick(double time) {
  if (!other_robot_ && time + 1e-9 >= next_clock_) {
    rosgraph_msgs::Clock clock;
    clock.clock = ::ros::Time(time);
    clock_pub_.publish(clock);
    last_clock_ = std::chrono::steady_clock::now();
    next_clock_ = time + (options_.clock_publish_rate > 0.0 ? 1.0 / options_.clock_publish_rate : 0.0);
  }
  sensors_->publish();
  plugins_->publish(time);
  publish_controller_states(time);
  if (options_.pr2) publish_pr2_outputs(time);
  if (tf_ && time + 1e-9 >= next_tf_) {
    publish_tf(time);
    next_tf_ = time + (options_.tf_rate > 0.0 ? 1.0 / options_.tf_rate : 0.0);
  }
}

void SimNode::publish_tf(double time) {
  bridge_->joint_positions(joint_positions_);
  tf_->publish(time, joint_positions_, bridge_->base_pose());
  last_tf_ = time;
}

void SimNode::advertise_sim_services() {
  using Req = std_srvs::Empty::Request;
  using Res = std_srvs::Empty::Response;
  services_.push_back(root_nh_.advertiseService<Req, Res>("/gazebo/pause_physics", [this](Req&, Res&) {
    bridge_->pause();
    return true;
  }));
  services_.push_back(root_nh_.advertiseService<Req, Res>("/gazebo/unpause_physics", [this](Req&, Res&) {
    bridge_->unpause();
    return true;
  }));
  // Both resets put the robot back at its spawn pose and restart the running controllers; time
  // goes on (sim/simulation.hpp says why).
  auto reset = [this](Req&, Res&) {
    bridge_->request_reset();
    return true;
  };
  services_.push_back(root_nh_.advertiseService<Req, Res>("/gazebo/reset_simulation", reset));
  services_.push_back(root_nh_.advertiseService<Req, Res>("/gazebo/reset_world", reset));
}

void SimNode::refresh_params(const std::string& controller) {
  XmlRpc::XmlRpcValue value;
  const std::string key = controller_ns(controller);
  if (!root_nh_.getParam(key, value)) return;  // the manager reports the missing parameters
  control::Params params = bridge_->controller_params();
  std::string warning;
  set_param_from_xmlrpc(params, controller, value, &warning);
  if (!warning.empty()) ROS_WARN_STREAM("mechsim: parameters not taken: " << warning);
}

std::string SimNode::controller_ns(const std::string& controller) const {
  const std::string& ns = robot_nh_.getNamespace();
  return (ns.empty() || ns.back() != '/' ? ns + "/" : ns) + controller;
}

}  // namespace mechsim::ros
