// switch_controller as ros_control's controller_manager answers it: strictness 0 (a request
// that leaves the field out) is BEST_EFFORT with a warning; BEST_EFFORT skips unknown names but
// refuses the whole switch on a resource conflict. And a switch made while paused: accepted at
// once, listed "waiting" until the unpause starts it, and the spawner says so.
#include <gmock/gmock.h>

#include <controller_manager_msgs/ListControllers.h>
#include <controller_manager_msgs/LoadController.h>
#include <controller_manager_msgs/SwitchController.h>
#include <std_srvs/Empty.h>

#include "ros_fixture.hpp"

namespace mechsim::ros::test {
namespace {

namespace cmm = controller_manager_msgs;
using ::testing::HasSubstr;
using ::testing::Not;

const std::string kCm = "/cc8/controller_manager/";

// name -> state, as list_controllers reports it.
std::map<std::string, std::string> states() {
  cmm::ListControllers srv;
  EXPECT_TRUE(call(kCm + "list_controllers", srv));
  std::map<std::string, std::string> out;
  for (const auto& c : srv.response.controller) out[c.name] = c.state;
  return out;
}

bool load(const std::string& name) {
  cmm::LoadController srv;
  srv.request.name = name;
  return call(kCm + "load_controller", srv) && srv.response.ok;
}

// The response's ok; the call itself must succeed.
bool switch_with(int strictness, const std::vector<std::string>& start, const std::vector<std::string>& stop = {}) {
  cmm::SwitchController srv;
  srv.request.start_controllers = start;
  srv.request.stop_controllers = stop;
  srv.request.strictness = strictness;
  EXPECT_TRUE(call(kCm + "switch_controller", srv));
  return srv.response.ok;
}

constexpr int kBestEffort = cmm::SwitchController::Request::BEST_EFFORT;
constexpr int kStrict = cmm::SwitchController::Request::STRICT;

TEST_F(CC8Node, StrictnessZeroIsBestEffortAndBestEffortRefusesResourceConflicts) {
  rosparam_load(std::string(MECHSIM_SOURCE_DIR) + "/robots/cc8/config/controllers.yaml");
  // A second controller on wheel_joint_FL.
  ::ros::param::set("/cc8/other_fl_controller/type", std::string("effort_controllers/JointVelocityController"));
  ::ros::param::set("/cc8/other_fl_controller/joint", std::string("wheel_joint_FL"));
  ::ros::param::set("/cc8/other_fl_controller/pid/p", 1.0);
  ASSERT_TRUE(load("wheel_joint_FL_velocity_controller"));
  ASSERT_TRUE(load("other_fl_controller"));

  // The common one-liner leaves strictness at 0.
  EXPECT_TRUE(switch_with(0, {"wheel_joint_FL_velocity_controller"}));
  EXPECT_EQ(states()["wheel_joint_FL_velocity_controller"], "running");
  EXPECT_TRUE(wait_until([&] { return node_->log().find("strictness 0") != std::string::npos; }, 5.0))
      << "no warning about strictness 0 in the node's log:\n" << node_->log();
  EXPECT_FALSE(switch_with(7, {}, {"wheel_joint_FL_velocity_controller"})) << "strictness 7 is no strictness";
  EXPECT_TRUE(switch_with(kStrict, {}, {"wheel_joint_FL_velocity_controller"}));

  // BEST_EFFORT: an unknown name is skipped, a resource conflict refuses everything.
  EXPECT_FALSE(switch_with(kBestEffort, {"wheel_joint_FL_velocity_controller", "other_fl_controller"}));
  EXPECT_THAT(states(), Not(::testing::Contains(::testing::Pair(::testing::_, "running"))));
  EXPECT_TRUE(switch_with(kBestEffort, {"wheel_joint_FL_velocity_controller", "no_such_controller"}));
  EXPECT_EQ(states()["wheel_joint_FL_velocity_controller"], "running");
  EXPECT_FALSE(switch_with(kBestEffort, {"other_fl_controller"})) << "conflicts with the running one";
  EXPECT_EQ(states()["other_fl_controller"], "initialized") << "never started, left as it was";
  // Swapping them in one switch is no conflict.
  EXPECT_TRUE(switch_with(0, {"other_fl_controller"}, {"wheel_joint_FL_velocity_controller"}));
  EXPECT_EQ(states()["other_fl_controller"], "running");
  EXPECT_EQ(states()["wheel_joint_FL_velocity_controller"], "stopped");
}

class CC8NodePaused : public CC8Node {
  std::vector<std::string> extra_node_args() const override { return {"_paused:=true"}; }
};

TEST_F(CC8NodePaused, SpawnerWhilePausedSaysTheyStartOnUnpauseAndListShowsThemWaiting) {
  rosparam_load(std::string(MECHSIM_SOURCE_DIR) + "/robots/cc8/config/controllers.yaml");
  ChildProcess& sp = spawner({"joint_state_controller", "wheel_joint_FL_velocity_controller"}, "paused_spawner");
  ASSERT_TRUE(wait_until([&] { return sp.log().find("will start on unpause") != std::string::npos; }, 30.0))
      << sp.log();
  EXPECT_THAT(sp.log(), Not(HasSubstr("started 2 controllers")));
  auto now = states();
  EXPECT_EQ(now["joint_state_controller"], "waiting");
  EXPECT_EQ(now["wheel_joint_FL_velocity_controller"], "waiting");
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_EQ(states()["wheel_joint_FL_velocity_controller"], "waiting") << "nothing starts while paused";

  std_srvs::Empty unpause;
  ASSERT_TRUE(call("/gazebo/unpause_physics", unpause));
  EXPECT_TRUE(wait_until(
      [&] {
        now = states();
        return now["joint_state_controller"] == "running" && now["wheel_joint_FL_velocity_controller"] == "running";
      },
      5.0));
}

}  // namespace
}  // namespace mechsim::ros::test
