#pragma once
// Private to src/physics: which terrain render tiles (terrain_tiles.hpp) a camera draws, and at
// which level of detail. A tile outside the view's frustum is not drawn; a visible one is drawn
// at the coarsest level whose cells project to at most `pixels_per_cell` pixels at the tile's
// nearest point.

#include <vector>

#include <mujoco/mujoco.h>

#include "physics/renderer.hpp"

namespace mechsim::physics {

// A view's frustum as six planes in the world frame (normals inside: n . p + d >= 0), from the
// image's edges (u in [-0.5, w - 0.5], v in [-0.5, h - 0.5]) and the clip distances.
class ViewFrustum {
 public:
  explicit ViewFrustum(const CameraView& view);
  // Whether the world box [lo, hi] lies wholly outside (conservative: true means not seen).
  bool outside_box(const double lo[3], const double hi[3]) const;
  // Whether the sphere of radius r (m) about c (world frame) lies wholly outside one plane.
  bool outside_sphere(const float c[3], double r) const;
  // Whether the box [lo, hi] of a frame at `pos` turned by `mat` (3x3, row-major, its columns the
  // frame's axes in the world) lies wholly outside one plane.
  bool outside_oriented_box(const float pos[3], const float mat[9], const float lo[3], const float hi[3]) const;
  // Whether the points `v` (n of them, xyz, in a frame at `pos` turned by `mat`) all lie outside
  // one plane: then so does their convex hull, e.g. a mesh.
  bool outside_points(const float pos[3], const float mat[9], const float* v, int n) const;

 private:
  double planes_[6][4];
};

class TerrainLod {
 public:
  TerrainLod() = default;
  explicit TerrainLod(const mjModel* m);  // finds the model's tiles (none: empty())
  bool empty() const { return tiles_.empty(); }

  // The level to draw per tile (-1: culled); adds the tiles and cells drawn to `stats`.
  std::vector<int> choose(const CameraView& view, double pixels_per_cell, RenderStats& stats) const;
  // Whether tile geom `geom` is drawn under `levels` (from choose()).
  bool drawn(int geom, const std::vector<int>& levels) const {
    const Entry& e = by_geom_[static_cast<std::size_t>(geom)];
    return e.tile >= 0 && levels[static_cast<std::size_t>(e.tile)] == e.level;
  }

 private:
  struct Level {
    double cell = 0.0;  // m
    long cells = 0;
  };
  struct Tile {
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};  // world box (m)
    std::vector<Level> levels;
  };
  struct Entry {
    int tile = -1, level = -1;
  };
  std::vector<Tile> tiles_;
  std::vector<Entry> by_geom_;
};

}  // namespace mechsim::physics
