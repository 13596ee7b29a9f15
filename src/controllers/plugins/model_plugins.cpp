#include "controllers/plugins/model_plugins.hpp"

#include <algorithm>
#include <functional>

#include "control/hardware.hpp"
#include "control/params_xml.hpp"
#include "controllers/plugins/diff_drive_plugin.hpp"
#include "controllers/plugins/gazebo_diff_drive_plugin.hpp"
#include "controllers/plugins/joint_state_publisher_plugin.hpp"
#include "controllers/plugins/mimic_joint_plugin.hpp"
#include "controllers/plugins/planar_move_plugin.hpp"
#include "controllers/plugins/skid_steer_plugin.hpp"
#include "controllers/plugins/tricycle_drive_plugin.hpp"
#include "description/mimic_plugin.hpp"
#include "description/ros2_control_plugin.hpp"
#include "description/sensor_spec.hpp"

namespace mechsim::control {
namespace {

using description::RobotModel;

struct PluginKind {
  const char* filename;
  const char* what;
  // The controller, given what the plugin may know: its context, the robot, its elements.
  std::function<std::unique_ptr<ModelPlugin>(const PluginContext&, const RobotModel&, const Params&)> make;
  std::function<std::vector<std::string>(const Params&)> joints;
  // What `mechsim check` adds after "simulated: <what>", or null.
  std::function<std::string(const RobotModel&)> note = nullptr;
  // Built on gazebo_plugins' GazeboRos helper: its namespace defaults to the model's name
  // (gazebo_ros_names.hpp, add_model_name_namespaces).
  bool gazebo_ros_helper = false;
};

// A kind whose controller needs nothing but itself.
template <class T>
std::unique_ptr<ModelPlugin> plain(const PluginContext&, const RobotModel&, const Params&) {
  return std::make_unique<T>();
}

// A kind whose controller needs its context.
template <class T>
std::unique_ptr<ModelPlugin> with_context(const PluginContext& c, const RobotModel&, const Params&) {
  return std::make_unique<T>(c);
}

std::vector<std::string> no_joints(const Params&) { return {}; }

std::unique_ptr<ModelPlugin> make_gazebo_diff_drive(const PluginContext&, const RobotModel& robot, const Params& params) {
  const std::vector<std::string> j = GazeboDiffDrivePlugin::joints(params);
  return std::make_unique<GazeboDiffDrivePlugin>(robot.name, gazebo_diff_drive_geometry(robot, j[0], j[1]));
}

std::string gazebo_diff_drive_note(const RobotModel& robot) {
  return "; mechsim has no Gazebo transport: its ~/" + robot.name + "/vel_cmd is the ROS topic " +
         gazebo_vel_cmd_topic(robot.name) +
         " (geometry_msgs/Pose as Gazebo's gazebo.msgs.Pose: position.x m/s, the orientation's yaw rad/s clockwise)";
}

const std::vector<PluginKind>& kinds() {
  // Immutable once made.
  static const std::vector<PluginKind> table = {
      {kDiffDrivePluginFile, "differential drive", with_context<DiffDrivePlugin>, DiffDrivePlugin::joints, nullptr, true},
      {kSkidSteerPluginFile, "skid-steer drive", plain<SkidSteerPlugin>, SkidSteerPlugin::joints},
      {kPlanarMovePluginFile, "planar move of the base", plain<PlanarMovePlugin>, no_joints},
      {kTricycleDrivePluginFile, "tricycle drive", with_context<TricycleDrivePlugin>, TricycleDrivePlugin::joints, nullptr,
       true},
      {kGazeboDiffDrivePluginFile, "Gazebo's own differential drive (no ROS)", make_gazebo_diff_drive,
       GazeboDiffDrivePlugin::joints, gazebo_diff_drive_note},
      {kJointStatePublisherPluginFile, "joint state publisher", with_context<JointStatePublisherPlugin>,
       JointStatePublisherPlugin::joints, nullptr, true},
      {"libroboticsgroup_gazebo_mimic_joint_plugin.so", "mimic joint",
       [](const PluginContext& c, const RobotModel&, const Params&) { return std::make_unique<MimicJointPlugin>(c, false); },
       MimicJointPlugin::joints},
      {"libroboticsgroup_upatras_gazebo_mimic_joint_plugin.so", "mimic joint",
       [](const PluginContext& c, const RobotModel&, const Params&) { return std::make_unique<MimicJointPlugin>(c, true); },
       MimicJointPlugin::joints},
  };
  return table;
}

const PluginKind* find_kind(const std::string& filename) {
  for (const PluginKind& k : kinds()) {
    if (filename == k.filename) return &k;
  }
  return nullptr;
}

std::string origin_of(const description::RobotModel& robot, const description::GazeboPlugin& p) {
  return robot.source + ":" + std::to_string(p.xml.line);
}

// "<leftJoint> (file:line) names" for the element whose text names `joint`, else "the plugin names"
// (a default or a list).
std::string naming(const Params& params, const std::string& joint) {
  for (const std::string& key : params.keys()) {
    const Params c = params.child(key);
    if (c.is_scalar() && c.as<std::string>() == joint) return "<" + key + "> (" + c.location() + ") names";
  }
  return "the plugin names";
}

}  // namespace

void add_model_name_namespaces(description::RobotModel& robot) {
  for (description::GazeboPlugin& p : robot.plugins) {
    const PluginKind* kind = p.sensor.empty() ? find_kind(p.filename) : nullptr;
    if (kind == nullptr || !kind->gazebo_ros_helper || p.xml.child("robotNamespace") != nullptr) continue;
    description::XmlNode ns;
    ns.name = "robotNamespace";
    ns.text = robot.name;
    ns.line = p.xml.line;
    p.xml.children.push_back(std::move(ns));
    p.parameters["robotNamespace"] = robot.name;
  }
}

std::vector<ModelPluginStatus> model_plugin_status(const description::RobotModel& robot) {
  std::vector<ModelPluginStatus> out;
  for (const description::GazeboPlugin& p : robot.plugins) {
    if (!p.sensor.empty()) continue;
    ModelPluginStatus s{p.name, p.filename, origin_of(robot, p), PluginHandling::NotSimulated, ""};
    if (const PluginKind* k = find_kind(p.filename)) {
      s.handling = PluginHandling::Controller;
      s.detail = std::string("simulated: ") + k->what + " (a model plugin controller)" + (k->note ? k->note(robot) : "");
    } else if (p.filename == "libgazebo_ros_control.so" || p.filename == "libgazebo_ros_controller_manager.so") {
      s.handling = PluginHandling::ControllerManager;
      s.detail = "simulated: mechsim's controller manager runs the controllers of the YAML";
      // A RobotHWSim of the user's own (gazebo_ros_control's <robotSimType>) is a Gazebo plugin
      // mechsim cannot load: its joints get DefaultRobotHWSim's behaviour.
      if (auto it = p.parameters.find("robotSimType");
          it != p.parameters.end() && !it->second.empty() && it->second != "gazebo_ros_control/DefaultRobotHWSim") {
        s.detail += "; robotSimType '" + it->second +
                    "' is NOT SIMULATED (mechsim cannot load a RobotHWSim plugin: gazebo_ros_control/DefaultRobotHWSim's "
                    "behaviour instead)";
      }
    } else if (description::is_ros2_control_plugin(p.filename)) {
      s.handling = PluginHandling::ControllerManager;
      s.detail = "simulated: mechsim's controller manager runs the ros2_control controllers of its ROS 2 parameter files "
                 "(docs/ros2_control.md)";
      if (p.xml.child("position_proportional_gain") != nullptr) {
        s.detail += "; position_proportional_gain is NOT SIMULATED (position commands reach mechsim's joint servo)";
      }
      if (p.xml.child("e_stop_topic") != nullptr) s.detail += "; e_stop_topic is NOT SIMULATED";
    } else if (p.filename.find("differential") != std::string::npos) {
      s.handling = PluginHandling::Physics;
      s.detail = "simulated: a law of the physics (the differential's spring)";
    } else {
      const auto sensor = std::find_if(robot.sensors.begin(), robot.sensors.end(), [&](const description::SensorSpec& spec) {
        return spec.type == "plugin" && spec.line == p.xml.line;
      });
      if (sensor != robot.sensors.end() && sensor->simulated()) {
        s.handling = PluginHandling::Sensor;
        s.detail = std::string("simulated: a sensor (") + sensor->kind_name() + ")";
      } else if (sensor != robot.sensors.end()) {
        s.detail = "NOT SIMULATED: " + std::get<description::UnsupportedSpec>(sensor->details).reason;
      } else {
        s.detail = "NOT SIMULATED: mechsim does not know this plugin; the robot runs without it";
      }
    }
    out.push_back(std::move(s));
  }
  return out;
}

std::string describe(const ModelPluginStatus& s) {
  return "gazebo plugin '" + s.name + "' (" + s.filename + ") at " + s.origin + ": " + s.detail;
}

std::vector<ModelPluginBuild> build_model_plugins(const description::RobotModel& robot, const PluginContext& context) {
  std::vector<ModelPluginBuild> out;
  for (const description::GazeboPlugin& p : robot.plugins) {
    if (!p.sensor.empty()) continue;
    const PluginKind* kind = find_kind(p.filename);
    if (kind == nullptr) continue;
    ModelPluginBuild b;
    b.name = p.name.empty() ? std::string(kind->what) : p.name;
    const std::string base = b.name;
    for (int n = 2; std::any_of(out.begin(), out.end(), [&](const ModelPluginBuild& o) { return o.name == b.name; }); ++n) {
      b.name = base + "#" + std::to_string(n);
    }
    b.filename = p.filename;
    b.origin = origin_of(robot, p);
    std::string key = b.name;
    std::replace(key.begin(), key.end(), '/', '_');
    b.params = params_from_xml(p.xml, robot.source, key);
    const std::string where = b.origin + ": gazebo plugin '" + b.name + "' (" + b.filename + "): ";
    try {
      b.joints = kind->joints(b.params);
    } catch (const std::exception& e) {
      throw ControllerConfigError(where + e.what());
    }
    for (const std::string& j : b.joints) {
      const description::Joint* joint = robot.joint(j);
      if (joint == nullptr) {
        throw ControllerConfigError(where + naming(b.params, j) + " joint '" + j + "', which robot '" + robot.name +
                                    "' does not have");
      }
      using description::JointType;
      if (joint->type != JointType::Revolute && joint->type != JointType::Continuous && joint->type != JointType::Prismatic) {
        throw ControllerConfigError(where + "joint '" + j + "' (line " + std::to_string(joint->line) +
                                    ") is not revolute, continuous or prismatic");
      }
    }
    try {
      b.controller = kind->make(context, robot, b.params);
    } catch (const ControllerConfigError& e) {
      throw ControllerConfigError(where + e.what());
    }
    out.push_back(std::move(b));
  }
  return out;
}

}  // namespace mechsim::control
