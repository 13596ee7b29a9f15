#pragma once
// Mesh files into bytes MuJoCo 2.2.2 reads from its virtual file system: binary STL and OBJ
// pass through unchanged; anything else assimp reads (Collada .dae, ASCII STL, ...) is
// converted to an in-memory binary STL with the file's node transforms and unit applied.
// Collada up_axis is ignored (vertices are used as authored, as Gazebo classic does).

#include <string>
#include <vector>

namespace mechsim::physics {

struct MeshBytes {
  std::string extension;  // ".stl" or ".obj": the format MuJoCo must parse
  std::vector<char> bytes;
  bool converted = false;  // true when assimp produced it
};

// Throws PhysicsError naming the file and what failed (unreadable, no triangles, ...).
MeshBytes load_mesh_for_mujoco(const std::string& path);

// The axis-aligned bounds of a mesh file's vertices in its own frame (m, as authored, node
// transforms applied, as load_mesh_for_mujoco), times `scale`. Throws PhysicsError as it does.
struct MeshBounds {
  double min[3] = {0.0, 0.0, 0.0};
  double max[3] = {0.0, 0.0, 0.0};
};
MeshBounds mesh_bounds(const std::string& path, const double scale[3]);

}  // namespace mechsim::physics
