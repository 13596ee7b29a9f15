// Sensors in whole simulations: the CC8's ZED2 IMU on a turning rover (its integrated gyro yaw
// against the true yaw over 10 s, noise on as configured), the shipped sensor scenarios (PR2
// lasers before a box, a laser added by a scenario over the Mars Yard), reproducible noise (the
// same scenario and seed give bit-identical sensor files, another seed other noise), and a bad
// sensor block in a scenario named by file and line.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "controllers/drive/rover_drive_ports.hpp"
#include "description/robot_loader.hpp"
#include "sim/pose_math.hpp"
#include "sim/route_follower.hpp"
#include "sim/scenario.hpp"
#include "sim/scenario_runner.hpp"
#include "sim/simulation.hpp"
#include "sim/world.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

const fs::path kSource = MECHSIM_SOURCE_DIR;

struct TempDir {
  fs::path path;
  TempDir() : path(fs::path(::testing::TempDir()) / ("mechsim_sensor_scenarios_" + std::to_string(::getpid()))) {
    fs::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(Cc8Imu, IntegratedGyroYawMatchesTheTrueYawOverTenSeconds) {
  description::LoadOptions load;
  load.packages["mechsim_cc8"] = (kSource / "robots/cc8").string();
  description::LoadedRobot robot = description::load_robot((kSource / "robots/cc8/urdf/cc8.urdf.xacro").string(), load);
  const control::Params params = control::Params::from_yaml_file((kSource / "robots/cc8/config/controllers.yaml").string()).child("cc8");
  SimulationOptions options;
  options.spawn.z = 0.01;
  Simulation sim(std::move(robot.model), make_world({}), params, options);
  sim.load_and_start({"joint_state_controller", "rover_drive_controller"});
  const auto imu = sim.sensors().find("zed2_imu_sensor");
  ASSERT_TRUE(imu.has_value());
  control::TwistCommandPort* cmd = nullptr;
  for (control::Port* p : sim.controllers().controller("rover_drive_controller")->ports())
    if (p->kind() == control::PortKind::TwistCommand) cmd = dynamic_cast<control::TwistCommandPort*>(p);
  ASSERT_NE(cmd, nullptr);

  // An Ackermann turn: 0.3 m/s and 0.4 rad/s from t = 0.5 s, for 10 s of gyro integration.
  control::Twist twist;
  twist.linear.x = 0.3;
  twist.angular.z = 0.4;
  double gyro_yaw = 0.0, true_yaw = 0.0, last_rate = 0.0, last_stamp = -1.0;
  double last_true = yaw_of(sim.physics().base_pose().orientation);
  std::uint64_t seen = sim.sensors().reading(*imu).count;
  while (sim.time() < 10.5 - 1e-9) {
    if (sim.ticks() % 20 == 0) cmd->write(twist);
    ASSERT_TRUE(sim.step().ok);
    const double y = yaw_of(sim.physics().base_pose().orientation);
    true_yaw += wrap_angle(y - last_true);
    last_true = y;
    const sensors::SensorReading& r = sim.sensors().reading(*imu);
    if (r.count == seen) continue;
    seen = r.count;
    // The sensor frame is level on the rover: its z rate is the yaw rate. Trapezoids between
    // samples (100 Hz).
    const double rate = std::get<sensors::ImuReading>(r.value).angular_velocity.z;
    if (last_stamp >= 0.0) gyro_yaw += 0.5 * (rate + last_rate) * (r.stamp - last_stamp);
    last_rate = rate;
    last_stamp = r.stamp;
  }
  const double error = std::abs(gyro_yaw - true_yaw) / std::abs(true_yaw);
  std::printf("CC8 turning 10 s: true yaw %.4f rad, integrated ZED2 gyro %.4f rad, error %.3f %%\n", true_yaw, gyro_yaw,
              100 * error);
  EXPECT_GT(std::abs(true_yaw), 3.0);
  EXPECT_LT(error, 0.005);
}

TEST(SensorScenarios, SameSeedGivesBitIdenticalSensorFilesAnotherSeedOtherNoise) {
  Scenario s = load_scenario((kSource / "robots/pr2/scenarios/base_laser_box.yaml").string());
  s.duration = 0.5;
  s.checks.clear();
  TempDir dir;
  RunOptions options;
  options.plots = false;
  std::vector<std::string> files;
  for (const std::uint64_t seed : {5u, 5u, 6u}) {
    s.seed = seed;
    options.output_dir = (dir.path / ("run" + std::to_string(files.size()))).string();
    const ScenarioResult r = run_scenario(s, options);
    ASSERT_TRUE(r.completed) << r.error;
    files.push_back(read_file(fs::path(options.output_dir) / "sensors" / "base_laser.csv") +
                    read_file(fs::path(options.output_dir) / "sensors" / "laser_tilt.csv"));
  }
  ASSERT_GT(files[0].size(), 1000u);
  EXPECT_EQ(files[0], files[1]) << "same scenario, same seed";
  EXPECT_NE(files[0], files[2]) << "another seed";
  // 20 Hz from t = 0 to 0.5 s: 11 scans, and the header.
  const std::string& f = files[0];
  EXPECT_EQ(std::count(f.begin(), f.begin() + static_cast<long>(f.find("t,", 10)), '\n'), 12);
}

TEST(SensorScenarios, ShippedSensorScenariosMeetTheirChecks) {
  TempDir dir;
  for (const char* file : {"robots/pr2/scenarios/base_laser_box.yaml", "robots/cc8/scenarios/laser_mars_yard.yaml"}) {
    const Scenario s = load_scenario((kSource / file).string());
    RunOptions options;
    options.output_dir = (dir.path / s.name).string();
    const ScenarioResult r = run_scenario(s, options);
    for (const CheckOutcome& c : r.checks) std::printf("[ figures  ] %s: %s %s\n", s.name.c_str(), c.passed ? "PASS" : "FAIL", c.detail.c_str());
    EXPECT_TRUE(r.passed) << file << ": " << r.error;
    EXPECT_TRUE(fs::exists(fs::path(options.output_dir) / "laser_scans.png")) << file;
    for (const std::string& w : r.warnings) ADD_FAILURE() << file << ": " << w;
  }
}

TEST(SensorScenarios, BadSensorBlockIsAnErrorNamingTheScenarioLine) {
  TempDir dir;
  const fs::path file = dir.path / "bad.yaml";
  std::ofstream(file) << "name: bad\n"
                         "robot:\n"
                         "  description: " << (kSource / "robots/cc8/urdf/cc8.urdf.xacro").string() << "\n"
                         "  packages: {mechsim_cc8: " << (kSource / "robots/cc8").string() << "}\n"
                         "controllers:\n"
                         "  file: " << (kSource / "robots/cc8/config/controllers.yaml").string() << "\n"
                         "  namespace: cc8\n"
                         "  start: [joint_state_controller]\n"
                         "duration: 0.1\n"
                         "sensors:\n"
                         "  - |\n"
                         "    <gazebo reference=\"base_link\">\n"
                         "      <sensor type=\"ray\" name=\"bad_laser\">\n"
                         "        <update_rate>-3</update_rate>\n"
                         "      </sensor>\n"
                         "    </gazebo>\n";
  const Scenario s = load_scenario(file.string());
  try {
    run_scenario(s, RunOptions{});
    FAIL() << "no error";
  } catch (const ScenarioError& e) {
    EXPECT_THAT(e.what(), HasSubstr(file.string() + ":14: sensor 'bad_laser': <update_rate> must be >= 0"));
  }
}

}  // namespace
}  // namespace mechsim::sim
