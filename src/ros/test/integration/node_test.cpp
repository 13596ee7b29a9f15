// mechsim_node under a real ROS master with the CC8 of robots/cc8: the clock, gazebo's
// simulation services, the controller manager services, controller topics, TF, and the spawner.
#include <gmock/gmock.h>

#include <atomic>
#include <cmath>
#include <mutex>

#include <controller_manager_msgs/ListControllers.h>
#include <controller_manager_msgs/LoadController.h>
#include <controller_manager_msgs/SwitchController.h>
#include <controller_manager_msgs/UnloadController.h>
#include <control_msgs/JointControllerState.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/Float64.h>
#include <std_srvs/Empty.h>
#include <tf2_msgs/TFMessage.h>

#include "ros_fixture.hpp"

namespace mechsim::ros::test {
namespace {

namespace cmm = controller_manager_msgs;
using ::testing::ElementsAre;

const char* const kCm = "/cc8/controller_manager/";

std::vector<cmm::ControllerState> list_controllers() {
  cmm::ListControllers srv;
  EXPECT_TRUE(call(std::string(kCm) + "list_controllers", srv));
  return srv.response.controller;
}

const cmm::ControllerState* find(const std::vector<cmm::ControllerState>& list, const std::string& name) {
  for (const auto& c : list) {
    if (c.name == name) return &c;
  }
  return nullptr;
}

bool load(const std::string& name) {
  cmm::LoadController srv;
  srv.request.name = name;
  EXPECT_TRUE(call(std::string(kCm) + "load_controller", srv));
  return srv.response.ok;
}

bool unload(const std::string& name) {
  cmm::UnloadController srv;
  srv.request.name = name;
  EXPECT_TRUE(call(std::string(kCm) + "unload_controller", srv));
  return srv.response.ok;
}

bool switch_controllers(const std::vector<std::string>& start, const std::vector<std::string>& stop,
                        int strictness = cmm::SwitchController::Request::STRICT) {
  cmm::SwitchController srv;
  srv.request.start_controllers = start;
  srv.request.stop_controllers = stop;
  srv.request.strictness = strictness;
  srv.request.timeout = 5.0;
  EXPECT_TRUE(call(std::string(kCm) + "switch_controller", srv));
  return srv.response.ok;
}

bool empty_service(const std::string& name) {
  std_srvs::Empty srv;
  return call(name, srv);
}

bool topic_published(const std::string& topic) {
  ::ros::master::V_TopicInfo topics;
  ::ros::master::getTopics(topics);
  for (const auto& t : topics) {
    if (t.name == topic) return true;
  }
  return false;
}

const std::vector<std::string> kCc8Controllers = {
    "joint_state_controller",
    "steering_FL_position_controller",    "steering_FR_position_controller",
    "steering_RL_position_controller",    "steering_RR_position_controller",
    "wheel_joint_FL_velocity_controller", "wheel_joint_FR_velocity_controller",
    "wheel_joint_ML_velocity_controller", "wheel_joint_MR_velocity_controller",
    "wheel_joint_RL_velocity_controller", "wheel_joint_RR_velocity_controller"};

TEST_F(CC8Node, ClockAdvancesAndPauseUnpauseResetWork) {
  const double t0 = clock_now();
  ASSERT_FALSE(std::isnan(t0)) << "no /clock";
  // Bounded waits rather than fixed sleeps: on a loaded machine (CI's two cores running other
  // tests) the simulation may run slower than real time, and /clock messages sent before the
  // pause may still be on their way a few hundred milliseconds later.
  EXPECT_TRUE(wait_until([&] { return clock_now() > t0 + 0.2; }, 5.0)) << "the clock runs";

  ASSERT_TRUE(empty_service("/gazebo/pause_physics"));
  double paused_at = clock_now();
  EXPECT_TRUE(wait_until(
      [&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        const double now = clock_now();
        const bool settled = now == paused_at;
        paused_at = now;
        return settled;
      },
      5.0))
      << "the clock stops after the pause";
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  EXPECT_DOUBLE_EQ(clock_now(), paused_at) << "time stands still while paused";

  ASSERT_TRUE(empty_service("/gazebo/unpause_physics"));
  EXPECT_TRUE(wait_until([&] { return clock_now() > paused_at + 0.2; }, 5.0));

  const double before_reset = clock_now();
  ASSERT_TRUE(empty_service("/gazebo/reset_simulation"));
  ASSERT_TRUE(empty_service("/gazebo/reset_world"));
  // Time never goes backwards (use_sim_time nodes would throw), and runs on.
  EXPECT_TRUE(wait_until([&] { return clock_now() > before_reset + 0.2; }, 5.0));
  EXPECT_TRUE(node_->running());
}

TEST_F(CC8Node, SpawnerStartsTheCc8ControllersWithTheirTopicsAndUnloadsThemOnSigint) {
  rosparam_load(std::string(MECHSIM_SOURCE_DIR) + "/robots/cc8/config/controllers.yaml");
  ChildProcess& sp = spawner(kCc8Controllers, "spawner");
  ASSERT_TRUE(wait_until(
      [&] {
        const auto list = list_controllers();
        if (list.size() != kCc8Controllers.size()) return false;
        for (const auto& c : list) {
          if (c.state != "running") return false;
        }
        return true;
      },
      20.0))
      << "spawner log:\n" << sp.log();
  const auto list = list_controllers();
  const cmm::ControllerState* wheel = find(list, "wheel_joint_FL_velocity_controller");
  ASSERT_NE(wheel, nullptr);
  EXPECT_EQ(wheel->type, "effort_controllers/JointVelocityController");
  ASSERT_EQ(wheel->claimed_resources.size(), 1u);
  EXPECT_EQ(wheel->claimed_resources[0].hardware_interface, "hardware_interface::EffortJointInterface");
  EXPECT_THAT(wheel->claimed_resources[0].resources, ElementsAre("wheel_joint_FL"));

  // joint_states at the joint_state_controller's publish_rate (50 Hz).
  std::mutex m;
  std::vector<double> stamps;
  std::vector<std::chrono::steady_clock::time_point> arrivals;
  double fl_velocity = 0.0;
  ::ros::Subscriber js = nh_.subscribe<sensor_msgs::JointState>(
      "/cc8/joint_states", 100, [&](const sensor_msgs::JointState::ConstPtr& msg) {
        std::lock_guard<std::mutex> lock(m);
        stamps.push_back(msg->header.stamp.toSec());
        arrivals.push_back(std::chrono::steady_clock::now());
        for (std::size_t i = 0; i < msg->name.size() && i < msg->velocity.size(); ++i) {
          if (msg->name[i] == "wheel_joint_FL") fl_velocity = msg->velocity[i];
        }
      });
  ASSERT_TRUE(wait_until([&] { std::lock_guard<std::mutex> l(m); return !stamps.empty(); }, 10.0));
  {
    std::lock_guard<std::mutex> l(m);
    stamps.clear();
    arrivals.clear();
  }
  const double sim_start = clock_now();
  std::this_thread::sleep_for(std::chrono::seconds(4));
  const double sim_end = clock_now();
  {
    std::lock_guard<std::mutex> l(m);
    ASSERT_GE(stamps.size(), 10u);
    const double wall = std::chrono::duration<double>(arrivals.back() - arrivals.front()).count();
    const double wall_rate = static_cast<double>(arrivals.size() - 1) / wall;
    const double sim_rate = static_cast<double>(stamps.size() - 1) / (stamps.back() - stamps.front());
    const double rtf = (sim_end - sim_start) / 4.0;
    std::printf("joint_states: %zu messages, %.2f Hz wall, %.2f Hz sim time, real-time factor %.3f\n",
                stamps.size(), wall_rate, sim_rate, rtf);
    EXPECT_NEAR(sim_rate, 50.0, 5.0);
    // The wall-clock rate is 50 Hz only while the simulation keeps real time.
    if (rtf > 0.95) {
      EXPECT_NEAR(wall_rate, 50.0, 5.0);
    }
    // Stamps are whole publish periods apart (one tick of jitter). A period may be skipped when
    // the publishing thread holds the snapshot as the tick offers it (realtime_tools' try-lock
    // rule) or under load, but rarely: at most 5 % of the gaps.
    std::size_t skipped = 0;
    for (std::size_t i = 1; i < stamps.size(); ++i) {
      const double gap = stamps[i] - stamps[i - 1];
      const double periods = std::round(gap / 0.02);
      EXPECT_GE(periods, 1.0) << "gap " << gap << " s";
      EXPECT_NEAR(gap, 0.02 * periods, 0.0011) << "gap " << gap << " s";
      if (periods > 1.0) ++skipped;
    }
    EXPECT_LE(skipped, stamps.size() / 20) << skipped << " of " << stamps.size() - 1 << " gaps skipped a period";
  }

  // A velocity command on the wheel's command topic turns the wheel; its state topic reports it.
  std::atomic<double> set_point{0.0};
  ::ros::Subscriber state = nh_.subscribe<control_msgs::JointControllerState>(
      "/cc8/wheel_joint_FL_velocity_controller/state", 10,
      [&](const control_msgs::JointControllerState::ConstPtr& msg) { set_point = msg->set_point; });
  ::ros::Publisher cmd = nh_.advertise<std_msgs::Float64>("/cc8/wheel_joint_FL_velocity_controller/command", 1, true);
  std_msgs::Float64 v;
  v.data = 3.0;
  cmd.publish(v);
  EXPECT_TRUE(wait_until([&] { std::lock_guard<std::mutex> l(m); return fl_velocity > 1.5; }, 10.0))
      << "wheel_joint_FL velocity " << fl_velocity;
  EXPECT_TRUE(wait_until([&] { return set_point.load() == 3.0; }, 5.0));

  // SIGINT: the spawner stops and unloads what it started, and the topics go with them.
  EXPECT_EQ(sp.stop(15.0), 0) << sp.log();
  EXPECT_TRUE(list_controllers().empty());
  EXPECT_TRUE(wait_until([] { return !topic_published("/cc8/wheel_joint_FL_velocity_controller/state"); }, 5.0));
}

TEST_F(CC8Node, BadRequestsAreRefusedAndTheSimulationKeepsRunning) {
  rosparam_load(std::string(MECHSIM_SOURCE_DIR) + "/robots/cc8/config/controllers.yaml");
  EXPECT_FALSE(load("no_such_controller"));
  ::ros::param::set("/cc8/bad_type_controller/type", std::string("nonexistent_controllers/Nothing"));
  EXPECT_FALSE(load("bad_type_controller"));
  // A second velocity controller on wheel_joint_FL: loads, but cannot run beside the first.
  ::ros::param::set("/cc8/other_fl_controller/type", std::string("effort_controllers/JointVelocityController"));
  ::ros::param::set("/cc8/other_fl_controller/joint", std::string("wheel_joint_FL"));
  ::ros::param::set("/cc8/other_fl_controller/pid/p", 1.0);
  ASSERT_TRUE(load("wheel_joint_FL_velocity_controller"));
  ASSERT_TRUE(load("other_fl_controller"));
  EXPECT_FALSE(load("other_fl_controller")) << "already loaded";

  EXPECT_FALSE(switch_controllers({"wheel_joint_FL_velocity_controller", "other_fl_controller"}, {}))
      << "conflicting resources under STRICT";
  EXPECT_FALSE(switch_controllers({"no_such_controller"}, {}));
  EXPECT_FALSE(switch_controllers({"wheel_joint_FL_velocity_controller"}, {}, 3)) << "strictness 3 is invalid";
  for (const auto& c : list_controllers()) EXPECT_NE(c.state, "running") << c.name;

  // BEST_EFFORT starts what it can.
  EXPECT_TRUE(switch_controllers({"wheel_joint_FL_velocity_controller", "no_such_controller"}, {},
                                 cmm::SwitchController::Request::BEST_EFFORT));
  const auto list = list_controllers();
  ASSERT_NE(find(list, "wheel_joint_FL_velocity_controller"), nullptr);
  EXPECT_EQ(find(list, "wheel_joint_FL_velocity_controller")->state, "running");
  EXPECT_FALSE(unload("wheel_joint_FL_velocity_controller")) << "running";
  EXPECT_FALSE(unload("never_loaded"));
  EXPECT_TRUE(switch_controllers({}, {"wheel_joint_FL_velocity_controller"}));
  EXPECT_TRUE(unload("wheel_joint_FL_velocity_controller"));
  EXPECT_TRUE(unload("other_fl_controller"));
  EXPECT_TRUE(list_controllers().empty());

  const double t = clock_now();
  EXPECT_TRUE(wait_until([&] { return clock_now() > t + 0.2; }, 5.0)) << "the simulation stopped";
  EXPECT_TRUE(node_->running());
}

// The rover drive (mechsim/RoverDriveController) from an inline configuration: geometry from the
// URDF, cmd_vel in, odometry out. reset_world puts the rover back at its spawn pose.
TEST_F(CC8Node, RoverDriveFollowsTwistOdomMovesAndResetReturnsToSpawn) {
  const std::string yaml = write_file("rover.yaml", R"(
rover_drive_controller:
  type: mechsim/RoverDriveController
  steering_joints: [steering_FL, steering_FR, steering_RL, steering_RR]
  wheel_joints: [wheel_joint_FL, wheel_joint_FR, wheel_joint_ML, wheel_joint_MR, wheel_joint_RL, wheel_joint_RR]
  steering_pid: {p: 60.0, i: 5.0, d: 3.0, i_clamp: 5.0}
  wheel_pid: {p: 8.0, i: 20.0, i_clamp: 15.0}
  base_frame_id: base_footprint
joint_state_controller:
  type: joint_state_controller/JointStateController
  publish_rate: 50
)");
  ChildProcess& sp = spawner({yaml}, "rover_spawner");
  ASSERT_TRUE(wait_until(
      [&] {
        const auto list = list_controllers();
        const cmm::ControllerState* c = find(list, "rover_drive_controller");
        return c && c->state == "running";
      },
      20.0))
      << sp.log();

  std::mutex m;
  double odom_x = 0.0;
  bool odom_seen = false;
  ::ros::Subscriber odom = nh_.subscribe<nav_msgs::Odometry>(
      "/cc8/rover_drive_controller/odom", 10, [&](const nav_msgs::Odometry::ConstPtr& msg) {
        std::lock_guard<std::mutex> l(m);
        odom_x = msg->pose.pose.position.x;
        odom_seen = true;
      });
  double world_x = std::nan("");
  std::vector<std::string> moving_children;
  ::ros::Subscriber tf = nh_.subscribe<tf2_msgs::TFMessage>("/tf", 100, [&](const tf2_msgs::TFMessage::ConstPtr& msg) {
    std::lock_guard<std::mutex> l(m);
    for (const auto& t : msg->transforms) {
      if (t.header.frame_id == "world") world_x = t.transform.translation.x;
      if (t.child_frame_id.rfind("wheel", 0) == 0 || t.child_frame_id.find("wheel") != std::string::npos) {
        moving_children.push_back(t.child_frame_id);
      }
    }
  });
  std::vector<std::string> static_children;
  ::ros::Subscriber tf_static = nh_.subscribe<tf2_msgs::TFMessage>(
      "/tf_static", 10, [&](const tf2_msgs::TFMessage::ConstPtr& msg) {
        std::lock_guard<std::mutex> l(m);
        for (const auto& t : msg->transforms) static_children.push_back(t.header.frame_id + "->" + t.child_frame_id);
      });
  ASSERT_TRUE(wait_until([&] { std::lock_guard<std::mutex> l(m); return odom_seen && !std::isnan(world_x) && !static_children.empty(); }, 10.0));
  double x0 = 0.0, world_x0 = 0.0;
  {
    std::lock_guard<std::mutex> l(m);
    x0 = odom_x;
    world_x0 = world_x;
    EXPECT_FALSE(moving_children.empty()) << "wheel transforms on /tf";
    EXPECT_THAT(static_children, ::testing::Contains("base_footprint->base_link"));
  }

  ::ros::Publisher cmd = nh_.advertise<geometry_msgs::Twist>("/cc8/rover_drive_controller/cmd_vel", 1);
  ASSERT_TRUE(wait_until([&] { return cmd.getNumSubscribers() > 0; }, 5.0));
  geometry_msgs::Twist twist;
  twist.linear.x = 0.3;
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (std::chrono::steady_clock::now() < until) {
    cmd.publish(twist);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  double x1 = 0.0, world_x1 = 0.0;
  {
    std::lock_guard<std::mutex> l(m);
    x1 = odom_x;
    world_x1 = world_x;
  }
  std::printf("rover: odom x %.3f -> %.3f m, physics x %.3f -> %.3f m\n", x0, x1, world_x0, world_x1);
  EXPECT_GT(x1 - x0, 0.3) << "odometry moves forward";
  EXPECT_GT(world_x1 - world_x0, 0.3) << "the rover moves forward";

  ASSERT_TRUE(empty_service("/gazebo/reset_world"));
  EXPECT_TRUE(wait_until([&] { std::lock_guard<std::mutex> l(m); return std::abs(world_x - world_x0) < 0.05; }, 5.0))
      << "after reset_world the rover is at x=" << world_x << " (spawned at " << world_x0 << ")";
}

}  // namespace
}  // namespace mechsim::ros::test

namespace mechsim::ros::test {
namespace {

TEST_F(CC8Node, SpawnerStoppedWaitForAndTimeout) {
  rosparam_load(std::string(MECHSIM_SOURCE_DIR) + "/robots/cc8/config/controllers.yaml");
  // --stopped loads without starting; --wait-for waits for a message on the topic first.
  ChildProcess& sp = spawner({"--stopped", "--wait-for", "/clock", "wheel_joint_FL_velocity_controller"}, "stopped");
  ASSERT_TRUE(wait_until([] { return list_controllers().size() == 1; }, 20.0)) << sp.log();
  EXPECT_EQ(list_controllers()[0].state, "initialized");
  EXPECT_EQ(sp.stop(15.0), 0) << sp.log();
  EXPECT_TRUE(list_controllers().empty()) << "unloaded on SIGINT";

  // No controller manager in that namespace: gives up after --timeout with status 1.
  ChildProcess& lost = spawner({"--namespace", "/nobody", "--timeout", "1", "joint_state_controller"}, "lost");
  EXPECT_EQ(lost.wait(15.0), 1) << lost.log();
  // An unknown controller: status 1, and what it loaded before is unloaded again.
  ChildProcess& bad = spawner({"joint_state_controller", "no_such_controller"}, "bad");
  EXPECT_EQ(bad.wait(20.0), 1) << bad.log();
  EXPECT_TRUE(list_controllers().empty());
}

}  // namespace
}  // namespace mechsim::ros::test
