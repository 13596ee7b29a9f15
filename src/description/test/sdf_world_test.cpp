// SDF worlds and models read with libsdformat (description/sdf): the PR2 package's own test worlds
// (../shared/robots/pr2_simulator/pr2_gazebo/test) with every object where the file puts it, and
// small documents for what those worlds do not hold (joints, friction, physics settings,
// model:// includes, heightmaps) and for bad input.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "description/package_path.hpp"
#include "description/sdf/sdf_model.hpp"

namespace mechsim::description {
namespace {

namespace fs = std::filesystem;

const fs::path kPr2Test = fs::path(MECHSIM_SHARED_DIR) / "robots" / "pr2_simulator" / "pr2_gazebo" / "test";

Eigen::Isometry3d iso(const Pose& p) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translate(Eigen::Vector3d(p.position.x, p.position.y, p.position.z));
  X.rotate(Eigen::Quaterniond(p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z));
  return X;
}

const SdfModel& model(const SdfWorld& w, const std::string& name) {
  for (const SdfModel& m : w.models)
    if (m.name == name) return m;
  throw std::runtime_error("no model '" + name + "' in " + w.file);
}

// World position of a model's first link's first collision centre (the model's root frame
// chain: model pose, root offset, collision origin).
Eigen::Vector3d collision_centre(const SdfModel& m, std::size_t link = 0) {
  const Link& l = m.robot.links.at(link);
  EXPECT_FALSE(l.collisions.empty()) << m.name << " link " << l.name;
  return (iso(m.pose) * iso(m.root_offset) * iso(l.collisions.at(0).origin)).translation();
}

bool mentions(const std::vector<std::string>& list, const std::string& what) {
  return std::any_of(list.begin(), list.end(), [&](const std::string& s) { return s.find(what) != std::string::npos; });
}

void expect_near(const Eigen::Vector3d& got, const Eigen::Vector3d& want, const std::string& what, double tol = 1e-9) {
  EXPECT_LT((got - want).norm(), tol) << what << ": got " << got.transpose() << ", want " << want.transpose();
}

class TempDir {
 public:
  TempDir() {
    char tmpl[] = "/tmp/mechsim_sdf_XXXXXX";
    path_ = mkdtemp(tmpl);
  }
  ~TempDir() { fs::remove_all(path_); }
  const fs::path& path() const { return path_; }
  fs::path write(const std::string& name, const std::string& text) const {
    const fs::path p = path_ / name;
    fs::create_directories(p.parent_path());
    std::ofstream(p) << text;
    return p;
  }

 private:
  fs::path path_;
};

std::string world_doc(const std::string& body) {
  return "<?xml version='1.0'?>\n<sdf version='1.6'>\n<world name='w'>\n" + body + "\n</world>\n</sdf>\n";
}

TEST(SdfWorld, Pr2ScanWorldObjectsWhereTheFileSays) {
  const fs::path file = kPr2Test / "sensors" / "scan.world";
  if (!fs::exists(file)) GTEST_SKIP() << "shared data not found at " << file << " (MECHSIM_SHARED_DIR)";
  const SdfWorld w = load_sdf_world(file.string(), SdfOptions{{}, {}, false});
  EXPECT_EQ(w.name, "scan_world");
  std::vector<std::string> names;
  for (const SdfModel& m : w.models) names.push_back(m.name);
  EXPECT_EQ(names, (std::vector<std::string>{"gplane", "sphere1_model", "box1_model", "cylinder1_model", "cup1_model"}));
  for (const SdfModel& m : w.models) EXPECT_TRUE(m.is_static) << m.name;
  EXPECT_DOUBLE_EQ(w.gravity.z, -9.8);

  // The ground box: link pose 0 0 -0.05 in its model at the origin.
  const SdfModel& plane = model(w, "gplane");
  ASSERT_EQ(plane.robot.links.size(), 1u);
  ASSERT_EQ(plane.robot.links[0].collisions.size(), 1u);
  const Geometry& g = plane.robot.links[0].collisions[0].geometry;
  EXPECT_EQ(g.type, GeometryType::Box);
  EXPECT_DOUBLE_EQ(g.size.x, 51.3);
  EXPECT_DOUBLE_EQ(g.size.z, 0.1);
  expect_near(collision_centre(plane), {0, 0, -0.05}, "gplane");

  const SdfModel& sphere = model(w, "sphere1_model");
  EXPECT_EQ(sphere.robot.links[0].collisions.at(0).geometry.type, GeometryType::Sphere);
  EXPECT_DOUBLE_EQ(sphere.robot.links[0].collisions[0].geometry.radius, 0.5);
  expect_near(collision_centre(sphere), {2.5, -0.5, 0.5064}, "sphere");

  const SdfModel& box = model(w, "box1_model");
  const Geometry& bg = box.robot.links[0].collisions.at(0).geometry;
  EXPECT_EQ(bg.type, GeometryType::Box);
  EXPECT_DOUBLE_EQ(bg.size.x, 0.05);
  EXPECT_DOUBLE_EQ(bg.size.y, 0.30);
  EXPECT_DOUBLE_EQ(bg.size.z, 0.5);
  expect_near(collision_centre(box), {2.0, -1.0, 0.24}, "box");

  const SdfModel& cylinder = model(w, "cylinder1_model");
  const Geometry& cg = cylinder.robot.links[0].collisions.at(0).geometry;
  EXPECT_EQ(cg.type, GeometryType::Cylinder);
  EXPECT_DOUBLE_EQ(cg.radius, 0.3);
  EXPECT_DOUBLE_EQ(cg.length, 2.0);
  expect_near(collision_centre(cylinder), {2.0, 0.8, 1.0}, "cylinder");

  // The cup's mesh (model://Media/models/cup.stl) is not shipped with the package: kept with an
  // empty path (the physics leaves it out and says so), its pose still the file's.
  const SdfModel& cup = model(w, "cup1_model");
  const Collision& cc = cup.robot.links[0].collisions.at(0);
  EXPECT_EQ(cc.geometry.type, GeometryType::Mesh);
  EXPECT_EQ(cc.geometry.mesh_uri, "model://Media/models/cup.stl");
  EXPECT_DOUBLE_EQ(cc.geometry.mesh_scale.x, 0.3);
  const Eigen::Isometry3d X_WC = iso(cup.pose) * iso(cup.root_offset) * iso(cc.origin);
  expect_near(X_WC.translation(), {3.0, 0.0, 0.009}, "cup");
  // rpy 1.5708 0 1.5708 (the file's 1.5708, not pi/2: 4e-6 rad off): its x axis along world y,
  // its z axis along world x.
  expect_near(X_WC.rotation() * Eigen::Vector3d::UnitX(), {0, 1, 0}, "cup x axis", 1e-5);
  expect_near(X_WC.rotation() * Eigen::Vector3d::UnitZ(), {1, 0, 0}, "cup z axis", 1e-5);

  // What is not simulated is listed, once each, and nothing of it is fatal.
  EXPECT_TRUE(mentions(w.not_simulated, "gui")) << "gui not listed";
  EXPECT_TRUE(mentions(w.not_simulated, "scene")) << "scene not listed";
  EXPECT_TRUE(mentions(w.not_simulated, "physics 'ode'")) << "ode solver settings not listed";
  EXPECT_TRUE(mentions(w.not_simulated, "surface contact parameters")) << "gplane's kp/kd not listed";
  EXPECT_FALSE(w.max_step_size.has_value());  // the file's <physics> sets none of these
}

TEST(SdfWorld, Pr2CameraWorldObjectsWhereTheFileSays) {
  const fs::path file = kPr2Test / "sensors" / "camera.world";
  if (!fs::exists(file)) GTEST_SKIP() << "shared data not found at " << file << " (MECHSIM_SHARED_DIR)";
  const SdfWorld w = load_sdf_world(file.string(), SdfOptions{{}, {}, false});
  ASSERT_EQ(w.models.size(), 4u);
  expect_near(collision_centre(model(w, "gplane")), {-1.5, 0, -0.05}, "gplane");
  const SdfModel& box = model(w, "box1_model");
  EXPECT_DOUBLE_EQ(box.robot.links[0].collisions.at(0).geometry.size.z, 1.0);
  expect_near(collision_centre(box), {0.78, 1.0, 0.5}, "box");
  expect_near(collision_centre(model(w, "cylinder1_model")), {0.78, 0.0, 0.5}, "cylinder");
}

TEST(SdfWorld, Pr2EmptyWorldGroundPlaneAndSun) {
  const fs::path file = kPr2Test / "Media" / "worlds" / "empty.world";
  if (!fs::exists(file)) GTEST_SKIP() << "shared data not found at " << file << " (MECHSIM_SHARED_DIR)";
  const SdfWorld w = load_sdf_world(file.string(), SdfOptions{{}, {}, false});
  const SdfModel& ground = model(w, "ground_plane");
  EXPECT_TRUE(ground.is_static);
  ASSERT_EQ(ground.planes.size(), 1u);
  EXPECT_EQ(ground.planes[0].mu, 100.0);
  EXPECT_EQ(ground.planes[0].mu2, 50.0);
  expect_near(iso(ground.planes[0].pose).rotation() * Eigen::Vector3d::UnitZ(), {0, 0, 1}, "plane normal");
  // The sun: a world light (Gazebo's light services read it), not a model.
  ASSERT_EQ(w.lights.size(), 1u);
  EXPECT_EQ(w.lights[0].name, "sun");
  EXPECT_EQ(w.lights[0].type, "directional");
  EXPECT_FALSE(mentions(w.not_simulated, "sun"));
}

TEST(SdfWorld, JointsFrictionPhysicsAndIncludes) {
  TempDir dir;
  dir.write("models/crate/model.config",
            "<?xml version='1.0'?><model><name>crate</name><sdf version='1.6'>model.sdf</sdf></model>");
  dir.write("models/crate/model.sdf",
            "<?xml version='1.0'?><sdf version='1.6'><model name='crate'><static>true</static>"
            "<link name='l'><collision name='c'><geometry><box><size>1 2 3</size></box></geometry></collision>"
            "</link></model></sdf>");
  const fs::path file = dir.write("arm.world", world_doc(R"(
    <physics name='p' type='ode'><max_step_size>0.002</max_step_size>
      <real_time_update_rate>500</real_time_update_rate><real_time_factor>2</real_time_factor></physics>
    <gravity>0 0 -3.7</gravity>
    <include><uri>model://ground_plane</uri></include>
    <include><uri>model://sun</uri></include>
    <include><uri>model://crate</uri><name>crate_a</name><pose>4 5 1.5 0 0 0</pose></include>
    <model name='arm'>
      <pose>1 0 0 0 0 0</pose>
      <link name='base'><pose>0 0 0.5 0 0 0</pose>
        <inertial><mass>2</mass><inertia><ixx>1</ixx><iyy>1</iyy><izz>1</izz></inertia></inertial>
        <collision name='c'><geometry><cylinder><radius>0.1</radius><length>1</length></cylinder></geometry>
          <surface><friction><ode><mu>0.4</mu><mu2>0.3</mu2></ode></friction></surface></collision></link>
      <link name='upper'><pose>0 0 1.2 0 0 0</pose>
        <inertial><mass>1</mass><inertia><ixx>0.1</ixx><iyy>0.1</iyy><izz>0.1</izz></inertia></inertial>
        <collision name='c'><pose>0 0 0.1 0 0 0</pose><geometry><sphere><radius>0.05</radius></sphere></geometry></collision></link>
      <joint name='shoulder' type='revolute'><parent>base</parent><child>upper</child>
        <pose>0 0 -0.2 0 0 0</pose>
        <axis><xyz>0 1 0</xyz><limit><lower>-1</lower><upper>1.5</upper><effort>30</effort></limit>
          <dynamics><damping>0.7</damping></dynamics></axis></joint>
    </model>)"));
  const SdfWorld w = load_sdf_world(file.string(), SdfOptions{{(dir.path() / "models").string()}, {}, false});
  ASSERT_TRUE(w.max_step_size && w.real_time_update_rate && w.real_time_factor);
  EXPECT_DOUBLE_EQ(*w.max_step_size, 0.002);
  EXPECT_DOUBLE_EQ(*w.real_time_update_rate, 500.0);
  EXPECT_DOUBLE_EQ(*w.real_time_factor, 2.0);
  EXPECT_DOUBLE_EQ(w.gravity.z, -3.7);
  // mechsim's own ground_plane: a plane at z = 0; sun: a directional world light.
  ASSERT_EQ(model(w, "ground_plane").planes.size(), 1u);
  ASSERT_EQ(w.lights.size(), 1u);
  EXPECT_EQ(w.lights[0].type, "directional");
  // model:// from SdfOptions::model_paths, renamed and placed by the include.
  expect_near(collision_centre(model(w, "crate_a")), {4, 5, 1.5}, "crate_a");

  const SdfModel& arm = model(w, "arm");
  EXPECT_FALSE(arm.is_static);
  EXPECT_EQ(arm.robot.root_link, "base");
  const Joint* shoulder = arm.robot.joint("shoulder");
  ASSERT_NE(shoulder, nullptr);
  EXPECT_EQ(shoulder->type, JointType::Revolute);
  EXPECT_DOUBLE_EQ(shoulder->axis.y, 1.0);
  ASSERT_TRUE(shoulder->limits && shoulder->dynamics);
  EXPECT_DOUBLE_EQ(shoulder->limits->lower, -1.0);
  EXPECT_DOUBLE_EQ(shoulder->limits->upper, 1.5);
  EXPECT_DOUBLE_EQ(shoulder->limits->effort, 30.0);
  EXPECT_DOUBLE_EQ(shoulder->dynamics->damping, 0.7);
  // The joint frame (SDF: in the child's frame, 0.2 m below it) becomes the child's link frame:
  // the child's collision keeps its world place (1, 0, 1.2 + 0.1).
  const Eigen::Isometry3d X_WB = iso(arm.pose) * iso(arm.root_offset);
  expect_near(X_WB.translation(), {1, 0, 0.5}, "arm base frame");
  const Link* upper = arm.robot.link("upper");
  ASSERT_NE(upper, nullptr);
  const Eigen::Isometry3d X_WU = X_WB * iso(shoulder->origin);
  expect_near(X_WU.translation(), {1, 0, 1.0}, "upper link frame = joint frame");
  expect_near((X_WU * iso(upper->collisions.at(0).origin)).translation(), {1, 0, 1.3}, "upper collision");
  ASSERT_TRUE(upper->inertial.has_value());
  expect_near((X_WU * iso(upper->inertial->origin)).translation(), {1, 0, 1.2}, "upper centre of mass");
  EXPECT_DOUBLE_EQ(upper->inertial->mass, 1.0);
  const auto gz = arm.robot.gazebo_links.find("base");
  ASSERT_NE(gz, arm.robot.gazebo_links.end());
  EXPECT_DOUBLE_EQ(gz->second.mu1.value_or(0.0), 0.4);
  EXPECT_DOUBLE_EQ(gz->second.mu2.value_or(0.0), 0.3);
}

// A package on ROS_PACKAGE_PATH exporting its models to gazebo_ros (package.xml <export>
// <gazebo_ros gazebo_model_path="${prefix}/models"/>): its model:// includes resolve, as gazebo_ros'
// launch scripts make Gazebo find them.
TEST(SdfWorld, ModelPathsExportedByPackages) {
  TempDir dir;
  dir.write("src/shelf_pkg/package.xml",
            "<?xml version='1.0'?><package format='2'><name>shelf_pkg</name><version>0.1.0</version>"
            "<description>d</description><maintainer email='a@b.c'>a</maintainer><license>BSD</license>"
            "<depend>gazebo_ros</depend><export><gazebo_ros gazebo_model_path=\"${prefix}/models\"/></export></package>");
  dir.write("src/shelf_pkg/models/shelf/model.config",
            "<?xml version='1.0'?><model><name>shelf</name><sdf version='1.6'>model.sdf</sdf></model>");
  dir.write("src/shelf_pkg/models/shelf/model.sdf",
            "<?xml version='1.0'?><sdf version='1.6'><model name='shelf'><static>true</static>"
            "<link name='l'><collision name='c'><geometry><box><size>1 1 2</size></box></geometry></collision>"
            "</link></model></sdf>");
  const fs::path file = dir.write("store.world", world_doc("<include><uri>model://shelf</uri><pose>2 0 1 0 0 0</pose></include>"));
  const char* before = std::getenv("ROS_PACKAGE_PATH");
  const std::string saved = before != nullptr ? before : "";
  setenv("ROS_PACKAGE_PATH", (dir.path() / "src").c_str(), 1);
  EXPECT_EQ(gazebo_ros_exports("gazebo_model_path"), std::vector<std::string>{(dir.path() / "src/shelf_pkg/models").string()});
  std::string error;
  try {
    const SdfWorld w = load_sdf_world(file.string(), SdfOptions{{}, {}, true});
    expect_near(collision_centre(model(w, "shelf")), {2, 0, 1}, "shelf");
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (before != nullptr) setenv("ROS_PACKAGE_PATH", saved.c_str(), 1);
  else unsetenv("ROS_PACKAGE_PATH");
  EXPECT_EQ(error, "");
}

TEST(SdfWorld, HeightmapAndSpawnedModel) {
  TempDir dir;
  const fs::path file = dir.write("hills.world", world_doc(R"(
    <model name='hills'><static>true</static><link name='l'><collision name='c'><geometry>
      <heightmap><uri>file://terrain.png</uri><size>20 20 2</size><pos>0 0 -1</pos></heightmap>
    </geometry></collision></link></model>)"));
  dir.write("terrain.png", "");  // resolved by path; the physics reads the image
  const SdfWorld w = load_sdf_world(file.string(), SdfOptions{{}, {}, false});
  const SdfModel& hills = model(w, "hills");
  ASSERT_EQ(hills.heightmaps.size(), 1u);
  EXPECT_DOUBLE_EQ(hills.heightmaps[0].size.x, 20.0);
  EXPECT_DOUBLE_EQ(hills.heightmaps[0].size.z, 2.0);
  EXPECT_DOUBLE_EQ(hills.heightmaps[0].position.z, -1.0);

  // spawn_sdf_model's string: one <model>.
  const SdfModel m = parse_sdf_model(
      "<sdf version='1.6'><model name='ball'><link name='b'><inertial><mass>0.5</mass></inertial>"
      "<collision name='c'><geometry><sphere><radius>0.1</radius></sphere></geometry></collision></link></model></sdf>",
      "<spawn ball>");
  EXPECT_EQ(m.name, "ball");
  EXPECT_FALSE(m.is_static);
  ASSERT_EQ(m.robot.links.size(), 1u);
  EXPECT_DOUBLE_EQ(m.robot.links[0].inertial->mass, 0.5);
}

TEST(SdfWorld, BadInputNamesFileAndLine) {
  TempDir dir;
  auto error_of = [&](const std::string& name, const std::string& body) {
    const fs::path file = dir.write(name, world_doc(body));
    try {
      load_sdf_world(file.string(), SdfOptions{{}, {}, false});
    } catch (const SdfError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string twice = error_of("twice.world", R"(
    <model name='a'><static>true</static><link name='l'/></model>
    <model name='a'><static>true</static><link name='l'/></model>)");
  EXPECT_NE(twice.find("twice.world"), std::string::npos) << twice;
  // libsdformat finds it first and names it as "name[a]".
  EXPECT_TRUE(twice.find("'a'") != std::string::npos || twice.find("[a]") != std::string::npos) << twice;

  const std::string loop = error_of("loop.world", R"(
    <model name='m'><link name='a'/><link name='b'/>
      <joint name='j1' type='revolute'><parent>a</parent><child>b</child><axis><xyz>0 0 1</xyz></axis></joint>
      <joint name='j2' type='revolute'><parent>a</parent><child>b</child><axis><xyz>0 0 1</xyz></axis></joint>
    </model>)");
  EXPECT_NE(loop.find("loop.world"), std::string::npos) << loop;

  const std::string floating = error_of("apart.world", "<model name='m'><link name='a'/><link name='b'/></model>");
  EXPECT_NE(floating.find("apart.world:"), std::string::npos) << floating;
  EXPECT_NE(floating.find("one tree"), std::string::npos) << floating;

  const std::string broken = error_of("broken.world", "<model name='m'><link name='a'>");
  EXPECT_NE(broken.find("broken.world"), std::string::npos) << broken;

  EXPECT_THROW(load_sdf_world((dir.path() / "absent.world").string()), SdfError);
  EXPECT_THROW(parse_sdf_model("<sdf version='1.6'><world name='w'/></sdf>", "<string>"), SdfError);
  EXPECT_THROW(parse_sdf_model("not xml", "<string>"), SdfError);
  EXPECT_TRUE(is_sdf_world_file("a/b.world"));
  EXPECT_FALSE(is_sdf_world_file("a/b.yaml"));
}

}  // namespace
}  // namespace mechsim::description
