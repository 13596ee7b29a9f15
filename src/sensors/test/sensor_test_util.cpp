#include "sensor_test_util.hpp"

#include "description/urdf/urdf_parser.hpp"

namespace mechsim::sensors::test {

std::string robot_urdf(const std::string& gazebo) {
  return R"(<robot name="boxes">
  <link name="base"><inertial><mass value="10"/><inertia ixx="0.27" ixy="0" ixz="0" iyy="0.27" iyz="0" izz="0.27"/></inertial>
    <collision><geometry><box size="0.4 0.4 0.4"/></geometry></collision></link>
  <joint name="neck" type="fixed"><parent link="base"/><child link="head"/><origin xyz="0 0 0.5"/></joint>
  <link name="head"><inertial><origin xyz="0.05 0 0"/><mass value="1"/><inertia ixx="0.002" ixy="0" ixz="0" iyy="0.002" iyz="0" izz="0.002"/></inertial>
    <collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision></link>
  <joint name="laser_joint" type="fixed"><parent link="base"/><child link="laser_link"/><origin xyz="0.1 0 0.3"/></joint>
  <link name="laser_link"/>
)" + gazebo + "\n</robot>\n";
}

description::RobotModel parse(const std::string& urdf) {
  return description::parse_urdf_string(urdf, "test.urdf", {});
}

std::shared_ptr<const physics::PhysicsModel> build(const description::RobotModel& robot, double wall_x,
                                                   physics::BuildOptions options) {
  options.spawn.z = 0.2;
  if (wall_x > 0.0) {
    physics::WorldBox wall;
    wall.name = "wall";
    wall.pose.position = {wall_x + 0.1, 0.0, 0.5};
    wall.size = {0.2, 4.0, 1.0};
    options.world.boxes.push_back(wall);
  }
  return physics::PhysicsModel::build(robot, options);
}

}  // namespace mechsim::sensors::test
