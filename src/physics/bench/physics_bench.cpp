// Bare MuJoCo stepping speed of the shipped robots at 1 kHz, the reference that the sim-layer
// tick is measured against, and the overhead of Physics::step() (checks, snapshot) over it.
// Reported as steps per second (items_per_second); nothing is asserted.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>

#include "description/urdf/urdf_parser.hpp"
#include "physics/mujoco_internal.hpp"
#include "physics/physics.hpp"

namespace mechsim::physics {
namespace {

const std::string kShared = MECHSIM_SHARED_DIR;

// Models are built once per program run and shared by the benchmarks.
std::shared_ptr<const PhysicsModel> robot_model(const std::string& file) {
  static std::map<std::string, std::shared_ptr<const PhysicsModel>> cache;
  auto it = cache.find(file);
  if (it != cache.end()) return it->second;
  description::UrdfOptions o;
  o.lenient = true;
  o.packages["cc8_description"] = kShared + "/robots/cc8_description";
  o.packages["pr2_description"] = kShared + "/robots/pr2_description";
  BuildOptions b;  // 1 ms step, implicit integrator, visuals built
  b.spawn.z = 0.02;
  auto model = PhysicsModel::build(description::parse_urdf_file(kShared + "/robots/reference/" + file, o), b);
  cache[file] = model;
  return model;
}

void bare_mj_step(benchmark::State& state, const std::string& file) {
  if (!std::filesystem::is_directory(kShared + "/robots/reference")) {
    state.SkipWithError("shared data folder absent");
    return;
  }
  auto model = robot_model(file);
  mjModel* m = mj_copyModel(nullptr, model->impl().model);
  mjData* d = mj_makeData(m);
  for (int i = 0; i < 1000; ++i) mj_step(m, d);  // settle onto the ground first
  for (auto _ : state) {
    mj_step(m, d);
    benchmark::DoNotOptimize(d->qpos[0]);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["sim_s_per_wall_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * m->opt.timestep, benchmark::Counter::kIsRate);
  state.counters["ncon"] = d->ncon;
  state.counters["nv"] = m->nv;
  mj_deleteData(d);
  mj_deleteModel(m);
}

void physics_step(benchmark::State& state, const std::string& file) {
  if (!std::filesystem::is_directory(kShared + "/robots/reference")) {
    state.SkipWithError("shared data folder absent");
    return;
  }
  Physics p(robot_model(file));
  for (int i = 0; i < 1000; ++i) p.step();
  for (auto _ : state) {
    const StepStatus s = p.step();
    benchmark::DoNotOptimize(s.code);
  }
  state.SetItemsProcessed(state.iterations());
}

BENCHMARK_CAPTURE(bare_mj_step, cc8, std::string("cc8.urdf"))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(bare_mj_step, pr2, std::string("pr2.urdf"))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(physics_step, cc8, std::string("cc8.urdf"))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(physics_step, pr2, std::string("pr2.urdf"))->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace mechsim::physics

BENCHMARK_MAIN();
