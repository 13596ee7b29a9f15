// validate_robot on models built in code, and the validation errors parse_urdf_string reports.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

#include "description/urdf/urdf_parser.hpp"
#include "description/urdf/validation.hpp"

namespace mechsim::description {
namespace {

using ::testing::AllOf;
using ::testing::Contains;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

Link make_link(const std::string& name, int line, double mass = 1.0) {
  Link l;
  l.name = name;
  l.line = line;
  Inertial in;
  in.mass = mass;
  in.ixx = in.iyy = in.izz = 0.1;
  l.inertial = in;
  return l;
}

Joint make_joint(const std::string& name, const std::string& parent, const std::string& child, int line) {
  Joint j;
  j.name = name;
  j.type = JointType::Revolute;
  j.parent_link = parent;
  j.child_link = child;
  j.axis = {0.0, 0.0, 1.0};
  j.limits = JointLimits{-1.0, 1.0, 10.0, 2.0};
  j.line = line;
  return j;
}

// base -j1-> a -j2-> b
RobotModel chain() {
  RobotModel m;
  m.name = "chain";
  m.source = "chain.urdf";
  m.links = {make_link("base", 2), make_link("a", 3), make_link("b", 4)};
  m.joints = {make_joint("j1", "base", "a", 5), make_joint("j2", "a", "b", 6)};
  return m;
}

TEST(Validation, AcceptsAValidChain) {
  const ValidationReport r = validate_robot(chain(), {});
  EXPECT_THAT(r.errors, IsEmpty());
  EXPECT_THAT(r.warnings, IsEmpty());
  EXPECT_TRUE(r.ok());
}

TEST(Validation, NegativeMass) {
  RobotModel m = chain();
  m.links[1].inertial->mass = -2.0;
  const ValidationReport r = validate_robot(m, {});
  EXPECT_THAT(r.errors, Contains(AllOf(HasSubstr("chain.urdf:3: link 'a'"), HasSubstr("negative mass -2"))));
}

TEST(Validation, InertiaNotPositiveDefinite) {
  RobotModel m = chain();
  m.links[2].inertial->ixy = 0.5;  // |ixy| > ixx: an indefinite matrix
  const ValidationReport r = validate_robot(m, {});
  EXPECT_THAT(r.errors, Contains(AllOf(HasSubstr("link 'b'"), HasSubstr("not positive definite"))));
}

TEST(Validation, ZeroInertiaWithMass) {
  RobotModel m = chain();
  m.links[1].inertial->ixx = m.links[1].inertial->iyy = m.links[1].inertial->izz = 0.0;
  EXPECT_THAT(validate_robot(m, {}).errors, Contains(HasSubstr("link 'a': inertia is not positive definite")));
}

TEST(Validation, MasslessLinkWithoutInertiaIsFine) {
  RobotModel m = chain();
  *m.links[1].inertial = Inertial{};
  EXPECT_TRUE(validate_robot(m, {}).ok());
}

TEST(Validation, TriangleInequality) {
  RobotModel m = chain();
  m.links[1].inertial->izz = 0.25;  // 0.1 + 0.1 < 0.25
  EXPECT_THAT(validate_robot(m, {}).errors, Contains(AllOf(HasSubstr("link 'a'"), HasSubstr("triangle inequality"))));
  m.links[1].inertial->izz = 0.2;  // the boundary (a thin disc) is physical
  EXPECT_TRUE(validate_robot(m, {}).ok());
}

TEST(Validation, LowerAboveUpper) {
  RobotModel m = chain();
  m.joints[0].limits->lower = 2.0;
  EXPECT_THAT(validate_robot(m, {}).errors,
              Contains(AllOf(HasSubstr("chain.urdf:5: joint 'j1'"), HasSubstr("lower limit 2 > upper limit 1"))));
}

TEST(Validation, LowerAboveUpperIsIgnoredForContinuousJoints) {
  RobotModel m = chain();
  m.joints[0].type = JointType::Continuous;
  m.joints[0].limits->lower = 2.0;
  EXPECT_TRUE(validate_robot(m, {}).ok());
}

TEST(Validation, NegativeEffortAndVelocity) {
  RobotModel m = chain();
  m.joints[1].limits->effort = -1.0;
  m.joints[1].limits->velocity = -3.0;
  const auto errors = validate_robot(m, {}).errors;
  EXPECT_THAT(errors, Contains(HasSubstr("joint 'j2': negative effort limit -1")));
  EXPECT_THAT(errors, Contains(HasSubstr("joint 'j2': negative velocity limit -3")));
}

TEST(Validation, ZeroAxis) {
  RobotModel m = chain();
  m.joints[1].axis = {0.0, 0.0, 0.0};
  EXPECT_THAT(validate_robot(m, {}).errors, Contains(HasSubstr("joint 'j2': zero axis")));
  m.joints[1].type = JointType::Fixed;  // a fixed joint's axis means nothing
  EXPECT_TRUE(validate_robot(m, {}).ok());
}

TEST(Validation, NotFiniteValues) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  RobotModel m = chain();
  m.links[1].inertial->mass = nan;
  m.joints[0].origin.position.x = inf;
  m.joints[1].limits->upper = nan;
  const auto errors = validate_robot(m, {}).errors;
  EXPECT_THAT(errors, Contains(HasSubstr("link 'a': inertial holds a value that is not finite")));
  EXPECT_THAT(errors, Contains(HasSubstr("joint 'j1': origin is not finite")));
  EXPECT_THAT(errors, Contains(HasSubstr("joint 'j2': limit holds a value that is not finite")));
}

TEST(Validation, ParentIsChild) {
  RobotModel m = chain();
  m.joints[1].child_link = "a";
  EXPECT_THAT(validate_robot(m, {}).errors,
              Contains(HasSubstr("joint 'j2': parent and child are the same link 'a'")));
}

TEST(Validation, KinematicCycle) {
  RobotModel m = chain();
  // base -> a -> b, and b -> a closes a loop (a then has two parents) ...
  m.joints.push_back(make_joint("j3", "b", "a", 7));
  EXPECT_THAT(validate_robot(m, {}).errors, Contains(HasSubstr("already has parent joint 'j1'")));
  // ... while a loop hanging off no root has every link with one parent.
  RobotModel loop = chain();
  loop.joints = {make_joint("j1", "base", "a", 5), make_joint("j2", "a", "b", 6), make_joint("j3", "b", "base", 7)};
  const auto errors = validate_robot(loop, {}).errors;
  EXPECT_THAT(errors, Contains(HasSubstr("kinematic cycle through joints")));
  EXPECT_THAT(errors, Contains(HasSubstr("no root link")));
}

TEST(Validation, MultipleRoots) {
  RobotModel m = chain();
  m.links.push_back(make_link("floating_thing", 9));
  EXPECT_THAT(validate_robot(m, {}).errors,
              Contains(AllOf(HasSubstr("chain.urdf:9:"), HasSubstr("several root links ('base', 'floating_thing')"))));
}

TEST(Validation, DuplicateNames) {
  RobotModel m = chain();
  m.links.push_back(make_link("a", 10));
  m.joints.push_back(make_joint("j2", "b", "a", 11));
  const auto errors = validate_robot(m, {}).errors;
  EXPECT_THAT(errors, Contains(HasSubstr("chain.urdf:10: link 'a' is defined twice (first at line 3)")));
  EXPECT_THAT(errors, Contains(HasSubstr("chain.urdf:11: joint 'j2' is defined twice (first at line 6)")));
}

TEST(Validation, MissingLinks) {
  RobotModel m = chain();
  m.joints[1].child_link = "ghost";
  EXPECT_THAT(validate_robot(m, {}).errors, Contains(HasSubstr("joint 'j2': child link 'ghost' does not exist")));
}

TEST(Validation, MimicAndTransmissionNamingMissingJoints) {
  RobotModel m = chain();
  m.joints[1].mimic = Mimic{"nope", 1.0, 0.0};
  Transmission t;
  t.name = "t";
  t.type = "transmission_interface/SimpleTransmission";
  t.line = 20;
  t.joints.push_back(TransmissionJoint{"missing", "", {}, std::nullopt});
  t.actuators.push_back(TransmissionActuator{"motor", "", std::nullopt, {}});
  m.transmissions.push_back(t);
  const auto errors = validate_robot(m, {}).errors;
  EXPECT_THAT(errors, Contains(HasSubstr("joint 'j2': mimics joint 'nope', which does not exist")));
  EXPECT_THAT(errors, Contains(HasSubstr("chain.urdf:20: transmission 't': joint 'missing' does not exist")));
}

TEST(Validation, LenientTurnsPhysicalProblemsIntoWarnings) {
  RobotModel m = chain();
  m.links[1].inertial->mass = -1.0;
  m.joints[0].limits->lower = 3.0;
  m.joints[1].axis = {0.0, 0.0, 0.0};  // structural: stays an error
  const ValidationReport r = validate_robot(m, ValidationOptions{true});
  EXPECT_THAT(r.warnings, Contains(HasSubstr("negative mass")));
  EXPECT_THAT(r.warnings, Contains(HasSubstr("lower limit 3 > upper limit 1")));
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_THAT(r.errors[0], HasSubstr("zero axis"));
}

// Through the parser: every problem is collected before the error is thrown.
TEST(Validation, TheParserReportsAllProblemsAtOnce) {
  const std::string urdf = R"(<robot name="r">
  <link name="base"/>
  <joint name="j" type="revolute">
    <parent link="base"/><child link="a"/><axis xyz="0 0 0"/>
    <limit lower="1" upper="0" effort="-5" velocity="1"/>
  </joint>
  <link name="a"><inertial><mass value="-3"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>
</robot>)";
  try {
    parse_urdf_string(urdf, "r.urdf", UrdfOptions{});
    FAIL() << "no error";
  } catch (const DescriptionError& e) {
    EXPECT_EQ(e.problems().size(), 4u);
    EXPECT_THAT(e.what(), HasSubstr("4 problems in r.urdf"));
    EXPECT_THAT(e.what(), HasSubstr("r.urdf:7: link 'a': negative mass -3"));
    EXPECT_THAT(e.what(), HasSubstr("r.urdf:3: joint 'j': zero axis"));
    EXPECT_THAT(e.what(), HasSubstr("r.urdf:3: joint 'j': lower limit 1 > upper limit 0"));
    EXPECT_THAT(e.what(), HasSubstr("r.urdf:3: joint 'j': negative effort limit -5"));
  }
  std::vector<std::string> warnings;
  UrdfOptions lenient;
  lenient.lenient = true;
  EXPECT_THROW(parse_urdf_string(urdf, "r.urdf", lenient, &warnings), DescriptionError);  // zero axis
}

}  // namespace
}  // namespace mechsim::description
