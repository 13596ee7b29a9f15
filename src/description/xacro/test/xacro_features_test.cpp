// xacro features on small inline documents: the exact output xacro 1.14 writes for them.
#include <gtest/gtest.h>

#include <cstdlib>

#include "xacro_test_util.hpp"

namespace mechsim::description {
namespace {
using test::expand_body;

constexpr const char* kNs = R"X(xmlns:xacro="http://www.ros.org/wiki/xacro")X";

std::string doc(const std::string& body) { return std::string("<r ") + kNs + ">" + body + "</r>"; }

TEST(XacroFeatures, PropertiesAreLazyAndTyped) {
  // b refers to a, defined later: lazy evaluation resolves it at first use. "true" becomes True.
  EXPECT_EQ(expand_body(doc(R"X(<xacro:property name="b" value="${2*a}"/><xacro:property name="a" value=" 21 "/>)X"
                            R"X(<xacro:property name="t" value="true"/><xacro:property name="s" value="'1 2'"/>)X"
                            R"X(<x b="${b}" half="${a/2}" t="${t}" f="${1.0}" s="${s}" u="${'a_1'}"/>)X")),
            "<r>\n  <x b=\"42\" f=\"1.0\" half=\"10.5\" s=\"1 2\" t=\"True\" u=\"a_1\"/>\n</r>\n");
}

TEST(XacroFeatures, NumbersPrintAsPython) {
  EXPECT_EQ(expand_body(doc(R"X(<x a="${pi/2}" b="${0.1}" c="${1e-5}" d="${10/5}" e="${10//5}" f="${True}"/>)X")),
            "<r>\n  <x a=\"1.5707963267948966\" b=\"0.1\" c=\"1e-05\" d=\"2.0\" e=\"2\" f=\"True\"/>\n</r>\n");
}

TEST(XacroFeatures, PropertyBlocksAndInsertBlock) {
  EXPECT_EQ(expand_body(doc(R"X(<xacro:property name="blk"><a v="${v}"/><b/></xacro:property>)X"
                            R"X(<xacro:property name="v" value="7"/><xacro:insert_block name="blk"/>)X")),
            "<r>\n  <a v=\"7\"/>\n  <b/>\n</r>\n");
}

TEST(XacroFeatures, MacrosWithDefaultsBlocksAndForwarding) {
  const std::string out = expand_body(doc(R"X(
<xacro:property name="side" value="left"/>
<xacro:macro name="m" params="name *origin **rest side:=^ mass:=^|2.5 count:=3">
  <link name="${name}_${side}" mass="${mass}" n="${count*2}"><xacro:insert_block name="origin"/><xacro:insert_block name="rest"/></link>
</xacro:macro>
<xacro:m name="l1"><origin xyz="0 0 1"/><rest><c/><d/></rest></xacro:m>
<xacro:m name="l2" mass="1" count="1"><origin/><rest/></xacro:m>)X"));
  EXPECT_EQ(out,
            "<r>\n  <link mass=\"2.5\" n=\"6\" name=\"l1_left\">\n    <origin xyz=\"0 0 1\"/>\n    <c/>\n"
            "    <d/>\n  </link>\n  <link mass=\"1\" n=\"2\" name=\"l2_left\">\n    <origin/>\n  </link>\n</r>\n");
}

TEST(XacroFeatures, RecursiveMacroTerminatesWithConditional) {
  EXPECT_EQ(expand_body(doc(R"X(<xacro:macro name="chain" params="n">)X"
                            R"X(<l i="${n}"/><xacro:if value="${n > 1}"><xacro:chain n="${n-1}"/></xacro:if></xacro:macro>)X"
                            R"X(<xacro:chain n="3"/>)X")),
            "<r>\n  <l i=\"3\"/>\n  <l i=\"2\"/>\n  <l i=\"1\"/>\n</r>\n");
}

TEST(XacroFeatures, ScopesParentAndGlobal) {
  EXPECT_EQ(expand_body(doc(R"X(<xacro:macro name="outer"><xacro:macro name="inner">)X"
                            R"X(<xacro:property name="g" value="G" scope="global"/><xacro:property name="p" value="P" scope="parent"/>)X"
                            R"X(</xacro:macro><xacro:inner/><o p="${p}"/></xacro:macro><xacro:outer/><t g="${g}"/>)X")),
            "<r>\n  <o p=\"P\"/>\n  <t g=\"G\"/>\n</r>\n");
}

TEST(XacroFeatures, ConditionalsElementsAttributesCalls) {
  EXPECT_EQ(expand_body(doc(R"X(<xacro:property name="k" value="kind"/>)X"
                            R"X(<xacro:if value="${k == 'kind'}"><yes/></xacro:if><xacro:unless value="0"><no/></xacro:unless>)X"
                            R"X(<xacro:element xacro:name="${k}_el" a="1"><xacro:attribute name="${k}" value="v"/></xacro:element>)X"
                            R"X(<xacro:macro name="kind_m"><called/></xacro:macro><xacro:call macro="${k}_m"/>)X")),
            "<r>\n  <yes/>\n  <no/>\n  <kind_el a=\"1\" kind=\"v\"/>\n  <called/>\n</r>\n");
}

TEST(XacroFeatures, ArgsAndSubstitutions) {
  XacroOptions options;
  options.args["given"] = "cmd";
  ::setenv("MECHSIM_XACRO_TEST_VAR", "envval", 1);
  EXPECT_EQ(expand_body(doc(R"X(<xacro:arg name="given" default="dflt"/><xacro:arg name="other" default="$(arg given)x"/>)X"
                            R"X(<a g="$(arg given)" o="$(arg other)" e="$(env MECHSIM_XACRO_TEST_VAR)")X"
                            R"X( oe="$(optenv MECHSIM_XACRO_UNSET_VAR fall back)" ev="$(eval 2 * 3)" x="${xacro.arg('given')}"/>)X"),
                        options),
            "<r>\n  <a e=\"envval\" ev=\"6\" g=\"cmd\" o=\"cmdx\" oe=\"fall back\" x=\"cmd\"/>\n</r>\n");
  ::unsetenv("MECHSIM_XACRO_TEST_VAR");
}

TEST(XacroFeatures, FindUsesThePackageOption) {
  XacroOptions options;
  options.packages["my_pkg"] = "/opt/somewhere/my_pkg";
  EXPECT_EQ(expand_body(doc(R"X(<m file="$(find my_pkg)/meshes/a.stl"/>)X"), options),
            "<r>\n  <m file=\"/opt/somewhere/my_pkg/meshes/a.stl\"/>\n</r>\n");
}

TEST(XacroFeatures, DollarEscapes) {
  EXPECT_EQ(expand_body(R"X(<a b="$${x}" c="$$(arg y)" d="cost: $5"/>)X"),
            "<a b=\"${x}\" c=\"$(arg y)\" d=\"cost: $5\"/>\n");
}

TEST(XacroFeatures, CommentsBeforeXacroTagsAreDropped) {
  EXPECT_EQ(expand_body(doc("\n  <!-- kept -->\n\n  <!-- dropped -->\n  <xacro:property name=\"p\" value=\"1\"/>\n"
                            "  <!-- kept too -->\n  <e/>\n  <!-- xacro:eval-comments -->\n  <!-- p=${p} -->\n")),
            "<r>\n  <!-- kept -->\n  <!-- kept too -->\n  <e/>\n  <!-- p=1 -->\n</r>\n");
}

TEST(XacroFeatures, IncludeWithNamespaceAndYaml) {
  test::TempDir dir;
  dir.write("parts/inc.xacro", std::string("<a ") + kNs + R"X(><xacro:property name="w" value="0.5"/>)X"
                                   R"X(<xacro:macro name="part" params="n"><p n="${n}" w="${w}"/></xacro:macro></a>)X");
  dir.write("parts/conf.yaml", "wheel: {radius: 0.25, count: 6}\nnames: [a, b]\n");
  const auto main = dir.write("main.xacro", doc(R"X(<xacro:include filename="parts/inc.xacro" ns="lib"/>)X"
                                                R"X(<xacro:property name="c" value="${xacro.load_yaml('parts/conf.yaml')}"/>)X"
                                                R"X(<xacro:lib.part n="${c.wheel.count * lib.w}"/><y r="${c['wheel']['radius']}" n="${c.names[1]}"/>)X"));
  std::ostringstream diagnostics;
  XacroOptions options;
  options.diagnostics = &diagnostics;
  EXPECT_EQ(test::strip_banner(expand_xacro_file(main.string(), options)),
            "<r>\n  <p n=\"3.0\" w=\"0.5\"/>\n  <y n=\"b\" r=\"0.25\"/>\n</r>\n");
}

TEST(XacroFeatures, DirnameAndGlobIncludes) {
  test::TempDir dir;
  dir.write("parts/a1.xml", "<a><one/></a>");
  dir.write("parts/a2.xml", "<a><two d=\"$(dirname)\"/></a>");
  const auto main = dir.write("main.xacro", doc(R"X(<here d="$(dirname)"/><xacro:include filename="parts/a?.xml"/>)X"));
  const std::string d = dir.path().string();
  EXPECT_EQ(test::strip_banner(expand_xacro_file(main.string(), {})),
            "<r>\n  <here d=\"" + d + "\"/>\n  <one/>\n  <two d=\"" + d + "/parts\"/>\n</r>\n");
}

TEST(XacroFeatures, BannerAndDeclaration) {
  const std::string out = expand_xacro_string("<a/>", "robot.xacro", {});
  EXPECT_EQ(out,
            "<?xml version=\"1.0\" ?>\n"
            "<!-- =================================================================================== -->\n"
            "<!-- |    This document was autogenerated by xacro from robot.xacro                    | -->\n"
            "<!-- |    EDITING THIS FILE BY HAND IS NOT RECOMMENDED                                 | -->\n"
            "<!-- =================================================================================== -->\n"
            "<a/>\n");
}

}  // namespace
}  // namespace mechsim::description
