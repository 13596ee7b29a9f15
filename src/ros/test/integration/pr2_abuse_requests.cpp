// The abuse test's requests (pr2_abuse_fixture.hpp): command topics, action goals and cancels,
// and the controller manager's services (switch storms, load/unload churn, lists, reloads,
// query_state, the laser tilt's set_periodic_cmd). The /gazebo/* ones are pr2_abuse_gazebo.cpp.
#include <algorithm>
#include <cmath>
#include <limits>

#include <controller_manager_msgs/ListControllerTypes.h>
#include <controller_manager_msgs/LoadController.h>
#include <controller_manager_msgs/ReloadControllerLibraries.h>
#include <controller_manager_msgs/SwitchController.h>
#include <controller_manager_msgs/UnloadController.h>
#include <gazebo_msgs/ModelState.h>
#include <geometry_msgs/Twist.h>
#include <pr2_controllers_msgs/Pr2GripperCommand.h>
#include <pr2_controllers_msgs/QueryTrajectoryState.h>
#include <pr2_mechanism_msgs/LoadController.h>
#include <pr2_mechanism_msgs/SwitchController.h>
#include <pr2_mechanism_msgs/UnloadController.h>
#include <pr2_msgs/PeriodicCmd.h>
#include <pr2_msgs/SetPeriodicCmd.h>
#include <std_msgs/Float64.h>
#include <std_msgs/Float64MultiArray.h>

#include "pr2_abuse_fixture.hpp"

namespace mechsim::ros::test {

namespace cmm = controller_manager_msgs;
namespace pmm = pr2_mechanism_msgs;
namespace pcm = pr2_controllers_msgs;

geometry_msgs::Pose bad_pose(AbuseInputs& in);  // pr2_abuse_gazebo.cpp

namespace {

// A pose inside every arm joint's limits (rad): the centre of the random goals.
const std::vector<double> kArmCentre = {0.0, 0.3, 0.0, -0.8, 0.0, -0.6, 0.0};

std::string topic(const std::string& controller, const std::string& port = "command") {
  return "/pr2/" + controller + "/" + port;
}

}  // namespace

// 70 % topic messages, 10 % action goals (half of them with a cancel of a recent goal), 20 %
// service calls.
void Pr2Abuse::main_request(AbuseInputs& in) {
  const int k = in.below(100);
  if (k < 70) return topic_request(in);
  if (k < 80) return action_request(in);
  const int s = in.below(100);
  if (s < 30) {
    switch_request(in, false);
  } else if (s < 45) {
    churn_request(in);
  } else if (s < 55) {
    if (in.chance(0.5)) {
      cmm::ListControllerTypes t;
      must_answer(kAbuseCm + "list_controller_types", t, "list_controller_types");
    } else {
      cmm::ReloadControllerLibraries r;  // controllers are loaded and force_kill is false: refused
      if (must_answer(kAbuseCm + "reload_controller_libraries", r, "reload_controller_libraries") && r.response.ok) {
        inconsistent_.push_back("reload_controller_libraries without force_kill accepted");
      }
    }
  } else if (s < 62) {
    pcm::QueryTrajectoryState q;  // any time at all; false is an answer (nothing to sample)
    q.request.time.sec = static_cast<std::uint32_t>(in.rng()());
    q.request.time.nsec = static_cast<std::uint32_t>(in.rng()());
    ask(topic("r_arm_controller", "query_state"), q, "query_state (random times)");
  } else if (s < 66) {
    pr2_msgs::SetPeriodicCmd c;  // false is an answer (a refused profile)
    c.request.command.profile = in.pick(std::vector<std::string>{"linear", "sine", "bogus"});
    c.request.command.period = in.nasty(3.0);
    c.request.command.amplitude = in.nasty(1.0);
    ask(topic("laser_tilt_controller", "set_periodic_cmd"), c, "laser tilt set_periodic_cmd service");
  } else {
    gazebo_request(in);
  }
}

void Pr2Abuse::topic_request(AbuseInputs& in) {
  ++published_;
  auto send = [&](const std::string& name, const auto& msg, const std::string& kind) {
    publishers_.at(name).publish(msg);
    ++sent_[kind];
  };
  auto trajectory = [&](const std::vector<std::string>& joints, const std::vector<double>& centre) {
    bool sane = false;
    return in.trajectory(joints, centre, 0.3, &sane);
  };
  switch (in.below(13)) {
    case 0: {
      std_msgs::Float64MultiArray m;  // two joints
      m.data.resize(static_cast<std::size_t>(in.chance(0.5) ? 2 : in.below(6)));
      for (double& v : m.data) v = in.nasty(0.5);
      return send(topic("head_group_position_controller"), m, "topic position array (head group)");
    }
    case 1: {
      std_msgs::Float64 m;
      m.data = in.nasty(1.0);
      return send(topic("laser_tilt_velocity_controller"), m, "topic velocity (laser tilt)");
    }
    case 2: {
      std_msgs::Float64 m;
      m.data = in.nasty(0.5);
      return send(topic("laser_tilt_effort_controller"), m, "topic effort (laser tilt)");
    }
    case 3: {
      std_msgs::Float64 m;
      m.data = in.nasty(0.5);
      return send(topic(in.chance(0.5) ? "r_shoulder_pan_position_controller" : "torso_lift_position_controller"), m,
                  "topic position (storm controllers)");
    }
    case 4:
    case 5: {
      geometry_msgs::Twist m;
      m.linear.x = in.nasty(0.3);
      m.linear.y = in.nasty(0.3);
      m.linear.z = in.nasty(0.3);
      m.angular.x = in.nasty(0.3);
      m.angular.z = in.nasty(0.3);
      return send(topic("base_controller"), m, "topic base cmd_vel");
    }
    case 6: {
      pcm::Pr2GripperCommand m;
      m.position = in.nasty(0.08);
      m.max_effort = in.nasty(100.0);
      return send(topic("r_gripper_controller"), m, "topic gripper command");
    }
    case 7:
    case 8:
      return send(topic("r_arm_controller"), trajectory(kAbuseRightArm, kArmCentre), "topic trajectory (r_arm)");
    case 9:
      return send(topic("l_arm_controller"), trajectory(kAbuseLeftArm, kArmCentre), "topic trajectory (l_arm)");
    case 10:
      if (in.chance(0.5)) {
        return send(topic("torso_controller"), trajectory({"torso_lift_joint"}, {0.1}), "topic trajectory (torso, head)");
      }
      return send(topic("head_traj_controller"), trajectory({"head_pan_joint", "head_tilt_joint"}, {0.0, 0.3}),
                  "topic trajectory (torso, head)");
    case 11: {
      pr2_msgs::PeriodicCmd m;
      m.profile = in.pick(std::vector<std::string>{"linear", "sine", "", "bogus", "blended_linear"});
      m.period = in.nasty(3.0);
      m.amplitude = in.nasty(1.0);
      m.offset = in.nasty(0.5);
      return send(topic("laser_tilt_controller", "set_periodic_cmd"), m, "topic laser tilt set_periodic_cmd");
    }
    default: {
      gazebo_msgs::ModelState m;  // never a usable state: a robot teleported at random is no abuse
      m.model_name = in.chance(0.7) ? "pr2" : in.bad_name();
      m.pose = bad_pose(in);
      return send("/gazebo/set_model_state", m, "topic /gazebo/set_model_state");
    }
  }
}

// A goal on one of the three actions, and now and then a cancel of one of the last five goals
// there (most still in flight).
void Pr2Abuse::action_request(AbuseInputs& in) {
  const int a = in.below(3);
  if (a == 0) {
    control_msgs::FollowJointTrajectoryGoal g;
    bool sane = false;
    g.trajectory = in.trajectory(kAbuseRightArm, kArmCentre, 0.3, &sane);
    if (in.chance(0.1)) g.goal_time_tolerance = in.bad_duration();
    if (in.chance(0.1)) {
      control_msgs::JointTolerance tol;
      tol.name = in.chance(0.5) ? kAbuseRightArm[0] : in.bad_name();
      tol.position = in.nasty(0.1);
      g.goal_tolerance.push_back(tol);
    }
    follow_.goals.push_back({follow_.client->sendGoal(g), why_malformed(g.trajectory, kAbuseRightArm)});
    ++sent_["action follow_joint_trajectory goal"];
  } else if (a == 1) {
    pcm::JointTrajectoryGoal g;
    bool sane = false;
    g.trajectory = in.trajectory(kAbuseLeftArm, kArmCentre, 0.3, &sane);
    jta_.goals.push_back({jta_.client->sendGoal(g), why_malformed(g.trajectory, kAbuseLeftArm)});
    ++sent_["action joint_trajectory_action goal"];
  } else {
    pcm::Pr2GripperCommandGoal g;
    g.command.position = in.nasty(0.08);
    g.command.max_effort = in.nasty(100.0);
    grip_.goals.push_back({grip_.client->sendGoal(g), std::isfinite(g.command.position) ? "" : "position not finite"});
    ++sent_["action gripper_action goal"];
  }
  if (!in.chance(0.5)) return;
  auto cancel_one = [&](auto& log) {
    const std::size_t from = log.goals.size() > 5 ? log.goals.size() - 5 : 0;
    log.goals[from + static_cast<std::size_t>(in.below(static_cast<int>(log.goals.size() - from)))].handle.cancel();
  };
  if (a == 0) cancel_one(follow_);
  else if (a == 1) cancel_one(jta_);
  else cancel_one(grip_);
  ++sent_["action cancel in flight"];
}

namespace {

bool conflicts(const Names& running, const std::map<std::string, Names>& joints) {
  std::map<std::string, int> claims;
  for (const std::string& c : running) {
    const auto it = joints.find(c);
    if (it == joints.end()) continue;
    for (const std::string& j : it->second)
      if (++claims[j] > 1) return true;
  }
  return false;
}


}  // namespace

// One switch_controller request (ros_control's or the PR2's service), then list_controllers:
// the answer must agree with what runs now. While paused an accepted start is pending.
void Pr2Abuse::switch_request(AbuseInputs& in, bool paused) {
  auto any_name = [&]() -> std::string {
    const int k = in.below(10);
    if (k < 6) return in.pick(kAbuseStorm);
    if (k < 8) return in.pick(kAbuseCore);
    return in.bad_name();
  };
  std::vector<std::string> start, stop;
  for (int n = in.below(4); n > 0; --n) start.push_back(any_name());
  for (int n = in.below(4); n > 0; --n) stop.push_back(in.chance(0.7) ? in.pick(kAbuseStorm) : in.bad_name());
  static const std::vector<int> kStrictness = {0, 1, 1, 2, 2, 2, 3, -1, 7, std::numeric_limits<int>::min()};
  const int strictness = in.pick(kStrictness);
  const bool valid_strictness = strictness >= 0 && strictness <= 2;
  const bool strict = strictness == 2;
  bool unknown = false;
  for (const auto& v : {start, stop})
    for (const std::string& s : v) unknown = unknown || !loaded_.count(s);
  // A core controller may be named to stop only where the whole request must be refused.
  if (in.chance(0.15) && (!valid_strictness || (strict && unknown))) stop.push_back(in.pick(kAbuseCore));
  double timeout = in.chance(0.5) ? in.nasty(5.0) : 0.0;
  if (in.chance(0.1)) timeout = 1e-9;
  if (paused && in.chance(0.5)) timeout = 1e9;

  bool answered = false, ok = false;
  const bool pr2 = in.chance(0.3);
  if (pr2) {
    pmm::SwitchController s;
    s.request.start_controllers = start;
    s.request.stop_controllers = stop;
    s.request.strictness = strictness;
    answered = must_answer(kAbusePr2Cm + "switch_controller", s, "switch_controller (pr2)");
    ok = s.response.ok;
  } else {
    cmm::SwitchController s;
    s.request.start_controllers = start;
    s.request.stop_controllers = stop;
    s.request.strictness = strictness;
    s.request.timeout = timeout;
    s.request.start_asap = in.chance(0.5);
    answered = must_answer(kAbuseCm + "switch_controller", s, "switch_controller");
    ok = s.response.ok;
  }
  if (!answered) return;

  // What ros_control's rules make of it (sim_bridge / controller_manager: BEST_EFFORT skips
  // unknown names and controllers already in the asked state; any conflict refuses all).
  Names stop_eff, start_eff;
  bool problem = false;
  for (const std::string& s : stop) {
    if (running_.count(s)) stop_eff.insert(s);
    else problem = true;
  }
  for (const std::string& s : start) {
    if (loaded_.count(s) && (!running_.count(s) || stop_eff.count(s))) start_eff.insert(s);
    else problem = true;
  }
  Names after;
  for (const std::string& s : running_)
    if (!stop_eff.count(s)) after.insert(s);
  after.insert(start_eff.begin(), start_eff.end());
  const bool predicted = valid_strictness && !(strict && problem) && !conflicts(after, joints_);
  Names now_running, now_loaded;
  if (!list(now_running, now_loaded)) return;
  // While paused, an accepted switch is listed "waiting" until the unpause.
  const Names expected = ok && !paused ? after : running_;
  if (now_running != expected) {
    inconsistent_.push_back(std::string(pr2 ? "pr2 " : "") + "switch start " + str(Names(start.begin(), start.end())) +
                            " stop " + str(Names(stop.begin(), stop.end())) + " strictness " +
                            std::to_string(strictness) + " timeout " + std::to_string(timeout) + ": answered ok=" +
                            (ok ? "true" : "false") + " but running " + str(now_running) + ", expected " +
                            str(expected));
  }
  // A timeout below a tick may refuse a switch it did not apply; every other answer is ros_control's.
  const bool ordinary_timeout = pr2 || !(timeout > 0.0 && timeout < 0.01);
  if (!paused && ordinary_timeout && ok != predicted) {
    inconsistent_.push_back("switch start " + str(Names(start.begin(), start.end())) + " stop " +
                            str(Names(stop.begin(), stop.end())) + " strictness " + std::to_string(strictness) +
                            ": answered ok=" + (ok ? "true" : "false") + ", ros_control's rules say " +
                            (predicted ? "true" : "false"));
  }
  if (!paused) running_ = now_running;
  loaded_ = now_loaded;
}

// Load and unload: unknown and absurd names, already loaded, running (refused), and a stopped
// storm controller unloaded and loaded again (its topics go and come while messages arrive).
void Pr2Abuse::churn_request(AbuseInputs& in) {
  const bool pr2 = in.chance(0.3);
  std::string name;
  bool load = in.chance(0.5);
  switch (in.below(4)) {
    case 0: name = in.bad_name(); break;
    case 1: name = in.chance(0.5) ? in.pick(kAbuseCore) : in.pick(kAbuseStorm); break;  // loaded (or running)
    default:
      name = in.pick(kAbuseStorm);
      load = !loaded_.count(name);
      break;
  }
  // Loading needs parameters (every core and storm controller has them) and a name not loaded;
  // unloading a loaded controller that is not running.
  const bool known = std::find(kAbuseCore.begin(), kAbuseCore.end(), name) != kAbuseCore.end() ||
                     std::find(kAbuseStorm.begin(), kAbuseStorm.end(), name) != kAbuseStorm.end();
  const bool expect_ok = load ? known && !loaded_.count(name) : loaded_.count(name) && !running_.count(name);
  bool answered = false, ok = false;
  if (load) {
    if (pr2) {
      pmm::LoadController s;
      s.request.name = name;
      answered = must_answer(kAbusePr2Cm + "load_controller", s, "load_controller (pr2)");
      ok = s.response.ok;
    } else {
      cmm::LoadController s;
      s.request.name = name;
      answered = must_answer(kAbuseCm + "load_controller", s, "load_controller");
      ok = s.response.ok;
    }
  } else if (pr2) {
    pmm::UnloadController s;
    s.request.name = name;
    answered = must_answer(kAbusePr2Cm + "unload_controller", s, "unload_controller (pr2)");
    ok = s.response.ok;
  } else {
    cmm::UnloadController s;
    s.request.name = name;
    answered = must_answer(kAbuseCm + "unload_controller", s, "unload_controller");
    ok = s.response.ok;
  }
  if (!answered) return;
  const std::string what = std::string(load ? "load" : "unload") + " '" + name.substr(0, 40) + "'";
  if (ok != expect_ok) inconsistent_.push_back(what + ": ok=" + (ok ? "true" : "false"));
  if (ok && load) loaded_.insert(name);
  if (ok && !load) loaded_.erase(name);
}
}  // namespace mechsim::ros::test
