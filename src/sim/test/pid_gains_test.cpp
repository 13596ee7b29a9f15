// gazebo_ros_control's pid_gains/<joint>: a position or velocity interface driven through a PID
// to effort (DefaultRobotHWSim) when gains are given, mechsim's servo when not; which path is
// read (legacyModeNS, robotNamespace); a robotSimType mechsim cannot load is named; its e-stop
// (<eStopTopic>: joints hold, controllers restart on release).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "control/pid.hpp"
#include "control/ports.hpp"
#include "controllers/plugins/model_plugins.hpp"
#include "description/urdf/urdf_parser.hpp"
#include "sim/simulation.hpp"

namespace mechsim::sim {
namespace {

// A 1 kg bob 0.5 m out on a hinge about z (gravity does not load it, no damping):
// I = 0.001 + 1 * 0.5^2 = 0.251 kg m^2; effort limit 50 N m, velocity limit 100 rad/s.
constexpr double kInertia = 0.251;
constexpr double kEffortLimit = 50.0;
constexpr double kVelocityLimit = 100.0;
constexpr double kDt = 0.001;

std::string robot_xml(const std::string& plugin) {
  return R"(<robot name="turntable">
  <link name="world"/>
  <joint name="fix" type="fixed"><parent link="world"/><child link="post"/><origin xyz="0 0 1"/></joint>
  <link name="post"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="hinge" type="continuous">
    <parent link="post"/><child link="bob"/><axis xyz="0 0 1"/>
    <limit effort="50" velocity="100"/>
  </joint>
  <link name="bob"><inertial><origin xyz="0.5 0 0"/><mass value="1"/>
    <inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <transmission name="hinge_trans"><type>transmission_interface/SimpleTransmission</type>
    <joint name="hinge">
      <hardwareInterface>hardware_interface/PositionJointInterface</hardwareInterface>
      <hardwareInterface>hardware_interface/VelocityJointInterface</hardwareInterface>
    </joint>
    <actuator name="hinge_motor"><mechanicalReduction>1</mechanicalReduction></actuator></transmission>
  <gazebo><plugin name="gazebo_ros_control" filename="libgazebo_ros_control.so">)" +
         plugin + R"(</plugin></gazebo>
</robot>)";
}

constexpr const char* kControllers = R"(
pos: {type: position_controllers/JointPositionController, joint: hinge}
vel: {type: velocity_controllers/JointVelocityController, joint: hinge}
)";

struct Response {
  std::vector<double> q, v;  // per tick after the command, rad and rad/s
};

// Builds the simulation (controllers at `ns` of the YAML `yaml`, that YAML the parameter root),
// starts `controller`, commands `target` and records `seconds`.
Response step_response(Simulation& sim, const std::string& controller, double target, double seconds) {
  sim.load_and_start({controller});
  if (!sim.step()) throw std::runtime_error("tick failed");
  auto* port = dynamic_cast<control::ScalarCommandPort*>(sim.controllers().controller(controller)->port("command"));
  if (port == nullptr || !port->write(target)) throw std::runtime_error("no command port");
  const std::size_t j = *sim.physics().model().joint_index("hinge");
  Response run;
  const auto ticks = static_cast<int>(seconds / kDt);
  for (int k = 0; k < ticks; ++k) {
    if (!sim.step()) throw std::runtime_error("tick failed");
    run.q.push_back(sim.physics().position(j));
    run.v.push_back(sim.physics().velocity(j));
  }
  return run;
}

std::unique_ptr<Simulation> make(const std::string& plugin, const std::string& yaml, const std::string& ns = "") {
  const control::Params root = control::Params::from_yaml_string(yaml, "controllers.yaml");
  SimulationOptions options;
  options.parameter_root = root;
  return std::make_unique<Simulation>(description::parse_urdf_string(robot_xml(plugin), "turntable.urdf", {}), make_world({}),
                                      ns.empty() ? root : root.child(ns), options);
}

// The same joint integrated on its own: I qdd = clamp(pid(error)), MuJoCo's semi-implicit Euler
// (v += dt a; q += dt v), the position command ramped by the velocity limit as the safety limits
// do, the PID control_toolbox's with the same gains.
Response reference(bool position, double target, double p, double i, double d, double i_clamp, double seconds) {
  control::Pid pid(p, i, d, std::abs(i_clamp), -std::abs(i_clamp));
  double q = 0.0, v = 0.0, command = 0.0;
  Response run;
  for (int k = 0; k < static_cast<int>(seconds / kDt); ++k) {
    command = std::clamp(target, command - kVelocityLimit * kDt, command + kVelocityLimit * kDt);
    const double error = position ? command - q : target - v;
    const double tau = std::clamp(pid.compute_command(error, kDt), -kEffortLimit, kEffortLimit);
    v += kDt * tau / kInertia;
    q += kDt * v;
    run.q.push_back(q);
    run.v.push_back(v);
  }
  return run;
}

double max_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double worst = 0.0;
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k) worst = std::max(worst, std::abs(a[k] - b[k]));
  return worst;
}

std::size_t peak_index(const std::vector<double>& x) {
  return static_cast<std::size_t>(std::max_element(x.begin(), x.end()) - x.begin());
}

bool any_contains(const std::vector<std::string>& lines, const std::string& text) {
  return std::any_of(lines.begin(), lines.end(), [&](const std::string& l) { return l.find(text) != std::string::npos; });
}

// p 20, d 0.5 on I = 0.251: wn = 8.9 rad/s, zeta = 0.11, about 70 % overshoot, peak near 0.35 s.
constexpr const char* kGains = R"(
gazebo_ros_control:
  pid_gains:
    hinge: {p: 20.0, i: 0.0, d: 0.5}
)";

TEST(PidGains, PositionStepFollowsThePidAndOvershootsAsItsGainsSay) {
  auto sim = make("", std::string(kGains) + kControllers);
  ASSERT_EQ(sim->joint_drive_notes().size(), 1u);
  EXPECT_NE(sim->joint_drive_notes()[0].find("joint 'hinge': position/velocity commands through a PID to effort "
                                             "(gazebo_ros_control pid_gains at /gazebo_ros_control/pid_gains/hinge: p 20"),
            std::string::npos)
      << sim->joint_drive_notes()[0];
  const Response run = step_response(*sim, "pos", 0.5, 1.5);
  const Response ref = reference(true, 0.5, 20.0, 0.0, 0.5, 0.0, 1.5);
  const std::size_t peak = peak_index(run.q), ref_peak = peak_index(ref.q);
  std::printf("position step 0.5 rad, pid_gains p 20 d 0.5: peak %.4f rad at %zu ms (reference %.4f at %zu ms), "
              "largest difference %.5f rad\n",
              run.q[peak], peak + 1, ref.q[ref_peak], ref_peak + 1, max_difference(run.q, ref.q));
  // The derivative kick of the first tick (d * 0.5 rad / 1 ms, clamped to 50 N m) is in both.
  EXPECT_NEAR(run.q[peak], ref.q[ref_peak], 0.005 * ref.q[ref_peak]);
  EXPECT_NEAR(static_cast<double>(peak), static_cast<double>(ref_peak), 3.0);  // ticks
  EXPECT_GT(run.q[peak], 0.5 * 1.5);  // a lightly damped PID overshoots by far
  EXPECT_LT(max_difference(run.q, ref.q), 1e-4);  // measured: below 1e-5 rad
}

// load_and_start starts the controllers at once: a command written before the first tick (a
// scenario's timeline event at t = 0) is not reset by their starting().
TEST(PidGains, ACommandWrittenRightAfterLoadAndStartIsKept) {
  auto sim = make("", std::string(kGains) + kControllers);
  sim->load_and_start({"pos"});
  auto* port = dynamic_cast<control::ScalarCommandPort*>(sim->controllers().controller("pos")->port("command"));
  ASSERT_NE(port, nullptr);
  ASSERT_TRUE(port->write(0.5));
  ASSERT_TRUE(sim->run_for(3.0));
  EXPECT_NEAR(sim->physics().position(*sim->physics().model().joint_index("hinge")), 0.5, 0.01);
}

TEST(PidGains, WithoutGainsThePositionServoStaysAndDoesNotOvershoot) {
  auto sim = make("", kControllers);
  ASSERT_EQ(sim->joint_drive_notes().size(), 1u);
  EXPECT_NE(sim->joint_drive_notes()[0].find(
                "joint 'hinge': position/velocity commands through mechsim's servo (no pid_gains at "
                "/gazebo_ros_control/pid_gains/hinge)"),
            std::string::npos)
      << sim->joint_drive_notes()[0];
  const Response run = step_response(*sim, "pos", 0.5, 1.5);
  std::printf("position step 0.5 rad, servo: peak %.4f rad, final %.4f rad\n", run.q[peak_index(run.q)], run.q.back());
  EXPECT_LT(run.q[peak_index(run.q)], 0.5 * 1.01);
  EXPECT_NEAR(run.q.back(), 0.5, 0.005);
}

TEST(PidGains, VelocityCommandFollowsAFirstOrderLagOfTimeConstantIOverP) {
  auto sim = make("", std::string(R"(
gazebo_ros_control:
  pid_gains:
    hinge: {p: 2.0, i: 0.0, d: 0.0}
)") + kControllers);
  const Response run = step_response(*sim, "vel", 1.0, 0.6);
  const Response ref = reference(false, 1.0, 2.0, 0.0, 0.0, 0.0, 0.6);
  const auto tau_ticks = static_cast<std::size_t>(kInertia / 2.0 / kDt);  // 125 ms
  EXPECT_NEAR(run.v[tau_ticks], 1.0 - std::exp(-1.0), 0.02);
  EXPECT_LT(max_difference(run.v, ref.v), 0.01);
  // Without gains the velocity motor reaches the speed within a few ticks.
  auto motor = make("", kControllers);
  const Response direct = step_response(*motor, "vel", 1.0, 0.3);
  std::printf("velocity step 1 rad/s: PID (p 2) %.3f at 125 ms (reference %.3f, 1 - 1/e = 0.632); servo %.3f at 10 ms, "
              "%.3f at 300 ms\n",
              run.v[tau_ticks], ref.v[tau_ticks], direct.v[10], direct.v.back());
  EXPECT_GT(direct.v[10], 0.9);
  EXPECT_NEAR(direct.v.back(), 1.0, 0.01);
}

TEST(PidGains, LegacyModeNsDecidesWhichPathIsRead) {
  const std::string in_root = std::string(kGains) + "arm:\n" + R"(
  pos: {type: position_controllers/JointPositionController, joint: hinge}
)";
  const std::string in_namespace = R"(
arm:
  gazebo_ros_control:
    pid_gains:
      hinge: {p: 20.0, i: 0.0, d: 0.5}
  pos: {type: position_controllers/JointPositionController, joint: hinge}
)";
  // legacyModeNS false: <robotNamespace>/gazebo_ros_control/pid_gains/<joint>.
  {
    auto sim = make("<robotNamespace>/arm</robotNamespace><legacyModeNS>false</legacyModeNS>", in_namespace, "arm");
    EXPECT_TRUE(any_contains(sim->joint_drive_notes(), "through a PID to effort (gazebo_ros_control pid_gains at "
                                                       "/arm/gazebo_ros_control/pid_gains/hinge"));
    const Response run = step_response(*sim, "pos", 0.5, 0.6);
    EXPECT_GT(run.q[peak_index(run.q)], 0.75);
  }
  {
    auto sim = make("<robotNamespace>/arm</robotNamespace><legacyModeNS>false</legacyModeNS>", in_root, "arm");
    EXPECT_TRUE(any_contains(sim->joint_drive_notes(),
                             "through mechsim's servo (no pid_gains at /arm/gazebo_ros_control/pid_gains/hinge); gains at "
                             "/gazebo_ros_control/pid_gains/hinge are not read: legacyModeNS is false"));
  }
  // Absent (Gazebo's default, true) or true: the absolute /gazebo_ros_control/pid_gains/<joint>.
  {
    auto sim = make("<robotNamespace>/arm</robotNamespace>", in_root, "arm");
    EXPECT_TRUE(any_contains(sim->joint_drive_notes(), "pid_gains at /gazebo_ros_control/pid_gains/hinge: p 20"));
  }
  {
    auto sim = make("<robotNamespace>/arm</robotNamespace>", in_namespace, "arm");
    EXPECT_TRUE(any_contains(sim->joint_drive_notes(),
                             "gains at /arm/gazebo_ros_control/pid_gains/hinge are not read: legacyModeNS is absent "
                             "(Gazebo's default: true)"));
    const Response run = step_response(*sim, "pos", 0.5, 1.0);
    EXPECT_LT(run.q[peak_index(run.q)], 0.5 * 1.01);  // the servo
  }
}

TEST(PidGains, ARobotSimTypeMechsimCannotLoadIsNamed) {
  auto sim = make("<robotSimType>my_robot_hw/MyRobotHWSim</robotSimType>", kControllers);
  EXPECT_TRUE(any_contains(sim->physics_warnings(),
                           "turntable.urdf:17: gazebo_ros_control robotSimType 'my_robot_hw/MyRobotHWSim' is not simulated"))
      << ::testing::PrintToString(sim->physics_warnings());
  // mechsim check lists it with the plugin.
  const std::vector<control::ModelPluginStatus> status = control::model_plugin_status(sim->robot());
  ASSERT_EQ(status.size(), 1u);
  EXPECT_NE(control::describe(status[0]).find("robotSimType 'my_robot_hw/MyRobotHWSim' is NOT SIMULATED"), std::string::npos)
      << control::describe(status[0]);
  auto plain = make("<robotSimType>gazebo_ros_control/DefaultRobotHWSim</robotSimType>", kControllers);
  EXPECT_FALSE(any_contains(plain->physics_warnings(), "robotSimType"));
}

// <controlPeriod>: the controllers update every 5 ticks with a 5 ms period; the PID runs every tick.
TEST(PidGains, ControlPeriodSpacesTheControllerUpdates) {
  auto sim = make("<controlPeriod>0.005</controlPeriod>", std::string(kGains) + kControllers);
  EXPECT_DOUBLE_EQ(sim->control_period(), 0.005);
  const Response run = step_response(*sim, "pos", 0.5, 0.3);
  auto* state = dynamic_cast<control::StatePort<control::JointControllerState>*>(sim->controllers().controller("pos")->port("state"));
  ASSERT_NE(state, nullptr);
  const control::JointControllerState s = state->read();
  EXPECT_DOUBLE_EQ(s.time_step, 0.005);
  EXPECT_NEAR(std::fmod(s.stamp + 1e-9, 0.005), 0.0, 1e-6);  // updated on multiples of 5 ms only
  EXPECT_GT(run.q[peak_index(run.q)], 0.75);                  // the PID still drives the step
  // Faster than the step, or not a whole number of steps: said, and rounded.
  auto fast = make("<controlPeriod>0.0001</controlPeriod>", kControllers);
  EXPECT_DOUBLE_EQ(fast->control_period(), 0.001);
  EXPECT_TRUE(any_contains(fast->physics_warnings(), "controlPeriod 0.0001 s is shorter than the period 0.001 s"));
  auto odd = make("<controlPeriod>0.0025</controlPeriod>", kControllers);
  EXPECT_TRUE(any_contains(odd->physics_warnings(), "controlPeriod 0.0025 s is not a whole number of periods"));
}

TEST(PidGains, BadPluginElementsNameTheirLine) {
  try {
    make("\n<legacyModeNS>maybe</legacyModeNS>", kControllers);
    FAIL() << "expected an error";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("turntable.urdf:18: gazebo_ros_control <legacyModeNS>maybe</legacyModeNS> is not a boolean"),
              std::string::npos)
        << e.what();
  }
}

// ---- e-stop (DefaultRobotHWSim::eStopActive, GazeboRosControlPlugin's reset_controllers)

void run_ticks(Simulation& sim, double seconds) {
  for (int k = 0; k < static_cast<int>(std::lround(seconds / kDt)); ++k) {
    if (!sim.step()) throw std::runtime_error("tick failed");
  }
}

control::ScalarCommandPort& command_port(Simulation& sim, const std::string& controller) {
  auto* port = dynamic_cast<control::ScalarCommandPort*>(sim.controllers().controller(controller)->port("command"));
  if (port == nullptr) throw std::runtime_error("no command port on " + controller);
  return *port;
}

TEST(EStop, TheTopicComesFromThePluginElement) {
  EXPECT_EQ(make("<eStopTopic>e_stop</eStopTopic>", kControllers)->e_stop_topic(), "e_stop");
  EXPECT_EQ(make("", kControllers)->e_stop_topic(), "");
}

// Servo path (no pid_gains): a position joint stopped mid-step stays where the e-stop found it
// while the controller keeps commanding 1 rad; on release the controller restarts, and a position
// controller's start takes the current position as its command: the joint stays there.
TEST(EStop, APositionJointHoldsWhereItWasAndStaysThereAfterTheRelease) {
  auto sim = make("<eStopTopic>e_stop</eStopTopic>", kControllers);
  const std::size_t j = *sim->physics().model().joint_index("hinge");
  sim->load_and_start({"pos"});
  run_ticks(*sim, 0.001);
  ASSERT_TRUE(command_port(*sim, "pos").write(1.0));
  run_ticks(*sim, 0.03);  // on its way: the servo follows the command (ramped at 100 rad/s)
  sim->set_e_stop(true);
  run_ticks(*sim, 0.001);
  const double held = sim->physics().position(j);
  EXPECT_GT(held, 0.02);
  EXPECT_LT(held, 0.9);
  run_ticks(*sim, 1.0);
  std::printf("e-stop at %.4f rad on the way to 1 rad: %.4f rad after 1 s\n", held, sim->physics().position(j));
  EXPECT_NEAR(sim->physics().position(j), held, 0.01);
  EXPECT_EQ(sim->controllers().controller_info("pos")->state, control::ControllerLifecycle::Running);
  sim->set_e_stop(false);
  run_ticks(*sim, 0.5);
  EXPECT_NEAR(sim->physics().position(j), held, 0.01);  // restarted: its command is where it stood
  // A new command after the release moves it again.
  ASSERT_TRUE(command_port(*sim, "pos").write(1.0));
  run_ticks(*sim, 0.5);
  EXPECT_NEAR(sim->physics().position(j), 1.0, 0.01);
}

TEST(EStop, AVelocityJointStopsAndMovesAgainOnlyOnANewCommand) {
  auto sim = make("<eStopTopic>e_stop</eStopTopic>", kControllers);
  const std::size_t j = *sim->physics().model().joint_index("hinge");
  sim->load_and_start({"vel"});
  run_ticks(*sim, 0.001);
  ASSERT_TRUE(command_port(*sim, "vel").write(2.0));
  run_ticks(*sim, 0.2);
  EXPECT_NEAR(sim->physics().velocity(j), 2.0, 0.05);
  sim->set_e_stop(true);
  run_ticks(*sim, 0.05);
  std::printf("velocity 50 ms into the e-stop: %.4f rad/s (2 rad/s before)\n", sim->physics().velocity(j));
  EXPECT_NEAR(sim->physics().velocity(j), 0.0, 0.05);
  const double q = sim->physics().position(j);
  run_ticks(*sim, 0.5);
  EXPECT_NEAR(sim->physics().position(j), q, 0.02);  // at 2 rad/s it would have turned 1 rad
  sim->set_e_stop(false);
  run_ticks(*sim, 0.2);
  // The velocity controller's start commands zero: the 2 rad/s from before the e-stop is gone.
  EXPECT_NEAR(sim->physics().velocity(j), 0.0, 0.05);
  ASSERT_TRUE(command_port(*sim, "vel").write(-1.0));
  run_ticks(*sim, 0.2);
  EXPECT_NEAR(sim->physics().velocity(j), -1.0, 0.05);
}

// With pid_gains the PID pulls the joint back to the position latched at the e-stop (it overshoots
// that position first: the joint was moving).
TEST(EStop, WithPidGainsThePidHoldsTheLatchedPosition) {
  constexpr const char* kDamped = R"(
gazebo_ros_control:
  pid_gains:
    hinge: {p: 20.0, i: 0.0, d: 4.0}
)";
  auto sim = make("<eStopTopic>e_stop</eStopTopic>", std::string(kDamped) + kControllers);
  const std::size_t j = *sim->physics().model().joint_index("hinge");
  sim->load_and_start({"pos"});
  run_ticks(*sim, 0.001);
  ASSERT_TRUE(command_port(*sim, "pos").write(1.0));
  run_ticks(*sim, 0.1);
  sim->set_e_stop(true);
  run_ticks(*sim, 0.001);
  const double held = sim->physics().position(j);
  EXPECT_LT(held, 0.8);
  run_ticks(*sim, 3.0);
  std::printf("pid_gains e-stop: latched %.4f rad, %.4f rad 3 s later\n", held, sim->physics().position(j));
  EXPECT_NEAR(sim->physics().position(j), held, 0.01);
}

TEST(EStop, AResetDuringTheEStopHoldsTheSpawnPosition) {
  auto sim = make("<eStopTopic>e_stop</eStopTopic>", kControllers);
  const std::size_t j = *sim->physics().model().joint_index("hinge");
  sim->load_and_start({"vel"});
  run_ticks(*sim, 0.001);
  ASSERT_TRUE(command_port(*sim, "vel").write(2.0));
  run_ticks(*sim, 0.3);
  sim->set_e_stop(true);
  run_ticks(*sim, 0.1);
  sim->reset();
  run_ticks(*sim, 0.3);
  EXPECT_NEAR(sim->physics().position(j), 0.0, 1e-3);
  EXPECT_TRUE(sim->e_stop_active());
}

}  // namespace
}  // namespace mechsim::sim
