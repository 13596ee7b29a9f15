// Camera sensors' cost per frame on the CPU (EGL surfaceless + Mesa llvmpipe, no GPU), through the
// sensor set as a simulation samples them (scene update shared per instant, distortion, noise,
// depth and points included): the CC8's ZED2 set on the Mars Yard (four 1280x720 sensors at one
// instant: left raw and right raw with distortion, the left depth camera with depth and points,
// the right rectified), and the PR2's head cameras in an empty world with a box (wide and narrow
// stereo pairs, 640x480; the 2448x2050 Prosilica). Reported, not asserted. `cpu_ms` is the whole
// process's CPU time per instant (llvmpipe rasterises on its own threads); `rt_budget` is the
// share of one real second the cameras need at their rates (instant cost x rate).
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <filesystem>
#include <memory>
#include <set>
#include <string>

#include "description/urdf/urdf_parser.hpp"
#include "physics/heightmap_sample.hpp"
#include "physics/mars_yard.hpp"
#include "description/camera_override.hpp"
#include "physics/physics.hpp"
#include "sensors/sensor_set.hpp"

namespace mechsim::sensors {
namespace {

const std::string kShared = MECHSIM_SHARED_DIR;

double process_cpu_s() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

struct Rig {
  description::RobotModel robot;
  std::shared_ptr<const physics::PhysicsModel> model;
  std::unique_ptr<physics::Physics> physics;
};

Rig cc8_on_mars_yard() {
  description::UrdfOptions o;
  o.lenient = true;
  o.packages["cc8_description"] = kShared + "/robots/cc8_description";
  Rig r;
  r.robot = description::parse_urdf_file(kShared + "/robots/reference/cc8.urdf", o);
  const physics::MarsYard yard = physics::generate_mars_yard(physics::kMarsYardDefaultSeed);
  physics::BuildOptions b;
  b.world.kind = physics::WorldSpec::Kind::Heightmap;
  b.world.terrain = yard.heightmap;
  b.render_terrain = true;
  b.spawn.x = yard.start.x;
  b.spawn.y = yard.start.y;
  b.spawn.z = physics::height_at(yard.heightmap, yard.start.x, yard.start.y) + 0.25;
  b.spawn.yaw = yard.start.yaw;
  r.model = physics::PhysicsModel::build(r.robot, b);
  r.physics = std::make_unique<physics::Physics>(r.model);
  for (int i = 0; i < 1500; ++i) r.physics->step();
  return r;
}

Rig pr2_before_a_box() {
  description::UrdfOptions o;
  o.lenient = true;
  o.packages["pr2_description"] = kShared + "/robots/pr2_description";
  Rig r;
  r.robot = description::parse_urdf_file(kShared + "/robots/reference/pr2.urdf", o);
  physics::BuildOptions b;
  physics::WorldBox box;
  box.name = "table";
  box.pose.position = {1.5, 0.0, 0.4};
  box.size = {0.8, 1.2, 0.8};
  b.world.boxes.push_back(box);
  r.model = physics::PhysicsModel::build(r.robot, b);
  r.physics = std::make_unique<physics::Physics>(r.model);
  return r;
}

// Samples the named cameras at one instant per iteration (all due together at `rate`).
// `width` > 0: every camera overridden to that width (aspect kept) and to `rate` (description/
// camera_override.hpp, a fast run's settings).
void cameras(benchmark::State& state, Rig (*make)(), std::set<std::string> names, double rate, int width = 0) {
  if (!std::filesystem::is_directory(kShared + "/robots/reference")) {
    state.SkipWithError("shared data folder absent");
    return;
  }
  Rig rig = make();
  if (width > 0) {
    description::CameraOverride o;
    o.rate = rate;
    o.width = width;
    description::apply_camera_overrides(rig.robot, {{"all", o}});
  }
  SensorSet set(rig.robot.sensors, rig.model, 1);
  std::size_t enabled = 0;
  for (std::size_t i = 0; i < set.size(); ++i) {
    const bool on = names.count(set.spec(i).name) > 0;
    set.set_enabled(i, on);
    enabled += on;
  }
  if (enabled != names.size()) {
    state.SkipWithError("a camera is missing from the description");
    return;
  }
  double t = 0.0;
  set.sample_due(*rig.physics, t);  // the first render compiles llvmpipe's shaders
  if (set.render_hub() == nullptr || !set.render_hub()->error().empty()) {
    state.SkipWithError("no renderer");
    return;
  }
  const CameraStages before = set.render_hub()->stages();
  const double cpu0 = process_cpu_s();
  for (auto _ : state) {
    t += 1.0 / rate;
    set.sample_due(*rig.physics, t);
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["instants_per_s"] = benchmark::Counter(n, benchmark::Counter::kIsRate);
  state.counters["cpu_ms"] = 1e3 * (process_cpu_s() - cpu0) / n;
  state.counters["renders"] = static_cast<double>(set.render_hub()->renders()) / (n + 1);
  state.counters["rate_hz"] = rate;
  // The stage budget per instant (CameraStages): wall ms as w_<stage>, process CPU ms as c_<stage>.
  const CameraStages& after = set.render_hub()->stages();
  const auto stage = [&](const char* name, physics::StageTime CameraStages::*member) {
    state.counters[std::string("w_") + name] = ((after.*member).wall_ms - (before.*member).wall_ms) / n;
    state.counters[std::string("c_") + name] = ((after.*member).cpu_ms - (before.*member).cpu_ms) / n;
  };
  const double renders = static_cast<double>(after.renders - before.renders);
  state.counters["geoms_per_render"] = static_cast<double>(after.geoms - before.geoms) / renders;
  state.counters["tiles_per_render"] = static_cast<double>(after.terrain_tiles - before.terrain_tiles) / renders;
  state.counters["cells_per_render"] = static_cast<double>(after.terrain_cells - before.terrain_cells) / renders;
  stage("scene", &CameraStages::scene);
  stage("prep", &CameraStages::prep);
  stage("draw", &CameraStages::draw);
  stage("read", &CameraStages::read);
  stage("convert", &CameraStages::convert);
  stage("resample", &CameraStages::resample);
  stage("noise", &CameraStages::noise);
  stage("points", &CameraStages::points);
}

void zed2_set(benchmark::State& s) {
  cameras(s, cc8_on_mars_yard, {"zed2_left_raw_camera", "zed2_left_camera", "zed2_right_raw_camera", "zed2_right_camera"}, 15.0);
}
// The same set with camera_overrides {all: {width: W, rate: 5}}: what a fast run costs.
void zed2_set_640x360_5hz(benchmark::State& s) {
  cameras(s, cc8_on_mars_yard, {"zed2_left_raw_camera", "zed2_left_camera", "zed2_right_raw_camera", "zed2_right_camera"}, 5.0, 640);
}
void zed2_set_640x360(benchmark::State& s) {
  cameras(s, cc8_on_mars_yard, {"zed2_left_raw_camera", "zed2_left_camera", "zed2_right_raw_camera", "zed2_right_camera"}, 15.0, 640);
}
void zed2_set_320x180_5hz(benchmark::State& s) {
  cameras(s, cc8_on_mars_yard, {"zed2_left_raw_camera", "zed2_left_camera", "zed2_right_raw_camera", "zed2_right_camera"}, 5.0, 320);
}
void zed2_depth_only(benchmark::State& s) { cameras(s, cc8_on_mars_yard, {"zed2_left_camera"}, 15.0); }
void pr2_stereo(benchmark::State& s) {
  cameras(s, pr2_before_a_box,
          {"wide_stereo_l_stereo_camera_sensor", "wide_stereo_r_stereo_camera_sensor",
           "narrow_stereo_l_stereo_camera_sensor", "narrow_stereo_r_stereo_camera_sensor"},
          25.0);
}
void pr2_prosilica(benchmark::State& s) { cameras(s, pr2_before_a_box, {"high_def_sensor"}, 20.0); }

BENCHMARK(zed2_set)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(zed2_set_640x360)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(zed2_set_640x360_5hz)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(zed2_set_320x180_5hz)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(zed2_depth_only)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(pr2_stereo)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(pr2_prosilica)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace mechsim::sensors

BENCHMARK_MAIN();
