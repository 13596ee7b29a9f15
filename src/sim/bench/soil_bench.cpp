// What the wheel-soil model costs the CC8 on the Mars Yard, measured in one run as a ratio (the
// target: the real-time factor on soil at least 90 % of rigid ground's). Two CC8s
// (robots/cc8, its rover drive), each in its own simulation of the Mars Yard 2024 from the start
// pad of mars_yard_route.yaml, driving at 0.3 m/s straight on: one on rigid ground, one on the
// soil of the benchmark's name. They are stepped in alternating blocks of 50 ticks and timed by
// the thread's CPU clock, so the machine's load falls on both alike. Counters: CPU microseconds
// per tick of each; rtf_ratio = rigid / soil, the soil run's real-time factor as a fraction of the
// rigid one's (>= 0.9 is the acceptance). A fixed 600 blocks (30 s, 9 m of driving) keep the
// rover on the yard. Run:
//   build/release/bin/sim_bench --benchmark_filter=Soil --benchmark_counters_tabular=true

#include <benchmark/benchmark.h>

#include <time.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "control/ports.hpp"
#include "sim/scenario.hpp"
#include "sim/scenario_build.hpp"
#include "sim/simulation.hpp"

namespace {

namespace fs = std::filesystem;
using namespace mechsim;

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

struct Rover {
  std::unique_ptr<sim::Simulation> sim;
  control::TwistCommandPort* drive = nullptr;
};

Rover rover_on_yard(std::optional<physics::SoilParameters> soil) {
  sim::Scenario s = sim::load_scenario((fs::path(MECHSIM_SOURCE_DIR) / "robots/cc8/scenarios/mars_yard_route.yaml").string());
  s.world.soil = std::move(soil);
  std::string urdf;
  Rover r;
  r.sim = sim::build_simulation(s, urdf);
  for (control::Port* p : r.sim->controllers().controller("rover_drive_controller")->ports())
    if (p->kind() == control::PortKind::TwistCommand) r.drive = dynamic_cast<control::TwistCommandPort*>(p);
  return r;
}

void BM_SoilShare(benchmark::State& state, const char* base, bool ding) {
  physics::SoilParameters soil = *physics::find_soil(base);
  if (ding) soil.model = physics::WheelSoilModel::Ding;
  Rover rigid = rover_on_yard(std::nullopt), on_soil = rover_on_yard(soil);
  if (rigid.drive == nullptr || on_soil.drive == nullptr) {
    state.SkipWithError("no rover drive port");
    return;
  }
  control::Twist twist;
  twist.linear.x = 0.3;
  constexpr int kBlock = 50;
  for (int i = 0; i < 500; ++i) {  // land and settle
    rigid.sim->step();
    on_soil.sim->step();
  }
  double cpu_rigid = 0.0, cpu_soil = 0.0;
  for (auto _ : state) {
    rigid.drive->write(twist);  // every 50 ms, as a teleoperation node sends cmd_vel
    on_soil.drive->write(twist);
    double t = cpu_seconds();
    for (int i = 0; i < kBlock; ++i) benchmark::DoNotOptimize(rigid.sim->step());
    const double mid = cpu_seconds();
    cpu_rigid += mid - t;
    for (int i = 0; i < kBlock; ++i) benchmark::DoNotOptimize(on_soil.sim->step());
    cpu_soil += cpu_seconds() - mid;
  }
  const double ticks = static_cast<double>(state.iterations()) * kBlock;
  state.counters["rigid_us"] = 1e6 * cpu_rigid / ticks;
  state.counters["soil_us"] = 1e6 * cpu_soil / ticks;
  state.counters["rtf_ratio"] = cpu_rigid / cpu_soil;
  state.counters["rigid_x_m"] = rigid.sim->base_pose().position.x;
  state.counters["soil_x_m"] = on_soil.sim->base_pose().position.x;
}

BENCHMARK_CAPTURE(BM_SoilShare, dry_sand_wong_reece, "dry_sand", false)->Name("CC8/MarsYardSoilShare/dry_sand/wong_reece")->Iterations(600);
BENCHMARK_CAPTURE(BM_SoilShare, dry_sand_ding, "dry_sand", true)->Name("CC8/MarsYardSoilShare/dry_sand/ding")->Iterations(600);
BENCHMARK_CAPTURE(BM_SoilShare, lete_sand_ding, "lete_sand", true)->Name("CC8/MarsYardSoilShare/lete_sand/ding")->Iterations(600);

}  // namespace
