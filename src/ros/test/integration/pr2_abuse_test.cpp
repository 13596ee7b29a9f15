// The ROS API abuse test (issue 19, item 3; src/ros/README.md "Tests"): the PR2 in mechsim_node
// in gzserver mode, paced at real time, with nine controllers running, then 10,000 seeded random
// or malformed requests and messages (pr2_abuse_fixture.hpp says which): switch storms (unknown
// names, conflicting sets, strictness 0/1/2/other, NaN/Inf/huge timeouts), load/unload churn,
// NaN/Inf/huge values and wrong-length arrays on the position, velocity, effort, gripper, base
// and trajectory command topics, trajectory goals with wrong joints, non-monotonic times, NaN and
// empty points, goals cancelled in flight, the /gazebo/* services with bad arguments; last 300
// requests of pause/unpause/step/reset and switches while paused. Asserted: every service call
// answers within 10 s (a watchdog kills the node otherwise, so the test stays bounded); each
// switch answer agrees with list_controllers after it and with ros_control's rules; bad
// arguments are refused; the node stays up (no abort, no sanitizer report, no divergence); the
// real-time factor during the main phase is within 10 % of the one before; every action goal
// ends; the controllers running at the end are those running before; the robot's state is
// finite. MECHSIM_ABUSE_SEED=N reproduces a run (the seed is printed). The master restart is
// pr2_abuse_master_restart_test.cpp.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include <controller_manager_msgs/LoadController.h>
#include <controller_manager_msgs/SwitchController.h>
#include <gazebo_msgs/GetModelState.h>
#include <sensor_msgs/JointState.h>
#include <std_srvs/Empty.h>

#include "pr2_abuse_fixture.hpp"

namespace mechsim::ros::test {
namespace {

namespace cmm = controller_manager_msgs;

TEST_F(Pr2Abuse, TenThousandRandomAndMalformedRequestsLeaveTheNodeRunningAndConsistent) {
  std::uint64_t seed = std::random_device{}();
  if (const char* s = std::getenv("MECHSIM_ABUSE_SEED")) seed = std::strtoull(s, nullptr, 10);
  std::printf("abuse seed %llu (MECHSIM_ABUSE_SEED=%llu reproduces this run)\n", static_cast<unsigned long long>(seed),
              static_cast<unsigned long long>(seed));
  AbuseInputs in(seed);
  ASSERT_TRUE(list(running_, loaded_));
  const Names running_before = running_;
  Names expected_before(kAbuseCore.begin(), kAbuseCore.end());
  expected_before.insert(kAbuseStormRunning.begin(), kAbuseStormRunning.end());
  ASSERT_EQ(running_before, expected_before);
  ASSERT_TRUE(connect()) << "publishers or action clients not connected within 10 s";

  const auto t0 = std::chrono::steady_clock::now();
  std::this_thread::sleep_for(std::chrono::seconds(3));
  const double rtf_before = rtf_between(t0, std::chrono::steady_clock::now());
  ASSERT_TRUE(std::isfinite(rtf_before) && rtf_before > 0.5) << "real-time factor before the abuse " << rtf_before;

  // The main phase, paced (most requests are topic messages, which would otherwise all land in
  // the node's one-message subscriber queues at once).
  const int main_requests = kAbuseRequests - kAbusePausedRequests;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < main_requests && watchdog_->hung().empty(); ++i) {
    std::this_thread::sleep_until(start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                              std::chrono::duration<double>(kAbusePace * i)));
    main_request(in);
  }
  const auto t2 = std::chrono::steady_clock::now();
  const double main_seconds = std::chrono::duration<double>(t2 - start).count();
  const double rtf_during = rtf_between(start, t2);
  double rtf_min = 1e9, rtf_max = 0.0;
  for (auto w = start; w + std::chrono::seconds(1) <= t2; w += std::chrono::seconds(1)) {
    const double r = rtf_between(w, w + std::chrono::seconds(1));
    if (std::isfinite(r)) rtf_min = std::min(rtf_min, r), rtf_max = std::max(rtf_max, r);
  }
  ASSERT_EQ(watchdog_->hung(), "") << "no answer within " << kAbuseAnswerBound << " s; the node's log:\n" << tail();
  ASSERT_TRUE(node_->running()) << tail();

  for (int i = 0; i < kAbusePausedRequests && watchdog_->hung().empty(); ++i) paused_phase_request(in);
  ASSERT_EQ(watchdog_->hung(), "") << "no answer within " << kAbuseAnswerBound << " s; the node's log:\n" << tail();
  std_srvs::Empty unpause;
  ASSERT_TRUE(must_answer("/gazebo/unpause_physics", unpause, "gazebo unpause_physics"));
  const auto t3 = std::chrono::steady_clock::now();

  std::map<std::string, int> outcomes;
  EXPECT_EQ(end_goals(15.0, outcomes), 0) << "action goals that never ended";

  // The storm controllers back as they were (one STRICT switch); the core never stopped.
  Names now_running, now_loaded;
  ASSERT_TRUE(list(now_running, now_loaded));
  for (const std::string& c : kAbuseCore) EXPECT_TRUE(now_running.count(c)) << c << " stopped by the abuse";
  cmm::SwitchController back;
  back.request.strictness = cmm::SwitchController::Request::STRICT;
  for (const std::string& c : now_running)
    if (!running_before.count(c)) back.request.stop_controllers.push_back(c);
  for (const std::string& c : running_before) {
    if (now_running.count(c)) continue;
    if (!now_loaded.count(c)) {
      cmm::LoadController l;
      l.request.name = c;
      ASSERT_TRUE(must_answer(kAbuseCm + "load_controller", l, "load_controller (check)")) << c;
    }
    back.request.start_controllers.push_back(c);
  }
  ASSERT_TRUE(must_answer(kAbuseCm + "switch_controller", back, "switch_controller (check)"));
  EXPECT_TRUE(back.response.ok);
  ASSERT_TRUE(list(now_running, now_loaded));
  EXPECT_EQ(now_running, running_before) << "running after the abuse " << str(now_running) << ", before "
                                         << str(running_before);

  // The robot's state is finite: joint_states and the model's pose.
  std::mutex m;
  std::vector<double> values;
  ::ros::Subscriber js = nh_.subscribe<sensor_msgs::JointState>(
      "/pr2/joint_states", 1, [&](const sensor_msgs::JointState::ConstPtr& msg) {
        std::lock_guard<std::mutex> l(m);
        values = msg->position;
        values.insert(values.end(), msg->velocity.begin(), msg->velocity.end());
      });
  EXPECT_TRUE(wait_until([&] { std::lock_guard<std::mutex> l(m); return !values.empty(); }, 10.0));
  {
    std::lock_guard<std::mutex> l(m);
    for (double v : values) EXPECT_TRUE(std::isfinite(v)) << "a joint's position or velocity is " << v;
  }
  gazebo_msgs::GetModelState pose;
  pose.request.model_name = "pr2";
  ASSERT_TRUE(must_answer("/gazebo/get_model_state", pose, "gazebo get_model_state (check)"));
  ASSERT_TRUE(pose.response.success) << pose.response.status_message;
  const auto& p = pose.response.pose;
  EXPECT_TRUE(std::isfinite(p.position.x + p.position.y + p.position.z + p.orientation.w + p.orientation.x +
                            p.orientation.y + p.orientation.z))
      << "the PR2's pose is not finite";
  EXPECT_TRUE(node_->running()) << tail();
  const std::string log = node_->log();
  for (const char* bad : {"AddressSanitizer", "runtime error", "diverge", "terminate called", "Aborted"}) {
    EXPECT_EQ(log.find(bad), std::string::npos) << "the node's log says '" << bad << "':\n" << tail();
  }
  EXPECT_THAT(inconsistent_, ::testing::IsEmpty());
  EXPECT_EQ(failures_, 0);

  int total = 0;
  std::printf("abuse: requests by kind (seed %llu; \"(check)\": the test's own verification calls)\n",
              static_cast<unsigned long long>(seed));
  for (const auto& [kind, n] : sent_) {
    std::printf("  %6d  %s\n", n, kind.c_str());
    if (kind.find("(check)") == std::string::npos) total += n;
  }
  std::printf("  %6d  in all: %d topic messages; the main phase (%d draws) took %.1f s wall, the paused phase (%d) "
              "%.1f s\n",
              total, published_, main_requests, main_seconds, kAbusePausedRequests,
              std::chrono::duration<double>(t3 - t2).count());
  std::printf("abuse: real-time factor before %.4f, during the main phase %.4f (1 s windows %.3f..%.3f)\n", rtf_before,
              rtf_during, rtf_min, rtf_max);
  for (const auto& [what, n] : outcomes) std::printf("  goals %6d  %s\n", n, what.c_str());
  EXPECT_GE(total, kAbuseRequests);
  EXPECT_NEAR(rtf_during / rtf_before, 1.0, 0.10) << "before " << rtf_before << ", during " << rtf_during;
}

}  // namespace
}  // namespace mechsim::ros::test
