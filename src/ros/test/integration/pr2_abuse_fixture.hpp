#pragma once
// The ROS API abuse test's world (pr2_abuse_test.cpp): the PR2 in mechsim_node in gzserver mode
// (~gazebo:=true, spawned through /gazebo/spawn_urdf_model, paced at real time, namespace /pr2),
// its controllers started by mechsim_spawner, and the requests that abuse it, one at a time from
// a seeded AbuseInputs: command topics (pr2_abuse_requests.cpp), action goals and cancels,
// controller manager services, and the /gazebo/* services (pr2_abuse_gazebo.cpp). Each request
// checks what it can at once (refusals, answers against list_controllers) and records what is
// wrong in `inconsistent_`; the test asserts at the end.

#include <gmock/gmock.h>

#include <chrono>
#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <actionlib/client/action_client.h>
#include <control_msgs/FollowJointTrajectoryAction.h>
#include <pr2_controllers_msgs/JointTrajectoryAction.h>
#include <pr2_controllers_msgs/Pr2GripperCommandAction.h>

#include "abuse_inputs.hpp"
#include "param_snapshot.hpp"
#include "ros_fixture.hpp"

namespace mechsim::ros::test {

using Names = std::set<std::string>;

extern const std::string kAbusePr2Urdf;
extern const std::string kAbuseCm;     // ros_control's controller manager of the PR2
extern const std::string kAbusePr2Cm;  // pr2_controller_manager's
constexpr int kAbuseRequests = 10000;       // in all, both phases
constexpr int kAbusePausedRequests = 300;   // of which the paused/stepped/reset phase
constexpr double kAbusePace = 0.003;        // s (wall) between requests of the main phase
constexpr double kAbuseAnswerBound = 10.0;  // s (wall) a service call may take

// Never named in a stop list that could be accepted: they must run throughout.
extern const std::vector<std::string> kAbuseCore;
// Switched at will: head and laser tilt controllers that conflict in pairs, and position
// controllers that conflict with the core's arm and torso controllers.
extern const std::vector<std::string> kAbuseStorm;
extern const std::vector<std::string> kAbuseStormRunning;  // those of kAbuseStorm running at first
extern const std::vector<std::string> kAbuseRightArm, kAbuseLeftArm;

// A service call that takes longer than kAbuseAnswerBound: the watchdog records it and kills
// the node, so that the blocked call returns and the test ends in bounded time.
class AbuseWatchdog {
 public:
  explicit AbuseWatchdog(pid_t node);
  ~AbuseWatchdog();
  void begin(const std::string& what);
  void end();
  std::string hung();  // the call that hung; "" while none did

 private:
  void run();
  pid_t node_;
  std::mutex m_;
  std::condition_variable cv_;
  bool done_ = false, busy_ = false;
  std::string what_, hung_;
  std::chrono::steady_clock::time_point since_;
  std::thread thread_;
};

// One action's goals, kept to their end.
template <class Action>
struct GoalLog {
  struct Goal {
    actionlib::ClientGoalHandle<Action> handle;
    std::string malformed;  // why any controller must refuse it ("" when well formed)
  };
  std::unique_ptr<actionlib::ActionClient<Action>> client;
  std::vector<Goal> goals;
};

// Why any trajectory controller must refuse `t` for `joints` ("" when it need not): an unknown or
// repeated joint, a point's wrong number of values, a non-finite value, times not increasing; a
// trajectory without points is a stop request, never malformed.
std::string why_malformed(const trajectory_msgs::JointTrajectory& t, const std::vector<std::string>& joints);
std::string str(const Names& n);  // "{a, b}"

class Pr2Abuse : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;
  std::string tail() const;  // the node's log, its last 8000 characters

  // A service call under the watchdog; false when the call failed (refused by the callback, no
  // such service, or no answer).
  template <class Srv>
  bool ask(const std::string& name, Srv& srv, const std::string& kind) {
    ++sent_[kind];
    ::ros::ServiceClient& client = clients_[name];
    if (!client.isValid()) client = nh_.serviceClient<Srv>(name, true);
    watchdog_->begin(kind + " " + name);
    const bool ok = client.call(srv);
    watchdog_->end();
    if (!ok) client = ::ros::ServiceClient();  // a persistent connection is not reused after a failure
    return ok;
  }
  // A call whose callback always answers (every controller manager and /gazebo service): false
  // is a missing answer.
  template <class Srv>
  bool must_answer(const std::string& name, Srv& srv, const std::string& kind) {
    const bool ok = ask(name, srv, kind);
    if (!ok && watchdog_->hung().empty()) {
      ADD_FAILURE() << kind << " " << name << ": no answer";
      ++failures_;
    }
    return ok;
  }

  // What list_controllers says runs and is loaded; records each controller's joints.
  bool list(Names& running, Names& loaded);
  // Sim seconds per wall second on /clock between two wall times; NaN without two samples.
  double rtf_between(std::chrono::steady_clock::time_point from, std::chrono::steady_clock::time_point to);
  // The publishers and action clients, connected (false when not within 10 s).
  bool connect();
  // Cancels every goal and waits (at most `timeout` s) until each ended; the number still open.
  int end_goals(double timeout, std::map<std::string, int>& outcomes);

  // One request of the main phase (any kind), and the kinds (pr2_abuse_requests.cpp,
  // pr2_abuse_gazebo.cpp).
  void main_request(AbuseInputs& in);
  void topic_request(AbuseInputs& in);
  void action_request(AbuseInputs& in);
  void switch_request(AbuseInputs& in, bool paused);
  void churn_request(AbuseInputs& in);
  void gazebo_request(AbuseInputs& in);
  void paused_phase_request(AbuseInputs& in);

  ::ros::NodeHandle nh_;
  std::unique_ptr<ChildProcess> node_, spawner_;
  ParamSnapshot params_;
  ::ros::Subscriber clock_sub_;
  std::mutex clock_mutex_;
  std::vector<std::pair<std::chrono::steady_clock::time_point, double>> clock_;  // wall, sim (s)
  std::unique_ptr<AbuseWatchdog> watchdog_;
  std::map<std::string, ::ros::ServiceClient> clients_;
  std::map<std::string, ::ros::Publisher> publishers_;  // by topic
  GoalLog<control_msgs::FollowJointTrajectoryAction> follow_;
  GoalLog<pr2_controllers_msgs::JointTrajectoryAction> jta_;
  GoalLog<pr2_controllers_msgs::Pr2GripperCommandAction> grip_;
  std::map<std::string, int> sent_;      // requests by kind
  int published_ = 0;                    // of which topic messages
  std::map<std::string, Names> joints_;  // controller -> claimed joints
  Names running_, loaded_;               // as the test expects them
  bool paused_ = false;                  // the paused phase: as the test last set it
  int failures_ = 0;                     // calls without an answer
  std::vector<std::string> inconsistent_;  // wrong answers, accepted bad requests
};

}  // namespace mechsim::ros::test
