// mechsim_absent_node: the stand-in for a node of a package mechsim does not provide, which a
// Gazebo launch file starts beside the simulation (pr2_gazebo's hokuyo_node, camera_synchronizer,
// robot_pose_ekf, ...; src/ros/packages/README.md, "Stand-ins"). It offers nothing: it says once
// what it stands in for and stays until shut down, so that the launch (and rostest, which fails
// a test when any node of its launch file does not start) runs as a whole.
#include <csignal>
#include <string>

#include <ros/ros.h>

int main(int argc, char** argv) {
  std::string program = argc > 0 ? argv[0] : "absent";
  const auto slash = program.find_last_of('/');
  const std::string type = slash == std::string::npos ? program : program.substr(slash + 1);
  const std::string package =
      slash == std::string::npos ? "" : program.substr(program.find_last_of('/', slash - 1) + 1, slash - program.find_last_of('/', slash - 1) - 1);
  ::ros::init(argc, argv, "mechsim_absent_node", ::ros::init_options::AnonymousName);
  ::ros::NodeHandle nh;
  ROS_WARN_STREAM("mechsim: " << package << "/" << type << " is not provided by mechsim: this stand-in ("
                              << ::ros::this_node::getName() << ") does nothing and stays until shut down");
  ::ros::spin();
  return 0;
}
