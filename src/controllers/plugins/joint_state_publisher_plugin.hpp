#pragma once
// libgazebo_ros_joint_state_publisher.so (gazebo_plugins' GazeboRosJointStatePublisher) as a model
// plugin controller: every 1/updateRate s the listed joints' positions and velocities (no
// effort, as the plugin) on "joint_states", published as <robotNamespace>/joint_states. It reads
// joints and commands none.
//
// Elements (gazebo_plugins' names and defaults):
//   jointName  the joints, comma-separated (blanks ignored); required
//   updateRate 100 (Hz, >= 0; 0: every step)
//   robotNamespace  gazebo_ros_names.hpp: an empty one is the model's name; without one, the root
//                   (the model's name for an SDF world's model: add_model_name_namespaces)
// Ports: "joint_states" StatePort<JointStateSnapshot>.

#include "control/ports.hpp"
#include "controllers/plugins/model_plugin.hpp"

namespace mechsim::control {

inline constexpr const char* kJointStatePublisherPluginFile = "libgazebo_ros_joint_state_publisher.so";

class JointStatePublisherPlugin : public ModelPlugin {
 public:
  explicit JointStatePublisherPlugin(PluginContext context) : context_(std::move(context)) {}
  bool init(RobotHardware& hardware, const Params& params, std::string& error) override;
  void starting(double time) override;
  UpdateStatus update(double time, double period) override;
  std::vector<Port*> ports() override { return {&joint_states_}; }

  static std::vector<std::string> joints(const Params& params);

 private:
  PluginContext context_;
  double update_period_ = 0.01;
  double last_update_ = 0.0;
  std::vector<JointStateHandle> joints_;
  StatePort<JointStateSnapshot> joint_states_{"joint_states"};
};

}  // namespace mechsim::control
