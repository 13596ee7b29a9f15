#include "sim/replay_assets.hpp"

#include <cstring>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "physics/mesh_loader.hpp"
#include "sim/scenario.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;
using nlohmann::ordered_json;

void write_file(const fs::path& file, const char* data, std::size_t size) {
  std::ofstream out(file, std::ios::binary);
  out.write(data, static_cast<std::streamsize>(size));
  out.close();
  if (!out) throw ScenarioError("replay: cannot write " + file.string());
}

void write_text(const fs::path& file, const std::string& text) { write_file(file, text.data(), text.size()); }

ordered_json pose_json(const description::Pose& X) {
  return {{"p", {X.position.x, X.position.y, X.position.z}},
          {"q", {X.orientation.w, X.orientation.x, X.orientation.y, X.orientation.z}}};
}

// A file name from a path's stem: letters, digits, '-' and '_' only.
std::string safe_stem(const std::string& path) {
  std::string stem = fs::path(path).stem().string();
  for (char& c : stem) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_';
    if (!ok) c = '_';
  }
  return stem.empty() ? "mesh" : stem;
}

// The links' visuals: the robot's, then each other robot's under its prefix ("<name>::<link>", as
// the physics and the replay's frames name them).
ordered_json robot_json(const Simulation& sim, const fs::path& dir) {
  ordered_json links = ordered_json::array();
  ordered_json warnings = ordered_json::array();
  std::map<std::string, std::string> meshes;  // resolved path -> file under replay/
  const auto add_robot = [&](const description::RobotModel& robot, const std::string& prefix) {
    for (const description::Link& link : robot.links) {
      const std::string name = prefix + link.name;  // as the physics and the frames name it
      double gazebo_rgb[3] = {0.6, 0.6, 0.6};
      bool has_gazebo_colour = false;
      if (auto it = robot.gazebo_links.find(link.name); it != robot.gazebo_links.end()) {
        has_gazebo_colour = gazebo_material_rgb(it->second.material, gazebo_rgb);
      }
      ordered_json visuals = ordered_json::array();
      for (const description::Visual& v : link.visuals) {
        ordered_json j = {{"origin", pose_json(v.origin)}};
        const description::Geometry& g = v.geometry;
        switch (g.type) {
          case description::GeometryType::Box:
            j["type"] = "box";
            j["size"] = {g.size.x, g.size.y, g.size.z};
            break;
          case description::GeometryType::Cylinder:
            j["type"] = "cylinder";
            j["radius"] = g.radius;
            j["length"] = g.length;
            break;
          case description::GeometryType::Sphere:
            j["type"] = "sphere";
            j["radius"] = g.radius;
            break;
          case description::GeometryType::Mesh: {
            if (g.mesh_path.empty()) {
              warnings.push_back("link '" + name + "': mesh '" + g.mesh_uri + "' was not found; left out");
              continue;
            }
            auto it = meshes.find(g.mesh_path);
            if (it == meshes.end()) {
              try {
                const physics::MeshBytes bytes = physics::load_mesh_for_mujoco(g.mesh_path);
                const std::string file = "meshes/" + std::to_string(meshes.size()) + "_" + safe_stem(g.mesh_path) + bytes.extension;
                write_file(dir / file, bytes.bytes.data(), bytes.bytes.size());
                it = meshes.emplace(g.mesh_path, file).first;
              } catch (const ScenarioError&) {
                throw;
              } catch (const std::exception& e) {
                warnings.push_back("link '" + name + "': " + e.what() + "; left out");
                continue;
              }
            }
            j["type"] = "mesh";
            j["file"] = it->second;
            j["scale"] = {g.mesh_scale.x, g.mesh_scale.y, g.mesh_scale.z};
            break;
          }
        }
        if (v.rgba) {
          j["rgba"] = {(*v.rgba)[0], (*v.rgba)[1], (*v.rgba)[2], (*v.rgba)[3]};
        } else {
          j["rgba"] = {gazebo_rgb[0], gazebo_rgb[1], gazebo_rgb[2], 1.0};
        }
        if (!v.rgba && !has_gazebo_colour) j["default_colour"] = true;
        visuals.push_back(j);
      }
      links.push_back({{"name", name}, {"visuals", visuals}});
    }
  };
  add_robot(sim.robot(), "");
  for (std::size_t i = 0; i < sim.other_count(); ++i) add_robot(sim.other(i).robot(), sim.other(i).physics_name(""));
  return {{"name", sim.robot().name}, {"root_link", sim.robot().root_link}, {"links", links}, {"warnings", warnings}};
}

// The world's passive models, body by body: each body's primitive shapes in its frame (the
// replay's frames move the bodies; "world" holds the shapes welded to the world, in its frame).
ordered_json passive_bodies_json(const physics::PhysicsModel& model) {
  ordered_json bodies = ordered_json::array();
  std::map<std::string, std::size_t> at;
  for (const physics::PassiveShape& s : model.passive_shapes()) {
    auto it = at.find(s.body_name);
    if (it == at.end()) {
      it = at.emplace(s.body_name, bodies.size()).first;
      bodies.push_back({{"name", s.body_name}, {"shapes", ordered_json::array()}});
    }
    const char* shape = s.kind == physics::PassiveShape::Kind::Cylinder ? "cylinder"
                        : s.kind == physics::PassiveShape::Kind::Sphere ? "sphere"
                                                                          : "box";
    bodies[it->second]["shapes"].push_back(
        {{"shape", shape}, {"pose", pose_json(s.X_BG)}, {"size", {s.size.x, s.size.y, s.size.z}}});
  }
  return bodies;
}

ordered_json world_json(const World& world, const fs::path& dir) {
  const physics::WorldSpec& spec = world.spec;
  ordered_json j = {{"name", world.name}};
  j["ground_plane"] = spec.kind == physics::WorldSpec::Kind::Empty && spec.ground_plane;
  ordered_json boxes = ordered_json::array();
  std::map<std::string, std::string> meshes;  // resolved path -> file under replay/
  for (const physics::WorldBox& b : spec.boxes) {
    const char* shape = b.shape == physics::WorldBox::Shape::Cylinder ? "cylinder"
                        : b.shape == physics::WorldBox::Shape::Sphere ? "sphere"
                        : b.shape == physics::WorldBox::Shape::Mesh   ? "mesh"
                                                                       : "box";
    ordered_json o = {{"name", b.name}, {"shape", shape}, {"pose", pose_json(b.pose)}, {"size", {b.size.x, b.size.y, b.size.z}},
                      {"fixed", b.fixed}};
    if (b.shape == physics::WorldBox::Shape::Mesh) {
      // The mesh as the physics reads it (STL or OBJ; other formats converted), written once.
      auto it = meshes.find(b.mesh_path);
      if (it == meshes.end()) {
        const physics::MeshBytes bytes = physics::load_mesh_for_mujoco(b.mesh_path);
        const std::string file = "meshes/world_" + std::to_string(meshes.size()) + "_" + safe_stem(b.mesh_path) + bytes.extension;
        write_file(dir / file, bytes.bytes.data(), bytes.bytes.size());
        it = meshes.emplace(b.mesh_path, file).first;
      }
      o["file"] = it->second;
      o["scale"] = {b.mesh_scale.x, b.mesh_scale.y, b.mesh_scale.z};
    }
    boxes.push_back(std::move(o));
  }
  j["boxes"] = boxes;
  if (spec.kind == physics::WorldSpec::Kind::Heightmap && spec.terrain) {
    const physics::Heightmap& map = *spec.terrain;
    float lo = map.heights.empty() ? 0.0f : map.heights.front(), hi = lo;
    for (float h : map.heights) {
      lo = std::min(lo, h);
      hi = std::max(hi, h);
    }
    write_file(dir / "terrain.bin", reinterpret_cast<const char*>(map.heights.data()), map.heights.size() * sizeof(float));
    j["heightfield"] = {{"file", "terrain.bin"}, {"rows", map.rows}, {"cols", map.cols}, {"size_x", map.size_x},
                        {"size_y", map.size_y}, {"min", lo}, {"max", hi}, {"source", map.source}};
  }
  if (world.usable) {
    j["usable"] = {{"x_min", world.usable->x_min}, {"x_max", world.usable->x_max}, {"y_min", world.usable->y_min},
                   {"y_max", world.usable->y_max}};
  }
  return j;
}

}  // namespace

bool gazebo_material_rgb(const std::string& name, double rgb[3]) {
  static constexpr struct {
    const char* name;
    double r, g, b;
  } kColours[] = {
      {"Gazebo/Grey", 0.7, 0.7, 0.7},        {"Gazebo/DarkGrey", 0.35, 0.35, 0.35}, {"Gazebo/LightGrey", 0.85, 0.85, 0.85},
      {"Gazebo/Black", 0.1, 0.1, 0.1},       {"Gazebo/White", 1.0, 1.0, 1.0},       {"Gazebo/Red", 0.85, 0.1, 0.1},
      {"Gazebo/Green", 0.1, 0.75, 0.1},      {"Gazebo/Blue", 0.1, 0.2, 0.85},       {"Gazebo/Yellow", 0.95, 0.85, 0.1},
      {"Gazebo/Orange", 1.0, 0.5, 0.05},     {"Gazebo/Purple", 0.55, 0.15, 0.65},   {"Gazebo/Turquoise", 0.1, 0.75, 0.75},
      {"Gazebo/Gold", 0.85, 0.7, 0.25},      {"Gazebo/Wood", 0.6, 0.42, 0.25},      {"Gazebo/FlatBlack", 0.1, 0.1, 0.1},
      {"Gazebo/Indigo", 0.3, 0.0, 0.5},      {"Gazebo/SkyBlue", 0.5, 0.75, 0.95},   {"Gazebo/ZincYellow", 0.9, 0.85, 0.3},
  };
  for (const auto& c : kColours) {
    if (name == c.name) {
      rgb[0] = c.r;
      rgb[1] = c.g;
      rgb[2] = c.b;
      return true;
    }
  }
  return false;
}

void write_replay_assets(const Simulation& sim, const fs::path& replay_dir, const std::string& urdf) {
  std::error_code ec;
  fs::create_directories(replay_dir / "meshes", ec);
  if (ec) throw ScenarioError("replay: cannot create " + (replay_dir / "meshes").string() + ": " + ec.message());
  write_text(replay_dir / "robot.urdf", urdf);
  write_text(replay_dir / "robot.json", robot_json(sim, replay_dir).dump(1));
  ordered_json world = world_json(sim.world(), replay_dir);
  world["bodies"] = passive_bodies_json(sim.physics().model());
  write_text(replay_dir / "world.json", world.dump(1));
}

}  // namespace mechsim::sim
