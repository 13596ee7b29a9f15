// The real PR2 (the reference pr2_description expansion, lenient) in mechsim_node with the PR2's
// interfaces: gripper_action and joint_trajectory_action (pr2_controllers_msgs), the base
// command and base_odometry, and pr2_controller_manager's joint_states, mechanism_statistics
// and /calibrated. The controllers come from robots/pr2/config/controllers.yaml (namespace
// /pr2). The node runs as fast as it can (about 3x real time): every check waits on sim time
// carried by the messages, with wall-clock bounds only as timeouts.
#include <gmock/gmock.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <set>

#include <actionlib/client/simple_action_client.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <pr2_controllers_msgs/JointControllerState.h>
#include <pr2_controllers_msgs/JointTrajectoryAction.h>
#include <pr2_controllers_msgs/JointTrajectoryControllerState.h>
#include <pr2_controllers_msgs/Pr2GripperCommandAction.h>
#include <pr2_mechanism_msgs/ListControllers.h>
#include <pr2_mechanism_msgs/MechanismStatistics.h>
#include <pr2_msgs/PeriodicCmd.h>
#include <pr2_msgs/PressureState.h>
#include <pr2_msgs/SetLaserTrajCmd.h>
#include <pr2_msgs/SetPeriodicCmd.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/Bool.h>
#include <tf2_msgs/TFMessage.h>

#include "ros_fixture.hpp"

namespace mechsim::ros::test {
namespace {

namespace pcm = pr2_controllers_msgs;
namespace pmm = pr2_mechanism_msgs;

const std::string kPr2Urdf = std::string(MECHSIM_SHARED_DIR) + "/robots/reference/pr2.urdf";

const std::vector<std::string> kRightArm = {"r_shoulder_pan_joint", "r_shoulder_lift_joint", "r_upper_arm_roll_joint",
                                            "r_elbow_flex_joint",   "r_forearm_roll_joint",  "r_wrist_flex_joint",
                                            "r_wrist_roll_joint"};

class Pr2Node : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(kPr2Urdf)) {
      GTEST_SKIP() << "the shared data folder has no PR2 (" << kPr2Urdf << "); skipping the PR2 node tests";
    }
    ASSERT_TRUE(::ros::master::check()) << "no ROS master";
    name_ = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    ChildProcess load({"/usr/bin/python3", "/usr/bin/rosparam", "load",
                       std::string(MECHSIM_SOURCE_DIR) + "/robots/pr2/config/controllers.yaml"},
                      log_dir() + "/rosparam_" + name_ + ".log");
    ASSERT_EQ(load.wait(30.0), 0) << load.log();
    // The controllers' namespace is /pr2 (the YAML's); the PR2 gazebo plugin in the URDF makes
    // the node a pr2_controller_manager.
    node_ = std::make_unique<ChildProcess>(
        std::vector<std::string>{MECHSIM_NODE_EXE, "__name:=mechsim", "_model:=" + kPr2Urdf, "_lenient:=true",
                                 "_robot_namespace:=/pr2"},
        log_dir() + "/node_" + name_ + ".log");
    pmm::ListControllers list;
    ASSERT_TRUE(call("/pr2_controller_manager/list_controllers", list, 30.0))
        << "the node did not come up; its log:\n" << node_->log();
  }

  void TearDown() override {
    if (spawner_) spawner_->stop();
    if (node_) {
      const int status = node_->stop(10.0);
      EXPECT_EQ(status, 0) << "mechsim_node did not stop cleanly on SIGINT; its log:\n" << node_->log();
    }
  }

  // Loads and starts `controllers` with mechsim_spawner (namespace /pr2); true once all run.
  bool spawn(const std::vector<std::string>& controllers) {
    std::vector<std::string> argv{MECHSIM_SPAWNER_EXE, "__ns:=/pr2", "__name:=spawner"};
    argv.insert(argv.end(), controllers.begin(), controllers.end());
    spawner_ = std::make_unique<ChildProcess>(argv, log_dir() + "/spawner_" + name_ + ".log");
    const bool running = wait_until(
        [&] {
          pmm::ListControllers list;
          if (!call("/pr2_controller_manager/list_controllers", list, 1.0)) return false;
          return static_cast<std::size_t>(std::count(list.response.state.begin(), list.response.state.end(),
                                                     "running")) == controllers.size();
        },
        20.0);
    if (!running) ADD_FAILURE() << "controllers not running; spawner log:\n" << spawner_->log();
    return running;
  }

  std::string name_;
  std::unique_ptr<ChildProcess> node_;
  std::unique_ptr<ChildProcess> spawner_;
  ::ros::NodeHandle nh_;
};

// The publication schedule from received stamps (sim time): the median interval between
// consecutive messages, and the fraction of intervals that are exactly one `period`. Under load
// the node may skip a publication (try-lock, never blocking the loop) and the subscriber may
// drop one, so a message count over the span would measure delivery, not the schedule.
double median_interval(const std::vector<double>& stamps) {
  std::vector<double> d;
  for (std::size_t k = 1; k < stamps.size(); ++k) d.push_back(stamps[k] - stamps[k - 1]);
  if (d.empty()) return std::nan("");
  std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
  return d[d.size() / 2];
}

double whole_periods(const std::vector<double>& stamps, double period) {
  std::size_t whole = 0;
  for (std::size_t k = 1; k < stamps.size(); ++k) {
    if (std::abs(stamps[k] - stamps[k - 1] - period) < 1e-6) ++whole;
  }
  return stamps.size() < 2 ? 0.0 : static_cast<double>(whole) / static_cast<double>(stamps.size() - 1);
}

TEST_F(Pr2Node, GripperActionOpensAndJointTrajectoryActionMovesTheArm) {
  ASSERT_TRUE(spawn({"r_gripper_controller", "r_arm_controller"}));

  // The gripper state speaks pr2_controllers_msgs.
  std::mutex m;
  double gap = NAN;
  ::ros::Subscriber gripper_state = nh_.subscribe<pcm::JointControllerState>(
      "/pr2/r_gripper_controller/state", 10, [&](const pcm::JointControllerState::ConstPtr& msg) {
        std::lock_guard<std::mutex> l(m);
        gap = msg->process_value;
      });

  actionlib::SimpleActionClient<pcm::Pr2GripperCommandAction> gripper("/pr2/r_gripper_controller/gripper_action",
                                                                      true);
  ASSERT_TRUE(gripper.waitForServer(::ros::Duration(10.0)));
  pcm::Pr2GripperCommandGoal open;
  open.command.position = 0.08;
  open.command.max_effort = -1.0;
  // Feedback and result arrive on separate topics (separate connections, callbacks on the
  // spinner's two threads): the last feedback may be handled after the result.
  std::atomic<int> feedback_count{0};
  gripper.sendGoal(open, {}, {}, [&](const pcm::Pr2GripperCommandFeedbackConstPtr&) { ++feedback_count; });
  ASSERT_TRUE(gripper.waitForResult(::ros::Duration(15.0))) << "no gripper result";
  EXPECT_EQ(gripper.getState(), actionlib::SimpleClientGoalState::SUCCEEDED) << gripper.getState().getText();
  ASSERT_TRUE(gripper.getResult());
  EXPECT_TRUE(gripper.getResult()->reached_goal);
  EXPECT_FALSE(gripper.getResult()->stalled);
  EXPECT_NEAR(gripper.getResult()->position, 0.08, 0.01);  // goal_threshold
  EXPECT_TRUE(wait_until([&] { return feedback_count.load() > 0; }, 2.0)) << "no feedback for the goal";
  EXPECT_TRUE(wait_until(
      [&] {
        std::lock_guard<std::mutex> l(m);
        return std::abs(gap - 0.08) < 0.01;
      },
      5.0))
      << "gripper state process_value " << gap;

  // pr2_gripper_action's stall: too little effort to move the fingers is a stall short of the
  // goal, ABORTED with stalled = true (the gripper keeps the command).
  pcm::Pr2GripperCommandGoal weak;
  weak.command.position = 0.0;
  weak.command.max_effort = 0.1;  // N
  gripper.sendGoal(weak);
  ASSERT_TRUE(gripper.waitForResult(::ros::Duration(15.0))) << "no gripper result";
  EXPECT_EQ(gripper.getState(), actionlib::SimpleClientGoalState::ABORTED) << gripper.getState().getText();
  ASSERT_TRUE(gripper.getResult());
  EXPECT_TRUE(gripper.getResult()->stalled);
  EXPECT_FALSE(gripper.getResult()->reached_goal);
  EXPECT_GT(gripper.getResult()->position, 0.03);

  // The plain command topic (no action): the set point follows.
  double set_point = NAN;
  ::ros::Subscriber set_points = nh_.subscribe<pcm::JointControllerState>(
      "/pr2/r_gripper_controller/state", 10, [&](const pcm::JointControllerState::ConstPtr& msg) {
        std::lock_guard<std::mutex> l(m);
        set_point = msg->set_point;
      });
  ::ros::Publisher command = nh_.advertise<pcm::Pr2GripperCommand>("/pr2/r_gripper_controller/command", 1, true);
  pcm::Pr2GripperCommand c;
  c.position = 0.05;
  c.max_effort = -1.0;
  command.publish(c);
  EXPECT_TRUE(wait_until(
      [&] {
        std::lock_guard<std::mutex> l(m);
        return std::abs(set_point - 0.05) < 1e-9 && std::abs(gap - 0.05) < 0.01;
      },
      10.0))
      << "set point " << set_point << ", gap " << gap;

  // The arm: joint_trajectory_action (a bare trajectory; the controller's constraints apply).
  std::vector<double> actual;
  ::ros::Subscriber arm_state = nh_.subscribe<pcm::JointTrajectoryControllerState>(
      "/pr2/r_arm_controller/state", 10, [&](const pcm::JointTrajectoryControllerState::ConstPtr& msg) {
        std::lock_guard<std::mutex> l(m);
        actual = msg->actual.positions;
      });
  actionlib::SimpleActionClient<pcm::JointTrajectoryAction> arm("/pr2/r_arm_controller/joint_trajectory_action", true);
  ASSERT_TRUE(arm.waitForServer(::ros::Duration(10.0)));
  const std::vector<double> target = {-0.1, 0.0, -0.1, -0.3, 0.0, -0.3, 0.0};
  pcm::JointTrajectoryGoal goal;
  goal.trajectory.joint_names = kRightArm;
  trajectory_msgs::JointTrajectoryPoint point;
  point.positions = target;
  point.velocities.assign(target.size(), 0.0);
  point.time_from_start = ::ros::Duration(1.5);
  goal.trajectory.points.push_back(point);
  arm.sendGoal(goal);
  ASSERT_TRUE(arm.waitForResult(::ros::Duration(20.0))) << "no arm result";
  EXPECT_EQ(arm.getState(), actionlib::SimpleClientGoalState::SUCCEEDED) << arm.getState().getText();
  {
    std::lock_guard<std::mutex> l(m);
    ASSERT_EQ(actual.size(), target.size());
    for (std::size_t j = 0; j < target.size(); ++j) EXPECT_NEAR(actual[j], target[j], 0.05) << kRightArm[j];
  }

  // A goal naming a joint the controller does not have is rejected.
  goal.trajectory.joint_names[0] = "no_such_joint";
  arm.sendGoal(goal);
  ASSERT_TRUE(arm.waitForResult(::ros::Duration(10.0)));
  EXPECT_EQ(arm.getState(), actionlib::SimpleClientGoalState::REJECTED);
}

// The laser tilt controller's pr2_msgs interface: set_periodic_cmd and set_traj_cmd as services
// (start_time in sim time; a bad command refused) and as topics; the set point follows each
// profile (from the controller's state, stamped in sim time).
TEST_F(Pr2Node, LaserTiltSetPeriodicAndSetTrajCommandsReshapeTheSweep) {
  ASSERT_TRUE(spawn({"laser_tilt_controller"}));
  std::mutex m;
  std::vector<std::pair<double, double>> set_points;  // (stamp, set point)
  ::ros::Subscriber state = nh_.subscribe<pcm::JointControllerState>(
      // 20 s of messages: a test process starved on a loaded machine must not drop the corners.
      "/pr2/laser_tilt_controller/state", 1000, [&](const pcm::JointControllerState::ConstPtr& msg) {
        std::lock_guard<std::mutex> l(m);
        set_points.emplace_back(msg->header.stamp.toSec(), msg->set_point);
      });
  // Extremes of the set point over [from, from + span] of sim time, once that much has come.
  const auto extremes = [&](double from, double span, double& low, double& high) {
    const bool done = wait_until(
        [&] {
          std::lock_guard<std::mutex> l(m);
          return !set_points.empty() && set_points.back().first > from + span;
        },
        30.0);
    std::lock_guard<std::mutex> l(m);
    low = 1e9;
    high = -1e9;
    for (const auto& [t, p] : set_points) {
      if (t < from || t > from + span) continue;
      low = std::min(low, p);
      high = std::max(high, p);
    }
    return done;
  };

  pr2_msgs::SetPeriodicCmd periodic;
  periodic.request.command.profile = "linear";
  periodic.request.command.period = 2.0;
  periodic.request.command.amplitude = 0.5;
  periodic.request.command.offset = 0.3;
  ASSERT_TRUE(call("/pr2/laser_tilt_controller/set_periodic_cmd", periodic, 10.0));
  const double t1 = periodic.response.start_time.toSec();
  EXPECT_GT(t1, 0.0);
  // Set points come at 50 Hz of sim time (0.02 rad apart at 1 rad/s), and the node's real-time
  // publisher drops states while its thread is starved: under a loaded CI run one window of two
  // periods once lost both top corners (0.15 rad of each). Four whole periods, the corners
  // within 0.03 rad.
  double low = 0.0, high = 0.0;
  ASSERT_TRUE(extremes(t1 + 0.1, 8.0, low, high));
  EXPECT_NEAR(low, -0.2, 0.03);
  EXPECT_NEAR(high, 0.8, 0.03);

  pr2_msgs::SetLaserTrajCmd traj;
  traj.request.command.profile = "blended_linear";
  traj.request.command.position = {0.0, 1.0, 0.0};
  traj.request.command.time_from_start = {::ros::Duration(0.0), ::ros::Duration(1.0), ::ros::Duration(2.0)};
  traj.request.command.max_acceleration = 20.0;
  ASSERT_TRUE(call("/pr2/laser_tilt_controller/set_traj_cmd", traj, 10.0));
  const double t2 = traj.response.start_time.toSec();
  EXPECT_GE(t2, t1 + 4.0);
  ASSERT_TRUE(extremes(t2 + 0.1, 4.0, low, high));
  // Blends of 2 rad/s over 20 rad/s^2 (0.1 s) cut the corners by (2 x 0.1) / 8 = 0.025 rad: the
  // top at 0.975 (sampled, maybe short of it), not the linear corner at 1; likewise the bottom.
  EXPECT_GT(high, 0.94);
  EXPECT_LT(high, 0.985);
  EXPECT_GT(low, 0.015);
  EXPECT_LT(low, 0.06);

  // A command the controller cannot run is refused (the service call fails); the sweep goes on.
  pr2_msgs::SetLaserTrajCmd bad;
  bad.request.command.profile = "linear";
  bad.request.command.position = {0.0, 1.0};
  bad.request.command.time_from_start = {::ros::Duration(0.0)};
  EXPECT_FALSE(call("/pr2/laser_tilt_controller/set_traj_cmd", bad, 10.0));

  // The topic form.
  ::ros::Publisher topic =
      nh_.advertise<pr2_msgs::PeriodicCmd>("/pr2/laser_tilt_controller/set_periodic_cmd", 1, true);
  pr2_msgs::PeriodicCmd narrow;
  narrow.profile = "linear";
  narrow.period = 1.0;
  narrow.amplitude = 0.2;
  narrow.offset = 0.5;
  ASSERT_TRUE(wait_until([&] { return topic.getNumSubscribers() > 0; }, 10.0));
  topic.publish(narrow);
  // Once taken, the last two seconds of set points span the new profile's range.
  const bool reshaped = wait_until(
      [&] {
        std::lock_guard<std::mutex> l(m);
        const double last = set_points.back().first;
        low = 1e9;
        high = -1e9;
        for (const auto& [t, p] : set_points) {
          if (t < last - 2.05) continue;
          low = std::min(low, p);
          high = std::max(high, p);
        }
        return std::abs(low - 0.3) < 0.03 && std::abs(high - 0.7) < 0.03;
      },
      30.0);
  EXPECT_TRUE(reshaped) << "the last two seconds' set points span [" << low << ", " << high << "]";
}

// The PR2 with its meshes (ROS_PACKAGE_PATH finds pr2_description in the shared data): the
// fingertips have collision shapes, so their contact sensors (and the pressure pads) exist.
class Pr2NodeWithMeshes : public Pr2Node {
 protected:
  void SetUp() override {
    const char* old = std::getenv("ROS_PACKAGE_PATH");
    std::string path = std::string(MECHSIM_SHARED_DIR) + "/robots";
    if (old && *old) path += std::string(":") + old;
    setenv("ROS_PACKAGE_PATH", path.c_str(), 1);
    Pr2Node::SetUp();
  }
};

// /pressure/<side>_gripper_motor (pr2_msgs/PressureState): 22 pads per fingertip at 25 Hz of sim
// time, all zero with nothing between the fingers (the fingertips do not collide with each other).
TEST_F(Pr2NodeWithMeshes, FingertipPressureAt25HzWith22PadsPerFingertip) {
  std::mutex m;
  std::vector<double> stamps;
  std::size_t bad_sizes = 0, nonzero = 0;
  ::ros::Subscriber pressure = nh_.subscribe<pr2_msgs::PressureState>(
      "/pressure/r_gripper_motor", 100, [&](const pr2_msgs::PressureState::ConstPtr& msg) {
        std::lock_guard<std::mutex> l(m);
        stamps.push_back(msg->header.stamp.toSec());
        if (msg->l_finger_tip.size() != 22 || msg->r_finger_tip.size() != 22) ++bad_sizes;
        for (const auto v : msg->l_finger_tip) nonzero += v != 0;
        for (const auto v : msg->r_finger_tip) nonzero += v != 0;
      });
  ASSERT_TRUE(wait_until(
      [&] {
        std::lock_guard<std::mutex> l(m);
        return stamps.size() >= 30;
      },
      30.0));
  std::lock_guard<std::mutex> l(m);
  EXPECT_NEAR(median_interval(stamps), 0.04, 1e-6);
  EXPECT_GT(whole_periods(stamps, 0.04), 0.8);
  EXPECT_EQ(bad_sizes, 0u);
  EXPECT_EQ(nonzero, 0u);
}

TEST_F(Pr2Node, BaseCommandTwistDrivesBaseOdometry) {
  ASSERT_TRUE(spawn({"base_controller", "base_odometry"}));
  std::mutex m;
  nav_msgs::Odometry last;
  std::vector<double> stamps;
  ::ros::Subscriber odom =
      nh_.subscribe<nav_msgs::Odometry>("/pr2/base_odometry/odom", 100, [&](const nav_msgs::Odometry::ConstPtr& msg) {
        std::lock_guard<std::mutex> l(m);
        last = *msg;
        stamps.push_back(msg->header.stamp.toSec());
      });
  bool odom_tf = false;
  ::ros::Subscriber tf = nh_.subscribe<tf2_msgs::TFMessage>("/tf", 100, [&](const tf2_msgs::TFMessage::ConstPtr& msg) {
    for (const auto& t : msg->transforms) {
      if (t.header.frame_id == "odom" && t.child_frame_id == "base_footprint") {
        std::lock_guard<std::mutex> l(m);
        odom_tf = true;
      }
    }
  });
  ::ros::Publisher cmd = nh_.advertise<geometry_msgs::Twist>("/pr2/base_controller/command", 1);
  ASSERT_TRUE(wait_until([&] { return cmd.getNumSubscribers() > 0; }, 10.0));
  // The odometry reaches us before the base moves (on a loaded machine the subscription can
  // connect late, and the drive would be over before enough stamps arrived).
  ASSERT_TRUE(wait_until(
      [&] {
        std::lock_guard<std::mutex> l(m);
        return !stamps.empty();
      },
      10.0));
  geometry_msgs::Twist twist;
  twist.linear.x = 0.2;
  // Keep commanding (the base controller stops on a stale command) until x has grown.
  double x = 0.0;
  const bool moved = wait_until(
      [&] {
        cmd.publish(twist);
        std::lock_guard<std::mutex> l(m);
        x = last.pose.pose.position.x;
        return x > 0.15;
      },
      20.0);
  EXPECT_TRUE(moved) << "base_odometry x = " << x;
  std::lock_guard<std::mutex> l(m);
  EXPECT_EQ(last.header.frame_id, "odom");
  EXPECT_EQ(last.child_frame_id, "base_footprint");
  EXPECT_NEAR(last.twist.twist.linear.x, 0.2, 0.05);
  EXPECT_LT(std::abs(last.pose.pose.position.y), 0.03);
  EXPECT_TRUE(odom_tf) << "no odom -> base_footprint on /tf";
  // Pr2Odometry's default odom_publish_rate: 30 Hz of sim time.
  ASSERT_GE(stamps.size(), 10u);
  // Due at whole multiples of 1/30 s, published on the 1 ms tick at or after: intervals of 33 or
  // 34 ms (median within one tick of 1/30 s), whatever the load drops.
  const double rate = 1.0 / median_interval(stamps);
  EXPECT_NEAR(median_interval(stamps), 1.0 / 30.0, 0.0011);
  std::printf("base_odometry/odom: %.1f Hz (sim time), x = %.3f m\n", rate, last.pose.pose.position.x);
}

TEST_F(Pr2Node, ControllerManagerPublishesJointStatesMechanismStatisticsAndCalibrated) {
  ASSERT_TRUE(spawn({"r_gripper_controller"}));
  std::mutex m;
  std::vector<double> stamps;
  std::vector<std::string> names;
  bool sizes_match = true;
  ::ros::Subscriber js = nh_.subscribe<sensor_msgs::JointState>(
      "/pr2/joint_states", 1000, [&](const sensor_msgs::JointState::ConstPtr& msg) {
        std::lock_guard<std::mutex> l(m);
        stamps.push_back(msg->header.stamp.toSec());
        names = msg->name;
        sizes_match = sizes_match && msg->position.size() == msg->name.size() &&
                      msg->velocity.size() == msg->name.size() && msg->effort.size() == msg->name.size();
      });
  std::vector<pmm::MechanismStatistics> statistics;
  ::ros::Subscriber ms = nh_.subscribe<pmm::MechanismStatistics>(
      "/pr2/mechanism_statistics", 10, [&](const pmm::MechanismStatistics::ConstPtr& msg) {
        std::lock_guard<std::mutex> l(m);
        statistics.push_back(*msg);
      });
  ASSERT_TRUE(wait_until(
      [&] {
        std::lock_guard<std::mutex> l(m);
        return statistics.size() >= 2 && stamps.size() >= 200;
      },
      20.0))
      << statistics.size() << " mechanism_statistics, " << stamps.size() << " joint_states";

  {
  std::lock_guard<std::mutex> l(m);
  // joint_states: every non-fixed joint, at 100 Hz of sim time (stamps whole periods apart).
  EXPECT_TRUE(sizes_match);
  EXPECT_THAT(names, ::testing::IsSupersetOf({"r_shoulder_pan_joint", "torso_lift_joint", "r_gripper_joint",
                                               "fl_caster_rotation_joint", "head_tilt_joint", "l_wrist_roll_joint"}));
  const double rate = 1.0 / median_interval(stamps);
  EXPECT_NEAR(rate, 100.0, 1e-3);
  EXPECT_GE(whole_periods(stamps, 0.01), 0.8);
  std::printf("joint_states: %zu messages at %.2f Hz (sim time), %zu joints\n", stamps.size(), rate, names.size());

  // mechanism_statistics: the same joints, the actuators, the controller; 1 Hz of sim time.
  const pmm::MechanismStatistics& s = statistics.back();
  std::vector<std::string> joint_names;
  for (const auto& j : s.joint_statistics) joint_names.push_back(j.name);
  EXPECT_EQ(joint_names, names);
  EXPECT_NEAR((s.header.stamp - statistics[statistics.size() - 2].header.stamp).toSec(), 1.0, 1e-6);
  for (const auto& j : s.joint_statistics) {
    EXPECT_LE(j.min_position, j.position + 1e-12) << j.name;
    EXPECT_GE(j.max_position, j.position - 1e-12) << j.name;
    EXPECT_TRUE(j.is_calibrated) << j.name;
  }
  std::vector<std::string> actuators;
  for (const auto& a : s.actuator_statistics) actuators.push_back(a.name);
  EXPECT_THAT(actuators, ::testing::IsSupersetOf({"r_shoulder_pan_motor", "r_gripper_motor", "torso_lift_motor"}));
  ASSERT_EQ(s.controller_statistics.size(), 1u);
  EXPECT_EQ(s.controller_statistics[0].name, "r_gripper_controller");
  EXPECT_TRUE(s.controller_statistics[0].running);
  EXPECT_GT(s.controller_statistics[0].mean_time.toSec(), 0.0);
  EXPECT_GE(s.controller_statistics[0].max_time.toSec(), s.controller_statistics[0].mean_time.toSec());
  std::printf("mechanism_statistics: %zu messages, %zu actuators, %zu joints, %zu controllers\n", statistics.size(),
              s.actuator_statistics.size(), s.joint_statistics.size(), s.controller_statistics.size());
  }

  // /calibrated: latched, so a late subscriber still gets it.
  std::atomic<int> calibrated{-1};
  ::ros::Subscriber cal = nh_.subscribe<std_msgs::Bool>(
      "/calibrated", 1, [&](const std_msgs::Bool::ConstPtr& msg) { calibrated = msg->data ? 1 : 0; });
  EXPECT_TRUE(wait_until([&] { return calibrated.load() >= 0; }, 10.0)) << "no latched /calibrated";
  EXPECT_EQ(calibrated.load(), 1);
}

// pr2_controller_manager's joint_state_publish_rate parameter (read at start).
class Pr2NodeAt250Hz : public Pr2Node {
 protected:
  void SetUp() override {
    ::ros::param::set("/pr2_controller_manager/joint_state_publish_rate", 250.0);
    Pr2Node::SetUp();
  }
  void TearDown() override {
    Pr2Node::TearDown();
    ::ros::param::del("/pr2_controller_manager/joint_state_publish_rate");
  }
};

TEST_F(Pr2NodeAt250Hz, JointStatesFollowJointStatePublishRate) {
  std::mutex m;
  std::vector<double> stamps;
  ::ros::Subscriber js = nh_.subscribe<sensor_msgs::JointState>(
      "/pr2/joint_states", 1000, [&](const sensor_msgs::JointState::ConstPtr& msg) {
        std::lock_guard<std::mutex> l(m);
        stamps.push_back(msg->header.stamp.toSec());
      });
  ASSERT_TRUE(wait_until(
      [&] {
        std::lock_guard<std::mutex> l(m);
        return stamps.size() >= 300;
      },
      20.0));
  std::lock_guard<std::mutex> l(m);
  const double rate = 1.0 / median_interval(stamps);
  EXPECT_NEAR(rate, 250.0, 1e-3);
  EXPECT_GE(whole_periods(stamps, 0.004), 0.8);
  std::printf("joint_states at joint_state_publish_rate 250: %.2f Hz (sim time)\n", rate);
}

}  // namespace
}  // namespace mechsim::ros::test
