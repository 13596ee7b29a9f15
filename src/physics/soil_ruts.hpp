#pragma once
// Private to src/physics: the ruts wheels leave in soil (wheel_soil.cpp), for the multi-pass
// effect (terramechanics.hpp, rut_depth): a sparse grid over the ground, kRutCell square, holding
// per cell the deepest sinkage a wheel reached there, which wheel pressed it last, and how deep it
// was before that wheel came (so that a wheel is never in its own rut, but a wheel that follows
// another, or comes back over another's track, is). Cells are made as wheels first press them,
// up to kMaxRutCells (about 900 m of track for six 12 cm wheels); past that, new ground is
// virgin and the first reset() or set_soil() starts again.

#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace mechsim::physics::detail {

inline constexpr double kRutCell = 0.02;  // m
inline constexpr std::size_t kMaxRutCells = 2'000'000;

class RutMap {
 public:
  // The rut depth (m) `wheel` meets at (x, y), world frame: the cell's depth, or, if `wheel`
  // pressed it last, its depth before that wheel came. 0 on virgin ground.
  double depth(int wheel, double x, double y) const {
    if (!on_grid(x, y)) return 0.0;
    const auto it = cells_.find(key(x, y));
    if (it == cells_.end()) return 0.0;
    const Cell& c = it->second;
    return c.wheel == wheel ? c.before : c.depth;
  }
  // `wheel` sank `sinkage` (m) at (x, y).
  void press(int wheel, double x, double y, double sinkage) {
    if (!on_grid(x, y)) return;
    const std::uint64_t k = key(x, y);
    auto it = cells_.find(k);
    if (it == cells_.end()) {
      if (cells_.size() >= kMaxRutCells) return;
      it = cells_.emplace(k, Cell{}).first;
    }
    Cell& c = it->second;
    if (c.wheel != wheel) {
      c.before = c.depth;
      c.wheel = wheel;
    }
    if (sinkage > c.depth) c.depth = static_cast<float>(sinkage);
  }
  void clear() { cells_.clear(); }
  std::size_t size() const { return cells_.size(); }

 private:
  struct Cell {
    float depth = 0.0f, before = 0.0f;  // m
    int wheel = -1;
  };
  // Within 10,000 km of the origin (the cell index fits 32 bits); NaN is not.
  static bool on_grid(double x, double y) { return std::abs(x) < 1e7 && std::abs(y) < 1e7; }
  static std::uint64_t key(double x, double y) {
    const auto ix = static_cast<std::int32_t>(std::floor(x / kRutCell));
    const auto iy = static_cast<std::int32_t>(std::floor(y / kRutCell));
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(ix)) << 32) | static_cast<std::uint32_t>(iy);
  }
  std::unordered_map<std::uint64_t, Cell> cells_;
};

}  // namespace mechsim::physics::detail
