#pragma once
// The <ros2_control> tags of a description, as ros2_control's component parser
// (hardware_interface/component_parser.cpp) reads them and as Gazebo's system plugins
// (gazebo_ros2_control/GazeboSystem on Gazebo classic, Humble; gz_ros2_control/GazeboSimSystem on
// modern Gazebo, Humble and Jazzy; its old name ign_ros2_control/IgnitionSystem) use them:
//
//   <ros2_control name="GazeboSystem" type="system">
//     <hardware><plugin>gazebo_ros2_control/GazeboSystem</plugin><param name="...">..</param></hardware>
//     <joint name="slider_to_cart">                      (mimic="true|false": Jazzy's parser)
//       <param name="mimic">other_joint</param>          (Humble's gazebo_ros2_control)
//       <param name="multiplier">1</param>
//       <command_interface name="position">             position | velocity | effort
//         <param name="min">-1</param><param name="max">1</param>
//       </command_interface>
//       <state_interface name="position"><param name="initial_value">1.0</param></state_interface>
//       <state_interface name="velocity"/><state_interface name="effort"/>
//     </joint>
//     <sensor name="imu_sensor">                        (a Gazebo <sensor> of that name)
//       <state_interface name="orientation.x"/> ... linear_acceleration.z
//     </sensor>
//     <gpio name="..."> ... </gpio>                      (read, not simulated)
//   </ros2_control>
//
// Plain data, read by the URDF reader (urdf/urdf_ros2_control.cpp), which reports bad input with
// the file and line of the element; RobotModel::ros2_control holds one entry per <ros2_control>.
// What a simulation makes of it: mechanism/ros2_control_joints.hpp.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "description/robot_model.hpp"

namespace mechsim::description {

// The hardware plugins that simulate a robot in Gazebo. Others (a real robot's, mock_components/
// GenericSystem) are read with a warning, their joints simulated as these simulate them.
inline constexpr const char* kGazeboSystem = "gazebo_ros2_control/GazeboSystem";
inline constexpr const char* kGazeboSimSystem = "gz_ros2_control/GazeboSimSystem";
inline constexpr const char* kIgnitionSystem = "ign_ros2_control/IgnitionSystem";
bool is_gazebo_system_plugin(const std::string& plugin);

// One <command_interface> or <state_interface>.
struct Ros2ControlInterface {
  std::string name;  // "position", "velocity", "effort", "orientation.x", ...
  // Parsed from <param name="min">, "max", "initial_value" (the reader checks they are numbers).
  std::optional<double> min, max, initial_value;
  std::map<std::string, std::string> parameters;  // every <param>, as written (trimmed)
  int line = 0;
};

// One <joint>, <sensor> or <gpio> of a <ros2_control>.
struct Ros2ControlComponent {
  std::string name;
  std::vector<Ros2ControlInterface> command_interfaces, state_interfaces;  // document order
  std::map<std::string, std::string> parameters;  // the component's own <param>s
  // Jazzy's <joint mimic="true|false">; nullopt when absent.
  std::optional<bool> mimic_attribute;
  int line = 0;

  const Ros2ControlInterface* command_interface(const std::string& interface_name) const;
  const Ros2ControlInterface* state_interface(const std::string& interface_name) const;
};

// One <ros2_control> element: a hardware component.
struct Ros2ControlHardware {
  std::string name;  // its name attribute
  std::string type;  // "system", "actuator" or "sensor"
  std::string plugin;  // <hardware><plugin>
  std::map<std::string, std::string> hardware_parameters;  // <hardware><param>
  std::vector<Ros2ControlComponent> joints, sensors, gpios;
  std::vector<XmlNode> transmissions;  // <transmission> inside the tag (Gazebo's systems ignore them)
  int line = 0;

  bool gazebo_system() const { return is_gazebo_system_plugin(plugin); }
};

// The mimic relation a ros2_control joint has in simulation: Jazzy's (the URDF <mimic> of a joint
// listed in <ros2_control> whose mimic attribute is not false) or Humble gazebo_ros2_control's
// (<param name="mimic"> with an optional <param name="multiplier">, default 1).
struct Ros2ControlMimic {
  std::string joint;   // the follower
  std::string leader;  // the joint it mimics
  double multiplier = 1.0;
  double offset = 0.0;  // follower = multiplier * leader + offset (rad or m)
  bool from_param = false;  // Humble's <param name="mimic">
};

// Every ros2_control joint of `robot` (all <ros2_control> tags, document order), with the tag.
struct Ros2ControlJointRef {
  const Ros2ControlHardware* hardware = nullptr;
  const Ros2ControlComponent* joint = nullptr;
};
std::vector<Ros2ControlJointRef> ros2_control_joints(const RobotModel& robot);
// The component named `joint` in any <ros2_control> tag, or null.
const Ros2ControlComponent* find_ros2_control_joint(const RobotModel& robot, const std::string& joint);
// The sensor component named `sensor`, or null.
const Ros2ControlComponent* find_ros2_control_sensor(const RobotModel& robot, const std::string& sensor);
// The mimic relation of ros2_control joint `joint` (see Ros2ControlMimic), or nullopt.
std::optional<Ros2ControlMimic> ros2_control_mimic(const RobotModel& robot, const Ros2ControlComponent& joint);

// The initial joint positions the tags give (rad or m): each joint's "position" state interface's
// <param name="initial_value">, as Gazebo's systems set the joint at load (before any spawn
// override: a scenario's or spawn_model's -J wins).
std::map<std::string, double> ros2_control_initial_positions(const RobotModel& robot);

// Interface names Gazebo's systems simulate.
bool is_joint_interface(const std::string& name);   // position, velocity, effort
bool is_imu_interface(const std::string& name);     // orientation.{x,y,z,w}, angular_velocity.*, linear_acceleration.*
bool is_force_torque_interface(const std::string& name);  // force.{x,y,z}, torque.{x,y,z}

}  // namespace mechsim::description
