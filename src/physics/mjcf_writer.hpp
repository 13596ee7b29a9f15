#pragma once
// Writing the MJCF document MuJoCo compiles, from a BodyPlan. Mesh files are loaded here into
// byte buffers for MuJoCo's virtual file system, so the model never depends on the working
// directory or on MuJoCo's own URDF import.

#include <set>
#include <string>
#include <vector>

#include "physics/body_plan.hpp"
#include "physics/physics_options.hpp"

namespace mechsim::physics {

// One <mesh> asset: a mesh file at one scale.
struct MeshAsset {
  std::string name;       // MuJoCo asset name, "mesh<N>"
  std::string vfs_file;   // file name in the virtual file system
  std::string path;       // source file
  description::Vec3 scale{1.0, 1.0, 1.0};
  std::vector<char> bytes;  // empty when loading failed
  std::string error;        // why loading failed
};

// Loads every distinct (file, scale) mesh the plan and the world's mesh objects use. Meshes that
// cannot be read or converted keep an `error` and their geoms are left out (with a warning) by
// write_mjcf.
std::vector<MeshAsset> collect_meshes(const BodyPlan& plan, const WorldSpec* world = nullptr);

// The warning for a mesh geom the model leaves out: the link, "collision"/"visual", the mesh as
// written, why (no file resolved, no such file, the loader's or MuJoCo's error) and the path
// tried. `asset`: the geom's loaded mesh, null when it has none.
std::string left_out_mesh_warning(const PlannedGeom& g, const MeshAsset* asset);

struct MjcfDocument {
  std::string xml;
  std::vector<std::string> warnings;  // geoms left out and why
};

// `skip_meshes`: asset names whose geoms are left out (e.g. ones MuJoCo refused to compile).
// `arena`: the <size> element's contacts and constraints.
MjcfDocument write_mjcf(const std::string& model_name, const BodyPlan& plan, const std::vector<MeshAsset>& meshes,
                        const BuildOptions& options, const std::set<std::string>& skip_meshes, const ArenaSize& arena);

// The <size> element write_mjcf writes for `arena` (MuJoCo computes the stack from it).
std::string mjcf_size_element(const ArenaSize& arena);

// Name of the MuJoCo hfield asset and geom of a heightmap world.
inline constexpr const char* kTerrainName = "terrain";
inline constexpr const char* kGroundName = "ground";

}  // namespace mechsim::physics
