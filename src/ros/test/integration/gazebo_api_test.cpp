// gazebo_ros' /gazebo/* API on mechsim_node in gzserver mode (~gazebo:=true), against a real
// master: a small robot (a floating box with a revolute arm, effort transmission, the
// gazebo_ros_control plugin under /bot) spawned through /gazebo/spawn_urdf_model, read and moved
// through gazebo_msgs services, pushed with wrenches and efforts, stepped while paused; bad
// requests are refused with a message while the world keeps running; spawn_model -J sets the
// joints before any unpause. Each test's waits add up to well under 60 s (wall).
#include <gmock/gmock.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <mutex>

#include <controller_manager_msgs/ListControllers.h>
#include <gazebo_msgs/ApplyBodyWrench.h>
#include <gazebo_msgs/ApplyJointEffort.h>
#include <gazebo_msgs/DeleteModel.h>
#include <gazebo_msgs/GetJointProperties.h>
#include <gazebo_msgs/GetLinkProperties.h>
#include <gazebo_msgs/GetLinkState.h>
#include <gazebo_msgs/GetModelProperties.h>
#include <gazebo_msgs/GetModelState.h>
#include <gazebo_msgs/GetPhysicsProperties.h>
#include <gazebo_msgs/GetWorldProperties.h>
#include <gazebo_msgs/JointRequest.h>
#include <gazebo_msgs/ModelStates.h>
#include <gazebo_msgs/PerformanceMetrics.h>
#include <gazebo_msgs/SetModelConfiguration.h>
#include <gazebo_msgs/SetModelState.h>
#include <gazebo_msgs/SetPhysicsProperties.h>
#include <gazebo_msgs/SpawnModel.h>
#include <mechsim_msgs/StepSimulation.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/JointState.h>
#include <std_srvs/Empty.h>

#include "gazebo_world_fixture.hpp"

namespace mechsim::ros::test {
namespace {

TEST_F(GazeboWorldNode, SpawnsIntoARunningWorldWithoutATimeJump) {
  start(false);
  ASSERT_TRUE(wait_until([&] { return clock_now() > 0.3; }, 10.0)) << "the empty world's clock does not run";
  const double before = clock_now();
  const auto s = spawn("bot", kBot, pose_at(1.0, 2.0, 0.2));
  ASSERT_TRUE(s.response.success) << s.response.status_message << "\n" << node_->log();
  const auto g = model_state("bot");
  ASSERT_TRUE(g.response.success) << g.response.status_message;
  EXPECT_NEAR(g.response.pose.position.x, 1.0, 0.01);
  EXPECT_NEAR(g.response.pose.position.y, 2.0, 0.01);
  EXPECT_GE(g.response.header.stamp.toSec(), before) << "time went back at the spawn";
  gazebo_msgs::GetWorldProperties w;
  ASSERT_TRUE(call("/gazebo/get_world_properties", w));
  EXPECT_THAT(w.response.model_names, ::testing::ElementsAre("ground_plane", "bot"));
  EXPECT_GE(w.response.sim_time, before);
  // The robot's loop goes on with the clock.
  const double after = clock_now();
  EXPECT_TRUE(wait_until([&] { return clock_now() > after + 0.2; }, 5.0));
  gazebo_msgs::GetModelProperties m;
  m.request.model_name = "bot";
  ASSERT_TRUE(call("/gazebo/get_model_properties", m));
  EXPECT_EQ(m.response.canonical_body_name, "base");
  EXPECT_THAT(m.response.body_names, ::testing::ElementsAre("base", "arm"));
  EXPECT_THAT(m.response.joint_names, ::testing::ElementsAre("arm_joint"));
  // The model's own controller manager under the plugin's namespace.
  controller_manager_msgs::ListControllers list;
  EXPECT_TRUE(call("/bot/controller_manager/list_controllers", list, 5.0));
}

TEST_F(GazeboWorldNode, RefusesBadRequestsWithAMessageAndKeepsRunning) {
  start(false);
  ASSERT_TRUE(spawn("bot", kBot, pose_at(0, 0, 0.2)).response.success) << node_->log();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<std::string> messages;
  {  // unknown model
    const auto g = model_state("no_such_model");
    EXPECT_FALSE(g.response.success);
    messages.push_back(g.response.status_message);
  }
  {  // NaN pose
    const auto s = spawn("other", kBot, pose_at(nan, 0, 0));
    EXPECT_FALSE(s.response.success);
    messages.push_back(s.response.status_message);
  }
  {  // malformed URDF
    const auto s = spawn("broken", "<robot name='broken'><link name='a'>", pose_at(0, 0, 0));
    EXPECT_FALSE(s.response.success);
    messages.push_back(s.response.status_message);
  }
  {  // duplicate name
    const auto s = spawn("bot", kBot, pose_at(3, 0, 0));
    EXPECT_FALSE(s.response.success);
    EXPECT_THAT(s.response.status_message, ::testing::HasSubstr("already"));
    messages.push_back(s.response.status_message);
  }
  {  // NaN state
    gazebo_msgs::SetModelState s;
    s.request.model_state.model_name = "bot";
    s.request.model_state.pose = pose_at(0, nan, 0);
    ASSERT_TRUE(call("/gazebo/set_model_state", s));
    EXPECT_FALSE(s.response.success);
    messages.push_back(s.response.status_message);
  }
  {  // unknown joint
    gazebo_msgs::SetModelConfiguration c;
    c.request.model_name = "bot";
    c.request.joint_names = {"no_joint"};
    c.request.joint_positions = {0.3};
    ASSERT_TRUE(call("/gazebo/set_model_configuration", c));
    EXPECT_FALSE(c.response.success);
    messages.push_back(c.response.status_message);
  }
  {  // unknown body, NaN wrench
    gazebo_msgs::ApplyBodyWrench a;
    a.request.body_name = "bot::nothing";
    a.request.duration = ::ros::Duration(1.0);
    ASSERT_TRUE(call("/gazebo/apply_body_wrench", a));
    EXPECT_FALSE(a.response.success);
    messages.push_back(a.response.status_message);
    a.request.body_name = "bot::base";
    a.request.wrench.force.x = nan;
    ASSERT_TRUE(call("/gazebo/apply_body_wrench", a));
    EXPECT_FALSE(a.response.success);
    messages.push_back(a.response.status_message);
  }
  {  // unknown joint properties
    gazebo_msgs::GetJointProperties j;
    j.request.joint_name = "bot::no_joint";
    ASSERT_TRUE(call("/gazebo/get_joint_properties", j));
    EXPECT_FALSE(j.response.success);
    messages.push_back(j.response.status_message);
  }
  {  // a time step mechsim does not run at
    gazebo_msgs::SetPhysicsProperties p;
    p.request.time_step = 0.002;
    ASSERT_TRUE(call("/gazebo/set_physics_properties", p));
    EXPECT_FALSE(p.response.success);
    messages.push_back(p.response.status_message);
  }
  {  // deleting what is not there
    gazebo_msgs::DeleteModel d;
    d.request.model_name = "no_such_model";
    ASSERT_TRUE(call("/gazebo/delete_model", d));
    EXPECT_FALSE(d.response.success);
    messages.push_back(d.response.status_message);
  }
  {  // stepping while running
    mechsim_msgs::StepSimulation s;
    s.request.steps = 10;
    ASSERT_TRUE(call("/mechsim/step_simulation", s));
    EXPECT_FALSE(s.response.success);
    messages.push_back(s.response.status_message);
  }
  for (const std::string& m : messages) EXPECT_FALSE(m.empty()) << "a refusal without a message";
  // The world runs on, the robot as it was.
  const double t = clock_now();
  EXPECT_TRUE(wait_until([&] { return clock_now() > t + 0.2; }, 5.0)) << "the clock stopped";
  const auto g = model_state("bot");
  ASSERT_TRUE(g.response.success);
  EXPECT_NEAR(g.response.pose.position.x, 0.0, 0.01);
  EXPECT_TRUE(std::isfinite(g.response.pose.position.z));
  std::printf("refusals:\n");
  for (const std::string& m : messages) std::printf("  %s\n", m.c_str());
}

TEST_F(GazeboWorldNode, SetsAndReadsStatesInReferenceFrames) {
  start(true);
  ASSERT_TRUE(spawn("bot", kBot, pose_at(0, 0, 1.0)).response.success) << node_->log();
  gazebo_msgs::SetModelState s;
  s.request.model_state.model_name = "bot";
  s.request.model_state.pose = pose_at(3.0, -1.0, 0.5);
  s.request.model_state.pose.orientation.z = std::sin(M_PI / 4);  // yaw 90 degrees
  s.request.model_state.pose.orientation.w = std::cos(M_PI / 4);
  s.request.model_state.twist.linear.x = 0.5;
  ASSERT_TRUE(call("/gazebo/set_model_state", s));
  ASSERT_TRUE(s.response.success) << s.response.status_message;
  const auto g = model_state("bot");
  ASSERT_TRUE(g.response.success);
  EXPECT_NEAR(g.response.pose.position.x, 3.0, 1e-9);
  EXPECT_NEAR(g.response.pose.position.y, -1.0, 1e-9);
  EXPECT_NEAR(g.response.pose.position.z, 0.5, 1e-9);
  EXPECT_NEAR(g.response.twist.linear.x, 0.5, 1e-9);
  // The arm's joint frame in the model's frame: 0.15 m up, whatever the model's pose.
  gazebo_msgs::GetLinkState l;
  l.request.link_name = "bot::arm";
  l.request.reference_frame = "bot";
  ASSERT_TRUE(call("/gazebo/get_link_state", l));
  ASSERT_TRUE(l.response.success) << l.response.status_message;
  EXPECT_NEAR(l.response.link_state.pose.position.x, 0.0, 1e-9);
  EXPECT_NEAR(l.response.link_state.pose.position.z, 0.15, 1e-9);
  // The world seen from the model: the world's origin 3 m behind, rotated by the yaw.
  const auto w = model_state("bot", "bot::base");
  EXPECT_NEAR(w.response.pose.position.x, 0.0, 1e-9);
  gazebo_msgs::GetLinkProperties p;
  p.request.link_name = "bot::arm";
  ASSERT_TRUE(call("/gazebo/get_link_properties", p));
  EXPECT_DOUBLE_EQ(p.response.mass, 0.5);
  EXPECT_DOUBLE_EQ(p.response.com.position.x, 0.1);
  EXPECT_TRUE(p.response.gravity_mode);
  // Another link than the root is moved by its joints, not set.
  gazebo_msgs::SetModelState arm;
  arm.request.model_state.model_name = "bot::arm";
  arm.request.model_state.pose = pose_at(0, 0, 0);
  ASSERT_TRUE(call("/gazebo/set_model_state", arm));
  EXPECT_FALSE(arm.response.success);
}

TEST_F(GazeboWorldNode, WrenchAndEffortActForTheirDurationWhileStepping) {
  start(true);
  ASSERT_TRUE(spawn("bot", kBot, pose_at(0, 0, 1.0)).response.success) << node_->log();
  zero_gravity();
  gazebo_msgs::GetPhysicsProperties props;
  ASSERT_TRUE(call("/gazebo/get_physics_properties", props));
  EXPECT_TRUE(props.response.pause);
  EXPECT_DOUBLE_EQ(props.response.time_step, 0.001);
  EXPECT_DOUBLE_EQ(props.response.gravity.z, 0.0);
  const double t0 = step(0);
  // 2 N along x for 0.1 s through the robot's centre of mass (0.02 m along x and 0.03 m up from
  // the base's: the arm's 0.5 kg at (0.1, 0, 0.15)), so that nothing turns: the 2.5 kg robot
  // gains 0.08 m/s, then coasts.
  gazebo_msgs::ApplyBodyWrench a;
  a.request.body_name = "bot::base";
  a.request.reference_point.x = 0.02;
  a.request.reference_point.z = 0.03;
  a.request.wrench.force.x = 2.0;
  a.request.duration = ::ros::Duration(0.1);
  ASSERT_TRUE(call("/gazebo/apply_body_wrench", a));
  ASSERT_TRUE(a.response.success) << a.response.status_message;
  const double t1 = step(200);
  EXPECT_NEAR(t1 - t0, 0.2, 1e-9) << "200 steps of 1 ms";
  const auto g = model_state("bot");
  // The root link's velocity: the whole robot's, as nothing turns it.
  EXPECT_NEAR(g.response.twist.linear.x, 0.08, 0.002);
  EXPECT_NEAR(g.response.twist.angular.y, 0.0, 0.01);
  const double v = g.response.twist.linear.x;
  step(100);
  EXPECT_NEAR(model_state("bot").response.twist.linear.x, v, 0.002) << "the wrench went on past its duration";

  // 0.05 N m on the arm's joint until cleared.
  gazebo_msgs::ApplyJointEffort e;
  e.request.joint_name = "arm_joint";
  e.request.effort = 0.05;
  e.request.duration = ::ros::Duration(-1.0);
  ASSERT_TRUE(call("/gazebo/apply_joint_effort", e));
  ASSERT_TRUE(e.response.success) << e.response.status_message;
  step(100);
  gazebo_msgs::GetJointProperties j;
  j.request.joint_name = "bot::arm_joint";
  ASSERT_TRUE(call("/gazebo/get_joint_properties", j));
  ASSERT_TRUE(j.response.success) << j.response.status_message;
  EXPECT_EQ(j.response.type, gazebo_msgs::GetJointProperties::Response::REVOLUTE);
  ASSERT_EQ(j.response.rate.size(), 1u);
  const double rate = j.response.rate[0];
  EXPECT_GT(rate, 0.1) << "the effort did not turn the arm";
  gazebo_msgs::JointRequest clear;
  clear.request.joint_name = "arm_joint";
  ASSERT_TRUE(call("/gazebo/clear_joint_forces", clear));
  step(100);
  ASSERT_TRUE(call("/gazebo/get_joint_properties", j));
  EXPECT_NEAR(j.response.rate[0], rate, 0.1 * rate) << "the cleared effort still turns the arm";
}

TEST_F(GazeboWorldNode, StepsWhilePausedAndPublishesStatesAndTheRealTimeFactor) {
  start(true);
  const double t0 = step(0);
  EXPECT_NEAR(step(250) - t0, 0.25, 1e-9) << "an empty world steps too";
  ASSERT_TRUE(spawn("bot", kBot, pose_at(0, 0, 0.2)).response.success) << node_->log();
  const double t1 = step(0);
  EXPECT_NEAR(t1, t0 + 0.25, 1e-9) << "the robot came in at the world's time";
  EXPECT_NEAR(step(1000) - t1, 1.0, 1e-9);

  std::mutex m;
  gazebo_msgs::ModelStates states;
  std::vector<double> factors;
  ::ros::Subscriber sub = nh_.subscribe<gazebo_msgs::ModelStates>(
      "/gazebo/model_states", 1, [&](const gazebo_msgs::ModelStates::ConstPtr& msg) {
        std::lock_guard<std::mutex> l(m);
        states = *msg;
      });
  ::ros::Subscriber perf = nh_.subscribe<gazebo_msgs::PerformanceMetrics>(
      "/gazebo/performance_metrics", 10, [&](const gazebo_msgs::PerformanceMetrics::ConstPtr& msg) {
        std::lock_guard<std::mutex> l(m);
        factors.push_back(msg->real_time_factor);
      });
  std_srvs::Empty unpause;
  ASSERT_TRUE(call("/gazebo/unpause_physics", unpause));
  ASSERT_TRUE(wait_until([&] { std::lock_guard<std::mutex> l(m); return factors.size() >= 3; }, 10.0));
  std::lock_guard<std::mutex> l(m);
  EXPECT_THAT(states.name, ::testing::ElementsAre("ground_plane", "bot"));
  ASSERT_EQ(states.pose.size(), 2u);
  EXPECT_NEAR(states.pose[1].position.x, 0.0, 0.01);
  // Paced at real time: the last full second's factor.
  EXPECT_NEAR(factors.back(), 1.0, 0.2);
  std::printf("performance_metrics real_time_factor: %.3f\n", factors.back());
}

// An SDF world's models in get_model_state and model_states: a static pillar where the file puts
// it; a crate dropped from 1 m where the file puts it before any robot is in, and once a robot's
// physics runs, falling and resting on the ground (its centre 0.1 m up), in both; set_model_state
// moves the crate and refuses the pillar.
TEST_F(GazeboWorldNode, AnSdfWorldsModelsAreWhereThePhysicsHasThem) {
  const std::string file = log_dir() + "/drop.world";  // the suite's folder, removed when it ends
  {
    std::ofstream out(file);
    out << R"(<?xml version="1.0"?><sdf version="1.6"><world name="drop">
      <model name="ground"><static>true</static><link name="l"><collision name="c"><geometry><plane><normal>0 0 1</normal>
        <size>20 20</size></plane></geometry></collision></link></model>
      <model name="pillar"><static>true</static><pose>-2 0 0.5 0 0 0.4</pose><link name="l"><collision name="c">
        <geometry><box><size>0.3 0.3 1</size></box></geometry></collision></link></model>
      <model name="crate"><pose>1 0.5 1 0 0 0</pose><link name="l"><inertial><mass>2</mass></inertial>
        <collision name="c"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision></link></model>
    </world></sdf>)";
  }
  start(true, file);
  gazebo_msgs::GetModelState crate = model_state("crate");
  ASSERT_TRUE(crate.response.success) << crate.response.status_message;
  EXPECT_NEAR(crate.response.pose.position.z, 1.0, 1e-9) << "before any robot: where the file puts it";
  ASSERT_TRUE(spawn("bot", kBot, pose_at(0, 3, 0.2)).response.success) << node_->log();
  crate = model_state("crate");
  EXPECT_NEAR(crate.response.pose.position.x, 1.0, 1e-9);
  EXPECT_NEAR(crate.response.pose.position.z, 1.0, 1e-9) << "paused: not moved yet";
  step(300);  // 0.3 s: falling (0.44 m down, 2.9 m/s)
  crate = model_state("crate");
  EXPECT_NEAR(crate.response.pose.position.z, 1.0 - 0.5 * 9.81 * 0.09, 0.01) << "falling";
  EXPECT_NEAR(crate.response.twist.linear.z, -9.81 * 0.3, 0.05);
  step(1700);
  crate = model_state("crate");
  EXPECT_NEAR(crate.response.pose.position.z, 0.1, 2e-3) << "resting on the ground";
  EXPECT_NEAR(crate.response.pose.position.x, 1.0, 1e-3);
  const gazebo_msgs::GetModelState pillar = model_state("pillar");
  ASSERT_TRUE(pillar.response.success) << pillar.response.status_message;
  EXPECT_NEAR(pillar.response.pose.position.x, -2.0, 1e-9);
  EXPECT_NEAR(pillar.response.pose.orientation.z, std::sin(0.2), 1e-9);

  // The crate moved (as a script resets an object), 0.6 m up: there, then falling again; the
  // static pillar cannot be moved.
  gazebo_msgs::SetModelState set;
  set.request.model_state.model_name = "crate";
  set.request.model_state.pose = pose_at(0.5, -1.0, 0.7);
  ASSERT_TRUE(call("/gazebo/set_model_state", set));
  EXPECT_TRUE(set.response.success) << set.response.status_message;
  crate = model_state("crate");
  EXPECT_NEAR(crate.response.pose.position.x, 0.5, 1e-9);
  EXPECT_NEAR(crate.response.pose.position.z, 0.7, 1e-9);
  step(1000);
  crate = model_state("crate");
  EXPECT_NEAR(crate.response.pose.position.z, 0.1, 2e-3) << "fell again";
  EXPECT_NEAR(crate.response.pose.position.y, -1.0, 1e-3);
  set.request.model_state.model_name = "pillar";
  ASSERT_TRUE(call("/gazebo/set_model_state", set));
  EXPECT_FALSE(set.response.success);
  EXPECT_THAT(set.response.status_message, ::testing::HasSubstr("static"));

  ModelStatesWatch watch(nh_);
  ASSERT_TRUE(wait_until([&] { return watch.connected(); }, 5.0));
  ASSERT_TRUE(wait_until(
      [&] {
        step(1);
        return watch.count() > 0;
      },
      10.0));
  const gazebo_msgs::ModelStates states = watch.latest();
  EXPECT_THAT(states.name, ::testing::ElementsAre("ground", "pillar", "crate", "bot"));
  ASSERT_EQ(states.pose.size(), 4u);
  EXPECT_NEAR(states.pose[1].position.x, -2.0, 1e-9);
  EXPECT_NEAR(states.pose[2].position.x, 0.5, 1e-3);
  EXPECT_NEAR(states.pose[3].position.y, 3.0, 0.05);
}

TEST_F(GazeboWorldNode, DeleteUnloadsTheControllersAndTheClockGoesOn) {
  start(false);
  ::ros::param::set("/bot/joint_state_controller/type", std::string("joint_state_controller/JointStateController"));
  ::ros::param::set("/bot/joint_state_controller/publish_rate", 50.0);
  ASSERT_TRUE(spawn("bot", kBot, pose_at(0, 0, 0.2)).response.success) << node_->log();
  ChildProcess spawner({MECHSIM_SPAWNER_EXE, "__ns:=/bot", "__name:=bot_spawner", "joint_state_controller"},
                       log_dir() + "/bot_spawner.log");
  ASSERT_TRUE(wait_until(
      [] {
        controller_manager_msgs::ListControllers list;
        return ::ros::service::call("/bot/controller_manager/list_controllers", list) &&
               list.response.controller.size() == 1 && list.response.controller[0].state == "running";
      },
      20.0))
      << spawner.log();
  const double before = clock_now();
  gazebo_msgs::DeleteModel d;
  d.request.model_name = "bot";
  ASSERT_TRUE(call("/gazebo/delete_model", d));
  ASSERT_TRUE(d.response.success) << d.response.status_message;
  EXPECT_THAT(node_->log(), ::testing::HasSubstr("1 controllers stopped and unloaded"));
  EXPECT_TRUE(wait_until([] { return !::ros::service::exists("/bot/controller_manager/list_controllers", false); }, 5.0))
      << "the deleted robot's controller manager is still there";
  const double after = clock_now();
  EXPECT_GE(after, before) << "time went back at the delete";
  EXPECT_TRUE(wait_until([&] { return clock_now() > after + 0.2; }, 5.0)) << "the world's clock stopped";
  gazebo_msgs::GetWorldProperties w;
  ASSERT_TRUE(call("/gazebo/get_world_properties", w));
  EXPECT_THAT(w.response.model_names, ::testing::ElementsAre("ground_plane"));
  // In again under the same name.
  EXPECT_TRUE(spawn("bot", kBot, pose_at(0, 0, 0.2)).response.success);
  spawner.stop();
}

// spawn_model -J (gazebo_ros_pkgs#93): the joints are where -J puts them before the world runs,
// in get_joint_properties and in the first joint_states (3 steps, still paused).
TEST_F(GazeboWorldNode, SpawnModelJSetsInitialJointPositionsBeforeUnpause) {
  start(true);
  ::ros::param::set("/bot_description", std::string(kBot));
  ::ros::param::set("/bot/joint_state_controller/type", std::string("joint_state_controller/JointStateController"));
  ::ros::param::set("/bot/joint_state_controller/publish_rate", 1000.0);
  const std::string spawn_model = std::string(MECHSIM_BINARY_DIR) + "/ros_package/gazebo_ros/spawn_model";
  ChildProcess run({spawn_model, "-urdf", "-param", "/bot_description", "-model", "bot", "-z", "0.3", "-J",
                    "arm_joint", "0.7"},
                   log_dir() + "/spawn_model_J.log");
  ASSERT_EQ(run.wait(30.0), 0) << run.log();
  gazebo_msgs::GetJointProperties j;
  j.request.joint_name = "arm_joint";
  ASSERT_TRUE(call("/gazebo/get_joint_properties", j));
  ASSERT_TRUE(j.response.success) << j.response.status_message;
  EXPECT_DOUBLE_EQ(j.response.position.at(0), 0.7);

  std::mutex m;
  std::vector<sensor_msgs::JointState> seen;
  ::ros::Subscriber sub = nh_.subscribe<sensor_msgs::JointState>(
      "/bot/joint_states", 10, [&](const sensor_msgs::JointState::ConstPtr& msg) {
        std::lock_guard<std::mutex> l(m);
        seen.push_back(*msg);
      });
  ChildProcess spawner({MECHSIM_SPAWNER_EXE, "__ns:=/bot", "__name:=bot_spawner", "joint_state_controller"},
                       log_dir() + "/bot_spawner_J.log");
  // Loaded, and its start waiting for the next tick (the world is paused).
  ASSERT_TRUE(wait_until(
      [] {
        controller_manager_msgs::ListControllers list;
        return ::ros::service::call("/bot/controller_manager/list_controllers", list) &&
               list.response.controller.size() == 1 && list.response.controller[0].state == "waiting";
      },
      20.0))
      << spawner.log();
  ASSERT_TRUE(wait_until([&] { return sub.getNumPublishers() > 0; }, 5.0));
  // ros_control's joint_state_controller publishes once an interval (1 ms here) has passed since
  // it started: 3 steps, still paused.
  step(3);
  ASSERT_TRUE(wait_until([&] { std::lock_guard<std::mutex> l(m); return !seen.empty(); }, 5.0)) << node_->log();
  gazebo_msgs::GetPhysicsProperties props;
  ASSERT_TRUE(call("/gazebo/get_physics_properties", props));
  EXPECT_TRUE(props.response.pause) << "-J without -unpause leaves the world paused";
  std::lock_guard<std::mutex> l(m);
  ASSERT_THAT(seen.front().name, ::testing::ElementsAre("arm_joint"));
  EXPECT_NEAR(seen.front().position.at(0), 0.7, 1e-3);
  spawner.stop();
}

}  // namespace
}  // namespace mechsim::ros::test
