#pragma once
// Gazebo model plugins as controllers (DESIGN.md, "Gazebo plugins in a description"): a plugin's
// <plugin> element becomes the Params of a controller that the same manager runs in the same
// tick (control::ControllerManager::add_model_plugin), reached through the same ports. What a
// plugin publishes and under which names is ROS's business; ModelPlugin says it in plain data
// (PluginRosInterface) so that the ROS layer binds the ports to gazebo_plugins' topic names and
// the standalone runner to a scenario's timeline and recorders.

#include <memory>
#include <string>
#include <vector>

#include "control/controller.hpp"
#include "control/params.hpp"

namespace mechsim::control {

// One port published or subscribed under a topic name of the plugin's choosing.
struct PluginTopic {
  std::string port;   // the port's name ("cmd_vel", "odom", "joint_states")
  // Relative to the plugin's namespace, as the plugin resolves it. Empty: the port is not
  // published on a topic of its own (a "joint_states" port that only feeds publishWheelTF).
  std::string topic;
  // The message on the wire where it is not the port's own (ports.hpp's PortType comments):
  // "geometry_msgs/Pose" for a TwistCommand port that takes Gazebo's gazebo.msgs.Pose velocity
  // command (position.x the speed, the orientation's yaw the turn rate: libDiffDrivePlugin.so).
  std::string message;
};

struct PluginRosInterface {
  std::string robot_namespace;       // <robotNamespace>, "" for the root namespace
  std::vector<PluginTopic> topics;
  bool odom_tf = false;              // the "odom" port's pose also on /tf (odom frame -> base frame)
  // publishWheelTF: each of these joints' parent -> child link transform on /tf with the
  // "joint_states" port's positions (the diff drive's wheels).
  std::vector<std::string> wheel_tf_joints;
  // The wheels' frames: the links' names resolved with this TF prefix (gazebo_ros_names.hpp:
  // tf_resolve); the tricycle drive names the child frame after the joint, not its link.
  std::string tf_prefix;
  bool wheel_tf_child_is_joint = false;
};

// What a plugin may know beyond its own elements.
struct PluginContext {
  std::string robot_name;  // the model's name (the joint state publisher's default namespace)
  Params server;           // the parameter server's robot namespace (mimic joint PID gains)
  // False when `server` is not the run's (`mechsim check` without the launch file's YAML): what a
  // plugin reads from the parameter server at run time is not checked, and each such read is
  // named in `deferred` instead ("...: read from the parameter server when the run starts").
  bool runtime_params = true;
  std::shared_ptr<std::vector<std::string>> deferred = std::make_shared<std::vector<std::string>>();
};

class ModelPlugin : public Controller {
 public:
  const PluginRosInterface& ros_interface() const { return ros_; }

 protected:
  PluginRosInterface ros_;
};

}  // namespace mechsim::control
