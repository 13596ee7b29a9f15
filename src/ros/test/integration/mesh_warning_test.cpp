// mechsim_node says which collision meshes the physics left out, once each, with the link and
// the path it tried (they used to be dropped without a word: a link without collision falls
// through the ground).
#include <gmock/gmock.h>

#include <filesystem>
#include <fstream>

#include <controller_manager_msgs/ListControllers.h>

#include "ros_fixture.hpp"

namespace mechsim::ros::test {
namespace {

namespace fs = std::filesystem;

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(MechsimNode, SaysOnceWhichCollisionMeshesItLeftOutWithLinkAndPathTried) {
  ASSERT_TRUE(::ros::master::check());
  const fs::path dir = fs::path(log_dir()) / "meshbot";
  fs::create_directories(dir);
  std::ofstream(dir / "bot.urdf") << R"(<robot name="meshbot">
  <link name="base"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><mesh filename="meshes/base.stl"/></geometry></collision></link>
  <joint name="j" type="revolute"><parent link="base"/><child link="arm"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="10" velocity="1"/></joint>
  <link name="arm"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision></link>
</robot>)";
  ChildProcess node({MECHSIM_NODE_EXE, "__name:=meshbot_sim", "_model:=" + (dir / "bot.urdf").string()},
                    log_dir() + "/node_meshbot.log");
  controller_manager_msgs::ListControllers list;
  ASSERT_TRUE(call("/controller_manager/list_controllers", list, 30.0)) << node.log();
  const std::string log = node.log();
  const std::string said = "link 'base': collision mesh 'meshes/base.stl'";
  EXPECT_EQ(count(log, said), 1u) << log;
  EXPECT_THAT(log, ::testing::HasSubstr("path tried: " + (dir / "meshes" / "base.stl").string()));
  EXPECT_EQ(node.stop(10.0), 0) << node.log();
}

}  // namespace
}  // namespace mechsim::ros::test
