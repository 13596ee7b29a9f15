// The PR2's right gripper under its default controller (Pr2GripperController through the
// PR2GripperTransmission): it opens to 0.08 m within 1 s, and closing on a box held between the
// fingers stalls, is reported as stalled and keeps squeezing with the goal's max_effort.
// The physics has no gap joint (the URDF's r_gripper_joint ends on a massless frame): the
// simulation drives the passive finger joints (src/sim/simulation.cpp, GapFromFingers).
// Simulated time: 1.5 s + 2 x 2.7 s.

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "controllers/gripper/pr2_gripper_controller.hpp"
#include "mechanism/pr2_gripper_transmission.hpp"
#include "sensors/pr2_fingertip_pressure.hpp"
#include "sim/test/scenario/pr2_util.hpp"

namespace mechsim::sim {
namespace {

const std::vector<std::string> kFingers = {"r_gripper_l_finger_joint", "r_gripper_r_finger_joint",
                                           "r_gripper_l_finger_tip_joint", "r_gripper_r_finger_tip_joint"};

double gap_of(const Simulation& sim) {
  return sim.mechanism_state().joints[static_cast<std::size_t>(sim.mechanism().joint_index("r_gripper_joint"))].position;
}

// The finger angle (rad) of a gap (m), from the transmission's linkage.
double finger_angle(const Simulation& sim, double gap) {
  for (const auto& t : sim.mechanism().transmissions)
    if (const auto* g = dynamic_cast<const mechanism::Pr2GripperTransmission*>(t.get()); g && t->name() == "r_gripper_trans")
      return g->at_motor(g->motor_angle(gap)).finger;
  throw std::runtime_error("no r_gripper_trans");
}

// Runs until the goal finishes or `limit` seconds pass; returns the time it took (s).
double run_until_done(Simulation& sim, control::GripperGoalPort& port, std::uint64_t id, double limit) {
  const double start = sim.time();
  while (sim.time() - start < limit) {
    EXPECT_TRUE(sim.step());
    const auto s = port.status(id);
    if (s && *s != control::GoalStatus::Active && *s != control::GoalStatus::Pending) break;
  }
  return sim.time() - start;
}

TEST(Pr2Gripper, OpensTo8cmWithinOneSecond) {
  if (!pr2_shared_data_present()) GTEST_SKIP() << "shared data absent: " << MECHSIM_SHARED_DIR;
  auto sim = make_pr2_simulation({"r_arm_controller", "r_gripper_controller"});
  ASSERT_TRUE(sim->run_for(0.2));
  EXPECT_NEAR(gap_of(*sim), 0.0, 0.005);  // spawned closed
  auto& gripper = pr2_controller<control::Pr2GripperController>(*sim, "r_gripper_controller");
  const control::GripperSubmission goal = gripper.goal_port().submit({0.08, 100.0});
  ASSERT_TRUE(goal.accepted) << goal.error;
  const double took = run_until_done(*sim, gripper.goal_port(), goal.id, 1.0);
  ASSERT_TRUE(sim->run_for(1.0 - took));
  const double gap_at_1s = gap_of(*sim);  // 1 s after the goal
  ASSERT_TRUE(sim->run_for(0.3));
  std::cout << "[ figures  ] gripper: goal 0.08 m reached (|error| < 0.01 m) after " << took << " s; gap at 1 s "
            << gap_at_1s << " m, at 1.3 s " << gap_of(*sim) << " m\n";
  EXPECT_EQ(gripper.goal_port().status(goal.id), control::GoalStatus::Succeeded);
  EXPECT_LT(took, 1.0);
  EXPECT_NEAR(gap_at_1s, 0.08, 0.002);
  // The fingers move together (mimic constraints hold under the drive).
  const double q0 = sim->physics().position(pr2_physics_joint(*sim, kFingers[0]));
  EXPECT_NEAR(q0, finger_angle(*sim, 0.08), 0.01);
  for (const std::string& f : kFingers) EXPECT_NEAR(sim->physics().position(pr2_physics_joint(*sim, f)), q0, 0.02) << f;
}

// A 4 cm box (across the gap) fixed where the fingertips meet: closing on it with 50 N stalls.
TEST(Pr2Gripper, ClosingOnABoxStallsAndHoldsWithMaxEffort) {
  if (!pr2_shared_data_present()) GTEST_SKIP() << "shared data absent: " << MECHSIM_SHARED_DIR;
  const std::vector<std::string> start = {"r_arm_controller", "r_gripper_controller"};
  // Where the tool frame (between the fingertip pads) settles with the gripper held open.
  auto open_fingers = [&](Simulation& sim) {
    const double q = finger_angle(sim, 0.08);
    for (const std::string& f : kFingers) sim.physics().set_joint_state(pr2_physics_joint(sim, f), q);
  };
  description::Pose tool;
  {
    auto probe = make_pr2_simulation(start);
    open_fingers(*probe);
    auto& g = pr2_controller<control::Pr2GripperController>(*probe, "r_gripper_controller");
    ASSERT_TRUE(probe->run_for(0.01));
    ASSERT_TRUE(g.goal_port().submit({0.08, 100.0}).accepted);
    ASSERT_TRUE(probe->run_for(0.7));
    tool = probe->physics().link_pose(*probe->physics().model().link_index("r_gripper_tool_frame"));
  }
  World world = make_world({});
  physics::WorldBox box;
  box.name = "block";
  // Centred between the fingertip pads: 2 cm back from the tool frame (at the tips' ends) along
  // its x axis (x = R e_x of the tool frame's orientation).
  const description::Quat& q = tool.orientation;
  const double back = 0.02;
  box.pose = tool;
  box.pose.position.x -= back * (1.0 - 2.0 * (q.y * q.y + q.z * q.z));
  box.pose.position.y -= back * 2.0 * (q.x * q.y + q.w * q.z);
  box.pose.position.z -= back * 2.0 * (q.x * q.z - q.w * q.y);
  box.size = {0.03, 0.04, 0.03};  // the gap closes along the tool frame's y axis
  box.fixed = true;
  world.spec.boxes.push_back(box);
  auto sim = make_pr2_simulation(start, &world);
  open_fingers(*sim);
  auto& gripper = pr2_controller<control::Pr2GripperController>(*sim, "r_gripper_controller");
  ASSERT_TRUE(sim->run_for(0.01));
  ASSERT_TRUE(gripper.goal_port().submit({0.08, 100.0}).accepted);
  ASSERT_TRUE(sim->run_for(0.7));
  ASSERT_NEAR(gap_of(*sim), 0.08, 0.005);

  constexpr double kMaxEffort = 50.0;  // N
  const control::GripperSubmission close = gripper.goal_port().submit({0.0, kMaxEffort});
  ASSERT_TRUE(close.accepted) << close.error;
  const double took = run_until_done(*sim, gripper.goal_port(), close.id, 2.0);
  const auto result = gripper.goal_port().result(close.id);
  ASSERT_TRUE(result.has_value());
  const double stalled_gap = gap_of(*sim);
  ASSERT_TRUE(sim->run_for(1.0));  // keeps squeezing
  std::vector<physics::Contact> contacts;
  sim->physics().contacts(contacts);
  double squeeze = 0.0;
  int finger_contacts = 0;
  for (const physics::Contact& c : contacts) {
    const std::string a(c.link_a), b(c.link_b);
    const std::string other = a == "box:block" ? b : b == "box:block" ? a : "";
    if (other.find("r_gripper_") == 0 && other.find("finger") != std::string::npos) {
      squeeze += c.normal_force;
      ++finger_contacts;
    }
  }
  const auto state = gripper.goal_port().feedback().state;
  std::cout << "[ figures  ] gripper on a 0.04 m box: stalled after " << took << " s at gap " << stalled_gap
            << " m (result: stalled " << result->stalled << ", effort " << result->effort << " N); 1 s later gap "
            << gap_of(*sim) << " m, effort " << state.effort << " N, " << finger_contacts
            << " finger contacts, normal force sum " << squeeze << " N\n";
  EXPECT_EQ(gripper.goal_port().status(close.id), control::GoalStatus::Aborted);
  EXPECT_TRUE(result->stalled);
  EXPECT_FALSE(result->reached_goal);
  EXPECT_LT(took, 1.5);
  EXPECT_NEAR(stalled_gap, 0.04, 0.006);  // the box's width (pads are compliant)
  EXPECT_NEAR(gap_of(*sim), stalled_gap, 0.002);
  EXPECT_NEAR(state.effort, -kMaxEffort, 1e-6);  // still squeezing at max_effort
  EXPECT_GE(finger_contacts, 2);
  EXPECT_GT(squeeze, 10.0);

  // The fingertip pressure pads (pr2_msgs/PressureState's values) from the fingertip contact
  // sensors: the box presses on the front arrays of both fingertips, carrying the squeeze (the
  // raw readings saturate: MuJoCo's one contact point per fingertip loads one element).
  double front_newtons = 0.0, other_newtons = 0.0;
  for (const auto& [name, finger] : {std::pair{"r_gripper_l_finger_tip_contact_sensor", sensors::Fingertip::Left},
                                     std::pair{"r_gripper_r_finger_tip_contact_sensor", sensors::Fingertip::Right}}) {
    const auto index = sim->sensors().find(name);
    ASSERT_TRUE(index) << name;
    const auto* reading = std::get_if<sensors::ContactsReading>(&sim->sensors().reading(*index).value);
    ASSERT_NE(reading, nullptr) << name;
    const auto pads = sensors::fingertip_pad_forces(*reading, finger);
    double front = 0.0;
    for (int k = 0; k < sensors::kFingertipPressureElements; ++k) {
      (k >= 7 ? front : other_newtons) += pads[static_cast<std::size_t>(k)];
    }
    const auto raw = sensors::fingertip_pressure(*reading, finger);
    std::cout << "[ figures  ] " << name << " raw pads:";
    for (const auto v : raw) std::cout << " " << v;
    std::cout << " (front array " << front << " N)\n";
    EXPECT_GT(front, 5.0) << name;
    front_newtons += front;
  }
  EXPECT_NEAR(front_newtons, squeeze, 0.35 * squeeze);  // the pads see the squeeze (mesh and pads differ)
  EXPECT_LT(other_newtons, 0.1 * front_newtons);
}

}  // namespace
}  // namespace mechsim::sim
