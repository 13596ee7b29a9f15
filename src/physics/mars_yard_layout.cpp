#include "physics/mars_yard_layout.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "physics/mars_yard_shapes.hpp"

namespace mechsim::physics::detail {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kTries = 400;  // placement attempts per feature before it is left out

double distance_to(const Channel& c, double x, double y) {
  return closest_on_polyline(c.centre, x, y).distance;
}

// Meandering polyline from a to b: `points` vertices, sideways sine of `amplitude` (m) and
// `waves` half-periods, damped near the start when `calm_start`.
std::vector<std::array<double, 2>> meander(std::mt19937_64& rng, std::array<double, 2> a,
                                           std::array<double, 2> b, int points, double amplitude,
                                           double waves, double jitter, bool calm_start) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double len = std::hypot(dx, dy);
  const double nx = -dy / len, ny = dx / len;
  const double phase = uniform(rng, 0.0, 2.0 * kPi);
  std::vector<std::array<double, 2>> line;
  for (int k = 0; k < points; ++k) {
    const double t = static_cast<double>(k) / (points - 1);
    double side = amplitude * std::sin(kPi * waves * t + phase) + uniform(rng, -jitter, jitter);
    if (calm_start) side *= smoothstep(4.0 * t);
    line.push_back({a[0] + t * dx + side * nx, a[1] + t * dy + side * ny});
  }
  return line;
}

}  // namespace

void lay_out_mars_yard(std::mt19937_64& rng, const MarsYardParams& p, MarsYard& yard) {
  const double hx = 0.5 * p.usable_x, hy = 0.5 * p.usable_y;
  yard.usable = Region{-hx, hx, -hy, hy};

  // Start pad near the west end, facing east along the yard.
  yard.start.x = -hx + 2.5;
  yard.start.y = uniform(rng, -0.12, 0.12) * p.usable_y;
  yard.start.radius = 1.5;
  yard.start.yaw = 0.0;

  // Canyon (the Valles Marineris theme): an east-west trough across the north half.
  Channel& canyon = yard.canyon;
  const double canyon_y = uniform(rng, 0.0, 0.08) * p.usable_y;
  canyon.centre = meander(rng, {-hx + 0.24 * p.usable_x, canyon_y}, {hx - 0.07 * p.usable_x, canyon_y},
                          9, 0.9, 2.6, 0.25, false);
  canyon.top_width = uniform(rng, 5.6, 6.2);
  canyon.floor_width = uniform(rng, 1.4, 1.8);
  canyon.depth = uniform(rng, 1.0, 1.3);

  // The plateau north of the canyon.
  yard.plateau.south_offset = 0.5 * canyon.floor_width;
  yard.plateau.ramp = 0.5 * (canyon.top_width - canyon.floor_width) + 2.0;
  yard.plateau.height = uniform(rng, 1.0, 1.3);

  // Dry river valley: leaves the canyon's south wall and runs off the south edge.
  Channel& river = yard.river;
  const double river_x = uniform(rng, -0.11, 0.03) * p.usable_x;
  const double river_start_y = polyline_y_at(canyon.centre, river_x);
  river.centre = meander(rng, {river_x, river_start_y},
                         {river_x + uniform(rng, -3.0, 3.0), -hy - 0.5 * p.margin}, 12,
                         uniform(rng, 1.2, 1.8), 3.0, 0.15, true);
  river.top_width = uniform(rng, 3.4, 3.8);
  river.floor_width = uniform(rng, 0.8, 1.0);
  river.depth = uniform(rng, 0.45, 0.55);

  const auto clear_of_channels = [&](double x, double y, double reach) {
    return distance_to(canyon, x, y) > 0.5 * canyon.top_width + reach &&
           distance_to(river, x, y) > 0.5 * river.top_width + reach;
  };
  const auto clear_of_start = [&](double x, double y, double reach) {
    return std::hypot(x - yard.start.x, y - yard.start.y) > yard.start.radius + 1.5 + reach;
  };

  // Dune field in the south-east.
  DuneField& dunes = yard.dunes;
  dunes.length = 8.0;
  dunes.width = 6.5;
  dunes.wavelength = uniform(rng, 2.0, 2.4);
  dunes.height = uniform(rng, 0.3, 0.4);
  dunes.wind_yaw = uniform(rng, -0.4, 0.4);
  const double dune_reach = 0.5 * std::hypot(dunes.length, dunes.width);
  for (int t = 0; t < kTries; ++t) {
    dunes.x = uniform(rng, 0.2, 0.5) * p.usable_x;
    dunes.y = uniform(rng, -0.36, -0.15) * p.usable_y;
    if (clear_of_channels(dunes.x, dunes.y, dune_reach - 0.5)) break;
  }

  // Volcanic mounds, flanks of 23-27 deg. The first, with a summit caldera, stands on the
  // plateau north of the canyon (the Tharsis side); the others where they fit.
  const double plateau_south = canyon_y + 0.5 * canyon.top_width + 1.0;
  for (int k = 0; k < p.mounds; ++k) {
    Mound m;
    m.radius = uniform(rng, 3.2, 4.0);
    m.height = m.radius * uniform(rng, 0.33, 0.38);
    double y_lo = -hy + m.radius, y_hi = hy - m.radius;
    if (k == 0) {
      m.radius = std::min(m.radius, 0.5 * (hy - plateau_south) + 0.5);
      m.height = m.radius * 0.36;
      m.caldera_radius = 0.3 * m.radius;
      m.caldera_depth = 0.3 * m.height;
      y_lo = plateau_south + m.radius - 1.0;
      y_hi = std::max(y_lo, hy - m.radius + 1.0);
    }
    for (int t = 0; t < kTries; ++t) {
      m.x = uniform(rng, -hx + m.radius, hx - m.radius);
      m.y = uniform(rng, y_lo, y_hi);
      bool ok = (k == 0 || clear_of_channels(m.x, m.y, m.radius - 0.8)) &&
                clear_of_start(m.x, m.y, m.radius) &&
                std::hypot(m.x - dunes.x, m.y - dunes.y) > dune_reach + m.radius - 2.0;
      for (const Mound& o : yard.mounds) ok = ok && std::hypot(m.x - o.x, m.y - o.y) > m.radius + o.radius;
      if (ok) {
        yard.mounds.push_back(m);
        break;
      }
    }
  }

  // Craters, largest first so that the small ones fill the gaps.
  std::vector<double> radii;
  for (int k = 0; k < p.craters; ++k) radii.push_back(uniform(rng, 0.6, 2.0));
  std::sort(radii.rbegin(), radii.rend());
  for (double radius : radii) {
    Crater c;
    c.radius = radius;
    c.depth = uniform(rng, 0.35, 0.45) * radius;
    c.rim_height = uniform(rng, 0.08, 0.12) * radius;
    // Aprons may overlap other landforms; bowls and rims keep clear of them.
    const double reach = 1.3 * radius;
    for (int t = 0; t < kTries; ++t) {
      c.x = uniform(rng, -hx + reach, hx - reach);
      c.y = uniform(rng, -hy + reach, hy - reach);
      bool ok = clear_of_channels(c.x, c.y, reach - 0.3) && clear_of_start(c.x, c.y, reach) &&
                std::hypot(c.x - dunes.x, c.y - dunes.y) > dune_reach + reach - 0.5;
      for (const Mound& m : yard.mounds) ok = ok && std::hypot(c.x - m.x, c.y - m.y) > m.radius + reach;
      for (const Crater& o : yard.craters) {
        ok = ok && std::hypot(c.x - o.x, c.y - o.y) > reach + 1.3 * o.radius;
      }
      if (ok) {
        yard.craters.push_back(c);
        break;
      }
    }
  }

  // Rocks of three sizes; large and medium ones keep apart, none on the start pad.
  struct Kind {
    int count;
    double min_length, max_length;
    RockSize size;
  };
  for (const Kind& kind : {Kind{p.large_rocks, 0.5, 0.9, RockSize::kLarge},
                           Kind{p.medium_rocks, 0.2, 0.45, RockSize::kMedium},
                           Kind{p.small_rocks, 0.08, 0.18, RockSize::kSmall}}) {
    for (int k = 0; k < kind.count; ++k) {
      Rock r;
      r.size = kind.size;
      r.length = uniform(rng, kind.min_length, kind.max_length);
      r.width = r.length * uniform(rng, 0.6, 0.9);
      r.height = r.width * uniform(rng, 0.4, 0.6);
      r.yaw = uniform(rng, 0.0, kPi);
      for (int t = 0; t < kTries; ++t) {
        r.x = uniform(rng, -hx + r.length, hx - r.length);
        r.y = uniform(rng, -hy + r.length, hy - r.length);
        bool ok = clear_of_start(r.x, r.y, 0.5 * r.length);
        if (kind.size != RockSize::kSmall) {
          for (const Rock& o : yard.rocks) {
            ok = ok && std::hypot(r.x - o.x, r.y - o.y) > 0.5 * (r.length + o.length) + 0.3;
          }
        }
        if (ok) {
          yard.rocks.push_back(r);
          break;
        }
      }
    }
  }
}

}  // namespace mechsim::physics::detail
