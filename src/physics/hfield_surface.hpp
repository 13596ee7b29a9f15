#pragma once
// Private to src/physics: the surface of a height field as MuJoCo defines it (ray_cast.hpp,
// HfieldGrid: two flat triangles per cell split along the (c, r)-(c + 1, r + 1) diagonal), looked
// up at a point: height, the triangle's normal and which triangle. What the wheel-terrain contact
// and the wheel-soil model read under each wheel. Frame: the height field's own (origin at the
// centre of its footprint, z up); lengths in m. Allocation-free, for the step.

#include <cmath>

#include "physics/ray_cast.hpp"

namespace mechsim::physics::detail {

struct SurfacePoint {
  double height = 0.0;              // z of the surface at (x, y) (m)
  double normal[3] = {0.0, 0.0, 1.0};  // unit, pointing out of the solid (up)
  long triangle = -1;               // 2 (r (cols - 1) + c) + (lower ? 1 : 0): equal iff same triangle
};

// A height field's grid with its spacing, for repeated look-ups.
struct HfieldSurface {
  HfieldGrid g;
  double dx = 0.0, dy = 0.0, inv_dx = 0.0, inv_dy = 0.0;  // sample spacing (m) and its inverse
  explicit HfieldSurface(const HfieldGrid& grid)
      : g(grid), dx(2.0 * grid.half_x / (grid.cols - 1)), dy(2.0 * grid.half_y / (grid.rows - 1)),
        inv_dx(1.0 / dx), inv_dy(1.0 / dy) {}

  // The cell under (x, y) and the corner heights: false outside the footprint (no ground there:
  // MuJoCo's height field has walls at its edges and nothing beyond).
  struct Cell {
    double u, w;               // position in the cell, [0, 1]
    double h00, h10, h01, h11;  // corner heights (m): (c, r), (c + 1, r), (c, r + 1), (c + 1, r + 1)
    long index;                // r (cols - 1) + c
  };
  bool cell(double x, double y, Cell& out) const {
    const double uf = (x + g.half_x) * inv_dx, wf = (y + g.half_y) * inv_dy;
    if (!(uf >= 0.0 && wf >= 0.0 && uf <= g.cols - 1 && wf <= g.rows - 1)) return false;
    int c = static_cast<int>(uf), r = static_cast<int>(wf);
    if (c > g.cols - 2) c = g.cols - 2;
    if (r > g.rows - 2) r = g.rows - 2;
    out.u = uf - c;
    out.w = wf - r;
    const float* row0 = g.data + static_cast<long>(r) * g.cols + c;
    const float* row1 = row0 + g.cols;
    out.h00 = row0[0] * g.top;
    out.h10 = row0[1] * g.top;
    out.h01 = row1[0] * g.top;
    out.h11 = row1[1] * g.top;
    out.index = static_cast<long>(r) * (g.cols - 1) + c;
    return true;
  }

  // Surface height at (x, y); false outside the footprint.
  bool height(double x, double y, double& h) const {
    Cell k;
    if (!cell(x, y, k)) return false;
    h = k.u >= k.w ? k.h00 + k.u * (k.h10 - k.h00) + k.w * (k.h11 - k.h10)
                   : k.h00 + k.w * (k.h01 - k.h00) + k.u * (k.h11 - k.h01);
    return true;
  }

  // Height, normal and triangle at (x, y); false outside the footprint.
  bool at(double x, double y, SurfacePoint& out) const {
    Cell k;
    if (!cell(x, y, k)) return false;
    const bool lower = k.u >= k.w;  // the triangle (c, r), (c + 1, r + 1), (c + 1, r)
    double sx, sy;                  // surface slopes dz/dx, dz/dy
    if (lower) {
      sx = (k.h10 - k.h00) * inv_dx;
      sy = (k.h11 - k.h10) * inv_dy;
      out.height = k.h00 + k.u * (k.h10 - k.h00) + k.w * (k.h11 - k.h10);
    } else {
      sx = (k.h11 - k.h01) * inv_dx;
      sy = (k.h01 - k.h00) * inv_dy;
      out.height = k.h00 + k.w * (k.h01 - k.h00) + k.u * (k.h11 - k.h01);
    }
    const double inv = 1.0 / std::sqrt(1.0 + sx * sx + sy * sy);
    out.normal[0] = -sx * inv;
    out.normal[1] = -sy * inv;
    out.normal[2] = inv;
    out.triangle = 2 * k.index + (lower ? 1 : 0);
    return true;
  }
};

}  // namespace mechsim::physics::detail
