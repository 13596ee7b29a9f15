#pragma once
// ros2_controllers' joint_state_broadcaster/JointStateBroadcaster: every update (the controller
// manager's update_rate, or the controller's own update_rate), a snapshot of the joints' state
// interfaces in the "joint_states" port (sensor_msgs/JointState; the wire layer publishes it on
// /joint_states, or ~/joint_states with use_local_topics, and dynamic_joint_states from the same
// snapshot). Claims nothing.
//
// Parameters (ros2_controllers' names):
//   joints, interfaces   both given: exactly those state interfaces of those joints (each joint
//                        must have each interface, as the broadcaster's claim would fail);
//                        either empty or absent: every state interface of every ros2_control joint
//   extra_joints         names added with position, velocity and effort 0
//   use_local_topics, map_interface_to_joint_state, use_urdf_to_filter: the wire layer's; read
//                        here only for their types
// A joint without one of position, velocity or effort among its broadcast interfaces gets NaN
// there, as the broadcaster's uninitialised value. Joints: the mechanism's ros2_control joints in
// their tags' order (a robot without <ros2_control> tags: every joint but model plugins').

#include <cstdint>
#include <vector>

#include "control/controller.hpp"

namespace mechsim::control {

inline constexpr const char* kJointStateBroadcasterType = "joint_state_broadcaster/JointStateBroadcaster";

class JointStateBroadcaster : public Controller {
 public:
  bool init(RobotHardware& hardware, const Params& params, std::string& error) override;
  UpdateStatus update(double time, double period) override;
  std::vector<Port*> ports() override { return {&joint_states_}; }

  StatePort<JointStateSnapshot>& joint_states_port() { return joint_states_; }

 private:
  struct Source {
    JointStateHandle joint;
    bool position = false, velocity = false, effort = false;
  };
  std::vector<Source> sources_;  // then extra joints (zeros) in the snapshot
  StatePort<JointStateSnapshot> joint_states_{"joint_states"};
};

}  // namespace mechsim::control
