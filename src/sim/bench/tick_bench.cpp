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
// PR2/LasersImuShare is the measure on a loaded machine: two PR2s in one loop, one with
// only its two Hokuyos and the torso IMU on (bumpers and ground truth off, as on ROS until they
// are subscribed), one without sensors, stepped in alternating blocks of 50 ticks and timed by
// the thread's CPU clock, so that the load of the machine falls on both alike; counters: CPU us
// per tick of each and their ratio.
// CC8/TwoInOneWorld/FullTick: two CC8s in one world (sim::OtherRobot), both controller sets
// running: against CC8/FullTick, what a second robot costs a tick. CC8/SpawnAndDelete: a second
// CC8 spawned beside a running one and deleted again (Simulation::add_other, remove_other: two
// physics rebuilds with the state carried over, its controllers loaded and started): the pause a
// /gazebo/spawn_urdf_model plus delete_model puts in the loop. CC8/InARobotlessWorld/FullTick: the
// CC8 as the other robot of a world with no robot of its own, the form mechsim_node's gzserver
// mode gives every spawned model: against CC8/FullTick, what that form costs.

#include <benchmark/benchmark.h>

#include <time.h>

#include <filesystem>
#include <memory>
#include <string>

#include "control/params.hpp"
#include "description/urdf/urdf_parser.hpp"
#include "sim/simulation.hpp"

namespace {

namespace fs = std::filesystem;
using namespace mechsim;

const fs::path kShared = MECHSIM_SHARED_DIR;

std::vector<std::string> cc8_controllers() {
  std::vector<std::string> names{"joint_state_controller"};
  for (const char* c : {"FL", "FR", "RL", "RR"}) names.push_back(std::string("steering_") + c + "_position_controller");
  for (const char* c : {"FL", "FR", "ML", "MR", "RL", "RR"}) names.push_back(std::string("wheel_joint_") + c + "_position_controller");
  return names;
}

description::RobotModel load_cc8() {
  description::UrdfOptions options;
  options.packages["cc8_description"] = (kShared / "robots/cc8_description").string();
  return description::parse_urdf_file((kShared / "robots/reference/cc8.urdf").string(), options);
}

control::Params cc8_params() {
  return control::Params::from_yaml_file((kShared / "robots/cc8_description/config/controller.yaml").string()).child("cc8");
}

sim::OtherRobot second_cc8(double y) {
  sim::OtherRobot o;
  o.name = "cc8_2";
  o.robot = load_cc8();
  o.controllers = cc8_params();
  o.spawn.y = y;
  return o;
}

std::unique_ptr<sim::Simulation> make_cc8_with(std::vector<sim::OtherRobot> others) {
  auto sim = std::make_unique<sim::Simulation>(load_cc8(), sim::make_world({}), cc8_params(), sim::SimulationOptions{},
                                               std::move(others));
  sim->load_and_start(cc8_controllers());
  for (std::size_t i = 0; i < sim->other_count(); ++i) sim->other(i).load_and_start(cc8_controllers());
  return sim;
}

std::unique_ptr<sim::Simulation> make_cc8() { return make_cc8_with({}); }

std::unique_ptr<sim::Simulation> make_cc8_in_robotless_world() {
  auto world = description::parse_urdf_string("<robot name='world'><link name='world'/></robot>", "world",
                                              description::UrdfOptions{});
  sim::OtherRobot cc8 = second_cc8(0.0);
  cc8.name = "cc8";
  auto sim = std::make_unique<sim::Simulation>(std::move(world), sim::make_world({}), control::Params{},
                                               sim::SimulationOptions{}, std::vector<sim::OtherRobot>{cc8});
  sim->other(0).load_and_start(cc8_controllers());
  return sim;
}
std::unique_ptr<sim::Simulation> make_two_cc8s() { return make_cc8_with({second_cc8(3.0)}); }

void BM_SpawnAndDelete(benchmark::State& state) {
  if (!fs::exists(kShared)) {
    state.SkipWithError("shared data absent");
    return;
  }
  auto sim = make_cc8();
  for (int i = 0; i < 200; ++i) sim->step();
  const sim::OtherRobot other = second_cc8(3.0);
  for (auto _ : state) {
    sim->add_other(other).load_and_start(cc8_controllers());
    sim->remove_other("cc8_2");
    sim->step();
  }
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

double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

void BM_LasersImuShare(benchmark::State& state) {
  if (!fs::exists(kShared)) {
    state.SkipWithError("shared data absent");
    return;
  }
  auto with = make_pr2(true);
  auto without = make_pr2(false);
  sensors::SensorSet& set = with->sensors();
  int kept = 0;
  for (std::size_t i = 0; i < set.size(); ++i) {
    const std::string kind = set.spec(i).kind_name();
    const bool keep = kind == "ray" || kind == "imu";
    set.set_enabled(i, keep);
    kept += keep ? 1 : 0;
  }
  for (int i = 0; i < 200; ++i) {
    with->step();
    without->step();
  }
  constexpr int kBlock = 50;
  double cpu_with = 0.0, cpu_without = 0.0;
  for (auto _ : state) {
    double t = thread_cpu_seconds();
    for (int i = 0; i < kBlock; ++i) benchmark::DoNotOptimize(with->step());
    const double mid = thread_cpu_seconds();
    cpu_with += mid - t;
    for (int i = 0; i < kBlock; ++i) benchmark::DoNotOptimize(without->step());
    cpu_without += thread_cpu_seconds() - mid;
  }
  const double ticks = static_cast<double>(state.iterations()) * kBlock;
  state.counters["sensors"] = kept;
  state.counters["with_us"] = 1e6 * cpu_with / ticks;
  state.counters["without_us"] = 1e6 * cpu_without / ticks;
  state.counters["ratio"] = cpu_with / cpu_without;
}

BENCHMARK(BM_BareStep<make_cc8>)->Name("CC8/BareStep")->MinTime(2.0);
BENCHMARK(BM_FullTick<make_cc8>)->Name("CC8/FullTick")->MinTime(2.0);
BENCHMARK(BM_BareStep<make_cc8_in_robotless_world>)->Name("CC8/InARobotlessWorld/BareStep")->MinTime(2.0);
BENCHMARK(BM_FullTick<make_cc8_in_robotless_world>)->Name("CC8/InARobotlessWorld/FullTick")->MinTime(2.0);
BENCHMARK(BM_FullTick<make_two_cc8s>)->Name("CC8/TwoInOneWorld/FullTick")->MinTime(2.0);
BENCHMARK(BM_SpawnAndDelete)->Name("CC8/SpawnAndDelete")->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_BareStep<make_pr2_with_sensors>)->Name("PR2/BareStep")->MinTime(2.0);
BENCHMARK(BM_FullTick<make_pr2_with_sensors>)->Name("PR2/FullTick")->MinTime(2.0);
BENCHMARK(BM_FullTick<make_pr2_without_sensors>)->Name("PR2/FullTickNoSensors")->MinTime(2.0);
BENCHMARK(BM_LasersImuShare)->Name("PR2/LasersImuShare")->MinTime(4.0);

}  // namespace

BENCHMARK_MAIN();
