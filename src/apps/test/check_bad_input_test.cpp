// The bad-input suite: malformed URDF and xacro documents run through `mechsim check` as a user
// would. Each must end with exit status 1 (not a signal, not a hang) and a message on stderr that
// names the problem and where it is: the file always, the line for URDF problems, and the
// element/link/joint/macro/property concerned.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "run_process.hpp"

namespace mechsim::apps::test {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

struct BadInput {
  std::string name;     // the file is written as NAME.urdf, or NAME.urdf.xacro when xacro
  bool xacro = false;
  std::string content;
  std::vector<std::string> expected;  // substrings of stderr, besides the file name
};

// gtest prints the case by name, not as bytes.
void PrintTo(const BadInput& c, std::ostream* os) { *os << c.name; }

// A valid two-link robot. Line numbers: 1 <robot>, 2 base, 3-6 joint j (4 parent/child/axis,
// 5 limit), 7 link arm with its inertial, 8 </robot>.
const std::string kBase = R"(<robot name="r">
  <link name="base"/>
  <joint name="j" type="revolute">
    <parent link="base"/><child link="arm"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="10" velocity="1"/>
  </joint>
  <link name="arm"><inertial><mass value="1"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial></link>
</robot>
)";

// kBase with the first `from` replaced by `to` (on one line, so the line numbers hold).
std::string with(const std::string& from, const std::string& to) {
  std::string s = kBase;
  const std::size_t at = s.find(from);
  if (at == std::string::npos) std::abort();  // a broken table, not a test outcome
  return s.replace(at, from.size(), to);
}

// kBase with `extra` on line 8, before </robot>.
std::string append(const std::string& extra) { return with("</robot>", extra + "</robot>"); }

const std::string kXacroHead = R"(<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="r">
)";
std::string xacro(const std::string& body) { return kXacroHead + body + "\n</robot>\n"; }

// `macros` macros, each calling the next from inside `depth` nested elements: every limit alone
// (macro depth 200, element depth 256) is respected, together they went 50,000 levels deep.
std::string deep_macro_bodies(int macros, int depth) {
  std::string open, close;
  for (int i = 0; i < depth; ++i) open += "<a>", close += "</a>";
  std::string body;
  for (int i = 0; i < macros; ++i) {
    const std::string inner = i + 1 < macros ? "<xacro:m" + std::to_string(i + 1) + "/>" : "<b/>";
    body += "<xacro:macro name=\"m" + std::to_string(i) + "\">" + open + inner + close + "</xacro:macro>\n";
  }
  return xacro(body + "<xacro:m0/>");
}

std::vector<BadInput> bad_inputs() {
  const std::string tip = R"(<link name="tip"/>)";
  return {
      // Malformed XML.
      {"truncated_xml", false, kBase.substr(0, 150), {"malformed XML"}},
      {"mismatched_tag", false, with("</joint>", "</link>"), {"malformed XML", "mismatched_tag.urdf:"}},
      {"empty_file", false, "", {"malformed XML"}},
      {"not_xml", false, "this is not a robot\n", {"malformed XML"}},
      {"duplicate_attribute", false, with(R"(<link name="base"/>)", R"(<link name="base" name="b2"/>)"),
       {"malformed XML", "duplicate_attribute.urdf:2"}},
      {"wrong_root", false, "<model name=\"m\"/>\n", {"wrong_root.urdf:1:", "<model>, not <robot>"}},
      {"no_links", false, "<robot name=\"r\"/>\n", {"no_links.urdf:1:", "has no links"}},
      // Missing attributes and elements, unknown names.
      {"robot_without_name", false, with(R"(<robot name="r">)", "<robot>"),
       {"robot_without_name.urdf:1:", "<robot> has no 'name'"}},
      {"link_without_name", false, with(R"(<link name="base"/>)", "<link/>"),
       {"link_without_name.urdf:2:", "<link> has no 'name'"}},
      {"joint_without_type", false, with(R"( type="revolute")", ""),
       {"joint_without_type.urdf:3:", "joint 'j': no 'type'"}},
      {"unknown_joint_type", false, with(R"(type="revolute")", R"(type="hinge")"),
       {"unknown_joint_type.urdf:3:", "joint 'j': unknown joint type 'hinge'"}},
      {"joint_without_parent", false, with(R"(<parent link="base"/>)", ""),
       {"joint_without_parent.urdf:3:", "joint 'j': no <parent>"}},
      {"parent_without_link", false, with(R"(<parent link="base"/>)", "<parent/>"),
       {"parent_without_link.urdf:4:", "joint 'j': <parent> has no 'link'"}},
      {"unknown_child_link", false, with(R"(<child link="arm"/>)", R"(<child link="ghost"/>)"),
       {"unknown_child_link.urdf:3:", "joint 'j': child link 'ghost' does not exist"}},
      {"revolute_without_limit", false, with(R"(<limit lower="-1" upper="1" effort="10" velocity="1"/>)", ""),
       {"revolute_without_limit.urdf:3:", "joint 'j': a revolute joint needs a <limit>"}},
      {"limit_without_effort", false, with(R"(effort="10" )", ""),
       {"limit_without_effort.urdf:5:", "joint 'j': <limit> has no 'effort'"}},
      {"inertial_without_mass", false, with(R"(<mass value="1"/>)", ""),
       {"inertial_without_mass.urdf:7:", "link 'arm': <inertial> has no <mass>"}},
      {"box_without_size", false, append(R"(<link name="boxy"><visual><geometry><box/></geometry></visual></link>)"),
       {"box_without_size.urdf:8:", "link 'boxy': <box> has no 'size'"}},
      {"unknown_geometry", false,
       append(R"(<link name="caps"><collision><geometry><capsule radius="1" length="2"/></geometry></collision></link>)"),
       {"unknown_geometry.urdf:8:", "link 'caps': unknown geometry <capsule>"}},
      {"mesh_without_filename", false, append(R"(<link name="m"><visual><geometry><mesh/></geometry></visual></link>)"),
       {"mesh_without_filename.urdf:8:", "link 'm': <mesh> has no 'filename'"}},
      {"empty_dynamics", false, with(R"(<axis xyz="0 0 1"/>)", R"(<axis xyz="0 0 1"/><dynamics/>)"),
       {"empty_dynamics.urdf:4:", "joint 'j': <dynamics> has neither 'damping' nor 'friction'"}},
      // Numbers.
      {"limit_not_a_number", false, with(R"(upper="1")", R"(upper="one")"),
       {"limit_not_a_number.urdf:5:", "joint 'j': <limit> attribute 'upper' is not a number: \"one\""}},
      {"mass_not_a_number", false, with(R"(<mass value="1"/>)", R"(<mass value="heavy"/>)"),
       {"mass_not_a_number.urdf:7:", "link 'arm': <mass> attribute 'value' is not a number: \"heavy\""}},
      {"origin_two_numbers", false,
       append(R"(<joint name="f" type="fixed"><parent link="arm"/><child link="tip"/><origin xyz="1 2"/></joint>)" + tip),
       {"origin_two_numbers.urdf:8:", "joint 'f': <origin> attribute 'xyz' must hold 3 numbers, not \"1 2\""}},
      {"mass_nan", false, with(R"(<mass value="1"/>)", R"(<mass value="nan"/>)"),
       {"mass_nan.urdf:7:", "link 'arm': <mass> attribute 'value' is not finite"}},
      {"limit_inf", false, with(R"(upper="1")", R"(upper="inf")"),
       {"limit_inf.urdf:5:", "joint 'j': <limit> attribute 'upper' is not finite"}},
      {"axis_nan", false, with(R"(xyz="0 0 1")", R"(xyz="nan 0 1")"),
       {"axis_nan.urdf:4:", "joint 'j': <axis> attribute 'xyz' is not finite"}},
      {"inertia_nan", false, with(R"(izz="0.1")", R"(izz="NaN")"),
       {"inertia_nan.urdf:7:", "link 'arm': <inertia> attribute 'izz' is not finite"}},
      // Physical plausibility.
      {"negative_mass", false, with(R"(<mass value="1"/>)", R"(<mass value="-2"/>)"),
       {"negative_mass.urdf:7:", "link 'arm': negative mass -2"}},
      {"inertia_not_positive_definite", false, with(R"(ixy="0")", R"(ixy="0.5")"),
       {"inertia_not_positive_definite.urdf:7:", "link 'arm': inertia is not positive definite"}},
      {"inertia_triangle_inequality", false, with(R"(izz="0.1")", R"(izz="0.5")"),
       {"inertia_triangle_inequality.urdf:7:", "link 'arm': inertia breaks the triangle inequality"}},
      {"lower_above_upper", false, with(R"(lower="-1" upper="1")", R"(lower="2" upper="1")"),
       {"lower_above_upper.urdf:3:", "joint 'j': lower limit 2 > upper limit 1"}},
      {"negative_effort", false, with(R"(effort="10")", R"(effort="-10")"),
       {"negative_effort.urdf:3:", "joint 'j': negative effort limit -10"}},
      {"negative_velocity", false, with(R"(velocity="1")", R"(velocity="-1")"),
       {"negative_velocity.urdf:3:", "joint 'j': negative velocity limit -1"}},
      {"zero_axis", false, with(R"(xyz="0 0 1")", R"(xyz="0 0 0")"), {"zero_axis.urdf:3:", "joint 'j': zero axis"}},
      {"negative_damping", false, with(R"(<axis xyz="0 0 1"/>)", R"(<axis xyz="0 0 1"/><dynamics damping="-1"/>)"),
       {"negative_damping.urdf:3:", "joint 'j': negative damping -1"}},
      {"soft_limits_inverted", false,
       with(R"(<axis xyz="0 0 1"/>)",
            R"(<axis xyz="0 0 1"/><safety_controller soft_lower_limit="1" soft_upper_limit="-1" k_velocity="1"/>)"),
       {"soft_limits_inverted.urdf:3:", "joint 'j': soft lower limit 1 > soft upper limit -1"}},
      // Structure.
      {"parent_is_child", false, with(R"(<child link="arm"/>)", R"(<child link="base"/>)"),
       {"parent_is_child.urdf:3:", "joint 'j': parent and child are the same link 'base'"}},
      {"two_parents", false, append(R"(<joint name="k" type="fixed"><parent link="base"/><child link="arm"/></joint>)"),
       {"two_parents.urdf:8:", "joint 'k': link 'arm' already has parent joint 'j'"}},
      {"kinematic_cycle", false,
       append(R"(<link name="a"/><link name="b"/><joint name="ab" type="fixed"><parent link="a"/><child link="b"/></joint>)"
              R"(<joint name="ba" type="fixed"><parent link="b"/><child link="a"/></joint>)"),
       {"kinematic_cycle.urdf:8:", "kinematic cycle through joints", "'ab'", "'ba'"}},
      {"multiple_roots", false, append(R"(<link name="stray"/>)"),
       {"multiple_roots.urdf:8:", "several root links ('base', 'stray')"}},
      {"duplicate_link", false, append(R"(<link name="arm"/>)"),
       {"duplicate_link.urdf:8:", "link 'arm' is defined twice (first at line 7)"}},
      {"duplicate_joint", false,
       append(R"(<joint name="j" type="fixed"><parent link="arm"/><child link="tip"/></joint>)" + tip),
       {"duplicate_joint.urdf:8:", "joint 'j' is defined twice (first at line 3)"}},
      {"mimic_missing_joint", false,
       append(R"(<joint name="m" type="continuous"><parent link="arm"/><child link="tip"/><mimic joint="nope"/></joint>)" + tip),
       {"mimic_missing_joint.urdf:8:", "joint 'm': mimics joint 'nope', which does not exist"}},
      {"mimic_itself", false,
       append(R"(<joint name="m" type="continuous"><parent link="arm"/><child link="tip"/><mimic joint="m"/></joint>)" + tip),
       {"mimic_itself.urdf:8:", "joint 'm': mimics itself"}},
      // Extensions.
      {"transmission_missing_joint", false,
       append(R"(<transmission name="t"><type>transmission_interface/SimpleTransmission</type>)"
              R"(<joint name="nope"/><actuator name="m"/></transmission>)"),
       {"transmission_missing_joint.urdf:8:", "transmission 't': joint 'nope' does not exist"}},
      {"transmission_without_type", false,
       append(R"(<transmission name="t"><joint name="j"/><actuator name="m"/></transmission>)"),
       {"transmission_without_type.urdf:8:", "transmission 't': no type"}},
      {"transmission_bad_reduction", false,
       append(R"(<transmission name="t"><type>transmission_interface/SimpleTransmission</type><joint name="j"/>)"
              R"(<actuator name="m"><mechanicalReduction>fast</mechanicalReduction></actuator></transmission>)"),
       {"transmission_bad_reduction.urdf:8:", "transmission 't': <mechanicalReduction> is not a number: \"fast\""}},
      {"wrist_without_reduction", false,
       append(R"(<transmission name="w" type="pr2_mechanism_model/WristTransmission"><rightActuator name="r"/>)"
              R"(<leftActuator name="l" mechanicalReduction="60"/><flexJoint name="j" mechanicalReduction="1"/></transmission>)"),
       {"wrist_without_reduction.urdf:8:", "transmission 'w': <rightActuator> has no 'mechanicalReduction'"}},
      {"gazebo_mu_not_a_number", false, append(R"(<gazebo reference="arm"><mu1>slippery</mu1></gazebo>)"),
       {"gazebo_mu_not_a_number.urdf:8:", "link 'arm' (gazebo): <mu1> is not a number: \"slippery\""}},
      {"gazebo_bool_not_a_boolean", false, append(R"(<gazebo reference="arm"><selfCollide>perhaps</selfCollide></gazebo>)"),
       {"gazebo_bool_not_a_boolean.urdf:8:", "<selfCollide> is not a boolean: \"perhaps\""}},
      {"gazebo_plugin_without_filename", false, append(R"(<gazebo><plugin name="p"/></gazebo>)"),
       {"gazebo_plugin_without_filename.urdf:8:", "gazebo plugin 'p': no 'filename'"}},
      // xacro: expansion errors, then a URDF error in an expanded document.
      {"xacro_truncated", true, kXacroHead + R"(<xacro:property name="a" value="1"/>)",
       {"XML parsing error", "xacro_truncated.urdf.xacro:3"}},
      {"xacro_unknown_macro", true, xacro(R"(<xacro:no_such_macro/>)"),
       {"no_such_macro", "xacro_unknown_macro.urdf.xacro:3"}},
      {"xacro_missing_include", true, xacro(R"(<xacro:include filename="missing_file.xacro"/>)"),
       {"missing_file.xacro", "xacro_missing_include.urdf.xacro:3"}},
      {"xacro_undefined_property", true, xacro(R"(<link name="${undefined_prop}"/>)"), {"undefined_prop", "xacro_undefined_property.urdf.xacro:3"}},
      {"xacro_endless_recursion", true,
       xacro(R"(<xacro:macro name="loop_forever"><xacro:loop_forever/></xacro:macro><xacro:loop_forever/>)"),
       {"loop_forever", "recursion", "xacro_endless_recursion.urdf.xacro:3"}},
      {"xacro_missing_macro_argument", true,
       xacro(R"(<xacro:macro name="wheel" params="needed_param"><link name="${needed_param}"/></xacro:macro><xacro:wheel/>)"),
       {"needed_param", "xacro_missing_macro_argument.urdf.xacro:3"}},
      {"xacro_unknown_macro_argument", true,
       xacro(R"(<xacro:macro name="wheel" params="side"><link name="${side}"/></xacro:macro><xacro:wheel side="l" bogus_arg="1"/>)"),
       {"bogus_arg", "xacro_unknown_macro_argument.urdf.xacro:3"}},
      {"xacro_undefined_arg", true, xacro(R"x(<link name="$(arg missing_arg)"/>)x"), {"missing_arg", "xacro_undefined_arg.urdf.xacro:3"}},
      {"xacro_unknown_package", true, xacro(R"x(<xacro:include filename="$(find no_such_pkg)/x.xacro"/>)x"),
       {"no_such_pkg", "xacro_unknown_package.urdf.xacro:3"}},
      {"xacro_bad_expression", true, xacro(R"(<xacro:property name="p" value="${1 +* 2}"/><link name="l${p}"/>)"),
       {"1 +* 2", "xacro_bad_expression.urdf.xacro:3"}},
      {"xacro_division_by_zero", true, xacro(R"(<link name="l${1/0}"/>)"),
       {"division by zero", "xacro_division_by_zero.urdf.xacro:3"}},
      {"xacro_mismatched_tag", true, xacro(R"(<link name="a"></joint>)"),
       {"mismatched tag", "xacro_mismatched_tag.urdf.xacro:3"}},
      {"xacro_non_numeric_mass", true,
       xacro(R"(<xacro:property name="m" value="heavy"/><link name="a"><inertial><mass value="${m}"/>)"
             R"(<inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>)"),
       {"(expanded)", "link 'a': <mass> attribute 'value' is not a number: \"heavy\""}},
      // Recursion without an end: bounded and located, never a stack overflow (issue 19).
      {"xacro_self_include", true, xacro(R"(<xacro:include filename="xacro_self_include.urdf.xacro"/>)"),
       {"includes nested more than 100 files deep", "include itself?", "xacro_self_include.urdf.xacro:3"}},
      {"xacro_deep_macro_bodies", true, deep_macro_bodies(199, 250),
       {"nested more than 1000 levels deep", "in macro 'm3'", "called from"}},
      {"xacro_negative_mass", true,
       xacro(R"(<xacro:property name="m" value="-3"/><link name="a"><inertial><mass value="${m}"/>)"
             R"(<inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>)"),
       {"(expanded)", "link 'a': negative mass -3"}},
  };
}

std::string exe() { return MECHSIM_EXE; }

class CheckBadInput : public ::testing::TestWithParam<BadInput> {
 protected:
  static void SetUpTestSuite() {
    dir_ = (fs::path(::testing::TempDir()) / ("mechsim_bad_input_" + std::to_string(getpid()))).string();
    fs::create_directories(dir_);
  }
  static void TearDownTestSuite() {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  static std::string dir_;
};
std::string CheckBadInput::dir_;

TEST_P(CheckBadInput, FailsWithAMessageNamingTheProblemAndWhere) {
  const BadInput& c = GetParam();
  const std::string file_name = c.name + (c.xacro ? ".urdf.xacro" : ".urdf");
  const std::string path = (fs::path(dir_) / file_name).string();
  write_file(path, c.content);
  const ProcessResult r = run_process({exe(), "check", path}, 30.0);
  ASSERT_TRUE(r.started) << exe();
  ASSERT_FALSE(r.timed_out) << "mechsim check hung on " << file_name;
  ASSERT_FALSE(r.signaled) << "mechsim check died of signal " << r.signal << " on " << file_name << "\n" << r.err;
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_THAT(r.err, HasSubstr("mechsim check: error: "));
  EXPECT_THAT(r.err, HasSubstr(file_name));
  for (const std::string& s : c.expected) EXPECT_THAT(r.err, HasSubstr(s));
  EXPECT_EQ(r.out, "");  // no summary for a broken description
  // Under -DMECHSIM_SANITIZE=ON a sanitizer report also exits with status 1: look for it.
  EXPECT_THAT(r.err, Not(HasSubstr("Sanitizer")));
  EXPECT_THAT(r.err, Not(HasSubstr("runtime error")));
}

INSTANTIATE_TEST_SUITE_P(Cases, CheckBadInput, ::testing::ValuesIn(bad_inputs()),
                         [](const ::testing::TestParamInfo<BadInput>& param_info) { return param_info.param.name; });

TEST(CheckBadInputTable, HasAtLeastFortyCases) { EXPECT_GE(bad_inputs().size(), 40u); }

}  // namespace
}  // namespace mechsim::apps::test
