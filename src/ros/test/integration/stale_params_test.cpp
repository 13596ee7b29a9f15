// Parameters left on the parameter server by an earlier run never reach a launched mechsim_node:
// every private parameter the node reads (`mechsim_node --params`) is set to a stale value
// first, then, on the same master, the PR2's launch and after it the CC8's run as they would
// on a fresh one (this used to end the CC8 launch with "unknown caster link
// 'fl_caster_rotation_link'": the PR2 run's robot_namespace, pr2 and lenient were taken).
// Each launch is bounded (60 s to come up) and stopped, also on failure.
#include <gmock/gmock.h>

#include <filesystem>
#include <sstream>

#include <controller_manager_msgs/ListControllers.h>

#include "ros_fixture.hpp"

namespace mechsim::ros::test {
namespace {

struct Param {
  std::string name, type, default_value;
};

std::vector<Param> node_params() {
  ChildProcess p({MECHSIM_NODE_EXE, "--params"}, log_dir() + "/params.txt");
  EXPECT_EQ(p.wait(10.0), 0);
  std::vector<Param> out;
  std::istringstream lines(p.log());
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream cols(line);
    Param param;
    std::getline(cols, param.name, '\t');
    std::getline(cols, param.type, '\t');
    std::getline(cols, param.default_value, '\t');
    if (!param.name.empty()) out.push_back(param);
  }
  return out;
}

// A value no launch file sets: of the parameter's type, but for a bool (whose both values a
// launch file may set) an int, which the node would not take either; the realistic stale bools
// are the PR2 run's (pr2: true).
XmlRpc::XmlRpcValue stale_value(const Param& p) {
  if (p.type == "bool") return XmlRpc::XmlRpcValue(2);
  if (p.type == "double") return XmlRpc::XmlRpcValue(12345.5);
  if (p.type == "map") {
    XmlRpc::XmlRpcValue v;
    v["stale_arg"] = std::string("stale");
    return v;
  }
  if (p.name == "robot_namespace") return XmlRpc::XmlRpcValue(std::string("/stale_ns"));
  return XmlRpc::XmlRpcValue(std::string("/stale/" + p.name));
}

bool is_stale(const Param& p, XmlRpc::XmlRpcValue& now) {
  XmlRpc::XmlRpcValue stale = stale_value(p);
  return now == stale;
}

std::size_t running(const std::string& list_service) {
  controller_manager_msgs::ListControllers list;
  if (!::ros::service::exists(list_service, false) || !::ros::service::call(list_service, list)) return 0;
  std::size_t n = 0;
  for (const auto& c : list.response.controller) n += c.state == "running" ? 1 : 0;
  return n;
}

class StaleParams : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists("/usr/bin/roslaunch")) GTEST_SKIP() << "/usr/bin/roslaunch is missing (python3-roslaunch)";
    ASSERT_TRUE(::ros::master::check());
    params_ = node_params();
    ASSERT_GE(params_.size(), 20u) << "mechsim_node --params lists too few";
  }

  void poison() {
    for (const Param& p : params_) ::ros::param::set("/mechsim/" + p.name, stale_value(p));
    ::ros::param::set("/mechsim/some_other_nodes_param", 7);
  }

  // Every parameter of the list is now the launch file's or gone, none stale.
  void expect_nothing_stale(const std::string& launch) {
    for (const Param& p : params_) {
      XmlRpc::XmlRpcValue now;
      if (::ros::param::get("/mechsim/" + p.name, now)) {
        EXPECT_FALSE(is_stale(p, now)) << launch << " left ~" << p.name << " stale";
      }
    }
  }

  // roslaunch PKG FILE, waits until `expected` controllers run in the list at `list_service`.
  void launch_and_wait(const std::string& pkg, const std::string& file, const std::string& list_service,
                       std::size_t expected) {
    ChildProcess launch({"/usr/bin/python3", "/usr/bin/roslaunch", pkg, file, "paused:=false"},
                        log_dir() + "/roslaunch_" + file + ".log");
    EXPECT_TRUE(wait_until([&] { return running(list_service) == expected || !launch.running(); }, 60.0));
    EXPECT_EQ(running(list_service), expected) << file << ":\n" << launch.log();
    expect_nothing_stale(file);
    EXPECT_NE(launch.stop(30.0), -1) << "roslaunch did not stop on SIGINT";
    EXPECT_TRUE(wait_until([&] { return !::ros::service::exists(list_service, false); }, 10.0));
  }

  std::vector<Param> params_;
};

TEST_F(StaleParams, Pr2LaunchThenCc8LaunchOnOneMasterEachIgnoreWhatWasLeftBefore) {
  poison();
  launch_and_wait("mechsim_pr2", "pr2_empty_world.launch", "/pr2/controller_manager/list_controllers", 9);
  // What the PR2 run left behind, plus stale values again for what it did not set.
  for (const Param& p : params_) {
    if (!::ros::param::has("/mechsim/" + p.name)) ::ros::param::set("/mechsim/" + p.name, stale_value(p));
  }
  launch_and_wait("mechsim_cc8", "cc8_mechsim.launch", "/cc8/controller_manager/list_controllers", 2);
}

}  // namespace
}  // namespace mechsim::ros::test
