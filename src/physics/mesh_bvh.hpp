#pragma once
// A bounding-volume hierarchy over one triangle mesh, for ray queries (range sensors): built once
// from the mesh's vertices and faces in its own frame, then queried by any number of threads.
// MuJoCo 2.2.2's mj_rayMesh tests every triangle of a mesh for every ray; on the PR2 (meshes of
// up to a few thousand triangles) that was 40 % of the CPU of a tick with its two Hokuyos
// subscribed. Here a ray visits the boxes it crosses and the few triangles in them.
//
// Written here rather than taken from Embree (Debian's libembree3): linking Embree costs every
// process that links the physics ~10 ms of start-up CPU (its TBB runtime) and 42 MB, for a
// query this small.

#include <array>
#include <cstdint>
#include <vector>

namespace mechsim::physics {

class MeshBvh {
 public:
  // `vertices`: x y z per vertex; `faces`: three vertex indices per triangle (MuJoCo's
  // mesh_vert / mesh_face layout). Indices out of range are a bug of the caller (checked).
  MeshBvh(const float* vertices, int vertex_count, const int* faces, int face_count);

  // Distance t in (0, t_max] along p + t v to the nearest triangle (either side), or -1 when the
  // ray misses them all. v need not be unit: t is in units of |v| (as mj_rayMesh).
  double intersect(const double p[3], const double v[3], double t_max) const noexcept;

  std::size_t triangle_count() const noexcept { return triangles_.size(); }
  std::size_t node_count() const noexcept { return nodes_.size(); }

 private:
  struct Triangle {
    std::array<double, 3> a, e1, e2;  // a vertex and the two edges from it
  };
  struct Node {
    std::array<double, 3> lo, hi;  // box
    // Leaf: triangles [first, first + count); inner: children `first` and `first + 1`, count 0.
    std::uint32_t first = 0, count = 0;
  };
  // Splits order[first, first + count) under `node` (boxes from `source`, split at the median
  // centroid along the widest axis).
  void build(std::size_t node, std::uint32_t first, std::uint32_t count, const std::vector<Triangle>& source,
             const std::vector<std::array<double, 3>>& centroids, std::vector<std::uint32_t>& order);

  std::vector<Triangle> triangles_;
  std::vector<Node> nodes_;
};

}  // namespace mechsim::physics
