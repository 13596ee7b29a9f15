#include "physics/mars_yard.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "physics/heightmap_sample.hpp"
#include "physics/mars_yard_layout.hpp"
#include "physics/mars_yard_shapes.hpp"

namespace mechsim::physics {
namespace {

using detail::smoothstep;

// The terrain as separately scalable layers, each rows*cols like Heightmap::heights:
//   z = (1 - flatten) * (roughness_scale * noise + landform_scale * landforms + fixed) + base.
// `fixed` holds what keeps its size (rocks, mounds); `base` is the plateau, levelled under the
// start pad and continued into the margin so that the margin has no cliff.
struct Layers {
  std::vector<float> noise, landforms, fixed, flatten, base;
};

struct GridBox {
  std::size_t r0, r1, c0, c1;  // inclusive sample ranges
};

// Samples covering the world rectangle [x_lo, x_hi] x [y_lo, y_hi] (m), clipped to the grid.
GridBox box_around(const Heightmap& map, double x_lo, double x_hi, double y_lo, double y_hi) {
  auto col = [&](double x) {
    return std::clamp((x + 0.5 * map.size_x) / map.cell_x(), 0.0, static_cast<double>(map.cols - 1));
  };
  auto row = [&](double y) {
    return std::clamp((y + 0.5 * map.size_y) / map.cell_y(), 0.0, static_cast<double>(map.rows - 1));
  };
  return {static_cast<std::size_t>(std::floor(row(y_lo))), static_cast<std::size_t>(std::ceil(row(y_hi))),
          static_cast<std::size_t>(std::floor(col(x_lo))), static_cast<std::size_t>(std::ceil(col(x_hi)))};
}

template <typename F>
void for_box(const Heightmap& map, const GridBox& b, F&& f) {
  for (std::size_t r = b.r0; r <= b.r1; ++r) {
    const double y = sample_y(map, r);
    for (std::size_t c = b.c0; c <= b.c1; ++c) f(r * map.cols + c, sample_x(map, c), y);
  }
}

void add_channel(const Heightmap& map, const Channel& ch, double taper_start, double taper_end,
                 std::vector<float>& carve) {
  double x_lo = INFINITY, x_hi = -INFINITY, y_lo = INFINITY, y_hi = -INFINITY;
  for (const auto& p : ch.centre) {
    x_lo = std::min(x_lo, p[0]);
    x_hi = std::max(x_hi, p[0]);
    y_lo = std::min(y_lo, p[1]);
    y_hi = std::max(y_hi, p[1]);
  }
  const double h = 0.5 * ch.top_width;
  const double length = detail::polyline_length(ch.centre);
  const detail::PolylineNearest nearest(ch.centre);
  for_box(map, box_around(map, x_lo - h, x_hi + h, y_lo - h, y_hi + h), [&](std::size_t i, double x, double y) {
    const auto hit = nearest(x, y);
    const auto z = static_cast<float>(detail::channel_profile(ch, hit.distance, hit.arc, length,
                                                              taper_start, taper_end));
    carve[i] = std::min(carve[i], z);  // where troughs meet, the deeper one wins
  });
}

Layers rasterise(std::mt19937_64& rng, const MarsYardParams& p, const MarsYard& yard,
                 const Heightmap& map) {
  const std::size_t n = map.rows * map.cols;
  // Five layers of 0.44 M floats: every buffer more is 1.8 MB of zeroing and page faults, which
  // dominated the yard's generation (the carving and the rocks borrow layers, below; the noise
  // and the base are appended in sample order, not zeroed first).
  Layers layers{{}, std::vector<float>(n, 0.0f), std::vector<float>(n, 0.0f), std::vector<float>(n, 0.0f), {}};
  layers.noise.reserve(n);
  layers.base.reserve(n);
  // Ground roughness: fractal noise from 6 m undulations down to 0.2 m grain, row by row (the
  // same values as noise(x, y) sample by sample, a third of the time).
  const detail::FractalNoise noise(rng, 6.4, 0.2, 0.8, map.size_x, map.size_y);
  std::vector<double> xs(map.cols), row(map.cols);
  for (std::size_t c = 0; c < map.cols; ++c) xs[c] = sample_x(map, c);
  const detail::FractalNoise::Columns columns = noise.columns(xs);
  for (std::size_t r = 0; r < map.rows; ++r) {
    noise.row(columns, sample_y(map, r), row);
    for (std::size_t c = 0; c < map.cols; ++c) layers.noise.push_back(static_cast<float>(0.1 * row[c]));
  }

  const Plateau& plateau = yard.plateau;
  auto plateau_at = [&](double x, double y) {
    const double south_edge = detail::polyline_y_at(yard.canyon.centre, x) + plateau.south_offset;
    return plateau.height * smoothstep((y - south_edge) / plateau.ramp);
  };
  std::vector<double> south_edge(map.cols);  // plateau_at's south edge, per column
  for (std::size_t c = 0; c < map.cols; ++c)
    south_edge[c] = detail::polyline_y_at(yard.canyon.centre, xs[c]) + plateau.south_offset;
  const double pad_level = plateau_at(yard.start.x, yard.start.y);
  // The troughs carve the landforms layer while it is still all zero: 0 + carve is carve.
  add_channel(map, yard.canyon, 3.0, 3.0, layers.landforms);
  add_channel(map, yard.river, 0.0, 0.0, layers.landforms);
  const DuneField& d = yard.dunes;
  const double dune_reach = 0.5 * std::hypot(d.length, d.width);
  for_box(map, box_around(map, d.x - dune_reach, d.x + dune_reach, d.y - dune_reach, d.y + dune_reach),
          [&](std::size_t i, double x, double y) {
            layers.landforms[i] += static_cast<float>(detail::dune_profile(d, x, y));
          });
  for (const Crater& c : yard.craters) {
    const double reach = detail::crater_reach(c);
    for_box(map, box_around(map, c.x - reach, c.x + reach, c.y - reach, c.y + reach),
            [&](std::size_t i, double x, double y) {
              layers.landforms[i] += static_cast<float>(detail::crater_profile(c, std::hypot(x - c.x, y - c.y)));
            });
  }
  for (const Mound& m : yard.mounds) {
    for_box(map, box_around(map, m.x - m.radius, m.x + m.radius, m.y - m.radius, m.y + m.radius),
            [&](std::size_t i, double x, double y) {
              layers.fixed[i] += static_cast<float>(detail::mound_profile(m, std::hypot(x - m.x, y - m.y)));
            });
  }
  // The rocks gather in the flatten layer, still all zero and written only below.
  std::vector<float>& rocks = layers.flatten;
  for (const Rock& rock : yard.rocks) {
    const double reach = 0.5 * rock.length;
    for_box(map, box_around(map, rock.x - reach, rock.x + reach, rock.y - reach, rock.y + reach),
            [&](std::size_t i, double x, double y) {
              // Touching rocks stack rather than add up into a tower.
              rocks[i] = std::max(rocks[i], static_cast<float>(detail::rock_profile(rock, x, y)));
            });
  }

  for (std::size_t i = 0; i < n; ++i) layers.fixed[i] += rocks[i];

  // Flattening: the margin levels out to the base height, the start pad is level.
  const Region& u = yard.usable;
  const double pad_reach = yard.start.radius + 1.0;  // beyond it the pad's smoothstep is 1: pad 0
  for_box(map, {0, map.rows - 1, 0, map.cols - 1}, [&](std::size_t i, double x, double y) {
    const double plateau_here = plateau.height * smoothstep((y - south_edge[i % map.cols]) / plateau.ramp);
    const double ox = std::max({0.0, u.x_min - x, x - u.x_max}), oy = std::max({0.0, u.y_min - y, y - u.y_max});
    const double out = ox == 0.0 && oy == 0.0 ? 0.0 : std::hypot(ox, oy);
    const double margin = smoothstep(out / (0.7 * p.margin));
    const double dx = x - yard.start.x, dy = y - yard.start.y;
    const double pad = std::abs(dx) > pad_reach || std::abs(dy) > pad_reach
                           ? 0.0
                           : 1.0 - smoothstep((std::hypot(dx, dy) - yard.start.radius) / 1.0);
    layers.flatten[i] = static_cast<float>(std::max(margin, pad));
    layers.base.push_back(static_cast<float>(plateau_here + pad * (pad_level - plateau_here)));  // the i-th
  });
  return layers;
}

// Writes the heights afresh into `z` (appended to an emptied buffer, which is not zeroed first).
void compose(const Layers& layers, double roughness, double landform, std::vector<float>& z) {
  z.clear();
  for (std::size_t i = 0; i < layers.noise.size(); ++i) {
    z.push_back((1.0f - layers.flatten[i]) *
                    static_cast<float>(roughness * layers.noise[i] + landform * layers.landforms[i] + layers.fixed[i]) +
                layers.base[i]);
  }
}

// Median slope (deg) and steep share over the usable ground, as compute_terrain_stats takes
// them, without building the full statistics (this runs once per calibration step).
struct SlopeProbe {
  GridBox box;
  std::vector<float> g2;  // squared gradient magnitudes, reused

  std::pair<double, double> operator()(const Heightmap& map) {
    g2.clear();
    g2.reserve((box.r1 - box.r0 + 1) * (box.c1 - box.c0 + 1));
    const double hx = 2.0 * map.cell_x(), hy = 2.0 * map.cell_y();
    const double steep2 = std::pow(std::tan(30.0 * std::numbers::pi / 180.0), 2);
    std::size_t steep = 0;
    for (std::size_t r = box.r0; r <= box.r1; ++r) {
      for (std::size_t c = box.c0; c <= box.c1; ++c) {
        const double gx = (map.at(r, c + 1) - map.at(r, c - 1)) / hx;
        const double gy = (map.at(r + 1, c) - map.at(r - 1, c)) / hy;
        const double s = gx * gx + gy * gy;
        steep += s > steep2 ? 1 : 0;
        g2.push_back(static_cast<float>(s));
      }
    }
    const double median = std::atan(std::sqrt(quantile(g2, 0.5))) * 180.0 / std::numbers::pi;
    return {median, static_cast<double>(steep) / static_cast<double>(g2.size())};
  }
};

void check(const MarsYardParams& p) {
  auto bad = [](const std::string& what) { throw std::invalid_argument("mars_yard_2024: " + what); };
  if (!(p.usable_x >= 5.0 && p.usable_y >= 5.0)) bad("usable_x and usable_y must be >= 5 m");
  if (!(p.margin >= 0.5)) bad("margin must be >= 0.5 m");
  if (!(p.cell > 0.0 && p.cell <= 0.5)) bad("cell must be in (0, 0.5] m");
  if ((p.usable_x + 2 * p.margin) * (p.usable_y + 2 * p.margin) / (p.cell * p.cell) > 5e7) {
    bad("grid of more than 5e7 samples");
  }
  if (p.craters < 0 || p.mounds < 0 || p.large_rocks < 0 || p.medium_rocks < 0 || p.small_rocks < 0) {
    bad("feature counts must be >= 0");
  }
  if (!(p.target_median_deg > 1.0 && p.target_median_deg < 40.0)) bad("target_median_deg must be in (1, 40)");
  if (!(p.target_steep_share >= 0.0 && p.target_steep_share < 0.5)) bad("target_steep_share must be in [0, 0.5)");
}

}  // namespace

MarsYard generate_mars_yard(std::mt19937_64& rng, const MarsYardParams& p) {
  check(p);
  MarsYard yard;
  detail::lay_out_mars_yard(rng, p, yard);

  Heightmap& map = yard.heightmap;
  map.cols = static_cast<std::size_t>(std::round((p.usable_x + 2.0 * p.margin) / p.cell)) + 1;
  map.rows = static_cast<std::size_t>(std::round((p.usable_y + 2.0 * p.margin) / p.cell)) + 1;
  map.size_x = static_cast<double>(map.cols - 1) * p.cell;
  map.size_y = static_cast<double>(map.rows - 1) * p.cell;
  map.heights.reserve(map.rows * map.cols);  // compose() writes them
  map.source = "mars_yard_2024";
  const Layers layers = rasterise(rng, p, yard, map);

  // Calibration: the median slope follows the roughness amplitude and the steep share the
  // landform scale, each roughly in proportion; alternate multiplicative corrections until
  // both sit within a small tolerance of their targets (or the step budget runs out).
  SlopeProbe probe{box_around(map, yard.usable.x_min, yard.usable.x_max, yard.usable.y_min, yard.usable.y_max), {}};
  probe.box.r0 = std::max<std::size_t>(probe.box.r0, 1);
  probe.box.c0 = std::max<std::size_t>(probe.box.c0, 1);
  probe.box.r1 = std::min(probe.box.r1, map.rows - 2);
  probe.box.c1 = std::min(probe.box.c1, map.cols - 2);
  const double target_tan = std::tan(p.target_median_deg * std::numbers::pi / 180.0);
  double roughness = 1.0, landform = 1.0;
  bool converged = false;
  for (int step = 0; step < 40; ++step) {
    compose(layers, roughness, landform, map.heights);
    const auto [median, steep] = probe(map);
    const bool median_ok = std::abs(median - p.target_median_deg) < 0.1;
    const bool steep_ok = std::abs(steep - p.target_steep_share) < 0.004;
    converged = median_ok && steep_ok;
    if (converged) break;
    const double median_tan = std::tan(median * std::numbers::pi / 180.0);
    roughness = std::clamp(roughness * target_tan / std::max(median_tan, 1e-3), 0.05, 20.0);
    if (p.target_steep_share > 0.0) {
      const double ratio = p.target_steep_share / std::max(steep, 1e-3);
      landform = std::clamp(landform * std::clamp(std::sqrt(ratio), 0.8, 1.25), 0.4, 2.5);
    }
  }
  if (!converged) compose(layers, roughness, landform, map.heights);  // the heights match the factors kept
  yard.roughness_scale = roughness;
  yard.landform_scale = landform;

  // Lowest point at 0; landform sizes as built.
  const float lowest = *std::min_element(map.heights.begin(), map.heights.end());
  for (float& z : map.heights) z -= lowest;
  yard.start.z = height_at(map, yard.start.x, yard.start.y);
  yard.canyon.depth *= landform;
  yard.river.depth *= landform;
  yard.dunes.height *= landform;
  for (Crater& c : yard.craters) {
    c.depth *= landform;
    c.rim_height *= landform;
  }
  return yard;
}

MarsYard generate_mars_yard(std::uint64_t seed, const MarsYardParams& params) {
  std::mt19937_64 rng(seed);
  MarsYard yard = generate_mars_yard(rng, params);
  yard.heightmap.source = "mars_yard_2024 seed " + std::to_string(seed);
  return yard;
}

}  // namespace mechsim::physics
