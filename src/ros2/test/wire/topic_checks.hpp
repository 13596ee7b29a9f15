#pragma once
// What a peer must have received and decoded from `mechsim ros2` on the test robot
// (../data/ros2bot.urdf.xacro), whichever peer it is: the Cyclone, Fast DDS and @foxglove/ros2
// peers print the same JSON (../peers/*).

#include <cmath>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "wire_util.hpp"

namespace mechsim::ros2::test {

// The peer's --sub arguments: every topic of the test robot.
inline std::vector<std::string> ros2bot_subscriptions() {
  return {"--sub", "/tf=tf", "--sub", "/tf_static=tf_static", "--sub", "/ros2bot/joint_states=joint_state",
          "--sub", "/ros2bot/scan=laser", "--sub", "/ros2bot/front_camera/image_raw=image",
          "--sub", "/ros2bot/front_camera/camera_info=camera_info", "--sub", "/robot_description=string",
          "--sub", "/ros2bot/diff_drive_controller/odom=odometry", "--sub", "/ros2bot/imu=imu",
          "--sub", "/clock=clock"};
}

inline void expect_ros2bot_topics(const std::vector<nlohmann::json>& lines) {

  // /tf_static: every fixed joint in one message (transient local: the peer came after it).
  const auto tf_static = summary(lines, "/tf_static");
  ASSERT_FALSE(tf_static.is_null());
  EXPECT_EQ(tf_static["count"], 1);
  std::vector<std::string> children;
  for (const auto& t : tf_static["last"]["transforms"]) children.push_back(t["child"]);
  EXPECT_THAT(children, ::testing::UnorderedElementsAre("base_link", "front_caster_link", "rear_caster_link",
                                                        "laser_link", "camera_link"));
  // /tf: the moving joints (20 Hz), and the diff drive's odom -> base_footprint.
  const auto tf = summary(lines, "/tf");
  ASSERT_FALSE(tf.is_null());
  EXPECT_GT(tf["count"].get<int>(), 40);
  // Both kinds of /tf message went by (robot_state_publisher's and the odometry's go out apart).
  EXPECT_THAT(tf["children"].get<std::vector<std::string>>(),
              ::testing::IsSupersetOf({"mast_link", "left_wheel_link", "right_wheel_link", "base_footprint"}))
      << tf;

  const auto js = summary(lines, "/ros2bot/joint_states");
  ASSERT_FALSE(js.is_null());
  EXPECT_THAT(js["last"]["name"].get<std::vector<std::string>>(),
              ::testing::IsSupersetOf({"left_wheel_joint", "right_wheel_joint", "pan_joint"}));
  EXPECT_GT(js["count"].get<int>(), 100);  // 50 Hz: 4 s of the peers' 6 (discovery takes the rest)

  // The laser looks 0.35 rad down from ~0.30 m: the ground ~0.87 m ahead, farther to the sides.
  const auto scan = summary(lines, "/ros2bot/scan");
  ASSERT_FALSE(scan.is_null());
  const auto& s = scan["last"];
  EXPECT_EQ(s["frame_id"], "laser_link");
  EXPECT_EQ(s["ranges"], 181);
  EXPECT_NEAR(s["angle_min"].get<double>(), -1.5708, 1e-4);
  EXPECT_GT(s["finite"].get<int>(), 100);
  EXPECT_NEAR(s["nearest"].get<double>(), 0.87, 0.1);
  EXPECT_GT(scan["count"].get<int>(), 40);  // 20 Hz

  const auto image = summary(lines, "/ros2bot/front_camera/image_raw");
  ASSERT_FALSE(image.is_null());
  EXPECT_EQ(image["last"]["width"], 64);
  EXPECT_EQ(image["last"]["height"], 48);
  EXPECT_EQ(image["last"]["encoding"], "rgb8");
  EXPECT_EQ(image["last"]["bytes"], 64 * 48 * 3);
  EXPECT_GT(image["last"]["mean"].get<double>(), 5.0);  // something was rendered
  EXPECT_EQ(image["last"]["frame_id"], "camera_link");
  const auto info = summary(lines, "/ros2bot/front_camera/camera_info");
  ASSERT_FALSE(info.is_null());
  EXPECT_EQ(info["last"]["width"], 64);
  EXPECT_NEAR(info["last"]["k"][0].get<double>(), 32.0 / std::tan(0.6), 0.5);  // fx from the 1.2 rad FOV

  const auto description = summary(lines, "/robot_description");
  ASSERT_FALSE(description.is_null());
  EXPECT_GT(description["last"]["length"].get<int>(), 2000);
  EXPECT_NE(description["last"]["head"].get<std::string>().find("<"), std::string::npos);

  const auto odometry = summary(lines, "/ros2bot/diff_drive_controller/odom");
  ASSERT_FALSE(odometry.is_null());
  EXPECT_EQ(odometry["last"]["frame_id"], "odom");
  EXPECT_EQ(odometry["last"]["child_frame_id"], "base_footprint");

  const auto imu = summary(lines, "/ros2bot/imu");
  ASSERT_FALSE(imu.is_null());
  EXPECT_EQ(imu["last"]["frame_id"], "base_link");
  EXPECT_NEAR(imu["last"]["linear_acceleration"][2].get<double>(), 9.81, 0.3);

  const auto clock = summary(lines, "/clock");
  ASSERT_FALSE(clock.is_null());
  EXPECT_GT(clock["count"].get<int>(), 100);
}

}  // namespace mechsim::ros2::test
