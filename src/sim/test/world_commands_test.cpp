// What Gazebo's world API needs of a Simulation (the ROS node's gzserver mode): a start time for a
// robot that joins a running world, commands run in the loop between ticks, steps while paused,
// and external wrenches and joint efforts with Gazebo's timing.

#include <gtest/gtest.h>

#include <thread>

#include "description/urdf/urdf_parser.hpp"
#include "sim/external_forces.hpp"
#include "sim/simulation.hpp"

namespace mechsim::sim {
namespace {

// A free 2 kg box with a 0.5 kg paddle on a hinge about z through the box's centre (the paddle's
// own centre on the axis, so that the two turn independently of the box's translation).
constexpr const char* kBox = R"(<robot name="box">
  <link name="base"><inertial><mass value="2"/><inertia ixx="0.0134" iyy="0.0134" izz="0.0134" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision></link>
  <joint name="paddle_joint" type="continuous"><parent link="base"/><child link="paddle"/><origin xyz="0 0 0.15"/><axis xyz="0 0 1"/></joint>
  <link name="paddle"><inertial><mass value="0.5"/><inertia ixx="0.0001" iyy="0.0017" izz="0.0017" ixy="0" ixz="0" iyz="0"/></inertial></link>
</robot>)";

std::unique_ptr<Simulation> make(SimulationOptions options) {
  description::RobotModel robot = description::parse_urdf_string(kBox, "box", {});
  options.spawn.z = 2.0;  // in the air
  return std::make_unique<Simulation>(std::move(robot), make_world({}), control::Params(), options);
}

TEST(ForceWindow, FollowsGazebosStartAndDuration) {
  const ForceWindow past = force_window(2.0, 0.001, 1.0, 0.5);  // a start in the past is now
  EXPECT_DOUBLE_EQ(past.start, 2.0);
  EXPECT_DOUBLE_EQ(past.end, 2.5);
  EXPECT_FALSE(force_window(2.0, 0.001, 0.0, -1.0).over_at(1e9));  // < 0: no end
  const ForceWindow none = force_window(2.0, 0.001, 0.0, 0.0);     // 0: nothing
  EXPECT_FALSE(none.active_at(2.0));
  const ForceWindow tick = force_window(2.0, 0.001, 0.0, 1e-6);  // shorter than a tick: one tick
  EXPECT_TRUE(tick.active_at(2.0));
  EXPECT_FALSE(tick.active_at(2.001));
  EXPECT_TRUE(force_window(2.0, 0.001, 3.0, 1.0).active_at(3.5));
  EXPECT_FALSE(force_window(2.0, 0.001, 3.0, 1.0).active_at(2.5));
}

TEST(WorldCommands, StartTimeContinuesTheWorldsClock) {
  SimulationOptions o;
  o.start_time = 12.345;
  auto sim = make(o);
  EXPECT_DOUBLE_EQ(sim->time(), 12.345);
  ASSERT_TRUE(sim->step());
  EXPECT_NEAR(sim->time(), 12.346, 1e-12);
  o.start_time = -1.0;
  EXPECT_THROW(make(o), std::invalid_argument);
}

TEST(WorldCommands, PostedCommandsRunBetweenTicksAndStepsRunWhilePaused) {
  SimulationOptions o;
  o.start_paused = true;
  auto sim = make(o);
  std::uint64_t seen_at = 99;
  sim->post([&](Simulation& s) { seen_at = s.ticks(); });
  EXPECT_EQ(seen_at, 99u) << "a command ran outside the loop";
  sim->request_steps(5);
  // The loop thread: paused, it applies the command, then ticks the five steps.
  std::thread loop([&] {
    for (int i = 0; i < 10; ++i) sim->run_for(sim->period());
  });
  EXPECT_TRUE(sim->wait_for_commands(5.0));
  loop.join();
  EXPECT_EQ(seen_at, 0u);
  EXPECT_EQ(sim->ticks(), 5u);
  EXPECT_EQ(sim->pending_steps(), 0u);
  EXPECT_TRUE(sim->paused());
}

TEST(WorldCommands, AWrenchActsForItsDurationAndAnEffortUntilCleared) {
  SimulationOptions o;
  auto sim = make(o);
  sim->physics().set_gravity({0.0, 0.0, 0.0});
  const std::size_t base = *sim->physics().model().link_index("base");
  const std::size_t paddle = *sim->physics().model().joint_index("paddle_joint");
  // 5 N along y for 0.2 s through the robot's centre of mass (0.03 m above the box's: the
  // paddle's 0.5 kg at 0.15 m): the 2.5 kg robot gains 0.4 m/s and keeps it.
  sim->external_forces().add_wrench({base, {0.0, 5.0, 0.0}, {}, {0.0, 0.0, 0.03}},
                                    force_window(sim->time(), sim->period(), 0.0, 0.2));
  // 0.01 N m on the paddle until cleared.
  sim->external_forces().add_effort(paddle, 0.01, force_window(sim->time(), sim->period(), 0.0, -1.0));
  ASSERT_TRUE(sim->run_for(0.3));
  EXPECT_NEAR(sim->physics().base_twist().linear.y, 0.4, 1e-3);
  EXPECT_NEAR(sim->physics().base_twist().linear.x, 0.0, 1e-6);
  const double rate = sim->physics().velocity(paddle);
  EXPECT_GT(rate, 0.5) << "the effort did not turn the paddle";
  sim->external_forces().clear_efforts(paddle);
  ASSERT_TRUE(sim->run_for(0.1));
  EXPECT_NEAR(sim->physics().velocity(paddle), rate, 0.02 * rate) << "the cleared effort still acts";
  EXPECT_TRUE(sim->external_forces().empty());
  // reset() clears what is queued.
  sim->external_forces().add_effort(paddle, 1.0, force_window(sim->time(), sim->period(), 0.0, -1.0));
  sim->reset();
  EXPECT_TRUE(sim->external_forces().empty());
}

}  // namespace
}  // namespace mechsim::sim
