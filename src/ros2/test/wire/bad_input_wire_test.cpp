// Bad input never stops the world: a malformed sample, a peer's endpoint of another type on one of
// mechsim's topics, a QoS that cannot match, a peer that leaves; each is a log line naming the
// topic, and the simulation goes on (its clock advances, its controllers take good commands).
#include <cstring>
#include <thread>

#include <mechsim_ros2_msgs/std_msgs.hpp>

#include "ros2/node.hpp"
#include "wire_fixture.hpp"

namespace mechsim::ros2::test {
namespace {

TEST_F(WireTest, BadInputIsLoggedAndTheWorldGoesOn) {
  auto args = ros2bot_args();
  args.insert(args.end(), {"--real-time-factor", "1"});
  Process& mechsim = start_mechsim(args);

  // A malformed Float64MultiArray: a length field claiming 2^31 dimensions in a 12-byte sample,
  // written by a DDS writer of the right topic and type name (this test's own participant).
  {
    ParticipantOptions o;
    o.domain_id = std::stoi(kDomain);
    o.log = [](const std::string&) {};
    Participant p(o);
    const int node = p.add_node("/", "vandal");
    EndpointSpec spec;
    spec.dds_topic = "rt/ros2bot/mast_controller/commands";
    spec.ros_topic = "/ros2bot/mast_controller/commands";
    spec.type_name = MessageTraits<std_msgs::msg::Float64MultiArray>::dds_name;
    spec.qos = Qos::defaults();
    auto writer = p.create_writer(node, spec);
    static const std::uint8_t garbage[] = {0, 1, 0, 0, 0, 0, 0, 0x80, 1, 2, 3, 4};
    OutMessage bad{garbage, [](const void*) -> std::size_t { return sizeof garbage; },
                   [](const void*, char* buffer, std::size_t capacity) -> std::size_t {
                     const std::size_t n = std::min(capacity, sizeof garbage);
                     std::memcpy(buffer, garbage, n);
                     return n;
                   }};
    for (int i = 0; i < 40 && !mechsim.wait_for_output("malformed", std::chrono::milliseconds(100)); ++i) writer->write(bad);
  }
  EXPECT_TRUE(mechsim.wait_for_output("/ros2bot/mast_controller/commands: malformed std_msgs/msg/Float64MultiArray sample",
                                      std::chrono::seconds(5)))
      << mechsim.output();

  // Another type on a command topic; a subscription asking /tf for transient local (mechsim's /tf
  // is volatile, as tf2_ros' broadcaster): neither matches, both are said.
  run_cyclone("jazzy", {"--seconds", "2", "--pub", "/ros2bot/diff_drive_controller/cmd_vel=string:hello", "--sub", "/tf=tf:tl"},
              "mismatch");
  EXPECT_TRUE(mechsim.wait_for_output("uses type std_msgs::msg::dds_::String_, mechsim's is geometry_msgs::msg::dds_::TwistStamped_",
                                      std::chrono::seconds(5)))
      << mechsim.output();
  EXPECT_TRUE(mechsim.wait_for_output("/tf: a subscriber asks for a durability", std::chrono::seconds(5))) << mechsim.output();
  // The peer has left: said, naming the participant.
  EXPECT_TRUE(mechsim.wait_for_output("left", std::chrono::seconds(5))) << mechsim.output();

  // The world goes on: its clock advances and a good command still moves the mast.
  const auto lines = run_cyclone("jazzy", {"--seconds", "3", "--pub", "/ros2bot/mast_controller/commands=float64_array:0.5",
                                           "--sub", "/ros2bot/joint_states=joint_state", "--sub", "/clock=clock"},
                                 "after");
  const std::string log = stop_mechsim();
  const auto clock = summary(lines, "/clock");
  ASSERT_FALSE(clock.is_null());
  EXPECT_GT(clock["count"].get<int>(), 100);
  const auto js = summary(lines, "/ros2bot/joint_states")["last"];
  const auto names = js["name"].get<std::vector<std::string>>();
  const auto it = std::find(names.begin(), names.end(), "pan_joint");
  ASSERT_NE(it, names.end());
  EXPECT_NEAR(js["position"][it - names.begin()].get<double>(), 0.5, 0.03) << log;
}

}  // namespace
}  // namespace mechsim::ros2::test
