#pragma once
// The model plugins of a description (<gazebo><plugin> outside any <sensor>): what mechsim does
// with each (`mechsim check` lists them all), and the controllers of those it simulates, ready
// for control::ControllerManager::add_model_plugin. Configuration time only.
//
//   libgazebo_ros_diff_drive.so            DiffDrivePlugin            (diff_drive_plugin.hpp)
//   libgazebo_ros_skid_steer_drive.so      SkidSteerPlugin            (skid_steer_plugin.hpp)
//   libgazebo_ros_planar_move.so           PlanarMovePlugin           (planar_move_plugin.hpp)
//   libgazebo_ros_tricycle_drive.so        TricycleDrivePlugin        (tricycle_drive_plugin.hpp)
//   libDiffDrivePlugin.so (Gazebo's own)   GazeboDiffDrivePlugin      (gazebo_diff_drive_plugin.hpp)
//   libgazebo_ros_joint_state_publisher.so JointStatePublisherPlugin  (joint_state_publisher_plugin.hpp)
//   libroboticsgroup[_upatras]_gazebo_mimic_joint_plugin.so  MimicJointPlugin (mimic_joint_plugin.hpp)
// Handled elsewhere: gazebo_ros_control (and the PR2's controller manager plugin) is mechsim's
// controller manager; a differential plugin is a physics law (physics/); sensor-like model
// plugins (p3d ground truth, hector's IMU) are sensors (sensors/). Anything else is not
// simulated: named once, never fatal.

#include <memory>
#include <string>
#include <vector>

#include "controllers/plugins/model_plugin.hpp"
#include "description/robot_model.hpp"

namespace mechsim::control {

enum class PluginHandling : std::uint8_t {
  Controller,         // a model plugin controller of this folder
  ControllerManager,  // gazebo_ros_control: the controllers of the YAML
  Physics,            // a law of the physics (the differential bar)
  Sensor,             // a simulated sensor (sensors/)
  NotSimulated,       // unknown to mechsim, or a sensor it cannot simulate
};

struct ModelPluginStatus {
  std::string name, filename;
  std::string origin;  // "file:line" of the <plugin> element
  PluginHandling handling = PluginHandling::NotSimulated;
  std::string detail;  // what simulates it, or why nothing does
  bool simulated() const { return handling != PluginHandling::NotSimulated; }
};

// Every model plugin of `robot`, in document order.
std::vector<ModelPluginStatus> model_plugin_status(const description::RobotModel& robot);
// "name (filename) at origin: simulated by ..." / "...: NOT SIMULATED: ..." for listings.
std::string describe(const ModelPluginStatus& status);

// What Gazebo does with a model it loads without a spawn namespace (an SDF world's model, a model
// spawned with an empty robot_namespace): the plugins built on gazebo_plugins' GazeboRos helper
// (diff drive, tricycle drive, joint state publisher) that name no <robotNamespace> are under the
// model's name (gazebo_ros_names.hpp). Writes robot.name in as their <robotNamespace>; other
// plugins keep theirs (those of gazebo_plugins default to the root). Call before
// build_model_plugins.
void add_model_name_namespaces(description::RobotModel& robot);

// A model plugin controller made from its <plugin> element, not initialised yet.
struct ModelPluginBuild {
  std::string name;      // the plugin's name (unique: a repeated name gets "#2", ...)
  std::string filename;  // the manager's `type` for it
  std::string origin;    // "file:line"
  Params params;         // its elements (control/params_xml.hpp)
  std::unique_ptr<ModelPlugin> controller;
  // The joints it drives or reads; they must be in the mechanism (mechanism/direct_joints.hpp).
  std::vector<std::string> joints;
};

// The controllers of the plugins model_plugin_status marks Controller. Throws
// ControllerConfigError "file:line: gazebo plugin 'name' (filename): ..." for a plugin whose joint
// elements cannot be read or name joints the robot lacks.
std::vector<ModelPluginBuild> build_model_plugins(const description::RobotModel& robot, const PluginContext& context);

}  // namespace mechsim::control
