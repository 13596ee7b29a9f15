// ROS 2 name resolution and rmw's DDS mangling.
#include <gtest/gtest.h>

#include "ros2/names.hpp"

namespace mechsim::ros2 {
namespace {

TEST(Names, ExpandsAsRcl) {
  EXPECT_EQ(expand_topic("/clock", "/cc8", "gazebo"), "/clock");
  EXPECT_EQ(expand_topic("joint_states", "/cc8", "joint_state_broadcaster"), "/cc8/joint_states");
  EXPECT_EQ(expand_topic("~/odom", "/cc8", "diff_drive_controller"), "/cc8/diff_drive_controller/odom");
  EXPECT_EQ(expand_topic("~/odom", "/", "diff_drive_controller"), "/diff_drive_controller/odom");
  EXPECT_EQ(expand_topic("scan", "/", "laser"), "/scan");
  EXPECT_EQ(normalize_namespace("cc8/"), "/cc8");
  EXPECT_EQ(normalize_namespace(""), "/");
}

TEST(Names, RemapsMatchExpandedNames) {
  const std::vector<Remap> remaps{parse_remap("~/out:=scan"), parse_remap("/old:=/new")};
  EXPECT_EQ(resolve_topic("~/out", "/ros2bot", "laser_plugin", remaps), "/ros2bot/scan");
  EXPECT_EQ(resolve_topic("/ros2bot/laser_plugin/out", "/ros2bot", "laser_plugin", remaps), "/ros2bot/scan");
  EXPECT_EQ(resolve_topic("old", "/", "n", remaps), "/new");
  EXPECT_EQ(resolve_topic("other", "/x", "n", remaps), "/x/other");
  EXPECT_THROW(parse_remap("no_rule"), NameError);
}

TEST(Names, RefusesWhatRclRefuses) {
  EXPECT_THROW(expand_topic("a//b", "/", "n"), NameError);
  EXPECT_THROW(expand_topic("a b", "/", "n"), NameError);
  EXPECT_THROW(expand_topic("1abc", "/", "n"), NameError);
  EXPECT_THROW(expand_topic("~abc", "/", "n"), NameError);
  EXPECT_THROW(expand_topic("abc/", "/", "n"), NameError);
  EXPECT_THROW(check_node_name("my-node"), NameError);
  EXPECT_THROW(check_node_name(""), NameError);
  try {
    expand_topic("bad name", "/ns", "n");
    FAIL();
  } catch (const NameError& e) {
    EXPECT_NE(std::string(e.what()).find("/ns/bad name"), std::string::npos) << e.what();
  }
}

TEST(Names, DdsManglingIsRmws) {
  EXPECT_EQ(dds_topic("/chatter"), "rt/chatter");
  EXPECT_EQ(dds_request_topic("/add_two_ints"), "rq/add_two_intsRequest");
  EXPECT_EQ(dds_reply_topic("/add_two_ints"), "rr/add_two_intsReply");
  EXPECT_EQ(ros_topic_of("rt/cc8/odom"), "/cc8/odom");
  EXPECT_EQ(ros_topic_of("rq/spawn_entityRequest"), "/spawn_entity");
  EXPECT_EQ(ros_topic_of("ros_discovery_info"), "");
}

}  // namespace
}  // namespace mechsim::ros2
