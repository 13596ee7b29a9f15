// Several robots in one world through the ROS node in gzserver mode (~gazebo:=true), against a
// real master: two CC8s (robots/cc8, expanded by `mechsim xacro` with robot_ns:=/cc8_a and
// /cc8_b, as a user gives each robot its own namespace) spawned through /gazebo/spawn_urdf_model,
// each with its own controller manager and rover drive started by mechsim_spawner, driven with
// different twists at real time. Checked: the second spawn does not disturb the first rover
// (no time jump, its controllers keep running, its speed holds); each odometry follows its own
// rover (the displacement within 3 %, the CC8 scenario's tolerance), and each one's ZED2 IMU
// gives its own heading; deleting the first unloads its controllers while the second drives on
// undisturbed; deleting the last leaves the clock running. Waits add up to about 25 s of wall time.
#include <gmock/gmock.h>

#include <cmath>
#include <deque>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>

#include <controller_manager_msgs/ListControllers.h>
#include <gazebo_msgs/DeleteModel.h>
#include <gazebo_msgs/GetModelState.h>
#include <gazebo_msgs/GetWorldProperties.h>
#include <gazebo_msgs/ModelStates.h>
#include <gazebo_msgs/SpawnModel.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/Imu.h>

#include "gazebo_world_fixture.hpp"

namespace mechsim::ros::test {
namespace {

struct Sample {
  double t, x, y;
};

// One rover as the test drives and watches it: its odometry (rover drive's odom) and twist.
struct Rover {
  std::string name, ns;
  std::mutex mutex;
  std::deque<Sample> odom;
  ::ros::Subscriber odom_sub;
  ::ros::Publisher cmd;
  geometry_msgs::Twist twist;

  // Odometry at sim time t, linearly between the two samples around it (nullopt: none yet).
  std::optional<Sample> odom_at(double t) {
    std::lock_guard<std::mutex> lock(mutex);
    for (std::size_t i = 1; i < odom.size(); ++i) {
      if (odom[i].t >= t && odom[i - 1].t <= t) {
        const double a = odom[i].t > odom[i - 1].t ? (t - odom[i - 1].t) / (odom[i].t - odom[i - 1].t) : 0.0;
        return Sample{t, odom[i - 1].x + a * (odom[i].x - odom[i - 1].x), odom[i - 1].y + a * (odom[i].y - odom[i - 1].y)};
      }
    }
    return std::nullopt;
  }
  double latest() {
    std::lock_guard<std::mutex> lock(mutex);
    return odom.empty() ? -1.0 : odom.back().t;
  }
  double first() {
    std::lock_guard<std::mutex> lock(mutex);
    return odom.empty() ? -1.0 : odom.front().t;
  }
};

class SeveralRobotsNode : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(::ros::master::check()) << "no ROS master";
    node_ = std::make_unique<ChildProcess>(
        std::vector<std::string>{MECHSIM_NODE_EXE, "__name:=gazebo", "_gazebo:=true", "_real_time_factor:=1.0",
                                 "_paused:=false"},
        log_dir() + "/gazebo_several_robots.log");
    ASSERT_TRUE(::ros::service::waitForService("/gazebo/spawn_urdf_model", ::ros::Duration(20.0))) << node_->log();
    // The CC8's controllers (robots/cc8/config/controllers.yaml, under /cc8) copied under each
    // rover's namespace.
    ChildProcess load({"/usr/bin/python3", "/usr/bin/rosparam", "load",
                       std::string(MECHSIM_SOURCE_DIR) + "/robots/cc8/config/controllers.yaml"},
                      log_dir() + "/rosparam_several_robots.log");
    ASSERT_EQ(load.wait(30.0), 0) << load.log();
    XmlRpc::XmlRpcValue controllers;
    ASSERT_TRUE(::ros::param::get("/cc8", controllers));
    ::ros::param::set("/cc8_a", controllers);
    ::ros::param::set("/cc8_b", controllers);
    clock_sub_ = nh_.subscribe<rosgraph_msgs::Clock>("/clock", 10, [this](const rosgraph_msgs::Clock::ConstPtr& m) {
      std::lock_guard<std::mutex> lock(mutex_);
      clock_ = m->clock.toSec();
    });
  }

  void TearDown() override {
    for (auto it = spawners_.rbegin(); it != spawners_.rend(); ++it) (*it)->stop();
    clock_sub_.shutdown();
    if (node_) {
      EXPECT_EQ(node_->stop(15.0), 0) << "mechsim_node did not stop cleanly; its log:\n" << node_->log();
    }
    params_.forget_new();
  }

  double clock_now() {
    std::lock_guard<std::mutex> lock(mutex_);
    return clock_;
  }

  // The CC8 description with its controller manager under `ns`.
  std::string description(const std::string& ns) {
    const std::string out = log_dir() + "/cc8" + std::to_string(descriptions_++) + ".urdf";
    ChildProcess xacro({MECHSIM_EXE, "xacro", std::string(MECHSIM_SOURCE_DIR) + "/robots/cc8/urdf/cc8.urdf.xacro",
                        "robot_ns:=" + ns, "--package", "mechsim_cc8=" + std::string(MECHSIM_SOURCE_DIR) + "/robots/cc8",
                        "-o", out},
                       log_dir() + "/xacro_several_robots.log");
    EXPECT_EQ(xacro.wait(30.0), 0) << xacro.log();
    std::ifstream in(out);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

  gazebo_msgs::SpawnModel spawn(const std::string& name, const std::string& ns, double x, double y, double yaw) {
    gazebo_msgs::SpawnModel s;
    s.request.model_name = name;
    s.request.model_xml = description(ns);
    s.request.initial_pose.position.x = x;
    s.request.initial_pose.position.y = y;
    s.request.initial_pose.position.z = 0.01;
    s.request.initial_pose.orientation.w = std::cos(yaw / 2);
    s.request.initial_pose.orientation.z = std::sin(yaw / 2);
    EXPECT_TRUE(call("/gazebo/spawn_urdf_model", s));
    return s;
  }

  // Starts the rover's joint_state_controller and rover drive; subscribes to its odometry.
  void start_rover(Rover& r) {
    spawners_.push_back(std::make_unique<ChildProcess>(
        std::vector<std::string>{MECHSIM_SPAWNER_EXE, "__ns:=" + r.ns, "__name:=spawner", "joint_state_controller",
                                 "rover_drive_controller"},
        log_dir() + "/spawner_" + r.name + ".log"));
    ASSERT_TRUE(wait_until([&] { return running(r.ns).size() == 2; }, 30.0)) << spawners_.back()->log();
    r.odom_sub = nh_.subscribe<nav_msgs::Odometry>(
        r.ns + "/rover_drive_controller/odom", 100, [&r](const nav_msgs::Odometry::ConstPtr& m) {
          std::lock_guard<std::mutex> lock(r.mutex);
          r.odom.push_back({m->header.stamp.toSec(), m->pose.pose.position.x, m->pose.pose.position.y});
          if (r.odom.size() > 2000) r.odom.pop_front();
        });
    r.cmd = nh_.advertise<geometry_msgs::Twist>(r.ns + "/rover_drive_controller/cmd_vel", 1);
    ASSERT_TRUE(wait_until([&] { return r.latest() > 0.0 && r.cmd.getNumSubscribers() > 0; }, 10.0));
  }

  std::vector<std::string> running(const std::string& ns) {
    controller_manager_msgs::ListControllers list;
    std::vector<std::string> out;
    if (!::ros::service::call(ns + "/controller_manager/list_controllers", list)) return out;
    for (const auto& c : list.response.controller)
      if (c.state == "running") out.push_back(c.name);
    std::sort(out.begin(), out.end());
    return out;
  }

  // The model's ground truth (x, y) and its stamp.
  Sample truth(const std::string& model) {
    gazebo_msgs::GetModelState g;
    g.request.model_name = model;
    EXPECT_TRUE(call("/gazebo/get_model_state", g));
    EXPECT_TRUE(g.response.success) << g.response.status_message;
    return {g.response.header.stamp.toSec(), g.response.pose.position.x, g.response.pose.position.y};
  }

  // Drives the rovers (their twists, re-sent at 20 Hz wall: the drive's cmd_vel timeout is 0.5 s
  // of sim time) for `seconds` of sim time.
  void drive(const std::vector<Rover*>& rovers, double seconds) {
    const double until = clock_now() + seconds;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(3.0 * seconds + 10.0);
    while (clock_now() < until && std::chrono::steady_clock::now() < deadline) {
      for (Rover* r : rovers) r->cmd.publish(r->twist);
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  }

  // |odometry displacement| against |ground truth displacement| between two truth samples.
  static double odometry_error(Rover& r, const Sample& t0, const Sample& t1, double* moved) {
    wait_until([&] { return r.latest() >= t1.t; }, 2.0);  // the odometry of t1 is on its way
    const auto o0 = r.odom_at(t0.t), o1 = r.odom_at(t1.t);
    EXPECT_TRUE(o0 && o1) << r.name << ": no odometry around t = " << t0.t << " and " << t1.t << " (odometry from "
                          << r.first() << " to " << r.latest() << " s)";
    if (!o0 || !o1) return 1.0;
    *moved = std::hypot(t1.x - t0.x, t1.y - t0.y);
    const double odom = std::hypot(o1->x - o0->x, o1->y - o0->y);
    return std::abs(odom - *moved) / std::max(*moved, 1e-9);
  }

  std::unique_ptr<ChildProcess> node_;
  std::vector<std::unique_ptr<ChildProcess>> spawners_;
  ParamSnapshot params_;
  ::ros::NodeHandle nh_;
  ::ros::Subscriber clock_sub_;
  std::mutex mutex_;
  double clock_ = -1.0;
  int descriptions_ = 0;
};

TEST_F(SeveralRobotsNode, TwoCc8sDriveUnderTheirOwnNamespacesAndTheFirstIsDeletedWhileTheOtherDrives) {
  Rover a, b;
  a.name = "cc8_a", a.ns = "/cc8_a";
  b.name = "cc8_b", b.ns = "/cc8_b";
  a.twist.linear.x = 0.3;                          // straight along +x
  b.twist.linear.x = 0.3, b.twist.angular.z = 0.2;  // a left turn of 1.5 m radius

  auto s = spawn(a.name, a.ns, 0.0, 0.0, 0.0);
  ASSERT_TRUE(s.response.success) << s.response.status_message << "\n" << node_->log();
  start_rover(a);
  drive({&a}, 1.5);  // up to speed

  // The second rover comes in while the first drives: time goes on, the first keeps its speed.
  const Sample a0 = truth(a.name);
  const double t_before = clock_now();
  s = spawn(b.name, b.ns, 0.0, 4.0, M_PI / 2);
  ASSERT_TRUE(s.response.success) << s.response.status_message << "\n" << node_->log();
  EXPECT_GE(clock_now(), t_before) << "time went back at the spawn";
  drive({&a}, 1.0);
  const Sample a1 = truth(a.name);
  const double speed_over_spawn = (a1.x - a0.x) / (a1.t - a0.t);
  EXPECT_NEAR(speed_over_spawn, 0.3, 0.03) << "the first rover's speed over the second's spawn";
  EXPECT_EQ(running(a.ns), (std::vector<std::string>{"joint_state_controller", "rover_drive_controller"}))
      << "the first rover's controllers after the second's spawn";
  {
    gazebo_msgs::GetWorldProperties w;
    ASSERT_TRUE(call("/gazebo/get_world_properties", w));
    EXPECT_THAT(w.response.model_names, ::testing::ElementsAre("ground_plane", "cc8_a", "cc8_b"));
  }
  // Each rover's sensors are its own, on its own topics: the ZED2 IMUs give their own headings.
  {
    std::mutex m;
    std::map<std::string, double> yaw;
    std::vector<::ros::Subscriber> subs;
    for (const std::string& ns : {a.ns, b.ns}) {
      subs.push_back(nh_.subscribe<sensor_msgs::Imu>(ns + "/zed2/imu/data", 10, [&, ns](const sensor_msgs::Imu::ConstPtr& msg) {
        const auto& q = msg->orientation;
        std::lock_guard<std::mutex> l(m);
        yaw[ns] = std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
      }));
    }
    EXPECT_TRUE(wait_until([&] { std::lock_guard<std::mutex> l(m); return yaw.size() == 2; }, 10.0))
        << "no IMU message from one of the rovers";
    std::lock_guard<std::mutex> l(m);
    EXPECT_NEAR(yaw[b.ns] - yaw[a.ns], M_PI / 2, 0.05) << "the second rover faces +y, the first +x";
  }
  // A third under a namespace in use is refused, and the world runs on.
  const auto refused = spawn("cc8_c", a.ns, 5.0, -4.0, 0.0);
  EXPECT_FALSE(refused.response.success);
  EXPECT_THAT(refused.response.status_message, ::testing::HasSubstr("namespace '/cc8_a'"));

  // Both drive, each under its own twist; each odometry follows its own rover.
  start_rover(b);
  drive({&a, &b}, 1.0);
  const Sample a2 = truth(a.name), b2 = truth(b.name);
  drive({&a, &b}, 5.0);
  const Sample a3 = truth(a.name), b3 = truth(b.name);
  double moved_a = 0.0, moved_b = 0.0;
  const double error_a = odometry_error(a, a2, a3, &moved_a);
  const double error_b = odometry_error(b, b2, b3, &moved_b);
  std::printf("two CC8s: a moved %.3f m (odometry error %.2f %%), b moved %.3f m (%.2f %%); a's speed over b's spawn "
              "%.3f m/s\n",
              moved_a, 100.0 * error_a, moved_b, 100.0 * error_b, speed_over_spawn);
  EXPECT_GT(moved_a, 1.2);
  EXPECT_GT(moved_b, 1.2);
  EXPECT_LT(error_a, 0.03);
  EXPECT_LT(error_b, 0.03);
  EXPECT_NEAR(a3.y, 0.0, 0.1) << "the first rover drives straight";
  EXPECT_LT(b3.x, -0.3) << "the second rover turns left (from facing +y towards -x)";
  // /gazebo/model_states holds both.
  {
    ModelStatesWatch watch(nh_);
    ASSERT_TRUE(watch.wait_for_more_than(0, 5.0));
    const gazebo_msgs::ModelStates states = watch.latest();
    ASSERT_THAT(states.name, ::testing::ElementsAre("ground_plane", "cc8_a", "cc8_b"));
    EXPECT_NEAR(states.pose[2].position.x, b3.x, 0.2);
  }

  // The first one goes (Gazebo deletes any model); the second drives on undisturbed.
  const Sample b4 = truth(b.name);
  gazebo_msgs::DeleteModel d;
  d.request.model_name = a.name;
  ASSERT_TRUE(call("/gazebo/delete_model", d));
  ASSERT_TRUE(d.response.success) << d.response.status_message;
  EXPECT_THAT(node_->log(), ::testing::HasSubstr("deleted 'cc8_a' (2 controllers stopped and unloaded)"));
  EXPECT_TRUE(wait_until([&] { return !::ros::service::exists(a.ns + "/controller_manager/list_controllers", false); }, 5.0))
      << "the deleted rover's controller manager is still there";
  drive({&b}, 2.0);
  const Sample b5 = truth(b.name);
  // A 1.5 m radius at 0.3 m/s: over dt the chord is 2 R sin(0.1 dt).
  const double dt = b5.t - b4.t;
  const double chord = std::hypot(b5.x - b4.x, b5.y - b4.y);
  double moved = 0.0;
  const double error_after = odometry_error(b, b4, b5, &moved);
  std::printf("after the delete of the first: the second moved %.3f m in %.3f s (%.3f m on its arc), odometry error "
              "%.2f %%\n", chord, dt, 2 * 1.5 * std::sin(0.1 * dt), 100.0 * error_after);
  EXPECT_NEAR(chord, 2 * 1.5 * std::sin(0.1 * dt), 0.03);
  EXPECT_LT(error_after, 0.03);
  EXPECT_EQ(running(b.ns), (std::vector<std::string>{"joint_state_controller", "rover_drive_controller"}));
  gazebo_msgs::GetWorldProperties w;
  ASSERT_TRUE(call("/gazebo/get_world_properties", w));
  EXPECT_THAT(w.response.model_names, ::testing::ElementsAre("ground_plane", "cc8_b"));
  // The last one goes: the world's clock goes on from where it was.
  const double before = clock_now();
  d.request.model_name = b.name;
  ASSERT_TRUE(call("/gazebo/delete_model", d));
  ASSERT_TRUE(d.response.success) << d.response.status_message;
  EXPECT_GE(clock_now(), before);
  EXPECT_TRUE(wait_until([&] { return clock_now() > before + 0.3; }, 5.0)) << "the clock stopped with the last model";
}

}  // namespace
}  // namespace mechsim::ros::test
