// Camera rendering on the CPU (EGL surfaceless + Mesa llvmpipe, no GPU): frames per second of the
// CC8's ZED2 left camera on the Mars Yard (rover on its start pad), 640x480 and 1280x720, colour
// alone and colour + depth from one render; the terrain from render tiles at the detail the view
// needs (default), or the collision height field itself (0.44 M samples); and the ZED2's set at
// one instant (left colour + depth, right colour, one shared scene update). Reported, not asserted.
// `cpu_ms` is the whole process's CPU time per frame (llvmpipe rasterises on its own threads): on a
// busy machine wall-clock rates fall with the share of the cores the program gets, CPU time less.
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <memory>

#include "description/urdf/urdf_parser.hpp"
#include "physics/heightmap_sample.hpp"
#include "physics/mars_yard.hpp"
#include "physics/physics.hpp"
#include "physics/renderer.hpp"

namespace mechsim::physics {
namespace {

const std::string kShared = MECHSIM_SHARED_DIR;

double process_cpu_s() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

struct Setup {
  std::shared_ptr<const PhysicsModel> model;
  std::unique_ptr<Physics> physics;
  std::size_t left = 0, right = 0;  // optical frame links
};

// One model per terrain choice, built and settled once per program run.
Setup& setup(bool tiles) {
  static std::map<bool, Setup> cache;
  auto it = cache.find(tiles);
  if (it != cache.end()) return it->second;
  description::UrdfOptions o;
  o.lenient = true;
  o.packages["cc8_description"] = kShared + "/robots/cc8_description";
  const MarsYard yard = generate_mars_yard(kMarsYardDefaultSeed);
  BuildOptions b;
  b.world.kind = WorldSpec::Kind::Heightmap;
  b.world.terrain = yard.heightmap;
  b.render_terrain = tiles;
  b.spawn.x = yard.start.x;
  b.spawn.y = yard.start.y;
  b.spawn.z = height_at(yard.heightmap, yard.start.x, yard.start.y) + 0.25;
  b.spawn.yaw = yard.start.yaw;
  Setup s;
  s.model = PhysicsModel::build(description::parse_urdf_file(kShared + "/robots/reference/cc8.urdf", o), b);
  s.physics = std::make_unique<Physics>(s.model);
  for (int i = 0; i < 1500; ++i) s.physics->step();
  s.left = *s.model->link_index("zed2_left_camera_optical_frame");
  s.right = *s.model->link_index("zed2_right_camera_optical_frame");
  return cache.emplace(tiles, std::move(s)).first->second;
}

// The ZED2's camera: horizontal FOV 1.7633 rad, clip 0.02-300 m.
CameraView zed2(const Physics& p, std::size_t link, int w, int h) {
  CameraView v;
  v.X_WC = p.link_pose(link);
  v.width = w;
  v.height = h;
  v.fx = v.fy = w / (2.0 * std::tan(1.7633 / 2));
  v.cx = (w - 1) / 2.0;
  v.cy = (h - 1) / 2.0;
  v.near = 0.02;
  v.far = 300.0;
  return v;
}

void render_fps(benchmark::State& state, int w, int h, bool depth, bool tiles) {
  if (!std::filesystem::is_directory(kShared + "/robots/reference")) {
    state.SkipWithError("shared data folder absent");
    return;
  }
  Setup& s = setup(tiles);
  RenderSettings rs;
  rs.max_width = w;
  rs.max_height = h;
  Renderer r(s.model, rs);
  r.update_scene(*s.physics);
  const CameraView v = zed2(*s.physics, s.left, w, h);
  Frame f;
  RenderStats st = r.render(v, f, true, depth);  // the first render compiles llvmpipe's shaders
  const double cpu0 = process_cpu_s();
  for (auto _ : state) {
    r.update_scene(*s.physics);
    st = r.render(v, f, true, depth);
    benchmark::DoNotOptimize(f.rgb.data());
  }
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["cpu_ms"] = 1e3 * (process_cpu_s() - cpu0) / static_cast<double>(state.iterations());
  state.counters["tiles"] = st.terrain_tiles;
  state.counters["cells"] = static_cast<double>(st.terrain_cells);
}

// The ZED2 at one instant: left colour + depth, right colour, one scene update.
void zed2_set(benchmark::State& state, int w, int h, bool tiles) {
  if (!std::filesystem::is_directory(kShared + "/robots/reference")) {
    state.SkipWithError("shared data folder absent");
    return;
  }
  Setup& s = setup(tiles);
  RenderSettings rs;
  rs.max_width = w;
  rs.max_height = h;
  Renderer r(s.model, rs);
  Frame left, right;
  r.update_scene(*s.physics);
  r.render(zed2(*s.physics, s.left, w, h), left);
  const double cpu0 = process_cpu_s();
  for (auto _ : state) {
    r.update_scene(*s.physics);
    r.render(zed2(*s.physics, s.left, w, h), left, true, true);
    r.render(zed2(*s.physics, s.right, w, h), right, true, false);
    benchmark::DoNotOptimize(right.rgb.data());
  }
  state.counters["sets_per_s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["cpu_ms"] = 1e3 * (process_cpu_s() - cpu0) / static_cast<double>(state.iterations());
}

BENCHMARK_CAPTURE(render_fps, rgb_640x480, 640, 480, false, true)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(render_fps, rgbd_640x480, 640, 480, true, true)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(render_fps, rgb_1280x720, 1280, 720, false, true)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(render_fps, rgbd_1280x720, 1280, 720, true, true)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(render_fps, rgbd_1280x720_full_hfield, 1280, 720, true, false)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(zed2_set, 1280x720, 1280, 720, true)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace mechsim::physics
