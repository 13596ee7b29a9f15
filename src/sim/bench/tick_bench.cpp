// The cost of mechsim's tick against the bare physics step of the same model (DESIGN.md: speed
// is reported as a ratio against the bare MuJoCo step). Run:
//   build/release/bin/sim_bench --benchmark_counters_tabular=true
// BM_BareStep: Physics::step() alone (one mj_step plus mechsim's NaN/runaway check).
// BM_FullTick: Simulation::step(): read joints, transmissions, controller manager with the
// robot's controllers running, safety limits, commands, the same physics step, and the robot's
// sensors sampled at their rates (the reference PR2 declares both Hokuyos, 640 rays each at 20
// and 40 Hz, the torso IMU at 100 Hz and six bumpers at 100 Hz; the reference CC8 two IMUs at
// 100 Hz; cameras are not simulated here). PR2/FullTickNoSensors is the same tick with
// SimulationOptions::sensors off: FullTick / FullTickNoSensors is what the sensors cost.

#include <benchmark/benchmark.h>

#include <filesystem>
#include <memory>

#include "control/params.hpp"
#include "description/urdf/urdf_parser.hpp"
#include "sim/simulation.hpp"

namespace {

namespace fs = std::filesystem;
using namespace mechsim;

const fs::path kShared = MECHSIM_SHARED_DIR;

std::unique_ptr<sim::Simulation> make_cc8() {
  description::UrdfOptions options;
  options.packages["cc8_description"] = (kShared / "robots/cc8_description").string();
  auto robot = description::parse_urdf_file((kShared / "robots/reference/cc8.urdf").string(), options);
  auto params = control::Params::from_yaml_file((kShared / "robots/cc8_description/config/controller.yaml").string());
  auto sim = std::make_unique<sim::Simulation>(std::move(robot), sim::make_world({}), params.child("cc8"));
  std::vector<std::string> names{"joint_state_controller"};
  for (const char* c : {"FL", "FR", "RL", "RR"}) names.push_back(std::string("steering_") + c + "_position_controller");
  for (const char* c : {"FL", "FR", "ML", "MR", "RL", "RR"}) names.push_back(std::string("wheel_joint_") + c + "_position_controller");
  sim->load_and_start(names);
  return sim;
}

std::unique_ptr<sim::Simulation> make_pr2(bool sensors) {
  description::UrdfOptions options;
  options.lenient = true;
  options.packages["pr2_description"] = (kShared / "robots/pr2_description").string();
  auto robot = description::parse_urdf_file((kShared / "robots/reference/pr2.urdf").string(), options);
  std::string yaml;
  std::vector<std::string> names;
  for (const std::string joint :
       {"torso_lift_joint", "head_pan_joint", "head_tilt_joint", "laser_tilt_mount_joint", "r_shoulder_pan_joint",
        "r_shoulder_lift_joint", "r_upper_arm_roll_joint", "r_elbow_flex_joint", "r_forearm_roll_joint",
        "r_wrist_flex_joint", "r_wrist_roll_joint", "l_shoulder_pan_joint", "l_shoulder_lift_joint",
        "l_upper_arm_roll_joint", "l_elbow_flex_joint", "l_forearm_roll_joint", "l_wrist_flex_joint",
        "l_wrist_roll_joint"}) {
    names.push_back(joint + "_controller");
    yaml += joint + "_controller: {type: robot_mechanism_controllers/JointPositionController, joint: " + joint +
            ", pid: {p: 300.0, i: 0.0, d: 5.0}}\n";
  }
  sim::SimulationOptions sim_options;
  sim_options.sensors = sensors;
  auto sim = std::make_unique<sim::Simulation>(std::move(robot), sim::make_world({}),
                                               control::Params::from_yaml_string(yaml, "pr2 bench"), sim_options);
  sim->load_and_start(names);
  return sim;
}

std::unique_ptr<sim::Simulation> make_pr2_with_sensors() { return make_pr2(true); }
std::unique_ptr<sim::Simulation> make_pr2_without_sensors() { return make_pr2(false); }

template <std::unique_ptr<sim::Simulation> (*Make)()>
void BM_BareStep(benchmark::State& state) {
  if (!fs::exists(kShared)) {
    state.SkipWithError("shared data absent");
    return;
  }
  auto sim = Make();
  for (int i = 0; i < 200; ++i) sim->step();  // settle, start the controllers
  for (auto _ : state) benchmark::DoNotOptimize(sim->physics().step());
  state.counters["steps/s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

template <std::unique_ptr<sim::Simulation> (*Make)()>
void BM_FullTick(benchmark::State& state) {
  if (!fs::exists(kShared)) {
    state.SkipWithError("shared data absent");
    return;
  }
  auto sim = Make();
  for (int i = 0; i < 200; ++i) sim->step();
  for (auto _ : state) benchmark::DoNotOptimize(sim->step());
  state.counters["steps/s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

BENCHMARK(BM_BareStep<make_cc8>)->Name("CC8/BareStep")->MinTime(2.0);
BENCHMARK(BM_FullTick<make_cc8>)->Name("CC8/FullTick")->MinTime(2.0);
BENCHMARK(BM_BareStep<make_pr2_with_sensors>)->Name("PR2/BareStep")->MinTime(2.0);
BENCHMARK(BM_FullTick<make_pr2_with_sensors>)->Name("PR2/FullTick")->MinTime(2.0);
BENCHMARK(BM_FullTick<make_pr2_without_sensors>)->Name("PR2/FullTickNoSensors")->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
