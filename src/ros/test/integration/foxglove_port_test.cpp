// ~foxglove_port: the node serves the Foxglove WebSocket protocol beside its ROS topics (a
// loopback client, live/test/foxglove_test_client.hpp, on the port the node logs).
#include <gmock/gmock.h>

#include <regex>

#include <nlohmann/json.hpp>

#include "live/test/foxglove_test_client.hpp"
#include "ros_fixture.hpp"

namespace mechsim::ros::test {
namespace {

class FoxglovePort : public CC8Node {
 protected:
  std::vector<std::string> extra_node_args() const override { return {"_foxglove_port:=0"}; }
};

TEST_F(FoxglovePort, NodeStreamsTfJointStatesAndTheDescription) {
  std::smatch m;
  std::string log;
  const std::regex line("live view on ws://127\\.0\\.0\\.1:([0-9]+)");
  ASSERT_TRUE(wait_until([&] {
    log = node_->log();
    return std::regex_search(log, m, line);
  }, 10.0)) << log;
  live::test::FoxgloveTestClient client(static_cast<unsigned short>(std::stoi(m[1])));
  for (const char* topic : {"/tf", "/joint_states", "/robot_description"}) {
    EXPECT_EQ(client.channels().count(topic), 1u) << topic;
  }
  // The node's controllers come later from spawners (and may go): its live view has no /odom.
  EXPECT_EQ(client.channels().count("/odom"), 0u);
  client.subscribe({"/tf", "/joint_states", "/robot_description"});
  const std::vector<live::test::ReceivedMessage> got = client.read_for(1.5);
  std::map<std::string, std::size_t> count;
  for (const auto& message : got) {
    ++count[message.topic];
    const nlohmann::json j = nlohmann::json::parse(message.payload);
    if (message.topic == "/robot_description") {
      EXPECT_NE(j.at("data").get<std::string>().find("<robot"), std::string::npos);
    }
    if (message.topic == "/tf") {
      EXPECT_EQ(j.at("transforms").at(0).at("parent_frame_id"), "world");
    }
  }
  EXPECT_EQ(count["/robot_description"], 1u);
  // 30 Hz of simulated time at the fixture's real-time pace: about 45 in 1.5 s.
  EXPECT_GT(count["/tf"], 25u);
  EXPECT_GT(count["/joint_states"], 25u);
}

}  // namespace
}  // namespace mechsim::ros::test
