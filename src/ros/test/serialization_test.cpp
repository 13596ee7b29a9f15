// The generated headers must put messages on the wire exactly as ROS 1 does: serialize,
// deserialize and compare, check sizes against the wire format (little-endian, uint32 length
// before strings and variable arrays), and reject truncated input.

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include <control_msgs/FollowJointTrajectoryGoal.h>
#include <control_msgs/JointControllerState.h>
#include <controller_manager_msgs/ListControllers.h>
#include <controller_manager_msgs/LoadController.h>
#include <ros/serialization.h>

namespace mechsim::ros {
namespace {

namespace ser = ::ros::serialization;

template <typename M>
std::vector<std::uint8_t> toWire(const M& msg) {
  std::vector<std::uint8_t> buffer(ser::serializationLength(msg));
  ser::OStream out(buffer.data(), static_cast<std::uint32_t>(buffer.size()));
  ser::serialize(out, msg);
  EXPECT_EQ(out.getLength(), 0u) << "serialize() did not fill the buffer it sized";
  return buffer;
}

template <typename M>
M fromWire(std::vector<std::uint8_t>& buffer) {
  M msg;
  ser::IStream in(buffer.data(), static_cast<std::uint32_t>(buffer.size()));
  ser::deserialize(in, msg);
  EXPECT_EQ(in.getLength(), 0u) << "deserialize() left bytes unread";
  return msg;
}

controller_manager_msgs::ListControllersResponse sampleListControllers() {
  controller_manager_msgs::ListControllersResponse res;
  controller_manager_msgs::ControllerState jsc;
  jsc.name = "joint_state_controller";
  jsc.state = "running";
  jsc.type = "joint_state_controller/JointStateController";
  controller_manager_msgs::ControllerState arm;
  arm.name = "r_arm_controller";
  arm.state = "stopped";
  arm.type = "effort_controllers/JointTrajectoryController";
  controller_manager_msgs::HardwareInterfaceResources claimed;
  claimed.hardware_interface = "hardware_interface::EffortJointInterface";
  claimed.resources = {"r_shoulder_pan_joint", "r_shoulder_lift_joint"};
  arm.claimed_resources.push_back(claimed);
  res.controller = {jsc, arm};
  return res;
}

TEST(RosSerialization, ListControllersResponseRoundTrips) {
  const auto res = sampleListControllers();
  auto wire = toWire(res);
  // 4 (array length) + jsc: 3 strings + 4 (empty array) + arm: 3 strings + 4 (array length) +
  // resources entry: 1 string + 4 (array length) + 2 strings; each string is 4 + its length.
  const auto str = [](const std::string& s) { return 4u + s.size(); };
  const auto& jsc = res.controller[0];
  const auto& arm = res.controller[1];
  const auto& claimed = arm.claimed_resources[0];
  const std::size_t expected = 4 + str(jsc.name) + str(jsc.state) + str(jsc.type) + 4 +
                               str(arm.name) + str(arm.state) + str(arm.type) + 4 +
                               str(claimed.hardware_interface) + 4 +
                               str(claimed.resources[0]) + str(claimed.resources[1]);
  EXPECT_EQ(wire.size(), expected);
  EXPECT_EQ(fromWire<controller_manager_msgs::ListControllersResponse>(wire), res);
}

TEST(RosSerialization, JointControllerStateRoundTrips) {
  control_msgs::JointControllerState state;
  state.header.seq = 7;
  state.header.stamp = ::ros::Time(12, 500000000);
  state.header.frame_id = "base_link";
  state.set_point = 0.5;
  state.process_value = 0.49;
  state.process_value_dot = -0.01;
  state.error = 0.01;
  state.time_step = 0.001;
  state.command = 3.25;
  state.p = 100.0;
  state.i = 2.0;
  state.d = 0.5;
  state.i_clamp = 10.0;
  state.antiwindup = true;
  auto wire = toWire(state);
  // header: seq 4 + stamp 8 + frame_id 4+9; ten float64; one bool byte.
  EXPECT_EQ(wire.size(), 4u + 8u + 4u + 9u + 10u * 8u + 1u);
  const auto back = fromWire<control_msgs::JointControllerState>(wire);
  EXPECT_EQ(back, state);
  EXPECT_EQ(back.header.stamp.nsec, 500000000u);
  EXPECT_TRUE(back.antiwindup);
}

TEST(RosSerialization, FollowJointTrajectoryGoalRoundTrips) {
  control_msgs::FollowJointTrajectoryGoal goal;
  goal.trajectory.header.frame_id = "torso_lift_link";
  goal.trajectory.joint_names = {"r_shoulder_pan_joint", "r_elbow_flex_joint"};
  for (int k = 1; k <= 3; ++k) {
    trajectory_msgs::JointTrajectoryPoint p;
    p.positions = {0.1 * k, -0.2 * k};
    p.velocities = {0.0, 0.0};
    p.time_from_start = ::ros::Duration(0.5 * k);
    goal.trajectory.points.push_back(p);
  }
  control_msgs::JointTolerance tol;
  tol.name = "r_elbow_flex_joint";
  tol.position = 0.05;
  tol.velocity = -1.0;
  goal.path_tolerance = {tol};
  goal.goal_tolerance = {tol, tol};
  goal.goal_time_tolerance = ::ros::Duration(0, 250000000);
  auto wire = toWire(goal);
  const auto back = fromWire<control_msgs::FollowJointTrajectoryGoal>(wire);
  EXPECT_EQ(back, goal);
  ASSERT_EQ(back.trajectory.points.size(), 3u);
  EXPECT_EQ(back.trajectory.points[2].time_from_start, ::ros::Duration(1.5));
  EXPECT_EQ(back.goal_time_tolerance.nsec, 250000000);

  // A message cut short must be refused, not read past its end.
  wire.resize(wire.size() - 3);
  control_msgs::FollowJointTrajectoryGoal truncated;
  ser::IStream in(wire.data(), static_cast<std::uint32_t>(wire.size()));
  EXPECT_THROW(ser::deserialize(in, truncated), ser::StreamOverrunException);
}

TEST(RosSerialization, StringIsLengthPrefixedLittleEndian) {
  controller_manager_msgs::LoadControllerRequest req;
  req.name = "abc";
  const auto wire = toWire(req);
  const std::vector<std::uint8_t> expected = {3, 0, 0, 0, 'a', 'b', 'c'};
  EXPECT_EQ(wire, expected);
}

}  // namespace
}  // namespace mechsim::ros
