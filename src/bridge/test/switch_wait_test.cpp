// switch_controller's wait for the tick, through the bridge (found by the ROS abuse test,
// test/integration/pr2_abuse_test.cpp): a switch that no tick applied within the caller's timeout
// is taken back, so that the refusal stays true (it used to be applied by the next tick after the
// caller was told it failed); and a wait ends when the world is paused meanwhile (it used to run
// to the caller's timeout, which may be 1e300 s, holding the controller manager's services).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "description/urdf/urdf_parser.hpp"
#include "bridge/sim_bridge.hpp"
#include "bridge/test/pendulum_robot.hpp"

namespace mechsim::bridge {
namespace {

const std::string kPendulum = test::pendulum_urdf(1);

std::unique_ptr<SimBridge> pendulum() {
  BridgeOptions options;
  options.robot = description::parse_urdf_string(kPendulum, "pendulum", {});
  options.controller_params =
      control::Params::from_yaml_string("push: {type: effort_controllers/JointEffortController, joint: hinge}", "c");
  auto bridge = std::make_unique<SimBridge>(std::move(options));
  EXPECT_TRUE(bridge->load_controller("push").ok);
  return bridge;
}

std::string state_of(SimBridge& bridge, const std::string& name) {
  for (const ControllerSummary& c : bridge.list_controllers()) {
    if (c.name == name) return c.state;
  }
  return "absent";
}

// Nobody ticks here (no loop thread), so the wait times out: the answer and the state must agree.
TEST(SwitchWait, ASwitchNotAppliedWithinTheTimeoutIsTakenBack) {
  auto bridge = pendulum();
  const BridgeResult r = bridge->switch_controllers({"push"}, {}, true, 0.05);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("taken back"), std::string::npos) << r.error;
  std::string error;
  ASSERT_TRUE(bridge->run_for(0.01, &error)) << error;
  EXPECT_EQ(state_of(*bridge, "push"), "initialized") << "refused, yet started by the next tick";
  // Nothing is left pending: the next switch is not refused for a previous one.
  std::thread ticker([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    std::string e;
    bridge->run_for(0.01, &e);
  });
  const BridgeResult again = bridge->switch_controllers({"push"}, {}, true, 5.0);
  ticker.join();
  EXPECT_TRUE(again.ok) << again.error;
  EXPECT_EQ(state_of(*bridge, "push"), "running");
}

// Paused while the call waits (with an absurd timeout): the call answers at once, the switch
// stays pending ("waiting") and applies after the unpause.
TEST(SwitchWait, PausingWhileASwitchWaitsEndsTheWait) {
  for (const double timeout : {20.0, 1e300, std::numeric_limits<double>::infinity()}) {
    auto bridge = pendulum();
    std::thread pauser([&] {
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
      bridge->pause();
    });
    const auto start = std::chrono::steady_clock::now();
    const BridgeResult r = bridge->switch_controllers({"push"}, {}, true, timeout);
    const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    pauser.join();
    EXPECT_TRUE(r.ok) << r.error;
    EXPECT_LT(waited, 2.0) << "timeout " << timeout;
    EXPECT_EQ(state_of(*bridge, "push"), "waiting");
    bridge->unpause();
    std::string error;
    ASSERT_TRUE(bridge->run_for(0.01, &error)) << error;
    EXPECT_EQ(state_of(*bridge, "push"), "running");
  }
}

}  // namespace
}  // namespace mechsim::bridge
