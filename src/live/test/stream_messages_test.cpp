#include "live/stream_messages.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace mechsim::live {
namespace {

constexpr double kHalfTurn = 3.141592653589793;

// base (root) turned 90 degrees about z at (1, 0, 0); arm, its child, at (1, 1, 0.5) in the world
// turned the same way: in base's frame the arm is 1 m along x (base's x points along world y).
StreamLayout two_links() {
  StreamLayout layout;
  layout.links = {"base", "arm"};
  layout.physics_link = {0, 1};
  layout.parent = {static_cast<std::size_t>(-1), 0};
  layout.joints = {"shoulder", "rocker"};
  layout.mechanism_joints = 1;
  layout.physics_joint = {3};
  LaserLayout laser;
  laser.name = "front";
  laser.topic = "/scan/front";
  laser.link = "arm";
  laser.angle_min = -1.0;
  laser.angle_max = 1.0;
  laser.rays = 3;
  laser.X_LS.position = {0.1, 0.0, 0.2};
  layout.lasers.push_back(laser);
  layout.waypoints = {{{5.0, 0.0}}, {{10.0, 3.0}}};
  return layout;
}

Snapshot state(const StreamLayout& layout) {
  Snapshot s = make_snapshot(layout);
  s.time = 2.25;
  const description::Quat yaw90{std::cos(kHalfTurn / 4), 0.0, 0.0, std::sin(kHalfTurn / 4)};
  s.X_WL[0].position = {1.0, 0.0, 0.0};
  s.X_WL[0].orientation = yaw90;
  s.X_WL[1].position = {1.0, 1.0, 0.5};
  s.X_WL[1].orientation = yaw90;
  s.position = {0.5, -0.25};
  s.velocity = {1.5, 0.0};
  s.effort = {3.0, 0.0};
  s.lasers[0].count = 4;
  s.lasers[0].stamp = 2.2;
  s.lasers[0].ranges = {1.5f, std::numeric_limits<float>::infinity(), 2.5f};
  return s;
}

TEST(StreamMessages, FrameTransformsGoFromTheWorldToTheRootThenParentToChild) {
  const StreamLayout layout = two_links();
  std::string text;
  encode_frame_transforms(layout, state(layout), text);
  const nlohmann::json j = nlohmann::json::parse(text);
  ASSERT_EQ(j["transforms"].size(), 2u);
  const nlohmann::json& root = j["transforms"][0];
  EXPECT_EQ(root["parent_frame_id"], "world");
  EXPECT_EQ(root["child_frame_id"], "base");
  EXPECT_EQ(root["timestamp"]["sec"], 2);
  EXPECT_EQ(root["timestamp"]["nsec"], 250000000);
  EXPECT_DOUBLE_EQ(root["translation"]["x"].get<double>(), 1.0);
  EXPECT_NEAR(root["rotation"]["z"].get<double>(), std::sin(kHalfTurn / 4), 1e-12);
  const nlohmann::json& arm = j["transforms"][1];
  EXPECT_EQ(arm["parent_frame_id"], "base");
  EXPECT_EQ(arm["child_frame_id"], "arm");
  EXPECT_NEAR(arm["translation"]["x"].get<double>(), 1.0, 1e-12);
  EXPECT_NEAR(arm["translation"]["y"].get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(arm["translation"]["z"].get<double>(), 0.5, 1e-12);
  EXPECT_NEAR(arm["rotation"]["w"].get<double>(), 1.0, 1e-12);  // same orientation as its parent
}

TEST(StreamMessages, JointStatesNameEveryJointWithItsState) {
  const StreamLayout layout = two_links();
  std::string text;
  encode_joint_states(layout, state(layout), text);
  const nlohmann::json j = nlohmann::json::parse(text);
  EXPECT_EQ(j["name"], nlohmann::json::array({"shoulder", "rocker"}));
  EXPECT_EQ(j["position"], nlohmann::json::array({0.5, -0.25}));
  EXPECT_EQ(j["velocity"][0], 1.5);
  EXPECT_EQ(j["effort"][0], 3.0);
  EXPECT_EQ(j["header"]["stamp"]["sec"], 2);
}

TEST(StreamMessages, LaserScanIsInItsLinksFrameAndNonFiniteRangesAreNull) {
  const StreamLayout layout = two_links();
  std::string text;
  encode_laser_scan(layout, 0, state(layout), text);
  const nlohmann::json j = nlohmann::json::parse(text);
  EXPECT_EQ(j["frame_id"], "arm");
  EXPECT_EQ(j["pose"]["position"]["z"], 0.2);
  EXPECT_EQ(j["start_angle"], -1.0);
  EXPECT_EQ(j["end_angle"], 1.0);
  ASSERT_EQ(j["ranges"].size(), 3u);
  EXPECT_EQ(j["ranges"][0], 1.5);
  EXPECT_TRUE(j["ranges"][1].is_null());
  EXPECT_EQ(j["timestamp"]["nsec"], 200000000);
}

TEST(StreamMessages, OdometryDescriptionAndMarkers) {
  StreamLayout layout = two_links();
  Snapshot s = state(layout);
  s.odom_x = 3.0;
  s.odom_orientation = {1.0, 0.0, 0.0, 0.0};
  std::string text;
  encode_odometry(layout, s, text);
  const nlohmann::json odom = nlohmann::json::parse(text);
  EXPECT_EQ(odom["header"]["frame_id"], "odom");
  EXPECT_EQ(odom["child_frame_id"], "base_link");
  EXPECT_EQ(odom["pose"]["pose"]["position"]["x"], 3.0);
  EXPECT_EQ(odom["pose"]["covariance"].size(), 36u);
  EXPECT_EQ(nlohmann::json::parse(encode_robot_description("<robot name=\"r\"/>"))["data"], "<robot name=\"r\"/>");
  const nlohmann::json markers = nlohmann::json::parse(encode_waypoint_markers(layout, 0.0));
  const nlohmann::json& entity = markers["entities"][0];
  EXPECT_EQ(entity["frame_id"], "world");
  ASSERT_EQ(entity["spheres"].size(), 2u);
  EXPECT_EQ(entity["spheres"][1]["pose"]["position"]["x"], 10.0);
  EXPECT_EQ(entity["lines"][0]["points"].size(), 2u);
}

TEST(StreamMessages, SchemasAreJsonSchemaObjects) {
  for (const std::string* schema : {&frame_transforms_schema(), &joint_state_schema(), &odometry_schema(),
                                    &laser_scan_schema(), &string_schema(), &scene_update_schema()}) {
    const nlohmann::json j = nlohmann::json::parse(*schema);
    EXPECT_EQ(j["type"], "object");
    EXPECT_TRUE(j["properties"].is_object());
  }
  EXPECT_TRUE(nlohmann::json::parse(frame_transforms_schema())["properties"]["transforms"]["items"]["properties"].contains(
      "parent_frame_id"));
}

}  // namespace
}  // namespace mechsim::live
