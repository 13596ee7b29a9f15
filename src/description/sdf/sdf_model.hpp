#pragma once
// SDF (Gazebo's Simulation Description Format) read with libsdformat: a world file's models and
// physics settings, or one model to spawn, each model turned into a RobotModel the physics builds
// like a URDF robot (links, joints, collision and visual geometry, inertia, friction).
//
// Frames. A RobotModel link's frame is its parent joint's frame (URDF); an SDF link has its own
// pose, and so has its joint. The conversion keeps SDF's geometry exactly: each link's frame
// becomes its parent joint's frame and its collisions, visuals and inertial move by the
// difference (none when the joint's <pose> is zero, the usual case). The root link keeps its own
// frame, `root_offset` in the model frame; a joint to `world` gives a root link named `world`
// at the model frame (the model is fixed there).
//
// A model's sensors and model plugins are read as a URDF's <gazebo> blocks are (their elements
// are SDF in both): RobotModel::sensors and plugins. What mechsim does not simulate (GUI, surface
// contact parameters, joint types beyond revolute/continuous/prismatic/fixed) is listed in
// `not_simulated`, once per thing, never an error. Errors (SdfError) name the file and line.
//
// Tolerance as Gazebo 11's: it reads SDF with libsdformat 9, which accepts what libsdformat 12
// reports as errors in files users have: a material <script> given by name alone (no <uri>), a
// camera image <format> outside sdformat 12's list (R16G16B16, L16, BAYER_*...), a model://
// include that no model path holds. Those are warnings here (the include is left out); any other
// error refuses the file.
//
// model:// URIs (includes, meshes, heightmaps) are looked up in SdfOptions::model_paths, then
// GAZEBO_MODEL_PATH, then ~/.gazebo/models; the models of Gazebo's library that worlds and
// tutorials name most (`ground_plane`, `sun`, `checkerboard_plane`, ...: BuiltinModels,
// sdf_paths.cpp) fall back to mechsim's own since Gazebo's model database is not installed.

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "description/package_path.hpp"
#include "description/robot_model.hpp"

namespace mechsim::description {

struct SdfError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct SdfOptions {
  std::vector<std::string> model_paths;  // searched before GAZEBO_MODEL_PATH
  PackageMap packages;                   // package:// URIs (then ROS_PACKAGE_PATH)
  bool use_environment = true;           // GAZEBO_MODEL_PATH, GAZEBO_RESOURCE_PATH, ~/.gazebo/models
};

// A <plane> collision of a static model: world geometry (infinite for contacts).
struct SdfPlane {
  std::string name;  // "<model>::<link>::<collision>"
  Pose pose;         // in the model frame; its z axis is the plane's normal
  std::optional<double> mu, mu2;  // <surface><friction><ode><mu>, <mu2> where written (Gazebo's default: 1)
};

// A <heightmap> collision of a static model.
struct SdfHeightmap {
  std::string name;  // "<model>::<link>::<collision>"
  std::string uri;   // as written
  std::string path;  // resolved; empty when it could not be
  Vec3 size;         // m: footprint x, y and the height range z
  Vec3 position;     // <pos>, m
  Pose pose;         // the collision frame in the model frame
};

struct SdfModel {
  std::string name;
  RobotModel robot;
  Pose pose;         // X_P<model>: the model frame in its parent (the world, or a spawn's frame)
  Pose root_offset;  // X_<model><root link frame>
  bool is_static = false;
  std::vector<SdfPlane> planes;
  std::vector<SdfHeightmap> heightmaps;
  std::vector<std::string> not_simulated;
  std::vector<std::string> warnings;
};

// A <light> of the world (Gazebo's light API reads and changes these; mechsim's cameras do not
// use them: their scene is lit by the renderer's own head light).
struct SdfLight {
  std::string name;
  std::string type;  // point, directional, spot
  bool cast_shadows = true;
  std::array<double, 4> diffuse{1.0, 1.0, 1.0, 1.0}, specular{0.1, 0.1, 0.1, 1.0};  // RGBA
  double attenuation_constant = 1.0, attenuation_linear = 0.0, attenuation_quadratic = 0.0;
  double range = 10.0;               // m
  Vec3 direction{0.0, 0.0, -1.0};    // in the light frame
  Pose pose;                         // X_WL
};

struct SdfWorld {
  std::string name;
  std::string file;
  std::vector<SdfModel> models;  // document order (includes where they stand)
  std::vector<SdfLight> lights;  // document order
  Vec3 gravity{0.0, 0.0, -9.8};  // m/s^2 (SDF's default when absent)
  // <physics> values written in the file; absent ones are left to the caller (SDF's defaults are
  // 0.001 s, 1000 Hz and 1).
  std::optional<double> max_step_size, real_time_update_rate, real_time_factor;
  std::vector<std::string> not_simulated;
  std::vector<std::string> warnings;
};

// `xml`: an <sdf> document holding one <model>. Throws SdfError.
SdfModel parse_sdf_model(const std::string& xml, const std::string& source, const SdfOptions& options = {});
// A .world / .sdf file holding a <world>. Throws SdfError.
SdfWorld load_sdf_world(const std::string& path, const SdfOptions& options = {});

// Whether `path` names an SDF world file mechsim reads with load_sdf_world (.world, .sdf).
bool is_sdf_world_file(const std::string& path);

}  // namespace mechsim::description
