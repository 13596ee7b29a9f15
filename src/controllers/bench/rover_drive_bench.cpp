// The rover drive controller's share of a tick: one update() of mechsim/RoverDriveController
// on the CC8's ten joints (kinematics, rate limits, ten PIDs, least-squares odometry, three
// snapshots), and its two kinematic cores alone. Geometry: the reference CC8's, rounded.

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>

#include "controllers/drive/rover_drive_controller.hpp"
#include "controllers/drive/rover_drive_odometry.hpp"
#include "mechanism/simple_transmission.hpp"

namespace mechsim::control {
namespace {

constexpr const char* kYaml = R"(rover:
  type: mechsim/RoverDriveController
  steering_joints: [steering_FL, steering_FR, steering_RL, steering_RR]
  wheel_joints: [wheel_joint_FL, wheel_joint_FR, wheel_joint_ML, wheel_joint_MR, wheel_joint_RL, wheel_joint_RR]
  wheel_radius: 0.09
  steering_pid: {p: 60.0, i: 5.0, d: 3.0, i_clamp: 5.0}
  wheel_pid: {p: 8.0, i: 20.0, i_clamp: 15.0}
  max_linear_acceleration: 1.0
  max_angular_acceleration: 1.0
  wheel_positions: {wheel_joint_FL: [0.496, 0.3895], wheel_joint_FR: [0.496, -0.3895], wheel_joint_ML: [0.0, 0.4446],
                    wheel_joint_MR: [0.0, -0.4446], wheel_joint_RL: [-0.503, 0.4137], wheel_joint_RR: [-0.503, -0.4137]}
  wheel_axis_signs: {wheel_joint_FL: 1, wheel_joint_FR: -1, wheel_joint_ML: -1, wheel_joint_MR: -1, wheel_joint_RL: 1, wheel_joint_RR: -1}
  wheel_steering: {wheel_joint_FL: steering_FL, wheel_joint_FR: steering_FR, wheel_joint_RL: steering_RL, wheel_joint_RR: steering_RR}
  steering_positions: {steering_FL: [0.496, 0.3905], steering_FR: [0.496, -0.3905], steering_RL: [-0.503, 0.4147], steering_RR: [-0.503, -0.4147]}
  steering_axis_signs: {steering_FL: -1, steering_FR: -1, steering_RL: -1, steering_RR: -1}
)";

mechanism::MechanismModel make_rover_model() {
  mechanism::MechanismModel model;
  int i = 0;
  for (const char* name : {"steering_FL", "steering_FR", "steering_RL", "steering_RR", "wheel_joint_FL", "wheel_joint_FR",
                           "wheel_joint_ML", "wheel_joint_MR", "wheel_joint_RL", "wheel_joint_RR"}) {
    mechanism::JointInfo info;
    info.name = name;
    info.type = description::JointType::Continuous;
    info.continuous = true;
    info.limits = description::JointLimits{0.0, 0.0, 30.0, i < 4 ? 3.0 : 20.0};
    info.interfaces = {HardwareInterface::Effort};
    info.transmission = i;
    model.joints.push_back(info);
    model.actuators.push_back(mechanism::ActuatorInfo{info.name + "_actr", i});
    model.transmissions.push_back(std::make_unique<mechanism::SimpleTransmission>(
        info.name + "_tran", "transmission_interface/SimpleTransmission", i, i, 1.0));
    ++i;
  }
  return model;
}

void BM_RoverDriveUpdate(benchmark::State& bench) {
  const mechanism::MechanismModel model = make_rover_model();
  mechanism::MechanismState state = mechanism::make_state(model);
  RoverDriveController controller;
  RobotHardware hardware(model, state);
  std::string error;
  if (!controller.init(hardware, Params::from_yaml_string(kYaml).child("rover"), error)) bench.SkipWithError("init failed");
  controller.starting(0.0);
  controller.command_port().write(Twist{{0.4, 0.0, 0.0}, {0.0, 0.0, 0.3}});
  double time = 0.0;
  for (auto _ : bench) {
    // The joints move a little each tick so every branch does real work.
    for (std::size_t j = 0; j < state.joints.size(); ++j) {
      state.joints[j].position += 1e-4;
      state.joints[j].velocity = j < 4 ? 0.1 : 4.0;
    }
    benchmark::DoNotOptimize(controller.update(time, 0.001));
    time += 0.001;
    if (static_cast<long>(time * 1000.0) % 200 == 0) controller.command_port().write(Twist{{0.4, 0.0, 0.0}, {0.0, 0.0, 0.3}});
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_RoverDriveUpdate)->Unit(benchmark::kNanosecond);

RoverKinematics cc8_kinematics() {
  RoverKinematics k;
  k.wheel_radius = 0.09;
  k.wheels = {{0.496, 0.3905, 0, -0.001, 1.0}, {0.496, -0.3905, 1, 0.001, -1.0}, {0.0, 0.4446, -1, 0.0, -1.0},
              {0.0, -0.4446, -1, 0.0, -1.0},   {-0.503, 0.4147, 2, -0.001, 1.0}, {-0.503, -0.4147, 3, 0.001, -1.0}};
  k.steering_axis_signs.assign(4, -1.0);
  finish_rover_kinematics(k);
  return k;
}

void BM_RoverInverseKinematics(benchmark::State& bench) {
  const RoverKinematics k = cc8_kinematics();
  std::array<double, 4> headings{};
  std::array<double, 6> speeds{};
  PlanarTwist t{0.4, 0.0, 0.3};
  for (auto _ : bench) {
    t.wz = -t.wz;
    inverse_kinematics(k, t, headings, headings, headings, speeds);
    benchmark::DoNotOptimize(speeds.data());
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_RoverInverseKinematics)->Unit(benchmark::kNanosecond);

void BM_RoverOdometryEstimate(benchmark::State& bench) {
  const RoverKinematics k = cc8_kinematics();
  std::array<double, 4> headings{};
  std::array<double, 6> speeds{};
  inverse_kinematics(k, {0.4, 0.0, 0.3}, headings, headings, headings, speeds);
  PlanarTwist twist;
  double residual = 0.0;
  for (auto _ : bench) {
    speeds[0] += 1e-9;
    benchmark::DoNotOptimize(estimate_twist(k, headings, speeds, twist, &residual));
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_RoverOdometryEstimate)->Unit(benchmark::kNanosecond);

// The controller's odometry: weighted least squares and three Cauchy reweighting passes.
void BM_RoverOdometryRobustEstimate(benchmark::State& bench) {
  const RoverKinematics k = cc8_kinematics();
  std::array<double, 4> headings{};
  std::array<double, 6> speeds{};
  inverse_kinematics(k, {0.4, 0.0, 0.3}, headings, headings, headings, speeds);
  speeds[0] *= 1.5;  // a slipping wheel, so that the reweighting has work to do
  std::array<double, 6> work_h{}, work_n{};
  PlanarTwist twist;
  double residual = 0.0;
  for (auto _ : bench) {
    speeds[1] += 1e-9;
    benchmark::DoNotOptimize(
        estimate_twist_robust(k, headings, speeds, {}, {}, RobustOdometryOptions{}, work_h, work_n, twist, &residual));
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_RoverOdometryRobustEstimate)->Unit(benchmark::kNanosecond);

}  // namespace
}  // namespace mechsim::control
