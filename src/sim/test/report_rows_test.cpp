// What a run's CSV files say, checked against physics: a pendulum on a cart that slides without
// friction, so that the centre of mass stays put and the cart's x (base.csv) and the pendulum's
// angle (joints.csv) are tied at every instant. Every file's row stamped t must hold the state
// at t (the rows were a tick late in joints.csv and controllers.csv, and the t = 0 row ignored
// spawn.joints), and joints without a transmission (the pendulum's hinge) must be recorded.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "sim/scenario.hpp"
#include "sim/scenario_runner.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;

// Cart: 5 kg, a 1.2 m square plate sliding on frictionless feet. Pendulum: 5 kg at 1 m below a
// passive hinge about y, 5 cm above the cart's origin (no collision: it swings through the
// ground). Flag: an actuated hinge about z at (0.3, 0, 0.05) whose mass sits on its axis, moved by
// a position controller (it moves no mass sideways). RK4, so that the centre of mass stays put to
// 1e-4 m over the run (semi-implicit Euler drifts it by 1e-3 m: q moves by dt v per step while the
// bob moves along a circle).
constexpr double kCartMass = 5.0, kBobMass = 5.0, kFlagMass = 0.5, kLength = 1.0, kHinge = 0.05, kFlagX = 0.3;
constexpr const char* kCartPole = R"(<robot name="cartpole">
  <link name="cart">
    <inertial><mass value="5"/><inertia ixx="0.6" iyy="0.6" izz="1.2" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="1.2 1.2 0.1"/></geometry></collision>
  </link>
  <gazebo reference="cart"><mu1>0</mu1><mu2>0</mu2></gazebo>
  <joint name="swing" type="continuous">
    <parent link="cart"/><child link="bob"/><origin xyz="0 0 0.05"/><axis xyz="0 1 0"/>
  </joint>
  <link name="bob"><inertial><origin xyz="0 0 -1"/><mass value="5"/>
    <inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="flag" type="revolute">
    <parent link="cart"/><child link="flag"/><origin xyz="0.3 0 0.05"/><axis xyz="0 0 1"/>
    <limit lower="-2" upper="2" effort="20" velocity="5"/>
  </joint>
  <link name="flag"><inertial><mass value="0.5"/>
    <inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <transmission name="t"><type>transmission_interface/SimpleTransmission</type>
    <joint name="flag"><hardwareInterface>hardware_interface/EffortJointInterface</hardwareInterface></joint>
    <actuator name="m"><mechanicalReduction>1</mechanicalReduction></actuator></transmission>
</robot>)";

constexpr const char* kControllers = R"(c:
  flag_controller:
    type: effort_controllers/JointPositionController
    joint: flag
    pid: {p: 20.0, d: 1.0, i: 0.0}
)";

constexpr double kSwing0 = 1.0;  // rad, spawn.joints

// A CSV file as columns by header name.
struct Csv {
  std::vector<std::string> names;
  std::map<std::string, std::vector<double>> columns;
  const std::vector<double>& operator[](const std::string& name) const {
    const auto it = columns.find(name);
    if (it == columns.end()) throw std::runtime_error("no column '" + name + "'");
    return it->second;
  }
  std::size_t rows() const { return columns.empty() ? 0 : columns.begin()->second.size(); }
};

Csv read_csv(const fs::path& file) {
  Csv csv;
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  std::stringstream header(line);
  for (std::string name; std::getline(header, name, ',');) csv.names.push_back(name);
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::string cell;
    for (const std::string& name : csv.names) {
      std::getline(row, cell, ',');
      csv.columns[name].push_back(cell.empty() ? std::nan("") : std::stod(cell));
    }
  }
  return csv;
}

class ReportRows : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mechsim_report_rows_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    std::ofstream(dir_ / "cartpole.urdf") << kCartPole;
    std::ofstream(dir_ / "controllers.yaml") << kControllers;
    std::ofstream(dir_ / "s.yaml") << "robot: {description: cartpole.urdf}\n"
                                   << "controllers: {file: controllers.yaml, namespace: c, start: [flag_controller]}\n"
                                   << "spawn: {z: 0.05, joints: {swing: " << kSwing0 << "}}\n"
                                   << "duration: 1.5\nrecord_rate: 1000\nintegrator: rk4\n"
                                   << "timeline:\n  - {at: 0.1, controller: flag_controller, command: 0.4}\n";
    RunOptions options;
    options.output_dir = (dir_ / "out").string();
    options.plots = false;
    result_ = run_scenario(load_scenario((dir_ / "s.yaml").string()), options);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
  ScenarioResult result_;
};

TEST_F(ReportRows, JointsBaseAndControllersDescribeTheSameInstant) {
  ASSERT_TRUE(result_.completed) << result_.error;
  const Csv joints = read_csv(dir_ / "out" / "joints.csv");
  const Csv base = read_csv(dir_ / "out" / "base.csv");
  const Csv controllers = read_csv(dir_ / "out" / "controllers.csv");

  // Actuated joints: position, velocity, effort, command; passive ones: position, velocity.
  EXPECT_EQ(joints.names, (std::vector<std::string>{"time", "flag/position", "flag/velocity", "flag/effort", "flag/command",
                                                    "swing/position", "swing/velocity"}));
  ASSERT_EQ(joints.rows(), base.rows());
  ASSERT_EQ(joints.rows(), controllers.rows());
  // Every tick of [0, 1.5) s: rows 0, 0.001, ..., 1.499.
  ASSERT_EQ(joints.rows(), 1500u);
  EXPECT_DOUBLE_EQ(joints["time"].back(), 1.499);

  // t = 0 holds the spawn state (spawn.joints).
  EXPECT_DOUBLE_EQ(joints["swing/position"][0], kSwing0);
  EXPECT_EQ(joints["swing/velocity"][0], 0.0);

  // No horizontal force on the robot: the centre of mass keeps its x. With the cart's pitch p
  // (tiny): the bob at x_cart + h sin(p) - l sin(q + p), the flag at x_cart + f cos(p) + h sin(p).
  const double total = kCartMass + kBobMass + kFlagMass;
  auto com_x = [&](std::size_t row, std::size_t swing_row) {
    const double x = base["x"][row], p = base["pitch"][row], q = joints["swing/position"][swing_row];
    return (kCartMass * x + kFlagMass * (x + kFlagX * std::cos(p) + kHinge * std::sin(p)) +
            kBobMass * (x + kHinge * std::sin(p) - kLength * std::sin(q + p))) / total;
  };
  double worst = 0.0, worst_shifted = 0.0;
  for (std::size_t k = 1; k < joints.rows(); ++k) {
    ASSERT_DOUBLE_EQ(joints["time"][k], base["time"][k]);
    worst = std::max(worst, std::abs(com_x(k, k) - com_x(0, 0)));
    // The same relation with the angle one row (one tick) old: what a tick-late file shows.
    worst_shifted = std::max(worst_shifted, std::abs(com_x(k, k - 1) - com_x(0, 0)));
  }
  EXPECT_LT(worst, 2e-4) << "m: the cart's x and the pendulum angle at the same stamp disagree";
  EXPECT_GT(worst_shifted, 1e-3) << "m: the check cannot tell a tick-late file";

  // Within joints.csv, a row's velocity is that of its positions: the central difference of the
  // neighbouring rows (a velocity one tick older is off by q'' dt, up to 1e-2 rad/s).
  const std::vector<double>& q = joints["swing/position"];
  const std::vector<double>& v = joints["swing/velocity"];
  double worst_rate = 0.0;
  for (std::size_t k = 1; k + 1 < joints.rows(); ++k) worst_rate = std::max(worst_rate, std::abs(v[k] - (q[k + 1] - q[k - 1]) / 0.002));
  EXPECT_LT(worst_rate, 2e-3) << "rad/s";
  const double swing_range = *std::max_element(joints["swing/position"].begin(), joints["swing/position"].end()) -
                             *std::min_element(joints["swing/position"].begin(), joints["swing/position"].end());
  EXPECT_GT(swing_range, 1.5) << "the pendulum swings through its bottom";

  // The controller's process value and command at t are the joint's position and command at t
  // (the joint's after the 20 N m effort limit).
  for (std::size_t k = 0; k < joints.rows(); ++k) {
    ASSERT_EQ(controllers["flag_controller/process_value"][k], joints["flag/position"][k]) << "row " << k;
    ASSERT_EQ(std::clamp(controllers["flag_controller/command"][k], -20.0, 20.0), joints["flag/command"][k]) << "row " << k;
  }
  EXPECT_NEAR(joints["flag/position"].back(), 0.4, 0.02);
}

}  // namespace
}  // namespace mechsim::sim
