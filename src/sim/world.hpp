#pragma once
// The worlds mechsim ships, by name: `empty` (ground plane and gravity), `mars_yard_2024`
// (generated from a seed), `slope` (a plane rising along +x at slope_deg), any heightmap file
// (8/16-bit PNG, float TIFF), and Gazebo SDF world files (.world, .sdf): their ground planes,
// gravity, static box models and single-box dynamic models; every other model is listed in
// World::not_simulated (the physics holds one robot). Any of the generated or heightmap worlds
// may be soil instead of rigid ground for the robot's wheels (physics::Physics::set_soil).

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "description/pose.hpp"
#include "description/robot_model.hpp"
#include "description/sdf/sdf_model.hpp"
#include "physics/heightmap_io.hpp"
#include "physics/mars_yard.hpp"
#include "physics/physics_options.hpp"
#include "physics/soil.hpp"
#include "physics/wheel_override.hpp"
#include "physics/terrain_stats.hpp"

namespace mechsim::sim {

struct WorldError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct WorldConfig {
  std::string name = "empty";  // "empty", "mars_yard_2024", or a heightmap file's path
  std::uint64_t seed = physics::kMarsYardDefaultSeed;  // mars_yard_2024 only
  physics::HeightmapOptions heightmap;                 // heightmap files only
  std::optional<double> slope_deg;                     // slope only (default 10)
  // The wheels meet soil (physics/soil.hpp) instead of rigid ground; nullopt: rigid.
  std::optional<physics::SoilParameters> soil;
  // Which links are soil wheels, over the description's (sim/wheel_config.hpp); with a soil only.
  std::vector<physics::WheelOverride> wheels;
  // An SDF world's models with sensors or model plugins are left out of the world's own objects
  // and listed in World::sdf_robots instead, for the caller to bring in as robots of their own
  // (gazebo_ros' gzserver mode: bridge::World). False: their sensors and plugins are listed as
  // not simulated and the model is a world object as any other.
  bool sdf_active_models_apart = false;
};

// An SDF world's model that is a robot of its own (WorldConfig::sdf_active_models_apart): its
// sensors and model plugins run. A static model is welded to the world: its root link is `world`,
// at the model frame.
struct SdfRobot {
  std::string name;
  description::RobotModel robot;
  description::Pose X_WR;  // its root link frame in the world (the spawn pose)
  bool is_static = false;
};

struct World {
  std::string name;
  physics::WorldSpec spec;                     // what the physics builds
  std::optional<physics::MarsYard> mars_yard;  // features, for route planning and reports
  // The ground a robot may use (m, W): the Mars Yard's usable ground inside its flat border, a
  // height field's footprint (past its edges there is no ground); none for the endless plane of
  // `empty`. `usable_what` names it in messages.
  std::optional<physics::Region> usable;
  std::string usable_what;
  std::optional<physics::SoilParameters> soil;  // WorldConfig::soil
  std::vector<physics::WheelOverride> wheels;   // WorldConfig::wheels
  // A Gazebo SDF world file (.world, .sdf): the models it simulates (as Gazebo names them: the
  // ground plane, static boxes) and what it leaves out, one line each ("model 'cup1_model': ...").
  std::vector<std::string> sdf_models;
  // Where each of sdf_models is (same order): its pose in the SDF, and for a moving one the
  // physics body that carries it (PhysicsModel::body_index) with the model frame in that body's
  // frame, so that the model's pose now is X_WB X_BM. Static models (and the ground): no body.
  struct ModelFrame {
    std::string name;
    description::Pose pose;  // X_WM in the SDF
    std::string body;        // "" for a static model
    description::Pose X_BM;
  };
  std::vector<ModelFrame> sdf_model_frames;
  std::vector<SdfRobot> sdf_robots;  // WorldConfig::sdf_active_models_apart
  std::vector<description::SdfLight> lights;  // an SDF world's
  std::vector<std::string> not_simulated;
  std::vector<std::string> warnings;  // what an SDF world holds that Gazebo tolerates, one line each
  // <physics> of an SDF world: s per step and the real-time factor it asks for (absent: unset).
  std::optional<double> max_step_size, real_time_factor;
};

// Throws WorldError (unknown name, unreadable heightmap: the message names the file).
World make_world(const WorldConfig& config);

}  // namespace mechsim::sim
