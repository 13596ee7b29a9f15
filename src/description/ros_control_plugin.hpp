#pragma once
// The gazebo_ros_control model plugin (libgazebo_ros_control.so) of a description: what its
// elements say. Element names and defaults are gazebo_ros_control's (ROS 1):
//   <robotNamespace>  where the controllers and the pid_gains live ("" when absent)
//   <robotSimType>    the RobotHWSim plugin; default gazebo_ros_control/DefaultRobotHWSim
//   <controlPeriod>   s between controller manager updates; default the physics step
//   <legacyModeNS>    with DefaultRobotHWSim: true (also when absent, where Gazebo logs an
//                     error) reads pid_gains at the absolute /gazebo_ros_control/pid_gains/<joint>;
//                     false at <robotNamespace>/gazebo_ros_control/pid_gains/<joint>
//   <eStopTopic>      a std_msgs/Bool topic (relative to <robotNamespace>): while the last message
//                     is true, effort joints get no effort, velocity joints zero velocity and
//                     position joints hold where they were when it came; the controllers run on
//                     and are restarted when it is released (DefaultRobotHWSim::eStopActive)

#include <optional>
#include <string>
#include <vector>

#include "description/robot_model.hpp"

namespace mechsim::description {

inline constexpr const char* kDefaultRobotHWSim = "gazebo_ros_control/DefaultRobotHWSim";

struct RosControlPlugin {
  std::string origin;           // "file:line" of the <plugin> element
  std::string robot_namespace;  // as written ("" when absent)
  std::string robot_sim_type = kDefaultRobotHWSim;
  std::optional<double> control_period;  // s, when given
  std::optional<bool> legacy_mode_ns;    // when given
  std::string e_stop_topic;              // as written ("" when absent: no e-stop)

  bool default_hw() const { return robot_sim_type == kDefaultRobotHWSim; }
  // Whether pid_gains are read at the absolute path (gazebo_ros_control's default is true; the
  // plugin applies legacyModeNS to DefaultRobotHWSim only).
  bool legacy() const { return default_hw() && legacy_mode_ns.value_or(true); }
  // The parameter namespace of joint `joint`'s gains, as gazebo_ros_control builds it:
  // "/gazebo_ros_control/pid_gains/<joint>" (legacy) or "<robotNamespace>/gazebo_ros_control/...".
  std::string pid_gains_path(const std::string& joint) const;
};

// The first libgazebo_ros_control.so model plugin of `robot`, or nullopt when it has none.
// Throws DescriptionError naming the file, line and element for a <controlPeriod> that is not a
// positive number or a <legacyModeNS> that is not a boolean (true/false/1/0).
std::optional<RosControlPlugin> find_ros_control_plugin(const RobotModel& robot);

}  // namespace mechsim::description
