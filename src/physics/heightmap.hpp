#pragma once
// A terrain elevation grid: plain data shared by terrain loading/generation and the MuJoCo
// height field. Row-major, row 0 at y = -size_y/2 (south), column 0 at x = -size_x/2 (west).

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <utility>
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

// A heightmap that every copy of the world holding it shares, immutable: a world is copied into
// the simulation, its physics options and the compiled model's options, and each copy of the
// Mars Yard's 1.8 MB cost its start-up megabytes of page faults. Reads like an
// std::optional<Heightmap> (assign a Heightmap or an optional one; test, *, ->).
class SharedHeightmap {
 public:
  SharedHeightmap() = default;
  SharedHeightmap(std::nullopt_t) {}  // NOLINT: as std::optional
  SharedHeightmap(Heightmap map) : map_(std::make_shared<const Heightmap>(std::move(map))) {}  // NOLINT
  SharedHeightmap(std::optional<Heightmap> map) {  // NOLINT
    if (map) map_ = std::make_shared<const Heightmap>(std::move(*map));
  }
  explicit operator bool() const { return map_ != nullptr; }
  bool has_value() const { return map_ != nullptr; }
  const Heightmap& operator*() const { return *map_; }
  const Heightmap* operator->() const { return map_.get(); }
  const Heightmap& value() const {
    if (!map_) throw std::bad_optional_access();
    return *map_;
  }
  void reset() { map_.reset(); }

 private:
  std::shared_ptr<const Heightmap> map_;
};

}  // namespace mechsim::physics
