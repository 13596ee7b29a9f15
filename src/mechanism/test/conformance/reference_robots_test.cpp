// Builds the mechanism of the reference robot descriptions (../shared/robots/reference) and checks
// it against an independent count of their <transmission> elements made here with tinyxml2.
#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <string>

#include "description/urdf/urdf_parser.hpp"
#include "mechanism/build_mechanism.hpp"
#include "mechanism/pr2_gripper_transmission.hpp"
#include "mechanism/propagation.hpp"

namespace mechsim::mechanism {
namespace {

namespace fs = std::filesystem;

struct Expected {
  std::map<std::string, int> transmissions_by_type;
  int actuators = 0;
  int joints = 0;
  int actuated = 0;
  int passive = 0;
  int simulated = 0;
  std::set<std::string> joint_names;
};

std::string type_of(const tinyxml2::XMLElement& t) {
  if (const auto* e = t.FirstChildElement("type"); e && e->GetText()) return e->GetText();
  const char* a = t.Attribute("type");
  return a ? a : "";
}

// The count the PR2 and ros_control loaders would make, from the XML alone.
Expected count(const std::string& path) {
  tinyxml2::XMLDocument doc;
  EXPECT_EQ(doc.LoadFile(path.c_str()), tinyxml2::XML_SUCCESS) << path;
  Expected x;
  const tinyxml2::XMLElement* robot = doc.FirstChildElement("robot");
  std::set<std::string> urdf_joints;
  for (const auto* j = robot->FirstChildElement("joint"); j; j = j->NextSiblingElement("joint"))
    urdf_joints.insert(j->Attribute("name"));
  for (const auto* t = robot->FirstChildElement("transmission"); t; t = t->NextSiblingElement("transmission")) {
    ++x.transmissions_by_type[type_of(*t)];
    for (const auto* c = t->FirstChildElement(); c; c = c->NextSiblingElement()) {
      const std::string tag = c->Name();
      const char* name = c->Attribute("name");
      if (tag == "actuator" || tag == "rightActuator" || tag == "leftActuator") ++x.actuators;
      if (tag == "joint" || tag == "flexJoint" || tag == "rollJoint" || tag == "gap_joint") {
        ++x.actuated;
        x.joint_names.insert(name);
      }
      if (tag == "passive_joint") {
        ++x.passive;
        x.joint_names.insert(name);
      }
      if (tag == "simulated_actuated_joint") {
        ++x.simulated;
        x.joint_names.insert(name);
        const char* slider = c->Attribute("passive_actuated_joint");
        if (slider && urdf_joints.count(slider)) {
          ++x.simulated;
          x.joint_names.insert(slider);
        }
      }
    }
  }
  x.joints = x.actuated + x.passive + x.simulated;
  return x;
}

class ReferenceRobot : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    path_ = fs::path(MECHSIM_SHARED_DIR) / "robots" / "reference" / GetParam();
    if (!fs::exists(path_)) GTEST_SKIP() << "shared test data absent: " << path_;
    description::UrdfOptions options;
    options.lenient = true;  // physical plausibility is not what this suite checks
    robot_ = description::parse_urdf_file(path_.string(), options);
  }
  fs::path path_;
  description::RobotModel robot_;
};

TEST_P(ReferenceRobot, MechanismMatchesIndependentCount) {
  const Expected x = count(path_.string());
  ASSERT_FALSE(x.transmissions_by_type.empty());
  const MechanismModel m = build_mechanism(robot_);

  std::map<std::string, int> by_type;
  for (const auto& t : m.transmissions) ++by_type[t->type()];
  EXPECT_EQ(by_type, x.transmissions_by_type);
  EXPECT_EQ(static_cast<int>(m.actuators.size()), x.actuators);
  EXPECT_EQ(static_cast<int>(m.joints.size()), x.joints);
  int actuated = 0, passive = 0, simulated = 0;
  std::set<std::string> names;
  for (const JointInfo& j : m.joints) {
    names.insert(j.name);
    actuated += j.role == JointRole::Actuated;
    passive += j.role == JointRole::Passive;
    simulated += j.role == JointRole::SimulatedActuated;
    EXPECT_EQ(j.interfaces.empty(), j.role != JointRole::Actuated) << j.name;
    EXPECT_NE(robot_.joint(j.name), nullptr) << j.name;
  }
  EXPECT_EQ(actuated, x.actuated);
  EXPECT_EQ(passive, x.passive);
  EXPECT_EQ(simulated, x.simulated);
  EXPECT_EQ(names, x.joint_names);
}

TEST_P(ReferenceRobot, JointStateSurvivesTheTickPropagations) {
  const MechanismModel m = build_mechanism(robot_);
  MechanismState s = make_state(m);
  std::vector<JointState> before(m.joints.size());
  for (std::size_t i = 0; i < m.joints.size(); ++i) {
    if (m.joints[i].role != JointRole::Actuated) continue;
    JointState& j = s.joints[i];
    // Mid-range, where the safety limits let a small command through.
    const JointInfo& info = m.joints[i];
    j.position = 0.01 + 0.001 * static_cast<double>(i % 7);
    if (info.limits && !info.continuous) j.position = 0.5 * (info.limits->lower + info.limits->upper);
    if (info.safety && info.limits && !info.continuous)
      j.position = 0.5 * (info.safety->soft_lower_limit + info.safety->soft_upper_limit);
    j.velocity = 0.02 * std::sin(static_cast<double>(i));
    j.measured_effort = 1.5 * std::cos(static_cast<double>(i));
    before[i] = j;
  }
  // Tick steps 1 and 2: physics -> encoders -> joints.
  propagate_joint_to_actuator_position(m, s);
  for (std::size_t i = 0; i < m.joints.size(); ++i)
    if (m.joints[i].role == JointRole::Actuated) s.joints[i] = JointState{};
  propagate_actuator_to_joint_position(m, s);
  for (std::size_t i = 0; i < m.joints.size(); ++i) {
    if (m.joints[i].role != JointRole::Actuated) continue;
    EXPECT_NEAR(s.joints[i].position, before[i].position, 1e-12) << m.joints[i].name;
    EXPECT_NEAR(s.joints[i].velocity, before[i].velocity, 1e-12) << m.joints[i].name;
    EXPECT_NEAR(s.joints[i].measured_effort, before[i].measured_effort, 1e-9) << m.joints[i].name;
  }
  // Commands through safety limits, to the motors and back: within the limits they are unchanged.
  for (std::size_t i = 0; i < m.joints.size(); ++i)
    if (m.joints[i].role == JointRole::Actuated) s.joints[i].commanded_effort = 0.001;
  enforce_safety_limits(m, s);
  propagate_joint_to_actuator_effort(m, s);
  for (std::size_t i = 0; i < m.joints.size(); ++i)
    if (m.joints[i].role == JointRole::Actuated) s.joints[i].commanded_effort = 0.0;
  propagate_actuator_to_joint_effort(m, s);
  for (std::size_t i = 0; i < m.joints.size(); ++i) {
    if (m.joints[i].role == JointRole::Actuated) {
      EXPECT_NEAR(s.joints[i].commanded_effort, 0.001, 1e-12) << m.joints[i].name;
    }
  }
  EXPECT_EQ(s.rejected_commands, 0u);
}

INSTANTIATE_TEST_SUITE_P(Reference, ReferenceRobot,
                         ::testing::Values("pr2.urdf", "cc8.urdf", "pr2_no_arms.urdf", "pr2_no_kinect.urdf",
                                           "pr2_se.urdf"),
                         [](const ::testing::TestParamInfo<std::string>& p) {
                           return p.param.substr(0, p.param.find('.'));
                         });

TEST(ReferencePr2, SafetyControllersAndGripperGeometryComeFromTheUrdf) {
  const fs::path path = fs::path(MECHSIM_SHARED_DIR) / "robots" / "reference" / "pr2.urdf";
  if (!fs::exists(path)) GTEST_SKIP() << "shared test data absent: " << path;
  description::UrdfOptions options;
  options.lenient = true;
  const MechanismModel m = build_mechanism(description::parse_urdf_file(path.string(), options));
  const int flex = m.joint_index("r_wrist_flex_joint");
  ASSERT_GE(flex, 0);
  ASSERT_TRUE(m.joints[flex].safety);
  EXPECT_EQ(m.joints[flex].safety->k_position, 20.0);
  EXPECT_EQ(m.joints[flex].limits->effort, 10.0);
  const int gap = m.joint_index("r_gripper_joint");
  ASSERT_GE(gap, 0);
  const auto* g = dynamic_cast<const Pr2GripperTransmission*>(m.transmissions[m.joints[gap].transmission].get());
  ASSERT_NE(g, nullptr);
  EXPECT_EQ(g->geometry().gear_ratio, 40.095);
  EXPECT_EQ(g->geometry().screw_reduction, 0.004);
  EXPECT_EQ(m.joints[m.joint_index("r_gripper_l_finger_joint")].role, JointRole::Passive);
  EXPECT_EQ(m.joints[m.joint_index("torso_lift_motor_screw_joint")].role, JointRole::SimulatedActuated);
  // The wrist's motors, right first.
  const auto& wrist = *m.transmissions[m.joints[flex].transmission];
  EXPECT_EQ(m.actuators[wrist.actuators()[0]].name, "r_wrist_r_motor");
}

}  // namespace
}  // namespace mechsim::mechanism
