// spawn_model: gazebo_ros' spawn_model in C++, for the gazebo_ros compatibility package
// (<build>/ros_package/gazebo_ros/spawn_model; src/ros/packages/README.md).
//
//   spawn_model -urdf|-sdf -file FILE|-param PARAM|-stdin -model NAME [-x X -y Y -z Z -R R -P P -Y Y]
//               [-J JOINT POSITION ...] [-unpause] [-wait MODEL] [-reference_frame FRAME]
//               [-robot_namespace NS] [-gazebo_namespace NS] [-timeout S] [-b] [-package_to_model]
//
// As gazebo_ros' script: the model's XML from a file, a parameter (resolved in the node's
// namespace) or standard input; waits for <gazebo_namespace>/spawn_urdf_model (or
// spawn_sdf_model) and calls it with the pose (x y z, roll pitch yaw about fixed axes); -J joint
// positions are then set through set_model_configuration (before any unpause: the robot starts
// there); -unpause calls unpause_physics last. -wait MODEL first waits until MODEL is in the world
// (get_world_properties). -b stays until shut down and then deletes the model. The robot
// namespace defaults to the node's own. -database (Gazebo's online model database) is refused.
// Exit status 0 on success, 1 when a call fails (the world's status message printed), 2 on bad
// arguments.
#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <ros/ros.h>

#include <gazebo_msgs/DeleteModel.h>
#include <gazebo_msgs/GetWorldProperties.h>
#include <gazebo_msgs/SetModelConfiguration.h>
#include <gazebo_msgs/SpawnModel.h>
#include <std_srvs/Empty.h>

namespace {

struct Args {
  bool urdf = false, sdf = false, stdin_model = false, unpause = false, bond = false;
  std::string file, param, model, reference_frame, wait_for;
  std::string robot_namespace;  // empty: the node's namespace
  bool robot_namespace_given = false;
  std::string gazebo_namespace = "/gazebo";
  double x = 0, y = 0, z = 0, roll = 0, pitch = 0, yaw = 0;
  double timeout = -1.0;  // s; < 0: wait for the services forever, as gazebo_ros
  std::vector<std::string> joints;
  std::vector<double> positions;
};

[[noreturn]] void usage_error(const std::string& what) {
  std::cerr << "spawn_model: error: " << what << "\n"
            << "usage: spawn_model -urdf|-sdf -file FILE|-param PARAM|-stdin -model NAME [-x X -y Y -z Z -R R -P P -Y Y] "
               "[-J JOINT POSITION ...] [-unpause] [-wait MODEL] [-reference_frame FRAME] [-robot_namespace NS] "
               "[-gazebo_namespace NS] [-timeout S] [-b]\n";
  std::exit(2);
}

double number(const std::string& option, const std::string& text) {
  try {
    std::size_t used = 0;
    const double v = std::stod(text, &used);
    if (used == text.size()) return v;
  } catch (const std::exception&) {
  }
  usage_error(option + ": '" + text + "' is not a number");
}

Args parse(const std::vector<std::string>& argv) {
  Args a;
  for (std::size_t i = 0; i < argv.size(); ++i) {
    const std::string& s = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argv.size()) usage_error(s + " needs a value");
      return argv[++i];
    };
    if (s == "-urdf") a.urdf = true;
    else if (s == "-sdf" || s == "-trimesh" || s == "-gazebo") a.sdf = true;
    else if (s == "-file") a.file = value();
    else if (s == "-param") a.param = value();
    else if (s == "-stdin") a.stdin_model = true;
    else if (s == "-model") a.model = value();
    else if (s == "-reference_frame") a.reference_frame = value();
    else if (s == "-robot_namespace") a.robot_namespace = value(), a.robot_namespace_given = true;
    else if (s == "-gazebo_namespace") a.gazebo_namespace = value();
    else if (s == "-wait") a.wait_for = value();
    else if (s == "-unpause") a.unpause = true;
    else if (s == "-b") a.bond = true;
    else if (s == "-package_to_model") {}  // mechsim resolves package:// itself
    else if (s == "-timeout") a.timeout = number(s, value());
    else if (s == "-x") a.x = number(s, value());
    else if (s == "-y") a.y = number(s, value());
    else if (s == "-z") a.z = number(s, value());
    else if (s == "-R") a.roll = number(s, value());
    else if (s == "-P") a.pitch = number(s, value());
    else if (s == "-Y") a.yaw = number(s, value());
    else if (s == "-J") {
      a.joints.push_back(value());
      a.positions.push_back(number("-J " + a.joints.back(), value()));
    } else if (s == "-database") usage_error("-database: Gazebo's model database is not available; use -file or -param");
    else if (s == "-h" || s == "--help") usage_error("help requested");
    else usage_error("unknown argument '" + s + "'");
  }
  if (a.model.empty()) usage_error("-model NAME is required");
  if (!a.urdf && !a.sdf) usage_error("one of -urdf or -sdf is required");
  const int sources = (a.file.empty() ? 0 : 1) + (a.param.empty() ? 0 : 1) + (a.stdin_model ? 1 : 0);
  if (sources != 1) usage_error("exactly one of -file, -param or -stdin is required");
  return a;
}

std::string service_name(const Args& a, const std::string& name) {
  std::string ns = a.gazebo_namespace;
  if (!ns.empty() && ns.back() == '/') ns.pop_back();
  return ns + "/" + name;
}

bool wait_for(const std::string& service, double timeout) {
  ROS_INFO_STREAM("spawn_model: waiting for service " << service);
  return ::ros::service::waitForService(service, timeout < 0.0 ? ::ros::Duration(-1) : ::ros::Duration(timeout));
}

// geometry_msgs/Quaternion of roll, pitch, yaw about the fixed x, y, z axes.
geometry_msgs::Quaternion quaternion(double roll, double pitch, double yaw) {
  const double cr = std::cos(roll / 2), sr = std::sin(roll / 2), cp = std::cos(pitch / 2), sp = std::sin(pitch / 2),
               cy = std::cos(yaw / 2), sy = std::sin(yaw / 2);
  geometry_msgs::Quaternion q;
  q.w = cr * cp * cy + sr * sp * sy;
  q.x = sr * cp * cy - cr * sp * sy;
  q.y = cr * sp * cy + sr * cp * sy;
  q.z = cr * cp * sy - sr * sp * cy;
  return q;
}

int run(const Args& a) {
  ::ros::NodeHandle nh;
  std::string xml;
  if (!a.file.empty()) {
    std::ifstream in(a.file);
    if (!in) {
      ROS_ERROR_STREAM("spawn_model: cannot read " << a.file);
      return 1;
    }
    std::ostringstream text;
    text << in.rdbuf();
    xml = text.str();
  } else if (!a.param.empty()) {
    if (!nh.getParam(a.param, xml)) {
      ROS_ERROR_STREAM("spawn_model: no parameter '" << nh.resolveName(a.param) << "' (-param)");
      return 1;
    }
  } else {
    std::ostringstream text;
    text << std::cin.rdbuf();
    xml = text.str();
  }
  if (xml.empty()) {
    ROS_ERROR_STREAM("spawn_model: the model's XML is empty");
    return 1;
  }

  if (!a.wait_for.empty()) {
    const std::string world = service_name(a, "get_world_properties");
    if (!wait_for(world, a.timeout)) return 1;
    ROS_INFO_STREAM("spawn_model: waiting for model " << a.wait_for);
    for (;;) {
      gazebo_msgs::GetWorldProperties p;
      if (::ros::service::call(world, p) &&
          std::find(p.response.model_names.begin(), p.response.model_names.end(), a.wait_for) !=
              p.response.model_names.end()) {
        break;
      }
      if (!::ros::ok()) return 1;
      ::ros::WallDuration(0.5).sleep();
    }
  }

  const std::string spawn = service_name(a, a.sdf ? "spawn_sdf_model" : "spawn_urdf_model");
  if (!wait_for(spawn, a.timeout)) {
    ROS_ERROR_STREAM("spawn_model: no service " << spawn << " within " << a.timeout << " s");
    return 1;
  }
  gazebo_msgs::SpawnModel call;
  call.request.model_name = a.model;
  call.request.model_xml = xml;
  call.request.robot_namespace = a.robot_namespace_given ? a.robot_namespace : ::ros::this_node::getNamespace();
  call.request.initial_pose.position.x = a.x;
  call.request.initial_pose.position.y = a.y;
  call.request.initial_pose.position.z = a.z;
  call.request.initial_pose.orientation = quaternion(a.roll, a.pitch, a.yaw);
  call.request.reference_frame = a.reference_frame;
  ROS_INFO_STREAM("spawn_model: calling " << spawn << " for '" << a.model << "'");
  if (!::ros::service::call(spawn, call) || !call.response.success) {
    ROS_ERROR_STREAM("spawn_model: " << spawn << " failed: " << call.response.status_message);
    return 1;
  }
  ROS_INFO_STREAM("spawn_model: " << call.response.status_message);

  if (!a.joints.empty()) {
    gazebo_msgs::SetModelConfiguration config;
    config.request.model_name = a.model;
    config.request.urdf_param_name = a.param;
    config.request.joint_names = a.joints;
    config.request.joint_positions = a.positions;
    const std::string name = service_name(a, "set_model_configuration");
    if (!wait_for(name, a.timeout) || !::ros::service::call(name, config) || !config.response.success) {
      ROS_ERROR_STREAM("spawn_model: -J: " << name << " failed: " << config.response.status_message);
      return 1;
    }
  }
  if (a.unpause) {
    std_srvs::Empty empty;
    const std::string name = service_name(a, "unpause_physics");
    if (!wait_for(name, a.timeout) || !::ros::service::call(name, empty)) {
      ROS_ERROR_STREAM("spawn_model: -unpause: " << name << " failed");
      return 1;
    }
  }
  if (a.bond) {  // the model lives as long as this node
    while (::ros::ok()) ::ros::WallDuration(0.1).sleep();
    gazebo_msgs::DeleteModel del;
    del.request.model_name = a.model;
    ::ros::service::call(service_name(a, "delete_model"), del);
  }
  return 0;
}

volatile std::sig_atomic_t g_signals = 0;
extern "C" void on_signal(int) {
  if (g_signals++ > 0) std::_Exit(130);
  ::ros::requestShutdown();
}

}  // namespace

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  ::ros::init(argc, argv, "spawn_model", ::ros::init_options::AnonymousName | ::ros::init_options::NoSigintHandler);
  std::vector<std::string> args;
  ::ros::removeROSArgs(argc, argv, args);
  args.erase(args.begin());
  const Args a = parse(args);
  if (a.bond) {
    ::ros::AsyncSpinner spinner(1);
    spinner.start();
    return run(a);
  }
  return run(a);
}
