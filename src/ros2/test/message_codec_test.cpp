// The generated message code: byte layout as XCDR1 puts it on the wire, round trips, and
// malformed samples refused with a reason, never a crash or an allocation beyond the sample.
#include <cstring>
#include <random>

#include <gtest/gtest.h>

#include <mechsim_ros2_msgs/humble/rmw_dds_common.hpp>
#include <mechsim_ros2_msgs/jazzy/rmw_dds_common.hpp>
#include <mechsim_ros2_msgs/rosgraph_msgs.hpp>
#include <mechsim_ros2_msgs/sensor_msgs.hpp>
#include <mechsim_ros2_msgs/std_msgs.hpp>
#include <mechsim_ros2_msgs/tf2_msgs.hpp>
#include <mechsim_ros2_msgs/trajectory_msgs.hpp>

#include "ros2/message_codec.hpp"

namespace mechsim::ros2 {
namespace {

using Bytes = std::vector<std::uint8_t>;

TEST(MessageCodec, ClockIsEncapsulationThenTwoLittleEndianWords) {
  rosgraph_msgs::msg::Clock c;
  c.clock.sec = 1;
  c.clock.nanosec = 500000000;
  // 00 01: CDR little endian, then 2 option bytes; sec, nanosec (0x1dcd6500).
  EXPECT_EQ(serialize(c), (Bytes{0x00, 0x01, 0x00, 0x00, 0x01, 0, 0, 0, 0x00, 0x65, 0xcd, 0x1d}));
}

TEST(MessageCodec, StringCountsItsNulAndDoublesAlignToEightAfterTheHeader) {
  std_msgs::msg::String s;
  s.data = "hi";
  EXPECT_EQ(serialize(s), (Bytes{0, 1, 0, 0, 3, 0, 0, 0, 'h', 'i', 0}));
  // A string then a float64: the double starts at body offset 16 (aligned from the byte after
  // the encapsulation header), after 3 bytes of padding.
  trajectory_msgs::msg::JointTrajectoryPoint p;
  p.positions = {1.0};
  const Bytes b = serialize(p);
  // positions: length at body 0, padding to 8, the double at body 8 (bytes 12..19).
  ASSERT_GE(b.size(), 20u);
  EXPECT_EQ(b[4], 1);
  double v = 0;
  std::memcpy(&v, b.data() + 12, 8);
  EXPECT_EQ(v, 1.0);
  EXPECT_EQ(b.size(), serialized_size(p));
}

TEST(MessageCodec, EmptyMessageHasRosidlsOneByteMember) {
  // rosidl gives a message without fields `uint8 structure_needs_at_least_one_member`.
  EXPECT_EQ(serialize(std_msgs::msg::Empty{}), (Bytes{0, 1, 0, 0, 0}));
}

TEST(MessageCodec, RoundTripsNestedSequencesAndArrays) {
  tf2_msgs::msg::TFMessage tf;
  for (int i = 0; i < 3; ++i) {
    auto& t = tf.transforms.emplace_back();
    t.header.stamp.sec = i;
    t.header.frame_id = "base_link";
    t.child_frame_id = "wheel_" + std::to_string(i);
    t.transform.translation.x = 0.1 * i;
    t.transform.rotation.z = 0.5;
  }
  tf2_msgs::msg::TFMessage back;
  std::string error;
  const Bytes b = serialize(tf);
  EXPECT_EQ(b.size(), serialized_size(tf));
  ASSERT_TRUE(deserialize(b.data(), b.size(), back, &error)) << error;
  EXPECT_EQ(back, tf);

  sensor_msgs::msg::CameraInfo info;
  info.distortion_model = "plumb_bob";
  info.d = {0.1, -0.2, 0, 0, 0.01};
  info.k = {500, 0, 320, 0, 500, 240, 0, 0, 1};
  info.roi.do_rectify = true;
  sensor_msgs::msg::CameraInfo info_back;
  const Bytes ib = serialize(info);
  ASSERT_TRUE(deserialize(ib.data(), ib.size(), info_back, &error)) << error;
  EXPECT_EQ(info_back, info);
  // The geometry default of rosidl: a quaternion is the identity.
  EXPECT_EQ(geometry_msgs::msg::Quaternion{}.w, 1.0);
}

TEST(MessageCodec, GraphMessageGidIsTwentyFourBytesInHumbleSixteenInJazzy) {
  humble::rmw_dds_common::msg::ParticipantEntitiesInfo h;
  jazzy::rmw_dds_common::msg::ParticipantEntitiesInfo j;
  EXPECT_EQ(serialize(h).size(), 4u + 24 + 4);
  EXPECT_EQ(serialize(j).size(), 4u + 16 + 4);
  auto& node = j.node_entities_info_seq.emplace_back();
  node.node_namespace = "/";
  node.node_name = "gazebo";
  node.writer_gid_seq.resize(2);
  jazzy::rmw_dds_common::msg::ParticipantEntitiesInfo back;
  std::string error;
  const Bytes b = serialize(j);
  ASSERT_TRUE(deserialize(b.data(), b.size(), back, &error)) << error;
  EXPECT_EQ(back, j);
}

TEST(MessageCodec, BigEndianSamplesAreRead) {
  // Encapsulation 00 00 (CDR big endian): a peer may write it.
  const Bytes b{0x00, 0x00, 0x00, 0x00, 0, 0, 0, 2, 0x1d, 0xcd, 0x65, 0x00};
  rosgraph_msgs::msg::Clock c;
  std::string error;
  ASSERT_TRUE(deserialize(b.data(), b.size(), c, &error)) << error;
  EXPECT_EQ(c.clock.sec, 2);
  EXPECT_EQ(c.clock.nanosec, 500000000u);
}

TEST(MessageCodec, MalformedSamplesAreRefusedWithAReason) {
  std::string error;
  sensor_msgs::msg::JointState js;
  // Too short for the header.
  const Bytes shorty{0, 1};
  EXPECT_FALSE(deserialize(shorty.data(), shorty.size(), js, &error));
  EXPECT_NE(error.find("encapsulation"), std::string::npos) << error;
  // XCDR2 (00 07: PL_CDR2_LE) is not a final ROS 2 type.
  const Bytes xcdr2{0, 7, 0, 0, 0, 0, 0, 0};
  EXPECT_FALSE(deserialize(xcdr2.data(), xcdr2.size(), js, &error));
  EXPECT_NE(error.find("not plain CDR"), std::string::npos) << error;
  // A sequence of 2^31 names in a 40-byte sample: refused before anything is allocated.
  sensor_msgs::msg::JointState good;
  good.header.frame_id = "x";
  Bytes b = serialize(good);
  // name's length follows the header (stamp 8 bytes, frame_id "x" 4+2 bytes, pad to 4).
  const std::size_t at = 4 + 8 + 4 + 2 + 2;
  ASSERT_LT(at + 4, b.size());
  b[at] = 0;
  b[at + 1] = 0;
  b[at + 2] = 0;
  b[at + 3] = 0x80;
  error.clear();
  EXPECT_FALSE(deserialize(b.data(), b.size(), js, &error));
  EXPECT_NE(error.find("cannot fit"), std::string::npos) << error;
  // Truncated in the middle of a double.
  trajectory_msgs::msg::JointTrajectoryPoint p;
  p.positions = {1, 2, 3};
  Bytes t = serialize(p);
  t.resize(t.size() - 30);
  EXPECT_FALSE(deserialize(t.data(), t.size(), p, &error));
  // A bool that is neither 0 nor 1.
  std_msgs::msg::Bool flag;
  const Bytes bad_bool{0, 1, 0, 0, 7};
  EXPECT_FALSE(deserialize(bad_bool.data(), bad_bool.size(), flag, &error));
}

TEST(MessageCodec, RandomBytesNeverCrashOrOverAllocate) {
  std::mt19937 rng(42);
  std::uniform_int_distribution<int> byte(0, 255);
  int accepted = 0;
  for (int round = 0; round < 3000; ++round) {
    Bytes b(4 + static_cast<std::size_t>(rng() % 200));
    for (auto& x : b) x = static_cast<std::uint8_t>(byte(rng));
    b[0] = 0;
    b[1] = 1;
    tf2_msgs::msg::TFMessage tf;
    trajectory_msgs::msg::JointTrajectory jt;
    sensor_msgs::msg::PointCloud2 pc;
    std::string error;
    accepted += deserialize(b.data(), b.size(), tf, &error) ? 1 : 0;
    accepted += deserialize(b.data(), b.size(), jt, &error) ? 1 : 0;
    accepted += deserialize(b.data(), b.size(), pc, &error) ? 1 : 0;
    // Whatever was accepted holds no more elements than the sample has bytes.
    EXPECT_LE(tf.transforms.size(), b.size());
    EXPECT_LE(jt.points.size(), b.size());
    EXPECT_LE(pc.fields.size(), b.size());
  }
  EXPECT_LT(accepted, 3 * 3000);
}

}  // namespace
}  // namespace mechsim::ros2
