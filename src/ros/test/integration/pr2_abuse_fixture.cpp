// The abuse test's fixture (pr2_abuse_fixture.hpp): the node, the PR2, its controllers, the
// watchdog, and what the test reads back (list_controllers, /clock, goal states).
#include "pr2_abuse_fixture.hpp"

#include <signal.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <type_traits>

#include <controller_manager_msgs/ListControllers.h>
#include <controller_manager_msgs/LoadController.h>
#include <gazebo_msgs/ModelState.h>
#include <gazebo_msgs/SpawnModel.h>
#include <geometry_msgs/Twist.h>
#include <pr2_controllers_msgs/Pr2GripperCommand.h>
#include <pr2_msgs/PeriodicCmd.h>
#include <rosgraph_msgs/Clock.h>
#include <std_msgs/Float64.h>
#include <std_msgs/Float64MultiArray.h>

namespace mechsim::ros::test {

namespace cmm = controller_manager_msgs;

const std::string kAbusePr2Urdf = std::string(MECHSIM_SHARED_DIR) + "/robots/reference/pr2.urdf";
const std::string kAbuseCm = "/pr2/controller_manager/";
const std::string kAbusePr2Cm = "/pr2_controller_manager/";
const std::vector<std::string> kAbuseCore = {"base_controller",      "base_odometry",        "torso_controller",
                                             "r_gripper_controller", "l_gripper_controller", "r_arm_controller",
                                             "l_arm_controller"};
const std::vector<std::string> kAbuseStorm = {"head_group_position_controller", "head_traj_controller",
                                              "laser_tilt_velocity_controller", "laser_tilt_effort_controller",
                                              "laser_tilt_controller",          "r_shoulder_pan_position_controller",
                                              "torso_lift_position_controller"};
const std::vector<std::string> kAbuseStormRunning = {"head_group_position_controller", "laser_tilt_velocity_controller"};
const std::vector<std::string> kAbuseRightArm = {"r_shoulder_pan_joint", "r_shoulder_lift_joint",
                                                 "r_upper_arm_roll_joint", "r_elbow_flex_joint",
                                                 "r_forearm_roll_joint", "r_wrist_flex_joint", "r_wrist_roll_joint"};
const std::vector<std::string> kAbuseLeftArm = {"l_shoulder_pan_joint", "l_shoulder_lift_joint",
                                                "l_upper_arm_roll_joint", "l_elbow_flex_joint",
                                                "l_forearm_roll_joint", "l_wrist_flex_joint", "l_wrist_roll_joint"};

namespace {

// Beside robots/pr2/config/controllers.yaml: ros_control's position (array), velocity and effort
// controllers on the head and the laser tilt joint.
const char* const kExtraControllers = R"(pr2:
  head_group_position_controller:
    type: effort_controllers/JointGroupPositionController
    joints: [head_pan_joint, head_tilt_joint]
    head_pan_joint: {pid: {p: 114.0, d: 7.04}}
    head_tilt_joint: {pid: {p: 718.0, d: 4.05}}
  laser_tilt_velocity_controller:
    type: effort_controllers/JointVelocityController
    joint: laser_tilt_mount_joint
    pid: {p: 0.5}
  laser_tilt_effort_controller:
    type: effort_controllers/JointEffortController
    joint: laser_tilt_mount_joint
)";

void load_params(const std::string& file) {
  ChildProcess p({"/usr/bin/python3", "/usr/bin/rosparam", "load", file}, log_dir() + "/rosparam_abuse.log");
  ASSERT_EQ(p.wait(30.0), 0) << p.log();
}

}  // namespace

AbuseWatchdog::AbuseWatchdog(pid_t node) : node_(node), thread_([this] { run(); }) {}

AbuseWatchdog::~AbuseWatchdog() {
  {
    std::lock_guard<std::mutex> l(m_);
    done_ = true;
  }
  cv_.notify_all();
  thread_.join();
}

void AbuseWatchdog::begin(const std::string& what) {
  std::lock_guard<std::mutex> l(m_);
  what_ = what;
  since_ = std::chrono::steady_clock::now();
  busy_ = true;
}

void AbuseWatchdog::end() {
  std::lock_guard<std::mutex> l(m_);
  busy_ = false;
}

std::string AbuseWatchdog::hung() {
  std::lock_guard<std::mutex> l(m_);
  return hung_;
}

void AbuseWatchdog::run() {
  std::unique_lock<std::mutex> l(m_);
  while (!done_) {
    cv_.wait_for(l, std::chrono::milliseconds(100));
    if (busy_ && hung_.empty() &&
        std::chrono::steady_clock::now() - since_ > std::chrono::duration<double>(kAbuseAnswerBound)) {
      hung_ = what_;
      ::kill(-node_, SIGKILL);  // the node's own process group (ChildProcess)
    }
  }
}

std::string why_malformed(const trajectory_msgs::JointTrajectory& t, const std::vector<std::string>& joints) {
  // No points: a stop request, whatever it names (mechsim's trajectory controllers; ros_controllers'
  // rejects unknown joint names in an action goal first).
  if (t.points.empty()) return "";
  Names seen;
  for (const std::string& n : t.joint_names) {
    if (std::find(joints.begin(), joints.end(), n) == joints.end()) return "unknown joint '" + n.substr(0, 20) + "'";
    if (!seen.insert(n).second) return "joint '" + n + "' twice";
  }
  for (std::size_t k = 0; k < t.points.size(); ++k) {
    const auto& p = t.points[k];
    const std::string at = "points[" + std::to_string(k) + "]";
    if (p.positions.size() != t.joint_names.size()) return at + ": " + std::to_string(p.positions.size()) + " positions";
    if (!p.velocities.empty() && p.velocities.size() != t.joint_names.size()) return at + ": velocities' length";
    for (double v : p.positions)
      if (!std::isfinite(v)) return at + ": a position not finite";
    for (double v : p.velocities)
      if (!std::isfinite(v)) return at + ": a velocity not finite";
    if (k > 0 && p.time_from_start.toSec() <= t.points[k - 1].time_from_start.toSec()) {
      return at + ": time " + std::to_string(p.time_from_start.toSec()) + " s not after " +
             std::to_string(t.points[k - 1].time_from_start.toSec()) + " s";
    }
  }
  return "";
}

std::string str(const Names& n) {
  std::string out;
  for (const std::string& s : n) out += (out.empty() ? "" : ", ") + s;
  return "{" + out + "}";
}

void Pr2Abuse::SetUp() {
  if (!std::filesystem::exists(kAbusePr2Urdf)) {
    GTEST_SKIP() << "the shared data folder has no PR2 (" << kAbusePr2Urdf << "); skipping the abuse test";
  }
  ASSERT_TRUE(::ros::master::check()) << "no ROS master";
  load_params(std::string(MECHSIM_SOURCE_DIR) + "/robots/pr2/config/controllers.yaml");
  const std::string extra = log_dir() + "/abuse_controllers.yaml";
  std::ofstream(extra) << kExtraControllers;
  load_params(extra);
  node_ = std::make_unique<ChildProcess>(
      std::vector<std::string>{MECHSIM_NODE_EXE, "__name:=gazebo", "_gazebo:=true", "_real_time_factor:=1.0",
                               "_paused:=false"},
      log_dir() + "/node_abuse.log");
  clock_sub_ = nh_.subscribe<rosgraph_msgs::Clock>("/clock", 100, [this](const rosgraph_msgs::Clock::ConstPtr& m) {
    std::lock_guard<std::mutex> l(clock_mutex_);
    clock_.emplace_back(std::chrono::steady_clock::now(), m->clock.toSec());
  });
  ASSERT_TRUE(::ros::service::waitForService("/gazebo/spawn_urdf_model", ::ros::Duration(30.0))) << node_->log();
  std::stringstream urdf;
  urdf << std::ifstream(kAbusePr2Urdf).rdbuf();
  gazebo_msgs::SpawnModel spawn;
  spawn.request.model_name = "pr2";
  spawn.request.model_xml = urdf.str();
  spawn.request.robot_namespace = "/pr2";
  spawn.request.initial_pose.orientation.w = 1.0;
  ASSERT_TRUE(call("/gazebo/spawn_urdf_model", spawn, 30.0)) << node_->log();
  ASSERT_TRUE(spawn.response.success) << spawn.response.status_message;
  std::vector<std::string> argv{MECHSIM_SPAWNER_EXE, "__ns:=/pr2", "__name:=abuse_spawner"};
  argv.insert(argv.end(), kAbuseCore.begin(), kAbuseCore.end());
  argv.insert(argv.end(), kAbuseStormRunning.begin(), kAbuseStormRunning.end());
  spawner_ = std::make_unique<ChildProcess>(argv, log_dir() + "/spawner_abuse.log");
  ASSERT_TRUE(wait_until([&] { return spawner_->log().find("started 9 controllers") != std::string::npos; }, 60.0))
      << spawner_->log() << "\n" << node_->log();
  for (const std::string& name : kAbuseStorm) {
    if (std::find(kAbuseStormRunning.begin(), kAbuseStormRunning.end(), name) != kAbuseStormRunning.end()) continue;
    cmm::LoadController load;
    load.request.name = name;
    ASSERT_TRUE(call(kAbuseCm + "load_controller", load));
    ASSERT_TRUE(load.response.ok) << name << "\n" << node_->log();
  }
  watchdog_ = std::make_unique<AbuseWatchdog>(node_->pid());
}

void Pr2Abuse::TearDown() {
  // Goal handles before their clients (actionlib's order), both before the node.
  follow_.goals.clear();
  jta_.goals.clear();
  grip_.goals.clear();
  follow_.client.reset();
  jta_.client.reset();
  grip_.client.reset();
  publishers_.clear();
  clients_.clear();
  clock_sub_.shutdown();
  watchdog_.reset();
  if (spawner_) spawner_->stop(15.0);
  if (node_) {
    const int status = node_->stop(15.0);
    EXPECT_EQ(status, 0) << "mechsim_node did not stop cleanly on SIGINT; its log:\n" << tail();
  }
  params_.forget_new();
}

std::string Pr2Abuse::tail() const {
  const std::string log = node_->log();
  return log.substr(log.size() > 8000 ? log.size() - 8000 : 0);
}

bool Pr2Abuse::list(Names& running, Names& loaded) {
  cmm::ListControllers l;
  if (!must_answer(kAbuseCm + "list_controllers", l, "list_controllers (check)")) return false;
  running.clear();
  loaded.clear();
  for (const auto& c : l.response.controller) {
    loaded.insert(c.name);
    if (c.state == "running") running.insert(c.name);
    for (const auto& r : c.claimed_resources)
      for (const auto& j : r.resources) joints_[c.name].insert(j);
  }
  return true;
}

double Pr2Abuse::rtf_between(std::chrono::steady_clock::time_point from, std::chrono::steady_clock::time_point to) {
  std::lock_guard<std::mutex> l(clock_mutex_);
  const auto first = std::find_if(clock_.begin(), clock_.end(), [&](const auto& s) { return s.first >= from; });
  auto last = first;
  for (auto it = first; it != clock_.end() && it->first <= to; ++it) last = it;
  if (first == clock_.end() || last == first) return std::nan("");
  return (last->second - first->second) / std::chrono::duration<double>(last->first - first->first).count();
}

bool Pr2Abuse::connect() {
  auto topic = [](const std::string& c, const std::string& port = "command") { return "/pr2/" + c + "/" + port; };
  auto add = [&](const std::string& name, auto* type) {
    publishers_[name] = nh_.advertise<std::remove_pointer_t<decltype(type)>>(name, 10);
  };
  add(topic("head_group_position_controller"), static_cast<std_msgs::Float64MultiArray*>(nullptr));
  for (const char* c : {"laser_tilt_velocity_controller", "laser_tilt_effort_controller",
                        "r_shoulder_pan_position_controller", "torso_lift_position_controller"}) {
    add(topic(c), static_cast<std_msgs::Float64*>(nullptr));
  }
  add(topic("base_controller"), static_cast<geometry_msgs::Twist*>(nullptr));
  add(topic("r_gripper_controller"), static_cast<pr2_controllers_msgs::Pr2GripperCommand*>(nullptr));
  for (const char* c : {"r_arm_controller", "l_arm_controller", "torso_controller", "head_traj_controller"}) {
    add(topic(c), static_cast<trajectory_msgs::JointTrajectory*>(nullptr));
  }
  add(topic("laser_tilt_controller", "set_periodic_cmd"), static_cast<pr2_msgs::PeriodicCmd*>(nullptr));
  add("/gazebo/set_model_state", static_cast<gazebo_msgs::ModelState*>(nullptr));
  follow_.client = std::make_unique<actionlib::ActionClient<control_msgs::FollowJointTrajectoryAction>>(
      topic("r_arm_controller", "follow_joint_trajectory"));
  jta_.client = std::make_unique<actionlib::ActionClient<pr2_controllers_msgs::JointTrajectoryAction>>(
      topic("l_arm_controller", "joint_trajectory_action"));
  grip_.client = std::make_unique<actionlib::ActionClient<pr2_controllers_msgs::Pr2GripperCommandAction>>(
      topic("r_gripper_controller", "gripper_action"));
  if (!follow_.client->waitForActionServerToStart(::ros::Duration(10.0)) ||
      !jta_.client->waitForActionServerToStart(::ros::Duration(10.0)) ||
      !grip_.client->waitForActionServerToStart(::ros::Duration(10.0))) {
    return false;
  }
  return wait_until(
      [&] {
        for (const auto& [name, p] : publishers_)
          if (p.getNumSubscribers() == 0) return false;
        return true;
      },
      10.0);
}

int Pr2Abuse::end_goals(double timeout, std::map<std::string, int>& outcomes) {
  for (auto& g : follow_.goals) g.handle.cancel();
  for (auto& g : jta_.goals) g.handle.cancel();
  for (auto& g : grip_.goals) g.handle.cancel();
  std::vector<std::string> wrong;
  auto tally = [&](auto& log, const std::string& what) {
    int open = 0;
    for (auto& g : log.goals) {
      if (g.handle.getCommState() != actionlib::CommState::DONE) {
        ++open;
        continue;
      }
      const auto state = g.handle.getTerminalState().state_;
      ++outcomes[what + (g.malformed.empty() ? " " : " (malformed) ") + actionlib::TerminalState(state).toString()];
      if (!g.malformed.empty() && state == actionlib::TerminalState::SUCCEEDED) {
        wrong.push_back(what + ": a malformed goal SUCCEEDED (" + g.malformed + ")");
      }
    }
    return open;
  };
  int open = 0;
  wait_until(
      [&] {
        outcomes.clear();
        wrong.clear();
        open = tally(follow_, "follow_joint_trajectory") + tally(jta_, "joint_trajectory_action") +
               tally(grip_, "gripper_action");
        return open == 0;
      },
      timeout);
  inconsistent_.insert(inconsistent_.end(), wrong.begin(), wrong.end());
  return open;
}

}  // namespace mechsim::ros::test
