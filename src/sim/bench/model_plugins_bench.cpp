// What Gazebo's model plugins cost the tick (issue 25: under 2 %), on mechsim's test robots
// (robots/testbots) driven by them: the diff drive (encoder odometry, wheel joint states), the
// skid steer, the planar move with a joint state publisher, and the gripper's mimic joint plugin
// (PID). Each runs its plugins while a twist (or a closing torque) is applied:
//   <robot>/FullTick   Simulation::step(), the whole tick; counters: plugins_us, the plugins'
//                      update() per tick as the controller manager measures it (mean since
//                      start), and plugins_%, that over the tick's time;
//   <robot>/BareStep   Physics::step() alone, the same model.
// Run: build/release/bin/sim_bench --benchmark_filter=Testbots --benchmark_counters_tabular=true

#include <benchmark/benchmark.h>

#include <chrono>
#include <filesystem>
#include <memory>

#include "control/params.hpp"
#include "control/ports.hpp"
#include "description/robot_loader.hpp"
#include "sim/simulation.hpp"

namespace {

namespace fs = std::filesystem;
using namespace mechsim;

const fs::path kTestbots = fs::path(MECHSIM_SOURCE_DIR) / "robots" / "testbots";

std::unique_ptr<sim::Simulation> make(const std::string& robot, std::map<std::string, std::string> args,
                                      const std::string& controllers = "", const std::string& ns = "") {
  description::LoadOptions options;
  options.packages = {{"mechsim_testbots", kTestbots.string()}};
  options.xacro_args = std::move(args);
  auto model = description::load_robot((kTestbots / "urdf" / (robot + ".urdf.xacro")).string(), options).model;
  control::Params params;
  if (!controllers.empty()) params = control::Params::from_yaml_file((kTestbots / "config" / controllers).string()).child(ns);
  return std::make_unique<sim::Simulation>(std::move(model), sim::make_world({}), params);
}

void drive(sim::Simulation& sim, const std::string& plugin, double vx, double wz) {
  auto* port = sim.controllers().controller(plugin)->port_as<control::TwistCommandPort>("cmd_vel");
  control::Twist t;
  t.linear.x = vx;
  t.angular.z = wz;
  port->write(t);
}

std::unique_ptr<sim::Simulation> diffbot() {
  auto sim = make("diffbot", {{"drive", "plugin"}, {"odometry_source", "encoder"}, {"wheel_acceleration", "1.0"}});
  drive(*sim, "differential_drive_controller", 0.3, 0.2);
  return sim;
}

std::unique_ptr<sim::Simulation> skidbot() {
  auto sim = make("skidbot", {{"drive", "plugin"}});
  drive(*sim, "skid_steer_drive_controller", 0.3, 0.2);
  return sim;
}

std::unique_ptr<sim::Simulation> planarbot() {
  auto sim = make("planarbot", {});
  drive(*sim, "object_controller", 0.3, 0.2);
  return sim;
}

std::unique_ptr<sim::Simulation> gripper() {
  auto sim = make("gripper", {{"mimic_pid", "true"}, {"block", "true"}}, "gripper_controllers.yaml", "gripper");
  sim->load_and_start({"finger_effort_controller"});
  sim->controllers().controller("finger_effort_controller")->port_as<control::ScalarCommandPort>("command")->write(0.05);
  return sim;
}

double plugins_seconds_per_tick(const sim::Simulation& sim) {
  double s = 0.0;
  for (const control::ControllerInfo& info : sim.controllers().list_controllers()) {
    if (info.model_plugin) s += info.statistics.mean_update_time;
  }
  return s;
}

template <std::unique_ptr<sim::Simulation> (*Make)()>
void BM_Tick(benchmark::State& state) {
  auto sim = Make();
  for (int i = 0; i < 200; ++i) sim->step();
  const auto start = std::chrono::steady_clock::now();
  for (auto _ : state) benchmark::DoNotOptimize(sim->step());
  const double tick = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() /
                      static_cast<double>(state.iterations());
  const double plugins = plugins_seconds_per_tick(*sim);
  state.counters["plugins_us"] = 1e6 * plugins;
  state.counters["plugins_%"] = 100.0 * plugins / tick;
}

template <std::unique_ptr<sim::Simulation> (*Make)()>
void BM_Bare(benchmark::State& state) {
  auto sim = Make();
  for (int i = 0; i < 200; ++i) sim->step();
  for (auto _ : state) benchmark::DoNotOptimize(sim->physics().step());
}

BENCHMARK(BM_Bare<diffbot>)->Name("Testbots/DiffDrivePlugin/BareStep")->MinTime(1.0);
BENCHMARK(BM_Tick<diffbot>)->Name("Testbots/DiffDrivePlugin/FullTick")->MinTime(1.0);
BENCHMARK(BM_Bare<skidbot>)->Name("Testbots/SkidSteerPlugin/BareStep")->MinTime(1.0);
BENCHMARK(BM_Tick<skidbot>)->Name("Testbots/SkidSteerPlugin/FullTick")->MinTime(1.0);
BENCHMARK(BM_Bare<planarbot>)->Name("Testbots/PlanarMoveAndJointStatePlugins/BareStep")->MinTime(1.0);
BENCHMARK(BM_Tick<planarbot>)->Name("Testbots/PlanarMoveAndJointStatePlugins/FullTick")->MinTime(1.0);
BENCHMARK(BM_Bare<gripper>)->Name("Testbots/MimicJointPluginPid/BareStep")->MinTime(1.0);
BENCHMARK(BM_Tick<gripper>)->Name("Testbots/MimicJointPluginPid/FullTick")->MinTime(1.0);

}  // namespace
