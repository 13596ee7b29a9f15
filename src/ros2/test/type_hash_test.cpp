// The generator's REP-2016 type hashes (RIHS01) against values that ROS 2's own generator
// (rosidl_generator_type_description) gives, as published in independent code bases: the shared
// README's std_msgs/msg/String, `ros2 topic info -v`'s TwistStamped, and the expected hashes that
// rosidl writes into generated C code for Time and Point.
#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include <mechsim_ros2_msgs/geometry_msgs.hpp>
#include <mechsim_ros2_msgs/std_msgs.hpp>
#include <mechsim_ros2_msgs/type_table.hpp>

namespace mechsim::ros2 {
namespace {

std::string hash_of(const std::string& set, const std::string& ros_name) {
  for (const GeneratedType& t : kGeneratedTypes) {
    if (set == t.set && ros_name == t.ros_name) return t.type_hash;
  }
  return "";
}

TEST(TypeHash, MatchesRosidlForKnownTypes) {
  EXPECT_EQ(hash_of("common", "std_msgs/msg/String"),
            "RIHS01_df668c740482bbd48fb39d76a70dfd4bd59db1288021743503259e948f6b1a18");
  EXPECT_EQ(hash_of("common", "geometry_msgs/msg/TwistStamped"),
            "RIHS01_5f0fcd4f81d5d06ad9b4c4c63e3ea51b82d6ae4d0558f1d475229b1121db6f64");
  EXPECT_EQ(hash_of("common", "builtin_interfaces/msg/Time"),
            "RIHS01_b106235e25a4c5ed35098aa0a61a3ee9c9b18d197f398b0e4206cea9acf9c197");
  EXPECT_EQ(hash_of("common", "geometry_msgs/msg/Point"),
            "RIHS01_6963084842a9b04494d6b2941d11444708d892da2f4b09843b9c43f42a7f6881");
  EXPECT_EQ(hash_of("common", "geometry_msgs/msg/Vector3").rfind("RIHS01_cc12fe83e4c02719f1ce8070bfd14aecd40f75a96696a6", 0), 0u);
  // The traits carry the same value.
  EXPECT_STREQ(MessageTraits<std_msgs::msg::String>::type_hash, hash_of("common", "std_msgs/msg/String").c_str());
}

TEST(TypeHash, EveryTypeHasAWellFormedHashAndDistroGidsDiffer) {
  for (const GeneratedType& t : kGeneratedTypes) {
    const std::string h = t.type_hash;
    EXPECT_EQ(h.size(), 7u + 64) << t.ros_name;
    EXPECT_EQ(h.rfind("RIHS01_", 0), 0u) << t.ros_name;
  }
  EXPECT_NE(hash_of("humble", "rmw_dds_common/msg/Gid"), hash_of("jazzy", "rmw_dds_common/msg/Gid"));
}

TEST(TypeHash, DdsNamesAreRmwsMangling) {
  EXPECT_STREQ(MessageTraits<geometry_msgs::msg::TwistStamped>::dds_name, "geometry_msgs::msg::dds_::TwistStamped_");
  EXPECT_STREQ(MessageTraits<geometry_msgs::msg::TwistStamped>::ros_name, "geometry_msgs/msg/TwistStamped");
}

}  // namespace
}  // namespace mechsim::ros2
