// Robustness of parse_urdf_string (run under the sanitizer build, which runs the unit label):
// every truncation of a valid document and every corrupted number gives a DescriptionError
// naming the file, never another exception, a crash or a hang.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <regex>

#include "description/urdf/urdf_parser.hpp"

namespace mechsim::description {
namespace {

using ::testing::HasSubstr;

constexpr const char* kRobot = R"(<robot name="bot">
  <material name="grey"><color rgba="0.5 0.5 0.5 1"/></material>
  <link name="base">
    <inertial><origin xyz="0 0 0.1" rpy="0 0 0"/><mass value="2"/>
      <inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>
    <visual><origin xyz="0 0 0"/><geometry><box size="0.2 0.2 0.2"/></geometry><material name="grey"/></visual>
    <collision><geometry><cylinder radius="0.1" length="0.2"/></geometry></collision>
  </link>
  <joint name="hinge" type="revolute">
    <parent link="base"/><child link="arm"/>
    <origin xyz="0 0 0.2" rpy="0 0 0"/><axis xyz="0 1 0"/>
    <limit lower="-1" upper="1" effort="10" velocity="2"/>
    <dynamics damping="0.1" friction="0.01"/>
    <safety_controller soft_lower_limit="-0.9" soft_upper_limit="0.9" k_position="10" k_velocity="1"/>
  </joint>
  <link name="arm">
    <inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
    <collision><geometry><sphere radius="0.05"/></geometry></collision>
  </link>
  <transmission name="hinge_tran">
    <type>transmission_interface/SimpleTransmission</type>
    <joint name="hinge"><hardwareInterface>EffortJointInterface</hardwareInterface></joint>
    <actuator name="hinge_motor"><mechanicalReduction>20</mechanicalReduction></actuator>
  </transmission>
  <gazebo reference="arm"><mu1>0.5</mu1><mu2>0.5</mu2><selfCollide>false</selfCollide></gazebo>
</robot>
)";

TEST(UrdfRobustness, TheDocumentIsValid) {
  const RobotModel m = parse_urdf_string(kRobot, "bot.urdf", UrdfOptions{});
  EXPECT_EQ(m.links.size(), 2u);
  EXPECT_EQ(m.transmissions.size(), 1u);
}

TEST(UrdfRobustness, EveryTruncationIsAnError) {
  const std::string doc = kRobot;
  const std::size_t end_of_robot = doc.rfind("</robot>") + std::string("</robot>").size();
  for (std::size_t n = 0; n < end_of_robot; ++n) {
    try {
      parse_urdf_string(doc.substr(0, n), "bot.urdf", UrdfOptions{});
      ADD_FAILURE() << "a truncation at " << n << " parsed";
    } catch (const DescriptionError& e) {
      EXPECT_THAT(e.what(), HasSubstr("bot.urdf")) << n;
    }
  }
}

// Every attribute value holding numbers, replaced by a non-number, a non-finite value, or a
// negative one: a DescriptionError naming the file and the line (of the element, or for a
// physical problem of its link or joint), or (for a negative value that is physically fine,
// e.g. an origin) a valid model.
TEST(UrdfRobustness, EveryCorruptedNumberIsReportedWithItsLine) {
  const std::string doc = kRobot;
  const std::regex number_attribute(R"re((\w+)="(-?[0-9.]+( -?[0-9.]+)*)")re");
  int errors = 0, accepted = 0;
  for (auto it = std::sregex_iterator(doc.begin(), doc.end(), number_attribute); it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    const std::size_t value_at = static_cast<std::size_t>(m.position(2));
    const std::size_t value_len = static_cast<std::size_t>(m.length(2));
    auto line_of = [&](std::size_t at) {
      return 1 + static_cast<int>(std::count(doc.begin(), doc.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
    };
    const int line = line_of(value_at);
    // Syntax problems name the element's line; physical ones the line of the link or joint.
    std::size_t owner_at = 0;
    for (const char* tag : {"<link ", "<joint "})
      if (const std::size_t at = doc.rfind(tag, value_at); at != std::string::npos) owner_at = std::max(owner_at, at);
    const int owner_line = line_of(owner_at);
    for (const std::string replacement : {"abc", "nan", "inf", "1e999", "-5", ""}) {
      std::string bad = doc;
      bad.replace(value_at, value_len, replacement);
      try {
        parse_urdf_string(bad, "bot.urdf", UrdfOptions{});
        ++accepted;
        EXPECT_EQ(replacement, "-5") << m.str(1) << " at line " << line << " accepted \"" << replacement << "\"";
      } catch (const DescriptionError& e) {
        ++errors;
        EXPECT_THAT(e.what(), ::testing::AnyOf(HasSubstr("bot.urdf:" + std::to_string(line) + ":"),
                                               HasSubstr("bot.urdf:" + std::to_string(owner_line) + ":")))
            << m.str(1) << " = \"" << replacement << "\"";
      }
    }
  }
  EXPECT_GT(errors, 100);
  EXPECT_GT(accepted, 0);
}

}  // namespace
}  // namespace mechsim::description
