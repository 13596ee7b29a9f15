#include "sim/world.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "description/sdf/sdf_model.hpp"
#include "description/sensor_spec.hpp"
#include "physics/mesh_loader.hpp"
#include "physics/transform.hpp"

#include "physics/terrain_world.hpp"

namespace mechsim::sim {

namespace {

// Why a model's mesh collision cannot be a world object ("" when it can): its file
// resolved, exists and is readable (the bounds are read here, so a bad file is named now).
std::string mesh_problem(const description::Geometry& g, physics::WorldBox& object) {
  if (g.mesh_path.empty()) return "mesh '" + g.mesh_uri + "' was not found (is its model on GAZEBO_MODEL_PATH?)";
  std::error_code ec;
  if (!std::filesystem::exists(g.mesh_path, ec)) return "mesh '" + g.mesh_uri + "': no such file " + g.mesh_path;
  const double scale[3] = {g.mesh_scale.x, g.mesh_scale.y, g.mesh_scale.z};
  try {
    const physics::MeshBounds b = physics::mesh_bounds(g.mesh_path, scale);
    object.size = {b.max[0] - b.min[0], b.max[1] - b.min[1], b.max[2] - b.min[2]};
    object.mesh_min = {b.min[0], b.min[1], b.min[2]};
  } catch (const std::exception& e) {
    return e.what();
  }
  object.shape = physics::WorldBox::Shape::Mesh;
  object.mesh_path = g.mesh_path;
  object.mesh_scale = g.mesh_scale;
  return {};
}

void set_shape(const description::Geometry& g, physics::WorldBox& object) {
  switch (g.type) {
    case description::GeometryType::Cylinder:
      object.shape = physics::WorldBox::Shape::Cylinder;
      object.size = {2.0 * g.radius, 2.0 * g.radius, g.length};
      break;
    case description::GeometryType::Sphere:
      object.shape = physics::WorldBox::Shape::Sphere;
      object.size = {2.0 * g.radius, 2.0 * g.radius, 2.0 * g.radius};
      break;
    default:
      object.shape = physics::WorldBox::Shape::Box;
      object.size = g.size;
  }
}

// Gazebo's world file: the ground and the boxes, cylinders, spheres and meshes the physics can hold (sdf_model.hpp says how models
// map to robots; a model's root link frame is its pose times root_offset).
// A static model as a robot of its own: its root welded to a `world` link at the model frame
// (the converter does so already for a model jointed to the world or of several roots).
description::RobotModel welded(const description::SdfModel& model) {
  description::RobotModel robot = model.robot;
  if (robot.root_link == "world") return robot;
  description::Link world;
  world.name = "world";
  description::Joint weld;
  weld.name = "__weld_" + robot.root_link;
  weld.type = description::JointType::Fixed;
  weld.parent_link = "world";
  weld.child_link = robot.root_link;
  weld.origin = model.root_offset;
  world.child_joints.push_back(weld.name);
  for (description::Link& l : robot.links)
    if (l.name == robot.root_link) l.parent_joint = weld.name;
  robot.links.insert(robot.links.begin(), std::move(world));
  robot.joints.push_back(std::move(weld));
  robot.root_link = "world";
  return robot;
}

World make_sdf_world(const std::string& path, bool active_apart) {
  description::SdfWorld sdf;
  try {
    sdf = description::load_sdf_world(path);
  } catch (const std::exception& e) {
    throw WorldError(e.what());
  }
  World world;
  world.name = path;
  world.spec.ground_plane = false;
  world.spec.gravity = -sdf.gravity.z;
  world.max_step_size = sdf.max_step_size;
  world.real_time_factor = sdf.real_time_factor;
  if (std::abs(sdf.gravity.x) > 1e-12 || std::abs(sdf.gravity.y) > 1e-12) {
    world.not_simulated.push_back("gravity's horizontal part (mechsim's worlds pull along -z only)");
  }
  for (const std::string& n : sdf.not_simulated) world.not_simulated.push_back(n);
  world.warnings = sdf.warnings;
  world.lights = sdf.lights;
  for (const description::SdfModel& model : sdf.models) {
    const bool active = !model.robot.sensors.empty() || std::any_of(model.robot.plugins.begin(), model.robot.plugins.end(),
                                                                    [](const description::GazeboPlugin& p) { return p.sensor.empty(); });
    if (active && active_apart) {
      SdfRobot robot;
      robot.name = model.name;
      robot.is_static = model.is_static || model.robot.root_link == "world";
      robot.robot = robot.is_static ? welded(model) : model.robot;
      robot.X_WR = robot.is_static ? model.pose : physics::compose(model.pose, model.root_offset);
      world.sdf_robots.push_back(std::move(robot));
      continue;
    }
    if (active) {
      for (const description::SensorSpec& sensor : model.robot.sensors)
        world.not_simulated.push_back("model '" + model.name + "': sensor '" + sensor.name + "'");
      for (const description::GazeboPlugin& plugin : model.robot.plugins)
        if (plugin.sensor.empty())
          world.not_simulated.push_back("model '" + model.name + "': model plugin '" + plugin.name + "' (" + plugin.filename + ")");
    }
    bool used = false;
    World::ModelFrame frame{model.name, model.pose, "", {}};  // static until a moving part is found
    for (const description::SdfPlane& plane : model.planes) {
      const description::Pose X_WP = physics::compose(model.pose, plane.pose);
      const description::Vec3 n = physics::rotate(X_WP.orientation, {0.0, 0.0, 1.0});
      if (std::abs(X_WP.position.z) < 1e-9 && n.z > 1.0 - 1e-9) {
        world.spec.ground_plane = true;
        // The plane's surface as written; what it leaves out is Gazebo's default (1).
        world.spec.ground_mu = plane.mu;
        world.spec.ground_mu2 = plane.mu2;
        used = true;
      } else {
        world.not_simulated.push_back("model '" + model.name + "': plane '" + plane.name + "' (not the ground z = 0)");
      }
    }
    const bool has_links = !model.robot.links.empty() &&
                           std::any_of(model.robot.links.begin(), model.robot.links.end(),
                                       [](const description::Link& l) { return !l.collisions.empty(); });
    // Static models whole; a moving model of one link with one shape (a box, cylinder, sphere or
    // mesh) as a free object; other moving models as passive articulated objects.
    const bool one_shape = model.robot.links.size() == 1 && model.robot.links.front().collisions.size() == 1;
    if (has_links && (model.is_static || one_shape)) {
      const description::Pose X_WR = physics::compose(model.pose, model.root_offset);
      const description::Link& root = model.robot.links.front();
      const std::size_t before = world.spec.boxes.size();
      for (const description::Link& link : model.robot.links) {
        if (!model.is_static && &link != &root) continue;
        for (std::size_t i = 0; i < link.collisions.size(); ++i) {
          const description::Collision& c = link.collisions[i];
          physics::WorldBox box;
          box.name = model.name + "::" + link.name + "::" + (c.name.empty() ? std::to_string(i) : c.name);
          // Static models: every link where the model's zero configuration puts it.
          description::Pose X_WL = X_WR;
          if (&link != &root) {
            for (const description::Joint& j : model.robot.joints)
              if (j.child_link == link.name) X_WL = physics::compose(X_WR, j.origin);
          }
          box.pose = physics::compose(X_WL, c.origin);
          box.laser_retro = c.laser_retro.value_or(0.0);
          if (c.geometry.type == description::GeometryType::Mesh) {
            const std::string problem = mesh_problem(c.geometry, box);
            if (!problem.empty()) {
              world.not_simulated.push_back("model '" + model.name + "': link '" + link.name + "': " + problem);
              continue;
            }
          } else {
            set_shape(c.geometry, box);
          }
          box.fixed = model.is_static;
          if (auto gz = model.robot.gazebo_links.find(link.name); gz != model.robot.gazebo_links.end()) {
            box.mu = gz->second.mu1;
            box.mu2 = gz->second.mu2;
          }
          if (!model.is_static) box.mass = link.inertial && link.inertial->mass > 0.0 ? link.inertial->mass : 1.0;
          world.spec.boxes.push_back(box);
        }
      }
      if (world.spec.boxes.size() > before) {
        used = true;
        if (!model.is_static) {
          // The free object's body sits at its one shape: model -> root link -> collision.
          frame.body = "box:" + world.spec.boxes.back().name;
          frame.X_BM = physics::inverse(physics::compose(model.root_offset, root.collisions.front().origin));
        }
      }
    } else if (has_links) {
      // A moving model of several links or shapes: a passive articulated object (its joints
      // free, nothing driving them; a model's plugins are not run).
      physics::WorldModel passive;
      passive.name = model.name;
      passive.robot = std::make_shared<const description::RobotModel>(model.robot);
      passive.pose = physics::compose(model.pose, model.root_offset);
      world.spec.models.push_back(std::move(passive));
      // A model jointed to the world stays where it is (its links move on their joints).
      if (model.robot.root_link != "world") {
        frame.body = model.name + "::" + model.robot.root_link;
        frame.X_BM = physics::inverse(model.root_offset);
      }
      used = true;
    }
    if (used) {
      world.sdf_models.push_back(model.name);
      world.sdf_model_frames.push_back(std::move(frame));
    }
  }
  return world;
}

}  // namespace

World make_world(const WorldConfig& config) {
  if (description::is_sdf_world_file(config.name)) {
    if (config.soil) {
      throw WorldError("world '" + config.name + "': soil is for mechsim's own worlds (empty, slope, mars_yard_2024, "
                       "heightmaps); an SDF world's ground is rigid");
    }
    return make_sdf_world(config.name, config.sdf_active_models_apart);
  }
  physics::WorldTerrainOptions options;
  if (config.name == "mars_yard_2024") options.seed = config.seed;
  if (config.name != "empty" && config.name != "mars_yard_2024" && config.name != "slope") options.heightmap = config.heightmap;
  options.slope_deg = config.slope_deg;
  physics::WorldTerrain terrain;
  try {
    terrain = physics::load_world_terrain(config.name, options);
  } catch (const std::exception& e) {
    throw WorldError("world '" + config.name + "': " + e.what());
  }
  World world;
  world.name = config.name;
  world.soil = config.soil;
  world.wheels = config.wheels;
  world.mars_yard = std::move(terrain.yard);
  if (terrain.usable) {
    world.usable = terrain.usable;
    const double border = terrain.heightmap ? (terrain.heightmap->size_x - (terrain.usable->x_max - terrain.usable->x_min)) / 2 : 0.0;
    char text[64];
    std::snprintf(text, sizeof text, "%.3g", border);
    world.usable_what = config.name + "'s usable ground (inside its " + text + " m border)";
  } else if (terrain.heightmap) {
    const double hx = terrain.heightmap->size_x / 2, hy = terrain.heightmap->size_y / 2;
    world.usable = physics::Region{-hx, hx, -hy, hy};
    world.usable_what = "the height field of " + config.name + " (no ground past its edges)";
  }
  if (terrain.heightmap) {
    world.spec.kind = physics::WorldSpec::Kind::Heightmap;
    world.spec.terrain = std::move(terrain.heightmap);
    world.spec.ground_plane = false;
  }
  return world;
}

}  // namespace mechsim::sim
