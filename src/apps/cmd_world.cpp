// `mechsim world`: look at a world's terrain.
//   mechsim world stats WORLD [--seed N] [--size-x M --size-y M] [--z-min M --z-max M]
//   mechsim world export WORLD -o FILE.png|FILE.tif [same options]
//   mechsim world features WORLD [--seed N]
//   mechsim world soils
// WORLD is `empty`, `mars_yard_2024`, `slope` or a heightmap image (PNG or TIFF).

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <numbers>
#include <string>

#include "apps/commands.hpp"
#include "physics/heightmap_io.hpp"
#include "physics/soil.hpp"
#include "physics/terrain_world.hpp"

namespace mechsim::apps {
namespace {

namespace ph = mechsim::physics;

struct WorldArgs {
  std::string world;
  std::optional<std::uint64_t> seed;
  std::optional<double> size_x, size_y, z_min, z_max;
  std::string output;
};

void add_world_options(CLI::App* cmd, WorldArgs& args) {
  cmd->add_option("WORLD", args.world, "empty, mars_yard_2024, slope, or a heightmap file (PNG/TIFF)")->required();
  cmd->add_option("--seed", args.seed, "mars_yard_2024: generator seed (default 2024)");
  cmd->add_option("--size-x", args.size_x, "heightmap file: footprint along x (m)");
  cmd->add_option("--size-y", args.size_y, "heightmap file: footprint along y (m)");
  cmd->add_option("--z-min", args.z_min, "integer heightmap: height of the lowest sample value (m)");
  cmd->add_option("--z-max", args.z_max, "integer heightmap: height of the highest sample value (m)");
}

struct Loaded {
  ph::WorldTerrain terrain;
  double seconds = 0.0;  // time to load or generate
};

Loaded load(const WorldArgs& args) {
  ph::WorldTerrainOptions options;
  options.seed = args.seed;
  options.heightmap.size_x = args.size_x;
  options.heightmap.size_y = args.size_y;
  options.heightmap.z_min = args.z_min;
  options.heightmap.z_max = args.z_max;
  const auto t0 = std::chrono::steady_clock::now();
  Loaded loaded{ph::load_world_terrain(args.world, options), 0.0};
  loaded.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return loaded;
}

std::string fmt(const char* format, double a, double b = 0.0, double c = 0.0, double d = 0.0) {
  char text[256];
  std::snprintf(text, sizeof text, format, a, b, c, d);
  return text;
}

std::string describe(const ph::WorldTerrain& terrain, const WorldArgs& args) {
  if (terrain.yard) {
    return terrain.name + " (seed " + std::to_string(args.seed.value_or(ph::kMarsYardDefaultSeed)) + ")";
  }
  return terrain.name;
}

void print_stats(const Loaded& loaded, const WorldArgs& args) {
  const ph::WorldTerrain& terrain = loaded.terrain;
  std::cout << "world        " << describe(terrain, args) << "\n";
  if (!terrain.heightmap) {
    std::cout << "terrain      flat ground plane at z = 0 m, unbounded; no heightmap (all slopes 0 deg)\n";
    return;
  }
  const ph::Heightmap& map = *terrain.heightmap;
  const ph::TerrainStats s = ph::compute_terrain_stats(map, terrain.usable);
  std::cout << "grid         " << map.cols << " x " << map.rows << " samples, "
            << fmt("%.4g m x %.4g m spacing", s.cell_x, s.cell_y) << "\n";
  std::cout << "footprint    " << fmt("%.2f m x %.2f m = %.1f m^2, centred on the origin", s.size_x, s.size_y, s.size_x * s.size_y) << "\n";
  if (terrain.usable) {
    const ph::Region& u = *terrain.usable;
    std::cout << "usable area  " << fmt("%.2f m x %.2f m = %.1f m^2 inside the margin", u.x_max - u.x_min, u.y_max - u.y_min, s.usable_area)
              << " (statistics below are over it)\n";
  } else {
    std::cout << "usable area  " << fmt("%.1f m^2 (the whole footprint)", s.usable_area) << "\n";
  }
  std::cout << "heights      " << fmt("min %.3f m, max %.3f m, relief %.3f m, mean %.3f m", s.z_min, s.z_max, s.relief, s.z_mean) << "\n";
  std::cout << "slope        " << fmt("median %.1f deg, 90th percentile %.1f deg, 95th percentile %.1f deg", s.slope_median_deg, s.slope_p90_deg, s.slope_p95_deg)
            << fmt(", mean %.1f deg, max %.1f deg", s.slope_mean_deg, s.slope_max_deg) << "\n";
  std::cout << "steep        " << fmt("%.1f %% of the area steeper than %.0f deg", 100.0 * s.steep_share, s.steep_threshold_deg) << "\n";
  std::cout << "             (slopes per grid sample from central differences over " << s.samples << " interior samples)\n";
  if (terrain.yard) {
    const ph::MarsYard& y = *terrain.yard;
    int sizes[3] = {0, 0, 0};
    for (const ph::Rock& r : y.rocks) ++sizes[static_cast<int>(r.size)];
    std::cout << "features     canyon, dry river valley, dune field, " << y.craters.size() << " craters, "
              << y.mounds.size() << " volcanic mounds, " << y.rocks.size() << " rocks (" << sizes[2] << " large, "
              << sizes[1] << " medium, " << sizes[0] << " small)\n";
    std::cout << "start        " << fmt("x %.2f m, y %.2f m, z %.3f m, level within %.1f m", y.start.x, y.start.y, y.start.z, y.start.radius)
              << fmt(", heading %.0f deg", y.start.yaw * 180.0 / std::numbers::pi) << "\n";
    std::cout << "generated in " << fmt("%.0f ms", loaded.seconds * 1e3) << "\n";
  } else {
    std::cout << "loaded from  " << map.source << fmt(" in %.0f ms", loaded.seconds * 1e3) << "\n";
  }
}

void print_features(const ph::MarsYard& y) {
  std::cout << "# kind x_m y_m size_m height_m extra  (frame: world, origin at the footprint centre)\n";
  std::cout << "start " << fmt("%.3f %.3f %.3f %.3f", y.start.x, y.start.y, 2.0 * y.start.radius, y.start.z)
            << " radius_m=" << fmt("%.2f", y.start.radius) << " yaw_rad=" << fmt("%.3f", y.start.yaw) << "\n";
  auto channel = [](const char* kind, const ph::Channel& c) {
    std::cout << kind << " " << fmt("%.3f %.3f %.3f %.3f", c.centre.front()[0], c.centre.front()[1], c.top_width, -c.depth)
              << " floor_width_m=" << fmt("%.2f", c.floor_width) << " centre_line=";
    for (std::size_t k = 0; k < c.centre.size(); ++k) {
      std::cout << (k ? ";" : "") << fmt("%.2f,%.2f", c.centre[k][0], c.centre[k][1]);
    }
    std::cout << "\n";
  };
  channel("canyon", y.canyon);
  channel("river", y.river);
  std::cout << "plateau - - - " << fmt("%.3f", y.plateau.height) << " ramp_m=" << fmt("%.2f", y.plateau.ramp)
            << " north_of_canyon\n";
  const ph::DuneField& d = y.dunes;
  std::cout << "dunes " << fmt("%.3f %.3f %.3f %.3f", d.x, d.y, d.length, d.height) << " width_m=" << fmt("%.2f", d.width)
            << " wind_yaw_rad=" << fmt("%.3f", d.wind_yaw) << " wavelength_m=" << fmt("%.2f", d.wavelength) << "\n";
  for (const ph::Crater& c : y.craters) {
    std::cout << "crater " << fmt("%.3f %.3f %.3f %.3f", c.x, c.y, 2.0 * c.radius, -c.depth)
              << " rim_height_m=" << fmt("%.3f", c.rim_height) << "\n";
  }
  for (const ph::Mound& m : y.mounds) {
    std::cout << "mound " << fmt("%.3f %.3f %.3f %.3f", m.x, m.y, 2.0 * m.radius, m.height)
              << " caldera_radius_m=" << fmt("%.2f", m.caldera_radius) << "\n";
  }
  static const char* kSize[3] = {"small", "medium", "large"};
  for (const ph::Rock& r : y.rocks) {
    std::cout << "rock " << fmt("%.3f %.3f %.3f %.3f", r.x, r.y, r.length, r.height) << " width_m="
              << fmt("%.3f", r.width) << " yaw_rad=" << fmt("%.3f", r.yaw) << " class=" << kSize[static_cast<int>(r.size)] << "\n";
  }
}

void export_world(const Loaded& loaded, const WorldArgs& args) {
  const ph::WorldTerrain& terrain = loaded.terrain;
  if (!terrain.heightmap) {
    throw UserError("world '" + terrain.name + "' has no heightmap to export (flat ground plane)");
  }
  const std::filesystem::path out(args.output);
  std::string ext = out.extension().string();
  for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  const ph::Heightmap& map = *terrain.heightmap;
  if (ext == ".png") {
    const ph::HeightRange range = ph::save_heightmap_png(map, out);
    std::cout << "wrote " << out.string() << ": " << map.cols << " x " << map.rows
              << " 16-bit grayscale PNG, footprint " << fmt("%.3f m x %.3f m", map.size_x, map.size_y)
              << fmt(", 0 = %.4f m, 65535 = %.4f m (%.3f mm per step)", range.z_min, range.z_max,
                     (range.z_max - range.z_min) / 65535.0 * 1e3)
              << "\n";
  } else if (ext == ".tif" || ext == ".tiff") {
    ph::save_heightmap_tiff(map, out);
    std::cout << "wrote " << out.string() << ": " << map.cols << " x " << map.rows
              << " 32-bit float TIFF of heights (m), footprint " << fmt("%.3f m x %.3f m", map.size_x, map.size_y)
              << " in GeoTIFF pixel scale tags\n";
  } else {
    throw UserError("output '" + out.string() + "': unknown image type; use .png (16-bit) or .tif (float)");
  }
}

}  // namespace

void add_world_command(CLI::App& app, CommandResult& /*result*/) {
  CLI::App* world = app.add_subcommand("world", "Terrain of a world: statistics, export, features");
  world->require_subcommand(1);
  auto args = std::make_shared<WorldArgs>();

  CLI::App* stats = world->add_subcommand("stats", "Print size, relief and slope statistics of a world's terrain");
  add_world_options(stats, *args);
  stats->callback([args] { print_stats(load(*args), *args); });

  CLI::App* exp = world->add_subcommand("export", "Write a world's heightmap as a 16-bit PNG or a float TIFF");
  add_world_options(exp, *args);
  exp->add_option("-o,--output", args->output, "output image: FILE.png or FILE.tif")->required();
  exp->callback([args] { export_world(load(*args), *args); });

  CLI::App* features = world->add_subcommand("features", "List a generated world's features (one per line)");
  add_world_options(features, *args);
  features->callback([args] {
    const Loaded loaded = load(*args);
    if (!loaded.terrain.yard) {
      throw UserError("world '" + args->world + "' has no feature list (only mars_yard_2024 has)");
    }
    print_features(*loaded.terrain.yard);
  });

  CLI::App* soils = world->add_subcommand("soils", "List the named soils a world can have (world.soil) and their sources");
  soils->callback([] {
    std::printf("# name n k_c(N/m^(n+1)) k_phi(N/m^(n+2)) c(Pa) phi(deg) K(m)  source\n");
    for (const ph::SoilParameters& s : ph::named_soils()) {
      std::printf("%-15s %5.2f %10.4g %12.6g %7.4g %5.1f %7.4g  %s\n", s.name.c_str(), s.n, s.k_c, s.k_phi, s.cohesion,
                  s.friction_angle * 180.0 / std::numbers::pi, s.shear_modulus, s.source.c_str());
    }
  });
}

}  // namespace mechsim::apps
