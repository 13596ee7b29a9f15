// mechsim's test robots (robots/testbots) through ROS, with a real master: the differential drive
// through diff_drive_controller (cmd_vel -> odom and /tf, cmd_vel_out) and through Gazebo's diff
// drive plugin alone (cmd_vel, odom at updateRate, /tf, wheel joint_states, the wheels' ramp at
// wheelAcceleration), the skid steer and planar move plugins and the joint state publisher plugin
// on their gazebo_plugins topics, effort_controllers/GripperActionController's
// control_msgs/GripperCommand action (reached for free closing, stalled on a block with its
// max_effort), and a controller plugin's type (examples/controller_plugin) spawned by name and
// commanded on its command topic. The node runs at half real time, so that commands timed by the wall clock are
// timed to a few ms of simulated time; every figure is measured in simulated time (message
// stamps), the true pose from the physics (_publish_odom_tf with odom frame "world").
#include <gmock/gmock.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <mutex>

#include <actionlib/client/simple_action_client.h>
#include <control_msgs/GripperCommandAction.h>
#include <controller_manager_msgs/ListControllers.h>
#include <geometry_msgs/Twist.h>
#include <geometry_msgs/TwistStamped.h>
#include <nav_msgs/Odometry.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Float64.h>
#include <tf2_msgs/TFMessage.h>

#include "ros_fixture.hpp"

namespace mechsim::ros::test {
namespace {

constexpr double kDeg = M_PI / 180.0;
const std::string kTestbots = std::string(MECHSIM_SOURCE_DIR) + "/robots/testbots";

double yaw_of(const geometry_msgs::Quaternion& q) {
  return std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
}

struct Planar {
  double x = 0.0, y = 0.0, yaw = 0.0, stamp = -1.0;
};

class TestbotNode : public ::testing::Test {
 protected:
  // Starts mechsim_node on robots/testbots/urdf/<robot>.urdf.xacro with `args` at half real time.
  // `robot` may also be a description file's path (one with a '/').
  void start(const std::string& robot, const std::map<std::string, std::string>& args, const std::string& controllers,
             const std::string& ns) {
    ASSERT_TRUE(::ros::master::check()) << "no ROS master";
    test_ = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    ns_ = ns;
    std::string yaml = "mechsim_" + test_ + ":\n  xacro_args:" + std::string(args.empty() ? " {}" : "") + "\n";
    for (const auto& [k, v] : args) yaml += "    " + k + ": '" + v + "'\n";
    load(write(test_ + "_node.yaml", yaml));
    if (!controllers.empty()) load(kTestbots + "/config/" + controllers);
    clock_sub_ = nh_.subscribe<rosgraph_msgs::Clock>("/clock", 10, [this](const rosgraph_msgs::Clock::ConstPtr& m) {
      std::lock_guard<std::mutex> lock(mutex_);
      clock_ = m->clock.toSec();
    });
    tf_sub_ = nh_.subscribe<tf2_msgs::TFMessage>("/tf", 1000, [this](const tf2_msgs::TFMessage::ConstPtr& m) {
      std::lock_guard<std::mutex> lock(mutex_);
      for (const geometry_msgs::TransformStamped& t : m->transforms) {
        Planar& p = tf_[t.header.frame_id + ">" + t.child_frame_id];
        p = {t.transform.translation.x, t.transform.translation.y, yaw_of(t.transform.rotation), t.header.stamp.toSec()};
      }
    });
    node_ = std::make_unique<ChildProcess>(
        std::vector<std::string>{MECHSIM_NODE_EXE, "__name:=mechsim_" + test_, "_model:=" + (robot.find('/') != std::string::npos ? robot : kTestbots + "/urdf/" + robot + ".urdf.xacro"),
                                 "_real_time_factor:=0.5", "_publish_odom_tf:=true", "_odom_frame:=world"},
        log_dir() + "/node_" + test_ + ".log");
    controller_manager_msgs::ListControllers list;
    ASSERT_TRUE(call(ns_ + "/controller_manager/list_controllers", list, 30.0)) << "the node did not come up:\n" << node_->log();
    ASSERT_TRUE(wait_until([&] { return now() > 0.0; }, 10.0));
  }

  void TearDown() override {
    if (spawner_) spawner_->stop();
    clock_sub_.shutdown();
    tf_sub_.shutdown();
    if (node_) {
      const int status = node_->stop(10.0);
      EXPECT_EQ(status, 0) << "mechsim_node did not stop cleanly on SIGINT; its log:\n" << node_->log();
    }
  }

  void load(const std::string& file) {
    ChildProcess p({"/usr/bin/python3", "/usr/bin/rosparam", "load", file}, log_dir() + "/rosparam_" + test_ + ".log");
    ASSERT_EQ(p.wait(30.0), 0) << p.log();
  }
  std::string write(const std::string& name, const std::string& text) {
    const std::string path = log_dir() + "/" + name;
    std::ofstream(path) << text;
    return path;
  }
  // Loads and starts `controllers` in the robot namespace; true once all run.
  bool spawn(const std::vector<std::string>& controllers) {
    std::vector<std::string> argv{MECHSIM_SPAWNER_EXE, "__ns:=" + (ns_.empty() ? std::string("/") : ns_), "__name:=spawner"};
    argv.insert(argv.end(), controllers.begin(), controllers.end());
    spawner_ = std::make_unique<ChildProcess>(argv, log_dir() + "/spawner_" + test_ + ".log");
    return wait_until(
        [&] {
          controller_manager_msgs::ListControllers list;
          if (!call(ns_ + "/controller_manager/list_controllers", list, 1.0)) return false;
          std::size_t running = 0;
          for (const auto& c : list.response.controller) running += c.state == "running";
          return running == controllers.size();
        },
        30.0);
  }
  double now() {
    std::lock_guard<std::mutex> lock(mutex_);
    return clock_;
  }
  Planar tf(const std::string& parent, const std::string& child) {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = tf_.find(parent + ">" + child);
    return it == tf_.end() ? Planar{} : it->second;
  }
  // Publishes `twist` on `topic` at 50 Hz (wall) for `duration` s of simulated time, then zero
  // for 0.5 s. Returns the simulated times of the first and the zero command.
  // The window is known to the test through /clock (100 Hz): each end within one clock period
  // (kWindowSlack) of when the node applied the first and the zero command.
  static constexpr double kWindowSlack = 0.01;  // s
  std::pair<double, double> drive(const std::string& topic, const geometry_msgs::Twist& twist, double duration) {
    ::ros::Publisher pub = nh_.advertise<geometry_msgs::Twist>(topic, 10);
    wait_until([&] { return pub.getNumSubscribers() > 0; }, 10.0);
    const double start = now();
    while (now() < start + duration) {
      pub.publish(twist);
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    const double stop = now();
    const double until = stop + 0.5;
    while (now() < until) {
      pub.publish(geometry_msgs::Twist{});
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return {start, stop};
  }
  // Waits until `t` s of simulated time have passed.
  void settle(double t) {
    const double until = now() + t;
    wait_until([&] { return now() >= until; }, 10.0 * t + 5.0);
  }

  std::string test_, ns_;
  ::ros::NodeHandle nh_;
  std::unique_ptr<ChildProcess> node_, spawner_;
  ::ros::Subscriber clock_sub_, tf_sub_;
  std::mutex mutex_;
  double clock_ = -1.0;
  std::map<std::string, Planar> tf_;
};

// Integrates the limited command the controller publishes on cmd_vel_out (every tick, stamped
// in simulated time): what it really commanded.
struct CommandIntegral {
  std::mutex mutex;
  double last = -1.0, distance = 0.0, angle = 0.0, v = 0.0, w = 0.0;
  std::size_t messages = 0;
  void add(const geometry_msgs::TwistStamped& m) {
    std::lock_guard<std::mutex> lock(mutex);
    const double t = m.header.stamp.toSec();
    if (last >= 0.0) {
      distance += v * (t - last);
      angle += w * (t - last);
    }
    last = t;
    v = m.twist.linear.x;
    w = m.twist.angular.z;
    ++messages;
  }
};

TEST_F(TestbotNode, DiffDriveControllerDrivesAMetreAndTurnsNinetyDegrees) {
  start("diffbot", {{"drive", "controller"}}, "diffbot_controllers.yaml", "/diffbot");
  ASSERT_TRUE(spawn({"joint_state_controller", "diff_drive_controller"})) << spawner_->log();
  CommandIntegral commanded;
  nav_msgs::Odometry odom;
  std::mutex m;
  ::ros::Subscriber out = nh_.subscribe<geometry_msgs::TwistStamped>(
      "/diffbot/diff_drive_controller/cmd_vel_out", 5000, [&](const geometry_msgs::TwistStamped::ConstPtr& msg) { commanded.add(*msg); });
  ::ros::Subscriber odom_sub = nh_.subscribe<nav_msgs::Odometry>("/diffbot/diff_drive_controller/odom", 100,
                                                                 [&](const nav_msgs::Odometry::ConstPtr& msg) {
                                                                   std::lock_guard<std::mutex> lock(m);
                                                                   odom = *msg;
                                                                 });
  geometry_msgs::Twist forward;
  forward.linear.x = 0.5;
  drive("/diffbot/diff_drive_controller/cmd_vel", forward, 2.0);
  settle(1.5);
  const Planar truth = tf("world", "base_footprint");
  {
    std::lock_guard<std::mutex> lock(commanded.mutex);
    std::lock_guard<std::mutex> l2(m);
    std::printf("[ figures  ] ROS diff_drive_controller: commanded %.4f m (%zu cmd_vel_out), moved %.4f m, odometry %.4f m\n",
                commanded.distance, commanded.messages, truth.x, odom.pose.pose.position.x);
    EXPECT_NEAR(commanded.distance, 1.0, 0.05);  // wall-clock timing
    EXPECT_NEAR(truth.x, commanded.distance, 0.01 * commanded.distance);
    EXPECT_NEAR(odom.pose.pose.position.x, truth.x, 0.01 * truth.x);
    EXPECT_EQ(odom.header.frame_id, "odom");
    EXPECT_EQ(odom.child_frame_id, "base_footprint");
  }
  EXPECT_GT(tf("odom", "base_footprint").stamp, 0.0);  // enable_odom_tf
  const double yaw_before = truth.yaw, odom_before = yaw_of(odom.pose.pose.orientation);
  const double angle_before = commanded.angle;
  geometry_msgs::Twist turn;
  turn.angular.z = M_PI / 4.0;
  drive("/diffbot/diff_drive_controller/cmd_vel", turn, 2.0);
  settle(1.5);
  const double turned = tf("world", "base_footprint").yaw - yaw_before;
  std::lock_guard<std::mutex> lock(commanded.mutex);
  std::lock_guard<std::mutex> l2(m);
  const double wanted = commanded.angle - angle_before;
  const double odom_turned = yaw_of(odom.pose.pose.orientation) - odom_before;
  std::printf("[ figures  ] ROS diff_drive_controller: commanded %.3f deg, turned %.3f deg, odometry %.3f deg\n", wanted / kDeg,
              turned / kDeg, odom_turned / kDeg);
  EXPECT_NEAR(turned, wanted, 1.0 * kDeg);
  EXPECT_NEAR(odom_turned, turned, 0.01 * std::abs(turned));
}

// allow_multiple_cmd_vel_publishers: false: while two nodes publish cmd_vel the controller takes
// none of it (ros_controllers' rule); once one is left, it drives.
TEST_F(TestbotNode, DiffDriveControllerRefusesSeveralCmdVelPublishersWhenAsked) {
  start("diffbot", {{"drive", "controller"}}, "diffbot_controllers.yaml", "/diffbot");
  load(write("single_publisher.yaml", "diffbot: {diff_drive_controller: {allow_multiple_cmd_vel_publishers: false}}\n"));
  ASSERT_TRUE(spawn({"diff_drive_controller"})) << spawner_->log();
  geometry_msgs::Twist forward;
  forward.linear.x = 0.5;
  // Two publishers: this program (connected first, silent) and a rostopic child.
  ::ros::Publisher mine = nh_.advertise<geometry_msgs::Twist>("/diffbot/diff_drive_controller/cmd_vel", 10);
  ASSERT_TRUE(wait_until([&] { return mine.getNumSubscribers() > 0; }, 10.0));
  ChildProcess pub({"/usr/bin/python3", "/usr/bin/rostopic", "pub", "-r", "20", "/diffbot/diff_drive_controller/cmd_vel",
                    "geometry_msgs/Twist", "{linear: {x: 0.5}}"},
                   log_dir() + "/rostopic_" + test_ + ".log");
  // rostopic publishes (so the node's subscriber has it too, give or take a connection).
  std::atomic<bool> heard{false};
  ::ros::Subscriber listen = nh_.subscribe<geometry_msgs::Twist>("/diffbot/diff_drive_controller/cmd_vel", 10,
                                                                 [&](const geometry_msgs::Twist::ConstPtr&) { heard = true; });
  ASSERT_TRUE(wait_until([&] { return heard.load(); }, 20.0)) << pub.log();
  std::this_thread::sleep_for(std::chrono::seconds(1));
  const double before = tf("world", "base_footprint").x;
  drive("/diffbot/diff_drive_controller/cmd_vel", forward, 1.0);
  const double refused = tf("world", "base_footprint").x - before;
  pub.stop();
  listen.shutdown();
  std::this_thread::sleep_for(std::chrono::seconds(1));  // the node sees one publisher again
  std::printf("[ figures  ] two cmd_vel publishers, allow_multiple_cmd_vel_publishers false: moved %.4f m\n", refused);
  EXPECT_LT(std::abs(refused), 0.01);
  drive("/diffbot/diff_drive_controller/cmd_vel", forward, 1.0);
  settle(0.5);
  EXPECT_GT(tf("world", "base_footprint").x, 0.3);  // one publisher: driven
}

TEST_F(TestbotNode, DiffDrivePluginDrivesWithoutRosControl) {
  start("diffbot", {{"drive", "plugin"}, {"odometry_source", "encoder"}, {"wheel_acceleration", "1.0"}}, "", "/");
  std::mutex m;
  std::vector<nav_msgs::Odometry> odoms;
  sensor_msgs::JointState wheels;
  ::ros::Subscriber odom_sub = nh_.subscribe<nav_msgs::Odometry>("/diffbot/odom", 1000, [&](const nav_msgs::Odometry::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(m);
    odoms.push_back(*msg);
  });
  ::ros::Subscriber js = nh_.subscribe<sensor_msgs::JointState>("/diffbot/joint_states", 10, [&](const sensor_msgs::JointState::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(m);
    wheels = *msg;
  });
  geometry_msgs::Twist forward;
  forward.linear.x = 0.5;
  const auto [start_t, stop_t] = drive("/diffbot/cmd_vel", forward, 2.0);
  settle(1.5);
  const Planar truth = tf("world", "base_footprint");
  std::lock_guard<std::mutex> lock(m);
  ASSERT_GT(odoms.size(), 100u);
  const nav_msgs::Odometry& last = odoms.back();
  const double commanded = 0.5 * (stop_t - start_t);
  std::printf("[ figures  ] ROS diff drive plugin: commanded %.4f m (by /clock), moved %.4f m, encoder odometry %.4f m\n", commanded,
              truth.x, last.pose.pose.position.x);
  EXPECT_NEAR(truth.x, commanded, 0.01 * commanded);
  EXPECT_NEAR(last.pose.pose.position.x, truth.x, 0.01 * truth.x);
  // gazebo_ros_diff_drive's frames take its namespace as their TF prefix (GazeboRos::resolveTF).
  EXPECT_EQ(last.header.frame_id, "diffbot/odom");
  EXPECT_EQ(last.child_frame_id, "diffbot/base_footprint");
  // At updateRate (100 Hz of simulated time), and the speed ramps at wheelAcceleration (1 m/s^2).
  std::vector<double> intervals;
  double steepest = 0.0;
  for (std::size_t i = 1; i < odoms.size(); ++i) {
    const double dt = (odoms[i].header.stamp - odoms[i - 1].header.stamp).toSec();
    intervals.push_back(dt);
    if (dt > 0.0) steepest = std::max(steepest, (odoms[i].twist.twist.linear.x - odoms[i - 1].twist.twist.linear.x) / dt);
  }
  std::nth_element(intervals.begin(), intervals.begin() + intervals.size() / 2, intervals.end());
  std::printf("[ figures  ] ROS diff drive plugin: odom every %.4f s (median), steepest acceleration %.3f m/s^2\n",
              intervals[intervals.size() / 2], steepest);
  EXPECT_NEAR(intervals[intervals.size() / 2], 0.01, 1e-6);
  EXPECT_LT(steepest, 1.0 * 1.15);
  EXPECT_GT(steepest, 1.0 * 0.85);
  EXPECT_GT(tf("diffbot/odom", "diffbot/base_footprint").stamp, 0.0);
  ASSERT_EQ(wheels.name.size(), 2u);
  EXPECT_EQ(wheels.name[0], "left_wheel_joint");
  // No controller manager for a plugin: gazebo_ros_control is not in this URDF.
  controller_manager_msgs::ListControllers list;
  ASSERT_TRUE(call("/controller_manager/list_controllers", list));
  EXPECT_TRUE(list.response.controller.empty());
}

TEST_F(TestbotNode, SkidSteerAndPlanarMovePluginsOnTheirTopics) {
  start("skidbot", {{"drive", "plugin"}}, "", "/");
  std::mutex m;
  nav_msgs::Odometry odom;
  ::ros::Subscriber sub = nh_.subscribe<nav_msgs::Odometry>("/skidbot/odom", 10, [&](const nav_msgs::Odometry::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(m);
    odom = *msg;
  });
  geometry_msgs::Twist forward;
  forward.linear.x = 0.4;
  const auto [start_t, stop_t] = drive("/skidbot/cmd_vel", forward, 2.0);
  settle(1.0);
  const Planar truth = tf("world", "base_footprint");
  std::lock_guard<std::mutex> lock(m);
  std::printf("[ figures  ] ROS skid steer plugin: commanded %.4f m, moved %.4f m, odometry %.4f m\n", 0.4 * (stop_t - start_t),
              truth.x, odom.pose.pose.position.x);
  EXPECT_NEAR(truth.x, 0.4 * (stop_t - start_t), 0.01 * 0.4 * (stop_t - start_t) + 0.4 * 2 * kWindowSlack);
  EXPECT_NEAR(odom.pose.pose.position.x, truth.x, 1e-3);  // the plugin's odometry is the world pose
  EXPECT_GT(tf("odom", "base_footprint").stamp, 0.0);     // broadcastTF
  EXPECT_DOUBLE_EQ(odom.pose.covariance[35], 0.01);       // covariance_yaw's default
}

TEST_F(TestbotNode, PlanarMoveAndJointStatePublisherPlugins) {
  start("planarbot", {}, "", "/");
  std::mutex m;
  nav_msgs::Odometry odom;
  std::vector<double> js_stamps;
  ::ros::Subscriber sub = nh_.subscribe<nav_msgs::Odometry>("/planarbot/odom", 10, [&](const nav_msgs::Odometry::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(m);
    odom = *msg;
  });
  ::ros::Subscriber js = nh_.subscribe<sensor_msgs::JointState>("/planarbot/joint_states", 100, [&](const sensor_msgs::JointState::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(m);
    if (msg->name == std::vector<std::string>{"mast_pan_joint"}) js_stamps.push_back(msg->header.stamp.toSec());
  });
  geometry_msgs::Twist sideways;
  sideways.linear.y = 0.3;
  const auto [start_t, stop_t] = drive("/planarbot/cmd_vel", sideways, 1.0);
  settle(0.5);
  const Planar truth = tf("world", "base_footprint");
  std::lock_guard<std::mutex> lock(m);
  std::printf("[ figures  ] ROS planar move plugin: commanded %.4f m sideways, moved %.4f m, odometry %.4f m\n",
              0.3 * (stop_t - start_t), truth.y, odom.pose.pose.position.y);
  EXPECT_NEAR(truth.y, 0.3 * (stop_t - start_t), 0.01 * 0.3 * (stop_t - start_t) + 0.3 * 2 * kWindowSlack);
  EXPECT_NEAR(truth.x, 0.0, 1e-3);
  EXPECT_NEAR(odom.pose.pose.position.y, truth.y, 0.01);
  EXPECT_GT(tf("odom", "base_footprint").stamp, 0.0);
  ASSERT_GT(js_stamps.size(), 20u);
  EXPECT_NEAR(js_stamps.back() - js_stamps[js_stamps.size() - 2], 0.02, 1e-6);  // updateRate 50
}

TEST_F(TestbotNode, GripperCommandActionReachesFreeAndStallsOnTheBlock) {
  start("gripper", {{"interface", "EffortJointInterface"}, {"block", "true"}}, "gripper_controllers.yaml", "/gripper");
  ASSERT_TRUE(spawn({"joint_state_controller", "gripper_action_controller"})) << spawner_->log();
  actionlib::SimpleActionClient<control_msgs::GripperCommandAction> client("/gripper/gripper_action_controller/gripper_cmd", true);
  ASSERT_TRUE(client.waitForServer(::ros::Duration(20.0)));
  control_msgs::GripperCommandGoal goal;
  goal.command.position = 0.15;
  goal.command.max_effort = 0.5;
  client.sendGoal(goal);
  ASSERT_TRUE(client.waitForResult(::ros::Duration(20.0)));
  EXPECT_EQ(client.getState(), actionlib::SimpleClientGoalState::SUCCEEDED) << client.getState().getText();
  EXPECT_TRUE(client.getResult()->reached_goal);
  EXPECT_FALSE(client.getResult()->stalled);
  EXPECT_NEAR(client.getResult()->position, 0.15, 0.01);
  goal.command.position = 0.5;
  goal.command.max_effort = 0.05;
  client.sendGoal(goal);
  ASSERT_TRUE(client.waitForResult(::ros::Duration(20.0)));
  EXPECT_EQ(client.getState(), actionlib::SimpleClientGoalState::ABORTED);
  const control_msgs::GripperCommandResult r = *client.getResult();
  std::printf("[ figures  ] ROS GripperCommand on the block: position %.4f rad, effort %.4f N m, stalled %d, reached %d\n", r.position,
              r.effort, r.stalled, r.reached_goal);
  EXPECT_TRUE(r.stalled);
  EXPECT_FALSE(r.reached_goal);
  EXPECT_NEAR(r.position, 0.253, 0.005);
  EXPECT_NEAR(r.effort, 0.05, 0.001);
}

// The example controller plugin's type, found through its package's export on ROS_PACKAGE_PATH as
// the node starts, is loaded by name by the spawner; std_msgs/Float64 on <controller>/command
// moves the finger there, and joint_states shows it.
TEST_F(TestbotNode, ControllerPluginTypeSpawnsByNameAndFollowsItsCommandTopic) {
  const std::string packages = std::string(MECHSIM_BINARY_DIR) + "/plugin_packages";
  const char* old = std::getenv("ROS_PACKAGE_PATH");
  const std::string saved = old != nullptr ? old : "";
  test_ = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  load(std::string(MECHSIM_SOURCE_DIR) + "/examples/controller_plugin/config/gripper_bang_bang.yaml");
  ::setenv("ROS_PACKAGE_PATH", (packages + (saved.empty() ? "" : ":" + saved)).c_str(), 1);
  start("gripper", {{"interface", "EffortJointInterface"}}, "", "/gripper");
  if (old != nullptr) ::setenv("ROS_PACKAGE_PATH", saved.c_str(), 1);
  else ::unsetenv("ROS_PACKAGE_PATH");
  std::mutex m;
  double finger = std::nan("");
  ::ros::Subscriber sub = nh_.subscribe<sensor_msgs::JointState>("/gripper/joint_states", 10, [&](const sensor_msgs::JointState::ConstPtr& js) {
    for (std::size_t i = 0; i < js->name.size() && i < js->position.size(); ++i) {
      if (js->name[i] != "left_finger_joint") continue;
      std::lock_guard<std::mutex> lock(m);
      finger = js->position[i];
    }
  });
  const auto position = [&] {
    std::lock_guard<std::mutex> lock(m);
    return finger;
  };
  ASSERT_TRUE(spawn({"joint_state_controller", "finger_bang_bang"})) << spawner_->log() << node_->log();
  // setpoint 0.2 rad from the YAML
  EXPECT_TRUE(wait_until([&] { return std::fabs(position() - 0.2) < 0.01; }, 20.0)) << "finger at " << position();
  ::ros::Publisher pub = nh_.advertise<std_msgs::Float64>("/gripper/finger_bang_bang/command", 1, true);
  std_msgs::Float64 target;
  target.data = -0.1;
  pub.publish(target);
  EXPECT_TRUE(wait_until([&] { return std::fabs(position() + 0.1) < 0.01; }, 20.0)) << "finger at " << position();
  settle(0.3);
  EXPECT_NEAR(position(), -0.1, 0.01);
}

// ---- gazebo_ros_control's pid_gains and e-stop on the turntable (robots/testbots/urdf/turntable.urdf)

// The turntable with <eStopTopic>e_stop</eStopTopic> in its gazebo_ros_control plugin, and a
// joint_state_controller beside `controllers`; the robot in the root namespace.
class TurntableNode : public TestbotNode {
 protected:
  void start_turntable(const std::string& controllers) {
    std::ifstream in(kTestbots + "/urdf/turntable.urdf");
    std::string urdf((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string plugin = R"(<plugin name="gazebo_ros_control" filename="libgazebo_ros_control.so"/>)";
    const std::size_t at = urdf.find(plugin);
    ASSERT_NE(at, std::string::npos) << "turntable.urdf changed: no plain gazebo_ros_control plugin element";
    urdf.replace(at, plugin.size(),
                 R"(<plugin name="gazebo_ros_control" filename="libgazebo_ros_control.so"><eStopTopic>e_stop</eStopTopic></plugin>)");
    const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    const std::string model = write(name + "_turntable.urdf", urdf);
    load(write(name + "_jsc.yaml", "joint_state_controller: {type: joint_state_controller/JointStateController, publish_rate: 200}\n"));
    start(model, {}, controllers, "");
    sub_ = nh_.subscribe<sensor_msgs::JointState>("/joint_states", 1000, [this](const sensor_msgs::JointState::ConstPtr& js) {
      for (std::size_t i = 0; i < js->name.size() && i < js->position.size(); ++i) {
        if (js->name[i] != "hinge") continue;
        std::lock_guard<std::mutex> lock(hinge_mutex_);
        hinge_ = js->position[i];
        peak_ = std::max(peak_, hinge_);
      }
    });
  }
  void TearDown() override {
    sub_.shutdown();
    TestbotNode::TearDown();
  }
  double hinge() {
    std::lock_guard<std::mutex> lock(hinge_mutex_);
    return hinge_;
  }
  double peak() {
    std::lock_guard<std::mutex> lock(hinge_mutex_);
    return peak_;
  }
  void command(double position) {
    if (!command_pub_) command_pub_ = nh_.advertise<std_msgs::Float64>("/hinge_position_controller/command", 1, true);
    std_msgs::Float64 m;
    m.data = position;
    command_pub_.publish(m);
  }
  void e_stop(bool active) {
    if (!e_stop_pub_) {
      e_stop_pub_ = nh_.advertise<std_msgs::Bool>("/e_stop", 1, true);
      wait_until([&] { return e_stop_pub_.getNumSubscribers() > 0; }, 10.0);
    }
    std_msgs::Bool m;
    m.data = active;
    e_stop_pub_.publish(m);
  }

  ::ros::Subscriber sub_;
  ::ros::Publisher command_pub_, e_stop_pub_;
  std::mutex hinge_mutex_;
  double hinge_ = std::nan(""), peak_ = -1e9;
};

// pid_gains from the parameter server (/gazebo_ros_control/pid_gains/hinge: p 20, d 0.5, a
// lightly damped loop): a 0.5 rad step overshoots by about 70 % as in Gazebo; mechsim's servo
// (no gains) would not overshoot.
TEST_F(TurntableNode, PidGainsFromTheParameterServerDriveThePositionJoint) {
  start_turntable("turntable_controllers.yaml");
  ASSERT_TRUE(spawn({"joint_state_controller", "hinge_position_controller"})) << spawner_->log() << node_->log();
  ASSERT_TRUE(wait_until([&] { return !std::isnan(hinge()); }, 10.0));
  command(0.5);
  settle(1.0);
  std::printf("[ figures  ] ROS pid_gains p 20 d 0.5: a 0.5 rad step peaks at %.4f rad\n", peak());
  EXPECT_GT(peak(), 0.75);
  EXPECT_LT(peak(), 0.95);
}

// <eStopTopic>: while true the position joint holds where it was although the controller is sent
// another position; on release the controller restarts (its command: where the joint is), and a
// new command moves the joint again.
TEST_F(TurntableNode, EStopHoldsTheJointAndTheReleaseRestartsTheControllers) {
  start_turntable("turntable_servo_controllers.yaml");
  ASSERT_TRUE(spawn({"joint_state_controller", "hinge_position_controller"})) << spawner_->log() << node_->log();
  command(0.5);
  ASSERT_TRUE(wait_until([&] { return std::fabs(hinge() - 0.5) < 0.005; }, 20.0)) << "hinge at " << hinge();
  e_stop(true);
  settle(0.2);
  command(1.0);
  settle(1.0);
  EXPECT_NEAR(hinge(), 0.5, 0.005) << "moved during the e-stop\n" << node_->log();
  e_stop(false);
  settle(1.0);
  EXPECT_NEAR(hinge(), 0.5, 0.005) << "the restarted controller should hold where the joint is";
  command(1.0);
  EXPECT_TRUE(wait_until([&] { return std::fabs(hinge() - 1.0) < 0.005; }, 20.0)) << "hinge at " << hinge();
  EXPECT_NE(node_->log().find("e-stop on /e_stop"), std::string::npos) << node_->log();
}

}  // namespace
}  // namespace mechsim::ros::test
