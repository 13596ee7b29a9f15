#include "physics_test_util.hpp"

#include <filesystem>
#include <sstream>

#include "description/urdf/urdf_parser.hpp"

namespace mechsim::physics::test {

namespace {
description::UrdfOptions options() {
  description::UrdfOptions o;
  o.packages["cc8_description"] = shared_dir() + "/robots/cc8_description";
  o.packages["pr2_description"] = shared_dir() + "/robots/pr2_description";
  return o;
}
}  // namespace

std::string shared_dir() { return MECHSIM_SHARED_DIR; }
bool shared_dir_present() { return std::filesystem::is_directory(shared_dir() + "/robots/reference"); }

description::RobotModel parse(const std::string& urdf) { return description::parse_urdf_string(urdf, "<test>", options()); }

description::RobotModel parse_file(const std::string& path) {
  auto o = options();
  o.lenient = true;
  return description::parse_urdf_file(path, o);
}

std::shared_ptr<const PhysicsModel> build(const std::string& urdf, const BuildOptions& options) {
  return PhysicsModel::build(parse(urdf), options);
}

std::string pendulum_urdf(double length, double mass, double inertia, const std::string& joint_extra,
                          const std::string& joint_type) {
  std::ostringstream s;
  s.precision(17);
  s << R"(<robot name="pendulum">
  <link name="world"/>
  <link name="bob">
    <inertial><origin xyz="0 0 )" << -length << R"("/><mass value=")" << mass << R"("/>
      <inertia ixx=")" << inertia << R"(" iyy=")" << inertia << R"(" izz=")" << inertia
    << R"(" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin xyz="0 0 )" << -length << R"("/><geometry><sphere radius="0.05"/></geometry></collision>
  </link>
  <joint name="hinge" type=")" << joint_type << R"(">
    <parent link="world"/><child link="bob"/>
    <origin xyz="0 0 2"/><axis xyz="0 1 0"/>
    )" << joint_extra << R"(
  </joint>
</robot>)";
  return s.str();
}

std::string box_urdf() {
  return R"(<robot name="box">
  <link name="box">
    <inertial><mass value="1"/><inertia ixx="0.001667" iyy="0.001667" izz="0.001667" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision>
    <visual><geometry><box size="0.1 0.1 0.1"/></geometry></visual>
  </link>
</robot>)";
}

std::string double_pendulum_urdf() {
  // Uniform rods: I_cm = m L^2 / 12 = 1/12 about x and y, tiny about the rod axis.
  return R"(<robot name="double_pendulum">
  <link name="world"/>
  <link name="rod1">
    <inertial><origin xyz="0 0 -0.5"/><mass value="1"/>
      <inertia ixx="0.0833333333333" iyy="0.0833333333333" izz="0.0001" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
  <link name="rod2">
    <inertial><origin xyz="0 0 -0.5"/><mass value="1"/>
      <inertia ixx="0.0833333333333" iyy="0.0833333333333" izz="0.0001" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
  <joint name="j1" type="continuous"><parent link="world"/><child link="rod1"/>
    <origin xyz="0 0 3"/><axis xyz="0 1 0"/></joint>
  <joint name="j2" type="continuous"><parent link="rod1"/><child link="rod2"/>
    <origin xyz="0 0 -1"/><axis xyz="0 1 0"/></joint>
</robot>)";
}

}  // namespace mechsim::physics::test
