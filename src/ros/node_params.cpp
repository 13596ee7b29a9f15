// mechsim_node's private parameters (node_params.hpp).
#include "ros/node_params.hpp"

#include <algorithm>
#include <map>
#include <sstream>
#include <stdexcept>

#include "description/camera_override.hpp"

namespace mechsim::ros {

const std::vector<PrivateParam>& private_params() {
  static const std::vector<PrivateParam> params = {
      {"model", "string", "", "xacro/URDF file to load; empty: the URDF in ~robot_description's parameter"},
      {"xacro_args", "map", "{}", "xacro arguments for ~model (name: value)"},
      {"robot_description", "string", "robot_description",
       "the parameter holding the URDF when ~model is empty (searched upwards from the node's namespace)"},
      {"spawn_timeout", "double", "60", "s (wall) to wait for that parameter"},
      {"lenient", "bool", "false", "description errors Gazebo tolerates become warnings"},
      {"world", "string", "empty", "empty | mars_yard_2024 | heightmap file | SDF .world file"},
      {"x", "double", "0", "spawn position (m), as spawn_model -x"},
      {"y", "double", "0", "spawn position (m)"},
      {"z", "double", "0", "spawn height (m) above the ground under x, y"},
      {"R", "double", "0", "spawn roll (rad)"},
      {"P", "double", "0", "spawn pitch (rad)"},
      {"Y", "double", "0", "spawn yaw (rad)"},
      {"paused", "bool", "false", "start paused, as gazebo's paused arg"},
      {"real_time_factor", "double", "0", "0: as fast as possible; 1: wall-clock pace"},
      {"robot_namespace", "string", "",
       "where the controllers live; empty: the gazebo_ros_control plugin's robotNamespace, else /"},
      {"pr2", "bool", "(plugin)",
       "also serve /pr2_controller_manager/*; unset: when the PR2's gazebo plugin is in the URDF"},
      {"publish_tf", "bool", "true", "built-in robot state publisher on /tf"},
      {"tf_rate", "double", "50", "Hz (sim time) of /tf"},
      {"publish_odom_tf", "bool", "false", "odom_frame -> root link from the physics on /tf"},
      {"odom_frame", "string", "odom", "the frame of publish_odom_tf"},
      {"state_publish_rate", "double", "50", "Hz (sim time) of <controller>/state; 0: every tick"},
      {"foxglove_port", "int", "(unset)",
       "serve a live view over the Foxglove WebSocket protocol on this port (Foxglove's 8765; 0: any free "
       "port, logged); unset: off"},
      {"foxglove_address", "string", "127.0.0.1", "the live view's address (0.0.0.0: every interface)"},
      {"foxglove_rate", "double", "30", "Hz (sim time) of the live view's /tf, /joint_states and /odom"},
      {"pub_clock_frequency", "double", "0",
       "Hz (sim time) of /clock; 0: every step (gazebo_ros' default; empty_world.launch sets it with "
       "use_clock_frequency)"},
      {"clock_publish_rate", "double", "(unset)", "the same as pub_clock_frequency (mechsim's earlier name)"},
      {"enable_ros_network", "bool", "true",
       "gazebo mode: false leaves /clock only: no /gazebo services, topics or dynamic_reconfigure (gazebo_ros')"},
      {"step_service", "bool", "true", "gazebo mode: mechsim's /mechsim/step_simulation (stepping while paused)"},
      {"gazebo", "bool", "false",
       "gzserver mode (gazebo_ros' empty_world.launch): an empty world, robots come and go through "
       "/gazebo/spawn_urdf_model and delete_model; ~model, ~robot_description, x..Y and robot_namespace are "
       "not read, ~lenient defaults to true and ~publish_tf to false (robot_state_publisher's job in Gazebo)"},
      {"gazebo_ignored", "string", "",
       "gazebo mode: gazebo_ros arguments that mean nothing here (GUI, ODE), logged once (empty_world.launch)"},
      {"camera_overrides", "map", "{}",
       "per camera sensor name (or all): {rate: Hz, width: px, height: px} in place of the description's, for "
       "faster runs (one of width/height keeps the aspect ratio; the field of view stays)"},
      {"model_states_rate", "double", "0",
       "gazebo mode: Hz (sim time) of /gazebo/model_states and link_states while subscribed; 0: every tick"},
  };
  return params;
}

std::string describe_private_params() {
  std::ostringstream out;
  for (const PrivateParam& p : private_params()) {
    out << p.name << '\t' << p.type << '\t' << p.default_value << '\t' << p.meaning << '\n';
  }
  return out.str();
}

void report_private_params(const ::ros::NodeHandle& pnh) {
  const std::string prefix = pnh.getNamespace() + "/";
  std::vector<std::string> names;
  ::ros::param::getParamNames(names);
  std::ostringstream taken;
  for (const PrivateParam& p : private_params()) {
    XmlRpc::XmlRpcValue value;
    if (!pnh.getParam(p.name, value)) continue;
    std::ostringstream text;
    if (value.getType() == XmlRpc::XmlRpcValue::TypeBoolean) {
      text << (static_cast<bool>(value) ? "true" : "false");
    } else {
      text << value;
    }
    taken << (taken.tellp() > 0 ? ", " : "") << "~" << p.name << "=" << text.str();
  }
  if (taken.tellp() > 0) ROS_INFO_STREAM("mechsim: private parameters from the parameter server: " << taken.str());
  std::vector<std::string> unknown;
  for (const std::string& full : names) {
    if (full.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string first = full.substr(prefix.size(), full.find('/', prefix.size()) - prefix.size());
    const bool known = std::any_of(private_params().begin(), private_params().end(),
                                   [&](const PrivateParam& p) { return first == p.name; });
    if (!known && std::find(unknown.begin(), unknown.end(), first) == unknown.end()) unknown.push_back(first);
  }
  for (const std::string& u : unknown) {
    ROS_WARN_STREAM("mechsim: ~" << u << " (" << prefix << u
                                 << ") is not a mechsim_node parameter (left from another node, or misspelt?); "
                                    "ignored. `mechsim_node --params` lists them");
  }
}

void apply_camera_overrides_param(const ::ros::NodeHandle& pnh, description::RobotModel& robot) {
  XmlRpc::XmlRpcValue value;
  if (!pnh.getParam("camera_overrides", value)) return;
  const std::string where = pnh.resolveName("camera_overrides");
  if (value.getType() != XmlRpc::XmlRpcValue::TypeStruct) {
    throw std::runtime_error(where + ": expected a map: camera sensor name (or all) -> {rate, width, height}");
  }
  std::map<std::string, description::CameraOverride> overrides;
  for (auto& [name, entry] : value) {
    const std::string at = where + "/" + name;
    if (entry.getType() != XmlRpc::XmlRpcValue::TypeStruct) throw std::runtime_error(at + ": expected {rate, width, height}");
    description::CameraOverride o;
    o.origin = "parameter " + at;
    for (auto& [key, v] : entry) {
      const bool number = v.getType() == XmlRpc::XmlRpcValue::TypeInt || v.getType() == XmlRpc::XmlRpcValue::TypeDouble;
      if (!number) throw std::runtime_error(at + "/" + key + ": expected a number");
      const double x = v.getType() == XmlRpc::XmlRpcValue::TypeInt ? static_cast<double>(static_cast<int>(v)) : static_cast<double>(v);
      if (key == "rate") {
        o.rate = x;
      } else if (key == "width" || key == "height") {
        if (v.getType() != XmlRpc::XmlRpcValue::TypeInt) throw std::runtime_error(at + "/" + key + ": expected whole pixels");
        (key == "width" ? o.width : o.height) = static_cast<int>(v);
      } else {
        throw std::runtime_error(at + "/" + key + ": unknown key (rate, width, height)");
      }
    }
    overrides[name] = o;
  }
  for (const std::string& note : description::apply_camera_overrides(robot, overrides)) ROS_INFO_STREAM("mechsim: " << note);
}

}  // namespace mechsim::ros
