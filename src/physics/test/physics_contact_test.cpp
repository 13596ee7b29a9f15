// Contact geometry: primitives, meshes (STL, OBJ, Collada via assimp), friction from gazebo
// mu1/mu2, self-collision rules, and what happens to meshes that cannot be used.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "physics_test_util.hpp"

namespace mechsim::physics {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

constexpr double kG = 9.81;

// A scratch folder unique to this test program run.
fs::path scratch() {
  const fs::path dir = fs::path(MECHSIM_BINARY_DIR) / "physics_test_scratch";
  fs::create_directories(dir);
  return dir;
}

// Unit cube [-0.5, 0.5]^3 as binary STL.
void write_cube_stl(const fs::path& path) {
  const float v[8][3] = {{-.5f, -.5f, -.5f}, {.5f, -.5f, -.5f}, {.5f, .5f, -.5f}, {-.5f, .5f, -.5f},
                         {-.5f, -.5f, .5f},  {.5f, -.5f, .5f},  {.5f, .5f, .5f},  {-.5f, .5f, .5f}};
  const int f[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                        {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  std::ofstream out(path, std::ios::binary);
  char header[80] = {};
  out.write(header, 80);
  const std::uint32_t n = 12;
  out.write(reinterpret_cast<const char*>(&n), 4);
  for (const auto& tri : f) {
    const float normal[3] = {0, 0, 0};
    out.write(reinterpret_cast<const char*>(normal), 12);
    for (int k = 0; k < 3; ++k) out.write(reinterpret_cast<const char*>(v[tri[k]]), 12);
    const std::uint16_t attr = 0;
    out.write(reinterpret_cast<const char*>(&attr), 2);
  }
}

void write_cube_obj(const fs::path& path) {
  std::ofstream out(path);
  out << "v -0.5 -0.5 -0.5\nv 0.5 -0.5 -0.5\nv 0.5 0.5 -0.5\nv -0.5 0.5 -0.5\n"
         "v -0.5 -0.5 0.5\nv 0.5 -0.5 0.5\nv 0.5 0.5 0.5\nv -0.5 0.5 0.5\n"
         "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n";
}

std::string mesh_box_urdf(const std::string& file, const std::string& scale) {
  return R"(<robot name="meshbox">
  <link name="box">
    <inertial><mass value="1"/><inertia ixx="0.001667" iyy="0.001667" izz="0.001667" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><mesh filename=")" + file + R"(" scale=")" + scale + R"("/></geometry></collision>
  </link>
</robot>)";
}

// Drops the body from 0.3 m and returns its resting height after 2 s.
double rest_height(const std::shared_ptr<const PhysicsModel>& model) {
  Physics p(model);
  while (p.time() < 2.0) EXPECT_TRUE(p.step().ok());
  return p.base_pose().position.z;
}

TEST(PhysicsContact, BoxRestsOnTheGroundPlane) {
  BuildOptions o;
  o.spawn.z = 0.3;
  EXPECT_NEAR(rest_height(test::build(test::box_urdf(), o)), 0.05, 2e-3);
}

TEST(PhysicsContact, ScaledStlAndObjMeshesCollide) {
  const fs::path stl = scratch() / "cube.stl", obj = scratch() / "cube.obj";
  write_cube_stl(stl);
  write_cube_obj(obj);
  BuildOptions o;
  o.spawn.z = 0.3;
  for (const fs::path& file : {stl, obj}) {
    auto model = test::build(mesh_box_urdf(file.string(), "0.1 0.1 0.1"), o);
    EXPECT_TRUE(model->warnings().empty()) << file << ": " << model->warnings().front();
    EXPECT_THAT(model->mjcf(), HasSubstr("type=\"mesh\""));
    EXPECT_NEAR(rest_height(model), 0.05, 2e-3) << file;
  }
}

TEST(PhysicsContact, AsciiStlIsConvertedByAssimp) {
  const fs::path path = scratch() / "ascii_cube.stl";
  {
    std::ofstream out(path);
    out << "solid cube\n";
    const double v[8][3] = {{-.5, -.5, -.5}, {.5, -.5, -.5}, {.5, .5, -.5}, {-.5, .5, -.5},
                            {-.5, -.5, .5},  {.5, -.5, .5},  {.5, .5, .5},  {-.5, .5, .5}};
    const int f[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                          {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
    for (const auto& t : f) {
      out << "facet normal 0 0 0\n outer loop\n";
      for (int k = 0; k < 3; ++k) out << "  vertex " << v[t[k]][0] << " " << v[t[k]][1] << " " << v[t[k]][2] << "\n";
      out << " endloop\nendfacet\n";
    }
    out << "endsolid cube\n";
  }
  BuildOptions o;
  o.spawn.z = 0.3;
  auto model = test::build(mesh_box_urdf(path.string(), "0.2 0.2 0.2"), o);
  EXPECT_NEAR(rest_height(model), 0.1, 2e-3);
}

TEST(PhysicsContact, ColladaMeshIsConvertedForCollision) {
  if (!test::shared_dir_present()) GTEST_SKIP() << "shared data folder absent: " << test::shared_dir();
  const std::string dae = test::shared_dir() + "/robots/cc8_description/meshes/ZED2.dae";
  auto model = test::build(mesh_box_urdf(dae, "1 1 1"));
  EXPECT_TRUE(model->warnings().empty()) << model->warnings().front();
  EXPECT_THAT(model->mjcf(), HasSubstr("name=\"box/collision/0\" type=\"mesh\""));
}

TEST(PhysicsContact, UnreadableMeshIsLeftOutWithAClearWarning) {
  auto model = test::build(mesh_box_urdf((scratch() / "missing.dae").string(), "1 1 1"));
  ASSERT_EQ(model->warnings().size(), 1u);
  EXPECT_THAT(model->warnings()[0], HasSubstr("link 'box': collision mesh"));
  EXPECT_THAT(model->warnings()[0], HasSubstr("no such file"));
  EXPECT_THAT(model->warnings()[0], HasSubstr("(path tried: " + (scratch() / "missing.dae").string() + ")"));
}

// A box sliding at 2 m/s stops after v^2 / (2 mu g): the link's gazebo <mu1>/<mu2> decide it,
// not the ground's default friction. Tolerance 10 % (soft contacts, pyramid friction cone).
TEST(PhysicsContact, GazeboMuSetsTheSlidingFriction) {
  for (double mu : {0.2, 0.5}) {
    const std::string urdf = test::box_urdf().substr(0, test::box_urdf().rfind("</robot>")) +
                             "<gazebo reference=\"box\"><mu1>" + std::to_string(mu) + "</mu1><mu2>" +
                             std::to_string(mu) + "</mu2></gazebo></robot>";
    BuildOptions o;
    o.spawn.z = 0.05;
    Physics p(test::build(urdf, o));
    for (int i = 0; i < 200; ++i) ASSERT_TRUE(p.step().ok());  // settle
    const double x0 = p.base_pose().position.x;
    p.set_base_twist({{2.0, 0.0, 0.0}, {0.0, 0.0, 0.0}});
    while (p.time() < 3.0) ASSERT_TRUE(p.step().ok());
    const double distance = p.base_pose().position.x - x0;
    const double expected = 4.0 / (2.0 * mu * kG);
    EXPECT_NEAR(distance, expected, 0.1 * expected) << "mu " << mu;
  }
}

// Two links hanging side by side from the world, overlapping; selfCollide on either makes
// them touch (SDF's rule), otherwise links of one robot pass through each other (Gazebo's
// default).
std::string overlapping_urdf(const std::string& gazebo) {
  return R"(<robot name="pair">
  <link name="world"/>
  <link name="a"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision></link>
  <link name="b"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision></link>
  <joint name="ja" type="prismatic"><parent link="world"/><child link="a"/><origin xyz="0 0 1"/><axis xyz="1 0 0"/>
    <limit lower="-1" upper="1" effort="10" velocity="1"/></joint>
  <joint name="jb" type="prismatic"><parent link="world"/><child link="b"/><origin xyz="0.15 0 1"/><axis xyz="1 0 0"/>
    <limit lower="-1" upper="1" effort="10" velocity="1"/></joint>
  )" + gazebo + "</robot>";
}

std::size_t contacts_between(const std::string& urdf, const char* a, const char* b) {
  Physics p(test::build(urdf));
  EXPECT_TRUE(p.step().ok());
  std::vector<Contact> cs;
  p.contacts(cs);
  std::size_t n = 0;
  for (const Contact& c : cs)
    if ((c.link_a == a && c.link_b == b) || (c.link_a == b && c.link_b == a)) ++n;
  return n;
}

TEST(PhysicsContact, SelfCollisionFollowsSelfCollide) {
  EXPECT_EQ(contacts_between(overlapping_urdf(""), "a", "b"), 0u);
  EXPECT_GT(contacts_between(overlapping_urdf("<gazebo reference=\"a\"><selfCollide>true</selfCollide></gazebo>"), "a", "b"), 0u);
}

TEST(PhysicsContact, ParentAndChildNeverCollideEvenWithSelfCollide) {
  const std::string urdf = R"(<robot name="chain">
  <link name="world"/>
  <link name="a"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision></link>
  <link name="b"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision></link>
  <joint name="ja" type="fixed"><parent link="world"/><child link="a"/><origin xyz="0 0 1"/></joint>
  <joint name="jb" type="continuous"><parent link="a"/><child link="b"/><origin xyz="0.1 0 0"/><axis xyz="0 0 1"/></joint>
  <gazebo reference="a"><selfCollide>true</selfCollide></gazebo>
  <gazebo reference="b"><selfCollide>true</selfCollide></gazebo>
</robot>)";
  EXPECT_EQ(contacts_between(urdf, "a", "b"), 0u);
}

TEST(PhysicsContact, ContactReportsLinksDepthAndForce) {
  BuildOptions o;
  o.spawn.z = 0.05;
  Physics p(test::build(test::box_urdf(), o));
  for (int i = 0; i < 500; ++i) ASSERT_TRUE(p.step().ok());
  std::vector<Contact> cs;
  ASSERT_GE(p.contacts(cs), 1u);
  double total = 0.0;
  for (const Contact& c : cs) {
    EXPECT_TRUE((c.link_a == "ground" && c.link_b == "box") || (c.link_a == "box" && c.link_b == "ground"));
    EXPECT_NEAR(c.position.z, 0.0, 2e-3);
    total += c.normal_force;
  }
  EXPECT_NEAR(total, 1.0 * kG, 0.05);  // the box's weight
}

}  // namespace
}  // namespace mechsim::physics
