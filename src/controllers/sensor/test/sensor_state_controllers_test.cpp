// The sensor interfaces (control/sensor_hardware.hpp) and ros_controllers' two sensor publishers
// over a hand-filled SensorHardware: handles by name, timing at publish_rate, the last sample
// held between samples, frames, errors, and no allocation in the tick. The same controllers
// over simulated sensors: sim/test/sensor_controllers_test.cpp.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "control/controller_check.hpp"
#include "control/controller_manager.hpp"
#include "controllers/builtin_controllers.hpp"
#include "controllers/sensor/sensor_state_controllers.hpp"
#include "controllers/test/allocation_counter.hpp"
#include "controllers/test/test_robot.hpp"

namespace mechsim::control {
namespace {

using ::testing::HasSubstr;

std::unique_ptr<SensorHardware> two_imus_one_ft() {
  ImuSensorData a;
  a.name = "torso_imu";
  a.frame_id = "imu_link";
  ImuSensorData b;
  b.name = "head_imu";
  b.frame_id = "head_link";
  ForceTorqueSensorData f;
  f.name = "wrist_ft";
  f.frame_id = "wrist_link";
  return std::make_unique<SensorHardware>(std::vector<ImuSensorData>{a, b}, std::vector<ForceTorqueSensorData>{f});
}

constexpr const char* kYaml = R"(
imu: {type: imu_sensor_controller/ImuSensorController, publish_rate: 50}
ft: {type: force_torque_sensor_controller/ForceTorqueSensorController, publish_rate: 20}
no_rate: {type: imu_sensor_controller/ImuSensorController}
negative: {type: force_torque_sensor_controller/ForceTorqueSensorController, publish_rate: -5}
)";

TEST(SensorHardware, HandlesByNameAndUnknownNamesAreErrorsListingTheSensors) {
  auto robot = testing::make_robot(1);
  auto sensors = two_imus_one_ft();
  RobotHardware hw(robot->model, robot->state);
  hw.set_sensors(sensors.get());
  EXPECT_FALSE(sensors->imu_used(1));
  const ImuSensorHandle h = hw.imu_sensor("head_imu", "/ns/c/imu");
  EXPECT_EQ(h.frame_id(), "head_link");
  EXPECT_TRUE(sensors->imu_used(1));   // the owner now keeps it sampled
  EXPECT_FALSE(sensors->imu_used(0));
  sensors->imus()[1].angular_velocity = {0.0, 0.0, 0.25};
  EXPECT_EQ(h.data().angular_velocity[2], 0.25);  // a view, not a copy
  ASSERT_EQ(hw.imu_sensors().size(), 2u);
  ASSERT_EQ(hw.force_torque_sensors().size(), 1u);
  EXPECT_EQ(hw.force_torque_sensor("wrist_ft").name(), "wrist_ft");
  ASSERT_EQ(hw.sensor_uses().size(), 2u);
  EXPECT_EQ(hw.sensor_uses()[1].interface, "hardware_interface::ForceTorqueSensorInterface");
  try {
    hw.imu_sensor("zed2_imu", "/cc8/drive/crab_heading_imu");
    FAIL() << "no error";
  } catch (const ControllerConfigError& e) {
    EXPECT_THAT(e.what(), HasSubstr("unknown IMU 'zed2_imu'"));
    EXPECT_THAT(e.what(), HasSubstr("/cc8/drive/crab_heading_imu"));
    EXPECT_THAT(e.what(), HasSubstr("torso_imu, head_imu"));
  }
  RobotHardware bare(robot->model, robot->state);  // no sensors at all
  EXPECT_TRUE(bare.imu_sensors().empty());
  EXPECT_THROW(bare.force_torque_sensor("wrist_ft"), ControllerConfigError);
}

TEST(SensorHardware, YawOfAQuaternion) {
  const double a = 0.7;
  EXPECT_NEAR(yaw_of({0.0, 0.0, std::sin(a / 2), std::cos(a / 2)}), a, 1e-12);
  // Rolled 0.3 rad then yawed: the heading stays the yaw.
  const double r = 0.3;
  const double cr = std::cos(r / 2), sr = std::sin(r / 2), cy = std::cos(a / 2), sy = std::sin(a / 2);
  EXPECT_NEAR(yaw_of({cy * sr, sy * sr, sy * cr, cy * cr}), a, 1e-12);
}

TEST(ImuSensorController, PublishesEveryHandleAtItsRateHoldingTheLastSample) {
  auto robot = testing::make_robot(1);
  auto sensors = two_imus_one_ft();
  ControllerManager manager(robot->model, robot->state, Params::from_yaml_string(kYaml), builtin_controller_registry());
  manager.set_sensor_hardware(sensors.get());
  auto* c = dynamic_cast<ImuSensorController*>(testing::load_and_start(manager, "imu"));
  ASSERT_NE(c, nullptr);
  ASSERT_EQ(c->sensor_count(), 2u);
  EXPECT_EQ(c->ports()[0]->name(), "torso_imu");
  EXPECT_EQ(c->ports()[1]->name(), "head_imu");
  const ControllerInfo info = *manager.controller_info("imu");
  EXPECT_TRUE(info.claims.empty());  // sensors claim nothing, but the interface and handles are listed
  ASSERT_EQ(info.sensors.size(), 1u);
  EXPECT_EQ(info.sensors[0].interface, "hardware_interface::ImuSensorInterface");
  EXPECT_THAT(info.sensors[0].sensors, ::testing::ElementsAre("torso_imu", "head_imu"));

  // A 100 Hz IMU: the owner writes a new sample every 10 ticks; the controller publishes at 50 Hz.
  double time = 0.0;
  std::uint64_t samples = 0;
  for (int tick = 0; tick < 1000; ++tick) {
    if (tick % 10 == 0) {
      ImuSensorData& d = sensors->imus()[0];
      d.stamp = time;
      d.count = ++samples;
      d.linear_acceleration = {0.0, 0.0, 9.81 + 0.001 * static_cast<double>(samples)};
      d.orientation_covariance[4] = 0.5;
    }
    manager.update(time, 0.001);
    robot->step(0.001);
    time += 0.001;
  }
  StatePort<ImuSnapshot>* port = c->sensor_port(0);
  // ros_controllers' timing: due when more than 1/rate has passed since the last one.
  EXPECT_GE(port->sequence(), 48u);
  EXPECT_LE(port->sequence(), 50u);
  const ImuSnapshot s = port->read();
  EXPECT_EQ(s.imu.frame_id, "imu_link");
  EXPECT_EQ(s.imu.name, "torso_imu");
  EXPECT_NEAR(s.imu.stamp, std::floor(s.stamp * 100.0 + 1e-6) / 100.0, 1e-9);  // the last 100 Hz sample
  EXPECT_GE(s.stamp, s.imu.stamp);
  EXPECT_NEAR(s.imu.linear_acceleration[2], 9.81 + 0.001 * static_cast<double>(s.imu.count), 1e-12);
  EXPECT_EQ(s.imu.orientation_covariance[4], 0.5);  // the whole matrix, not one element
  EXPECT_EQ(c->sensor_port(1)->read().imu.frame_id, "head_link");
}

TEST(ForceTorqueSensorController, PublishesTheWrenchAtItsRate) {
  auto robot = testing::make_robot(1);
  auto sensors = two_imus_one_ft();
  ControllerManager manager(robot->model, robot->state, Params::from_yaml_string(kYaml), builtin_controller_registry());
  manager.set_sensor_hardware(sensors.get());
  auto* c = dynamic_cast<ForceTorqueSensorController*>(testing::load_and_start(manager, "ft"));
  ASSERT_NE(c, nullptr);
  sensors->force_torque()[0].force = {1.0, -2.0, 9.81};
  sensors->force_torque()[0].torque = {0.0, -0.49, 0.1};
  sensors->force_torque()[0].count = 1;
  testing::run(manager, *robot, 0.0, 1001);
  StatePort<WrenchSnapshot>* port = c->sensor_port(0);
  EXPECT_GE(port->sequence(), 19u);
  EXPECT_LE(port->sequence(), 20u);
  const WrenchSnapshot s = port->read();
  EXPECT_EQ(s.wrench.frame_id, "wrist_link");
  EXPECT_EQ(s.wrench.force[1], -2.0);
  EXPECT_EQ(s.wrench.torque[1], -0.49);
}

TEST(SensorStateControllers, BadRateAndMissingSensorsAreErrorsNamingControllerAndParameter) {
  auto robot = testing::make_robot(1);
  auto sensors = two_imus_one_ft();
  ControllerManager manager(robot->model, robot->state, Params::from_yaml_string(kYaml, "c.yaml"),
                            builtin_controller_registry());
  manager.set_sensor_hardware(sensors.get());
  ControlResult r = manager.load_controller("no_rate");
  EXPECT_FALSE(r.ok);
  EXPECT_THAT(r.error, HasSubstr("'no_rate'"));
  EXPECT_THAT(r.error, HasSubstr("imu_sensor_controller/ImuSensorController"));
  EXPECT_THAT(r.error, HasSubstr("no_rate/publish_rate not set"));
  r = manager.load_controller("negative");
  EXPECT_FALSE(r.ok);
  EXPECT_THAT(r.error, HasSubstr("negative/publish_rate must be a finite rate > 0"));
  EXPECT_THAT(r.error, HasSubstr("-5"));

  ControllerManager without(robot->model, robot->state, Params::from_yaml_string(kYaml), builtin_controller_registry());
  r = without.load_controller("imu");
  EXPECT_FALSE(r.ok);
  EXPECT_THAT(r.error, HasSubstr("'imu'"));
  EXPECT_THAT(r.error, HasSubstr("the robot has no IMU"));
  r = without.load_controller("ft");
  EXPECT_FALSE(r.ok);
  EXPECT_THAT(r.error, HasSubstr("the robot has no force-torque sensor"));
  EXPECT_THAT(without.list_controller_types(), ::testing::Contains("imu_sensor_controller/ImuSensorController"));
  EXPECT_THAT(without.list_controller_types(),
              ::testing::Contains("force_torque_sensor_controller/ForceTorqueSensorController"));
}

TEST(SensorStateControllers, CheckListsTheSensorsEachReads) {
  auto robot = testing::make_robot(1);
  auto sensors = two_imus_one_ft();
  const std::vector<ControllerCheck> checks =
      check_controllers(robot->model, Params::from_yaml_string(kYaml), builtin_controller_registry(), sensors.get());
  ASSERT_EQ(checks.size(), 4u);
  EXPECT_THAT(describe(checks[0]), HasSubstr("claims nothing; reads ImuSensorInterface [torso_imu, head_imu]"));
  EXPECT_THAT(describe(checks[1]), HasSubstr("claims nothing; reads ForceTorqueSensorInterface [wrist_ft]"));
  EXPECT_THAT(describe(checks[3]), HasSubstr("ERROR"));
}

TEST(SensorStateControllers, UpdateAllocatesNothing) {
  auto robot = testing::make_robot(1);
  auto sensors = two_imus_one_ft();
  ControllerManager manager(robot->model, robot->state, Params::from_yaml_string(kYaml), builtin_controller_registry());
  manager.set_sensor_hardware(sensors.get());
  ASSERT_TRUE(manager.load_controller("imu").ok);
  ASSERT_TRUE(manager.load_controller("ft").ok);
  ASSERT_TRUE(manager.switch_controllers({"imu", "ft"}, {}, SwitchStrictness::Strict).ok);
  testing::start_counting_allocations();
  testing::run(manager, *robot, 0.0, 500);
  const long allocations = testing::stop_counting_allocations();
  EXPECT_EQ(allocations, 0);
  auto* imu = dynamic_cast<ImuSensorController*>(manager.controller("imu"));
  EXPECT_GE(imu->sensor_port(1)->sequence(), 23u);
}

}  // namespace
}  // namespace mechsim::control
