// ros2_controllers' actions on the PR2, called by clients of both middlewares at once: the
// Fast DDS peer (rmw_fastrtps' forms) sends FollowJointTrajectory goals to the right arm
// (success within the goal tolerances, a path tolerance violated, cancel, preemption, a goal
// refused, a goal tolerance violated) and a GripperCommand to the right gripper, while the Cyclone DDS client
// (rmw_cyclonedds' in-payload header) sends, cancels and preempts goals on the left arm, violates
// a path tolerance there and commands the left gripper. And a
// client vanishing mid-action and mid-service leaves nothing behind. Humble and Jazzy.
#include <cmath>

#include "wire_fixture.hpp"

namespace mechsim::ros2::test {
namespace {

using nlohmann::json;

const std::vector<std::string> kRight = {"r_shoulder_pan_joint", "r_shoulder_lift_joint", "r_upper_arm_roll_joint",
                                         "r_elbow_flex_joint",   "r_forearm_roll_joint",  "r_wrist_flex_joint",
                                         "r_wrist_roll_joint"};
const std::vector<std::string> kLeft = {"l_shoulder_pan_joint", "l_shoulder_lift_joint", "l_upper_arm_roll_joint",
                                        "l_elbow_flex_joint",   "l_forearm_roll_joint",  "l_wrist_flex_joint",
                                        "l_wrist_roll_joint"};
const std::vector<double> kTarget = {0.4, 0.1, 0.0, -0.4, 0.0, -0.3, 0.0};
const std::vector<double> kHome = {0.0, 0.0, 0.0, -0.15, 0.0, -0.1, 0.0};

json duration(double s) {
  return {{"sec", static_cast<int>(std::floor(s))}, {"nanosec", static_cast<unsigned>(std::lround((s - std::floor(s)) * 1e9))}};
}
// A FollowJointTrajectory goal: one point at `seconds`.
json goal(const std::vector<std::string>& joints, const std::vector<double>& positions, double seconds) {
  return {{"trajectory",
           {{"joint_names", joints}, {"points", {{{"positions", positions}, {"time_from_start", duration(seconds)}}}}}}};
}
json tolerances(const std::vector<std::string>& joints, double position) {
  json out = json::array();
  for (const auto& j : joints) out.push_back({{"name", j}, {"position", position}, {"velocity", 0.0}, {"acceleration", 0.0}});
  return out;
}
json send(const std::string& controller, const json& g, const std::string& as) {
  return {{"op", "send_goal"},
          {"action", "/pr2/" + controller + "/follow_joint_trajectory"},
          {"type", "control_msgs/action/FollowJointTrajectory"},
          {"goal", g},
          {"as", as}};
}
json result(const std::string& as, double timeout = 20.0) { return {{"op", "result"}, {"goal", as}, {"timeout", timeout}}; }
json cancel(const std::string& as) { return {{"op", "cancel"}, {"goal", as}}; }
json sleep_for(double s) { return {{"op", "sleep"}, {"seconds", s}}; }

std::vector<std::string> pr2_args(const std::string& distro) {
  const std::string src = MECHSIM_SOURCE_DIR;
  return {src + "/robots/pr2/urdf/pr2.urdf.xacro", "--package", "mechsim_pr2=" + src + "/robots/pr2", "--controllers",
          src + "/robots/pr2/config/controllers.yaml", "--start", "joint_state_controller", "r_arm_controller",
          "l_arm_controller", "r_gripper_controller", "l_gripper_controller", "--real-time-factor", "1", "--ros-distro", distro};
}

class ActionWire : public WireTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(ActionWire, Pr2ArmsAndGripperFromBothMiddlewares) {
  const std::string distro = GetParam();
  start_mechsim(pr2_args(distro));
  // The right arm and gripper from Fast DDS.
  json ok = goal(kRight, kTarget, 1.5);
  ok["goal_tolerance"] = tolerances(kRight, 0.02);
  ok["goal_time_tolerance"] = duration(1.0);
  json fast_path = goal(kRight, {-0.4, 0.1, 0.0, -0.4, 0.0, -0.3, 0.0}, 0.5);
  fast_path["path_tolerance"] = json::array({{{"name", "r_shoulder_pan_joint"}, {"position", 0.0005}, {"velocity", 0.0}, {"acceleration", 0.0}}});
  json bad = goal({"no_such_joint"}, {0.1}, 1.0);
  // A goal tolerance no servo meets, and 0.1 s past the trajectory's end to meet it.
  json tight = goal(kRight, kHome, 0.5);
  tight["goal_tolerance"] = tolerances(kRight, 1e-6);
  tight["goal_time_tolerance"] = duration(0.1);
  const json right = {
      send("r_arm_controller", ok, "ok"),                                             // 0
      result("ok"),                                                                   // 1 SUCCEEDED
      {{"op", "take"}, {"topic", "/tf"}, {"type", "tf2_msgs/TFMessage"}, {"print", true}},  // 2
      send("r_arm_controller", fast_path, "path"),                                    // 3
      result("path"),                                                                 // 4 ABORTED, -4
      send("r_arm_controller", goal(kRight, kHome, 4.0), "canceled"),                 // 5
      sleep_for(0.5),                                                                 // 6
      cancel("canceled"),                                                             // 7
      result("canceled"),                                                             // 8 CANCELED
      cancel("canceled"),                                                             // 9 ERROR_GOAL_TERMINATED
      send("r_arm_controller", goal(kRight, kTarget, 4.0), "old"),                    // 10
      sleep_for(0.3),                                                                 // 11
      send("r_arm_controller", goal(kRight, kHome, 1.0), "new"),                      // 12
      result("old"),                                                                  // 13 CANCELED, -1
      result("new"),                                                                  // 14 SUCCEEDED
      send("r_arm_controller", bad, "bad"),                                           // 15 rejected
      {{"op", "send_goal"}, {"action", "/pr2/r_gripper_controller/gripper_cmd"}, {"type", "control_msgs/action/GripperCommand"},
       {"goal", {{"command", {{"position", 0.06}, {"max_effort", 100.0}}}}}, {"as", "grip"}},  // 16
      result("grip"),                                                                 // 17 SUCCEEDED, reached_goal
      send("r_arm_controller", tight, "tight"),                                       // 18
      result("tight"),                                                                // 19 ABORTED, -5
  };
  // The left arm and gripper from Cyclone DDS at the same time.
  json left_path = goal(kLeft, {-0.4, 0.1, 0.0, -0.4, 0.0, -0.3, 0.0}, 0.5);
  left_path["path_tolerance"] = json::array({{{"name", "l_shoulder_pan_joint"}, {"position", 0.0005}, {"velocity", 0.0}, {"acceleration", 0.0}}});
  const json left = {
      send("l_arm_controller", goal(kLeft, kTarget, 1.0), "ok"),   // 0
      result("ok"),                                                // 1 SUCCEEDED
      send("l_arm_controller", goal(kLeft, kHome, 4.0), "old"),    // 2
      sleep_for(0.3),                                              // 3
      send("l_arm_controller", goal(kLeft, kTarget, 4.0), "new"),  // 4 preempts old
      sleep_for(0.3),                                              // 5
      cancel("new"),                                               // 6
      result("old"),                                               // 7 CANCELED, -1
      result("new"),                                               // 8 CANCELED, 0
      send("l_arm_controller", left_path, "path"),                 // 9
      result("path"),                                              // 10 ABORTED, -4
      {{"op", "send_goal"}, {"action", "/pr2/l_gripper_controller/gripper_cmd"}, {"type", "control_msgs/action/GripperCommand"},
       {"goal", {{"command", {{"position", 0.03}, {"max_effort", 100.0}}}}}, {"as", "grip"}},  // 11
      result("grip"),                                              // 12 SUCCEEDED, reached_goal
  };
  Process& fast = start_fastdds_script(distro, right, "fastdds_right");
  Process& cyclone = start_cyclone_script(distro, left, "cyclone_left");
  const auto r = steps_of(fast);
  const auto l = steps_of(cyclone);
  const std::string log = stop_mechsim();
  ASSERT_EQ(r.size(), right.size()) << fast.output() << log;
  ASSERT_EQ(l.size(), left.size()) << cyclone.output() << log;
  for (const auto& s : r) EXPECT_FALSE(s.contains("error")) << s;
  for (const auto& s : l) EXPECT_FALSE(s.contains("error")) << s;

  // Within the goal tolerances: SUCCEEDED, SUCCESSFUL, and the joints where the goal put them.
  EXPECT_EQ(r[0]["form"], "rmw_fastrtps");
  EXPECT_TRUE(r[0]["accepted"].get<bool>()) << r[0] << log;
  EXPECT_EQ(r[1]["status"], 4) << r[1];
  EXPECT_EQ(r[1]["result"]["error_code"], 0) << r[1];
  EXPECT_EQ(r[1]["result"]["error_string"], "Goal successfully reached!");
  EXPECT_GT(r[1]["feedback"].get<int>(), 5) << r[1];
  // The status topic (keep last 1, as rcl_action's) saw it EXECUTING, then SUCCEEDED.
  EXPECT_EQ(r[1]["statuses"], json::array({2, 4})) << r[1];
  // The joints as robot_state_publisher puts them on /tf: each arm joint's origin has no rotation,
  // so its transform is the rotation about its axis (z, y, x, y, x, y, x).
  const json& tf = r[2]["value"];
  ASSERT_TRUE(r[2]["got"].get<bool>()) << r[2];
  const int axis[] = {2, 1, 0, 1, 0, 1, 0};
  const char* xyz[] = {"x", "y", "z"};
  double worst = 0.0;
  for (std::size_t k = 0; k < kRight.size(); ++k) {
    const std::string child = kRight[k].substr(0, kRight[k].size() - 5) + "link";  // r_..._joint -> r_..._link
    bool found = false;
    for (const auto& t : tf["transforms"]) {
      if (t["child_frame_id"] != child) continue;
      found = true;
      const auto& q = t["transform"]["rotation"];
      const double angle = 2.0 * std::atan2(q[xyz[axis[k]]].get<double>(), q["w"].get<double>());
      worst = std::max(worst, std::abs(angle - kTarget[k]));
    }
    EXPECT_TRUE(found) << child << " " << tf;
  }
  EXPECT_LT(worst, 0.02) << tf;
  std::printf("%s: FollowJointTrajectory on the right arm SUCCEEDED in %.0f ms; worst joint error after it %.4f rad "
              "(goal tolerance 0.02)\n",
              distro.c_str(), r[1]["ms"].get<double>() + r[0]["ms"].get<double>(), worst);
  // Beyond a path tolerance: ABORTED with PATH_TOLERANCE_VIOLATED.
  EXPECT_TRUE(r[3]["accepted"].get<bool>()) << r[3];
  EXPECT_EQ(r[4]["status"], 6) << r[4];
  EXPECT_EQ(r[4]["result"]["error_code"], -4) << r[4];
  EXPECT_EQ(r[4]["result"]["error_string"].get<std::string>().rfind("Aborted due to path tolerance violation", 0), 0u) << r[4];
  std::printf("%s: path tolerance 0.0005 rad: %s, error_code %d (%s)\n", distro.c_str(),
              r[4]["status"] == 6 ? "ABORTED" : "not aborted", r[4]["result"]["error_code"].get<int>(),
              r[4]["result"]["error_string"].get<std::string>().c_str());
  // Cancel: CANCELING, then CANCELED with an empty result; a second cancel finds it ended.
  EXPECT_EQ(r[7]["return_code"], 0) << r[7];
  EXPECT_EQ(r[7]["canceling"], 1) << r[7];
  EXPECT_EQ(r[8]["status"], 5) << r[8];
  EXPECT_EQ(r[8]["result"]["error_code"], 0) << r[8];
  // CANCELING (3) may be overwritten by CANCELED before the client reads it (keep last 1).
  EXPECT_EQ(r[8]["statuses"].front(), 2) << r[8];
  EXPECT_EQ(r[8]["statuses"].back(), 5) << r[8];
  EXPECT_EQ(r[9]["return_code"], 3) << r[9];
  // Preemption by a newer goal.
  EXPECT_EQ(r[13]["status"], 5) << r[13];
  EXPECT_EQ(r[13]["result"]["error_code"], -1) << r[13];
  EXPECT_EQ(r[13]["result"]["error_string"], "Current goal cancelled due to new incoming action.") << r[13];
  EXPECT_EQ(r[14]["status"], 4) << r[14];
  // A goal the controller refuses.
  EXPECT_TRUE(r[15]["replied"].get<bool>()) << r[15];
  EXPECT_FALSE(r[15]["accepted"].get<bool>()) << r[15];
  // The gripper.
  EXPECT_TRUE(r[16]["accepted"].get<bool>()) << r[16];
  EXPECT_EQ(r[17]["status"], 4) << r[17] << log;
  EXPECT_TRUE(r[17]["result"]["reached_goal"].get<bool>()) << r[17];
  // reached: within the PR2 gripper's goal_threshold (0.01 m) of the goal
  EXPECT_LT(std::abs(r[17]["result"]["position"].get<double>() - 0.06), 0.0101) << r[17];

  // Beyond the goal tolerances once goal_time_tolerance is over: ABORTED, GOAL_TOLERANCE_VIOLATED.
  EXPECT_TRUE(r[18]["accepted"].get<bool>()) << r[18];
  EXPECT_EQ(r[19]["status"], 6) << r[19] << log;
  EXPECT_EQ(r[19]["result"]["error_code"], -5) << r[19];
  EXPECT_EQ(r[19]["result"]["error_string"].get<std::string>().rfind("Aborted due to goal tolerance violation", 0), 0u) << r[19];

  // Cyclone DDS, the left arm.
  EXPECT_EQ(l[0]["form"], "rmw_cyclonedds");
  EXPECT_TRUE(l[0]["accepted"].get<bool>()) << l[0] << log;
  EXPECT_EQ(l[1]["status"], 4) << l[1];
  EXPECT_EQ(l[1]["result"]["error_code"], 0) << l[1];
  EXPECT_GT(l[1]["feedback"].get<int>(), 3) << l[1];
  EXPECT_EQ(l[7]["status"], 5) << l[7];
  EXPECT_EQ(l[7]["result"]["error_code"], -1) << l[7];
  EXPECT_EQ(l[6]["return_code"], 0) << l[6];
  EXPECT_EQ(l[8]["status"], 5) << l[8];
  EXPECT_EQ(l[8]["result"]["error_code"], 0) << l[8];
  EXPECT_TRUE(l[9]["accepted"].get<bool>()) << l[9];
  EXPECT_EQ(l[10]["status"], 6) << l[10];
  EXPECT_EQ(l[10]["result"]["error_code"], -4) << l[10];
  EXPECT_TRUE(l[11]["accepted"].get<bool>()) << l[11];
  EXPECT_EQ(l[12]["status"], 4) << l[12] << log;
  EXPECT_TRUE(l[12]["result"]["reached_goal"].get<bool>()) << l[12];
  EXPECT_LT(std::abs(l[12]["result"]["position"].get<double>() - 0.03), 0.0101) << l[12];
  EXPECT_NE(log.find("action goals: "), std::string::npos) << log;
  EXPECT_NE(log.find("0 requests waiting"), std::string::npos) << log;
}

// A client that vanishes mid-action (its process gone without a word: a crash): its waiting
// get_result request is dropped as soon as its reader is gone (before the goal ends), the goal
// runs to its end. One that closes with 300 calls queued: their replies are dropped without a
// wait. The services go on for everyone else.
TEST_P(ActionWire, ClientVanishingMidCallLeavesNothing) {
  const std::string distro = GetParam();
  start_mechsim(pr2_args(distro));
  const json mid_action = {send("l_arm_controller", goal(kLeft, kTarget, 4.0), "long"), sleep_for(0.2), {{"op", "vanish"}}};
  Process& a = start_fastdds_script(distro, mid_action, "vanish_action", {"--lease", "1"});
  const auto sa = steps_of(a);
  ASSERT_EQ(sa.size(), 2u) << a.output();  // the vanish prints nothing
  EXPECT_TRUE(sa[0]["accepted"].get<bool>()) << sa[0];
  // Dropped within its lease (1 s) and a poll, long before the goal's 4 s are over.
  EXPECT_TRUE(mechsim_->wait_for_output("get_result request(s) dropped: the client is gone", std::chrono::seconds(3)))
      << mechsim_->output();
  // Mid-service: 300 calls queued on the world's worker, and the client closes (as a client
  // stopped with Ctrl-C) before their replies: they are dropped at no cost, and others are served.
  const json mid_service = {
      {{"op", "call"}, {"service", "/get_model_list"}, {"type", "gazebo_msgs/srv/GetModelList"}},
      {{"op", "call"}, {"service", "/get_entity_state"}, {"type", "gazebo_msgs/srv/GetEntityState"},
       {"request", {{"name", "pr2"}, {"reference_frame", "world"}}}, {"count", 300}, {"wait", false}},
      {{"op", "exit"}}};
  Process& b = start_fastdds_script(distro, mid_service, "vanish_service");
  const auto sb = steps_of(b);
  ASSERT_EQ(sb.size(), 2u) << b.output();
  EXPECT_EQ(sb[1]["sent"], 300) << sb[1];
  EXPECT_TRUE(mechsim_->wait_for_output("/get_entity_state: the reply to", std::chrono::seconds(5))) << mechsim_->output();
  // Everyone else is still served (from Cyclone DDS): unpause, list, and the abandoned goal ended.
  const json after = {{{"op", "call"}, {"service", "/get_model_list"}, {"type", "gazebo_msgs/srv/GetModelList"}},
                      {{"op", "call"}, {"service", "/pr2/controller_manager/list_controllers"},
                       {"type", "controller_manager_msgs/srv/ListControllers"}},
                      sleep_for(4.0)};
  const auto sc = steps_of(start_cyclone_script(distro, after, "after"));
  const std::string log = stop_mechsim();
  ASSERT_EQ(sc.size(), 3u);
  EXPECT_EQ(sc[0]["replies"], 1) << sc[0];
  EXPECT_LT(sc[0]["reply_ms"].get<double>(), 500.0) << sc[0];  // not held up by the dropped replies
  EXPECT_EQ(sc[1]["replies"], 1) << sc[1];
  EXPECT_NE(log.find("was dropped: the client is gone"), std::string::npos) << log;
  // The end-of-run line: the goal ended, one result dropped, nothing waiting.
  EXPECT_NE(log.find("1 accepted, 0 rejected; 1 succeeded"), std::string::npos) << log;
  EXPECT_NE(log.find("0 sent, 1 dropped (client gone), 0 requests waiting"), std::string::npos) << log;
}

INSTANTIATE_TEST_SUITE_P(Distros, ActionWire, ::testing::Values("humble", "jazzy"),
                         [](const ::testing::TestParamInfo<std::string>& i) { return i.param; });

}  // namespace
}  // namespace mechsim::ros2::test
