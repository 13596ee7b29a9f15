// One controller-manager tick (propagation, 40 running effort_controllers/
// JointPositionController PID updates, safety limits, effort propagation) on 40 joints driven
// by SimpleTransmissions. The global operator new is replaced by a counting one so the
// benchmark also reports allocations per tick (expected: 0).

#include <benchmark/benchmark.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <sstream>

#include "control/controller_manager.hpp"
#include "controllers/builtin_controllers.hpp"
#include "mechanism/simple_transmission.hpp"

namespace {
std::atomic<long> g_allocations{0};

void* counted_alloc(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  void* p = std::malloc(size == 0 ? 1 : size);
  if (p == nullptr) throw std::bad_alloc();
  return p;
}
}  // namespace

void* operator new(std::size_t size) { return counted_alloc(size); }
void* operator new[](std::size_t size) { return counted_alloc(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace mechsim::control {
namespace {

mechanism::MechanismModel make_model(int joints) {
  mechanism::MechanismModel model;
  for (int i = 0; i < joints; ++i) {
    mechanism::JointInfo info;
    info.name = std::string("joint_").append(std::to_string(i));
    info.type = description::JointType::Revolute;
    info.limits = description::JointLimits{-3.0, 3.0, 100.0, 10.0};
    info.interfaces = {HardwareInterface::Effort};
    info.transmission = i;
    model.joints.push_back(info);
    model.actuators.push_back(mechanism::ActuatorInfo{info.name + "_motor", i});
    model.transmissions.push_back(std::make_unique<mechanism::SimpleTransmission>(
        info.name + "_trans", "transmission_interface/SimpleTransmission", i, i, 50.0));
  }
  return model;
}

void BM_ManagerTick(benchmark::State& bench) {
  const int n = static_cast<int>(bench.range(0));
  const mechanism::MechanismModel model = make_model(n);
  mechanism::MechanismState state = mechanism::make_state(model);
  std::ostringstream yaml;
  std::vector<std::string> names;
  for (int i = 0; i < n; ++i) {
    names.push_back(std::string("c").append(std::to_string(i)));
    yaml << names.back() << ": {type: effort_controllers/JointPositionController, joint: joint_" << i
         << ", pid: {p: 100, i: 1, d: 20, i_clamp: 5}}\n";
  }
  ControllerManager manager(model, state, Params::from_yaml_string(yaml.str()),
                            builtin_controller_registry());
  for (const auto& name : names) {
    if (!manager.load_controller(name).ok) bench.SkipWithError("load failed");
  }
  manager.switch_controllers(names, {}, SwitchStrictness::Strict);
  manager.update(0.0, 0.001);
  for (int i = 0; i < n; ++i) manager.controller(names[i])->port_as<ScalarCommandPort>("command")->write(0.01 * i);

  double time = 0.001;
  long ticks = 0;
  const long before = g_allocations.load();
  for (auto _ : bench) {
    // Encoders move a little each tick so the PIDs do real work.
    for (std::size_t a = 0; a < state.actuators.size(); ++a) state.actuators[a].position += 1e-4;
    manager.update(time, 0.001);
    time += 0.001;
    ++ticks;
    benchmark::ClobberMemory();
  }
  const long allocations = g_allocations.load() - before;
  bench.counters["allocs_per_tick"] = ticks > 0 ? static_cast<double>(allocations) / static_cast<double>(ticks) : 0.0;
  bench.counters["controllers"] = n;
}
BENCHMARK(BM_ManagerTick)->Arg(40)->Arg(1)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace mechsim::control

BENCHMARK_MAIN();
