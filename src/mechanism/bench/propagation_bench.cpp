// The mechanism's share of one 1 kHz tick on the PR2 and the CC8 reference robots: the four
// transmission propagations plus the safety limits, and each propagation alone. Counters give
// the mechanism's size.
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>

#include "description/urdf/urdf_parser.hpp"
#include "mechanism/build_mechanism.hpp"
#include "mechanism/propagation.hpp"

namespace mechsim::mechanism {
namespace {

namespace fs = std::filesystem;

bool load(benchmark::State& state, const char* file, MechanismModel& model) {
  const fs::path path = fs::path(MECHSIM_SHARED_DIR) / "robots" / "reference" / file;
  if (!fs::exists(path)) {
    state.SkipWithError("shared test data absent");
    return false;
  }
  description::UrdfOptions options;
  options.lenient = true;
  model = build_mechanism(description::parse_urdf_file(path.string(), options));
  state.counters["joints"] = static_cast<double>(model.joints.size());
  state.counters["actuators"] = static_cast<double>(model.actuators.size());
  state.counters["transmissions"] = static_cast<double>(model.transmissions.size());
  return true;
}

void mid_range(const MechanismModel& m, MechanismState& s) {
  for (std::size_t i = 0; i < m.joints.size(); ++i) {
    const JointInfo& info = m.joints[i];
    JointState& j = s.joints[i];
    j.position = info.limits && !info.continuous ? 0.5 * (info.limits->lower + info.limits->upper) : 0.1;
    j.velocity = 0.01 * std::sin(static_cast<double>(i));
    j.commanded_effort = 0.5;
  }
}

void BM_MechanismTick(benchmark::State& state, const char* file) {
  MechanismModel m;
  if (!load(state, file, m)) return;
  MechanismState s = make_state(m);
  mid_range(m, s);
  for (auto _ : state) {
    propagate_joint_to_actuator_position(m, s);
    propagate_actuator_to_joint_position(m, s);
    enforce_safety_limits(m, s);
    propagate_joint_to_actuator_effort(m, s);
    propagate_actuator_to_joint_effort(m, s);
    benchmark::DoNotOptimize(s.joints.data());
    benchmark::ClobberMemory();
  }
}

void BM_ActuatorToJointPosition(benchmark::State& state, const char* file) {
  MechanismModel m;
  if (!load(state, file, m)) return;
  MechanismState s = make_state(m);
  mid_range(m, s);
  propagate_joint_to_actuator_position(m, s);
  for (auto _ : state) {
    propagate_actuator_to_joint_position(m, s);
    benchmark::DoNotOptimize(s.joints.data());
    benchmark::ClobberMemory();
  }
}

void BM_SafetyLimits(benchmark::State& state, const char* file) {
  MechanismModel m;
  if (!load(state, file, m)) return;
  MechanismState s = make_state(m);
  mid_range(m, s);
  for (auto _ : state) {
    enforce_safety_limits(m, s);
    benchmark::DoNotOptimize(s.joints.data());
    benchmark::ClobberMemory();
  }
}

BENCHMARK_CAPTURE(BM_MechanismTick, pr2, "pr2.urdf");
BENCHMARK_CAPTURE(BM_MechanismTick, cc8, "cc8.urdf");
BENCHMARK_CAPTURE(BM_ActuatorToJointPosition, pr2, "pr2.urdf");
BENCHMARK_CAPTURE(BM_SafetyLimits, pr2, "pr2.urdf");

}  // namespace
}  // namespace mechsim::mechanism

BENCHMARK_MAIN();
