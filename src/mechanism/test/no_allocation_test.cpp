// The hot path allocates nothing: every propagation and the safety limits, over every
// transmission type, run with a counting global operator new.
// Replacing operator new confuses GCC 12's inlining-based diagnostics in this file only.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#pragma GCC diagnostic ignored "-Wrestrict"
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "mechanism/differential_transmission.hpp"
#include "mechanism/four_bar_transmission.hpp"
#include "mechanism/pr2_gripper_transmission.hpp"
#include "mechanism/pr2_wrist_transmission.hpp"
#include "mechanism/propagation.hpp"
#include "mechanism/simple_transmission.hpp"

namespace {
std::atomic<long> g_allocations{0};  // test instrumentation only
}

void* operator new(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace mechsim::mechanism {
namespace {

TEST(Propagation, AllocatesNothing) {
  MechanismModel m;
  for (int i = 0; i < 13; ++i) {
    m.joints.push_back(JointInfo{});
    m.joints.back().limits = description::JointLimits{-1.0, 1.0, 10.0, 2.0};
    m.joints.back().safety = description::SafetyController{-0.9, 0.9, 10.0, 5.0};
  }
  for (int i = 0; i < 9; ++i) m.actuators.push_back(ActuatorInfo{"a" + std::to_string(i), i});
  m.joints[10].role = m.joints[11].role = JointRole::Passive;
  m.joints[12].role = JointRole::SimulatedActuated;
  m.transmissions.push_back(std::make_unique<SimpleTransmission>("s", "x", 0, 0, 5.0, 0.1, 9, 3141.6));
  m.transmissions.push_back(std::make_unique<DifferentialTransmission>("d", "x", std::array{1, 2}, std::array{1, 2},
                                                                       std::array{2.0, 3.0}, std::array{1.0, 1.0}));
  m.transmissions.push_back(std::make_unique<FourBarLinkageTransmission>("f", "x", std::array{3, 4}, std::array{3, 4},
                                                                         std::array{2.0, 3.0}, std::array{1.0, 1.0}));
  m.transmissions.push_back(std::make_unique<Pr2WristTransmission>("w", "x", std::array{5, 6}, std::array{5, 6},
                                                                   std::array{60.0, 60.0}, std::array{-1.0, 1.0}));
  m.transmissions.push_back(std::make_unique<Pr2GripperTransmission>("g", "x", 7, std::vector<int>{10, 11}, 12, -1, 7,
                                                                     GripperGeometry{}, 3141.6));
  m.transmissions.push_back(std::make_unique<SimpleTransmission>("s2", "x", 8, 8, -2.0));
  MechanismState s = make_state(m);
  for (JointState& j : s.joints) {
    j.position = 0.02;
    j.commanded_effort = 100.0;
    j.command_mode = HardwareInterface::Position;
    j.commanded_position = 0.5;
  }

  {  // the instrument counts
    const long c = g_allocations.load();
    auto probe = std::make_unique<double>(1.0);
    EXPECT_EQ(g_allocations.load() - c, 1);
  }
  const long before = g_allocations.load();
  for (int tick = 0; tick < 100; ++tick) {
    propagate_joint_to_actuator_position(m, s);
    propagate_actuator_to_joint_position(m, s);
    s.joints[0].commanded_position = 0.5;  // what a position controller writes every tick
    enforce_safety_limits(m, s, 0.001);
    propagate_joint_to_actuator_effort(m, s);
    propagate_actuator_to_joint_effort(m, s);
  }
  EXPECT_EQ(g_allocations.load() - before, 0);
  // And it did run: the effort was clamped to the limit and the position command ramps.
  EXPECT_NEAR(s.joints[0].commanded_effort, 10.0, 1e-9);
  EXPECT_NEAR(s.joints[0].commanded_position, 0.02 + 100 * 0.002, 1e-9);
}

}  // namespace
}  // namespace mechsim::mechanism
