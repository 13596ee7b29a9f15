// The scenario's `world:`: the world's name, seed, heightmap extent and soil, and its objects
// (boxes, cylinders, spheres, meshes).
#include <cmath>
#include <exception>
#include <filesystem>
#include <string>

#include "physics/mesh_loader.hpp"

#include "sim/scenario_read.hpp"
#include "sim/soil_config.hpp"
#include "sim/wheel_config.hpp"

namespace mechsim::sim {

namespace fs = std::filesystem;
using namespace scenario_read;

namespace scenario_read {

std::vector<physics::WorldBox> read_boxes(const Params& list, const fs::path& base) {
  if (!list.is_list()) fail(list, "expected a list of boxes");
  std::vector<physics::WorldBox> boxes;
  for (const Params& b : list.items()) {
    only_keys(b, {"name", "shape", "size", "radius", "length", "mesh", "scale", "x", "y", "z", "roll", "pitch", "yaw", "quat",
                  "fixed", "mass"});
    physics::WorldBox box;
    box.name = b.get<std::string>("name");
    for (const physics::WorldBox& other : boxes) {
      if (other.name == box.name) fail(b.child("name"), "box '" + box.name + "' is named twice");
    }
    const std::string shape = b.get<std::string>("shape", "box");
    auto positive = [&](const char* key, const char* what) {
      const double v = finite(b, key, 0.0);
      if (!b.has(key)) fail(b, std::string("a ") + shape + " needs '" + key + "' (" + what + ")");
      if (!(v > 0.0)) fail(b.child(key), "must be > 0 m");
      return v;
    };
    auto none_of = [&](std::initializer_list<const char*> keys) {
      for (const char* k : keys)
        if (b.has(k)) fail(b.child(k), "a " + shape + " takes no '" + k + "'");
    };
    if (shape == "box") {
      none_of({"radius", "length"});
      const auto size = values_of(b, "size", 3);
      for (double v : size) {
        if (!(v > 0.0)) fail(b.child("size"), "edge lengths must be > 0 m");
      }
      box.size = {size[0], size[1], size[2]};
    } else if (shape == "cylinder") {
      none_of({"size"});
      const double d = 2.0 * positive("radius", "m"), l = positive("length", "m, along its z axis");
      box.shape = physics::WorldBox::Shape::Cylinder;
      box.size = {d, d, l};
    } else if (shape == "sphere") {
      none_of({"size", "length"});
      const double d = 2.0 * positive("radius", "m");
      box.shape = physics::WorldBox::Shape::Sphere;
      box.size = {d, d, d};
    } else if (shape == "mesh") {
      // The file's own frame at the pose (not its centre): as a robot's or an SDF model's mesh.
      none_of({"size", "radius", "length"});
      if (!b.has("mesh")) fail(b, "a mesh needs 'mesh' (its file: STL, OBJ, DAE, ...; relative to this file)");
      const std::string file = resolve_path(base, b.get<std::string>("mesh"));
      std::error_code ec;
      if (!fs::is_regular_file(file, ec)) fail(b.child("mesh"), "no such file: " + file);
      if (b.has("scale")) {
        const auto scale = values_of(b, "scale", 3);
        for (double v : scale)
          if (!(v > 0.0)) fail(b.child("scale"), "must be > 0 along x, y and z");
        box.mesh_scale = {scale[0], scale[1], scale[2]};
      }
      const double scale[3] = {box.mesh_scale.x, box.mesh_scale.y, box.mesh_scale.z};
      try {
        const physics::MeshBounds bounds = physics::mesh_bounds(file, scale);
        box.size = {bounds.max[0] - bounds.min[0], bounds.max[1] - bounds.min[1], bounds.max[2] - bounds.min[2]};
        box.mesh_min = {bounds.min[0], bounds.min[1], bounds.min[2]};
      } catch (const std::exception& e) {
        fail(b.child("mesh"), e.what());
      }
      box.shape = physics::WorldBox::Shape::Mesh;
      box.mesh_path = file;
    } else {
      fail(b.child("shape"), "expected box, cylinder, sphere or mesh, got '" + shape + "'");
    }
    if (shape != "mesh" && b.has("scale")) fail(b.child("scale"), "a " + shape + " takes no 'scale' (a mesh's)");
    box.pose.position = {finite(b, "x", 0.0), finite(b, "y", 0.0), finite(b, "z", 0.0)};
    if (b.has("quat")) {
      if (b.has("roll") || b.has("pitch") || b.has("yaw")) fail(b.child("quat"), "give quat or roll/pitch/yaw, not both");
      const auto q = values_of(b, "quat", 4);
      const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
      if (!(n > 1e-9)) fail(b.child("quat"), "must not be zero");
      box.pose.orientation = {q[0] / n, q[1] / n, q[2] / n, q[3] / n};
    } else {
      // ZYX: q = qz(yaw) qy(pitch) qx(roll).
      const double r = finite(b, "roll", 0.0) / 2, p = finite(b, "pitch", 0.0) / 2, y = finite(b, "yaw", 0.0) / 2;
      const double cr = std::cos(r), sr = std::sin(r), cp = std::cos(p), sp = std::sin(p), cy = std::cos(y), sy = std::sin(y);
      box.pose.orientation = {cr * cp * cy + sr * sp * sy, sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy,
                              cr * cp * sy - sr * sp * cy};
    }
    box.fixed = b.get<bool>("fixed", true);
    box.mass = finite(b, "mass", box.mass);
    if (!(box.mass > 0.0)) fail(b.child("mass"), "must be > 0 kg");
    boxes.push_back(box);
  }
  return boxes;
}

}  // namespace scenario_read

WorldConfig read_world_config(const Params& world, const fs::path& base) {
  WorldConfig w;
  const std::string name = world.get<std::string>("name", "empty");
  w.name = (name == "empty" || name == "mars_yard_2024" || name == "slope") ? name : resolve_path(base, name);
  if (world.has("slope_deg")) w.slope_deg = finite(world, "slope_deg", 10.0);
  if (auto soil = world.find("soil")) w.soil = read_soil(*soil, base);
  if (auto wheels = world.find("wheels")) w.wheels = read_wheel_overrides(*wheels);
  w.seed = static_cast<std::uint64_t>(world.get<int>("seed", static_cast<int>(physics::kMarsYardDefaultSeed)));
  if (world.has("size_x")) w.heightmap.size_x = world.get<double>("size_x");
  if (world.has("size_y")) w.heightmap.size_y = world.get<double>("size_y");
  if (world.has("z_min")) w.heightmap.z_min = world.get<double>("z_min");
  if (world.has("z_max")) w.heightmap.z_max = world.get<double>("z_max");
  return w;
}

}  // namespace mechsim::sim
