#pragma once
// A terrain elevation grid: plain data shared by terrain loading/generation and the MuJoCo
// height field. Row-major, row 0 at y = -size_y/2 (south), column 0 at x = -size_x/2 (west).

#include <cstddef>
#include <string>
#include <vector>

namespace mechsim::physics {

struct Heightmap {
  std::size_t rows = 0, cols = 0;  // samples along y and x (>= 2 each)
  double size_x = 0.0, size_y = 0.0;  // footprint (m), centred on the world origin
  std::vector<float> heights;         // rows*cols elevations (m), absolute
  std::string source;                 // file or generator that made it

  float at(std::size_t row, std::size_t col) const { return heights[row * cols + col]; }
  double cell_x() const { return size_x / static_cast<double>(cols - 1); }  // sample spacing (m)
  double cell_y() const { return size_y / static_cast<double>(rows - 1); }
};

}  // namespace mechsim::physics
