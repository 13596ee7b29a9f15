#include "control/params.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace mechsim::control {
namespace {

using ::testing::HasSubstr;

constexpr const char* kCc8 = R"(cc8:
  joint_state_controller:
    type: joint_state_controller/JointStateController
    publish_rate: 50
  steering_FL_position_controller:
    type: effort_controllers/JointPositionController
    joint: steering_FL
    pid: {p: 1.0, i: 0.001, d: 0.01}
  group:
    joints: [a, b, c]
    gains: [1, 2.5, -3e-2]
    enabled: yes
    quoted: "12"
    limits: {a: 1.5, b: 2}
)";

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const ParamsError& e) {
    return e.what();
  }
  return "<no error>";
}

TEST(Params, ReadsTypedValuesFromYaml) {
  Params root = Params::from_yaml_string(kCc8, "controller.yaml");
  Params cc8 = root.child("cc8");
  EXPECT_EQ(cc8.path(), "/cc8");
  EXPECT_EQ(cc8.keys(), (std::vector<std::string>{"joint_state_controller", "steering_FL_position_controller", "group"}));
  EXPECT_EQ(cc8.get<int>("joint_state_controller/publish_rate"), 50);
  EXPECT_DOUBLE_EQ(cc8.get<double>("joint_state_controller/publish_rate"), 50.0);
  Params pid = cc8.child("steering_FL_position_controller/pid");
  EXPECT_EQ(pid.path(), "/cc8/steering_FL_position_controller/pid");
  EXPECT_DOUBLE_EQ(pid.get<double>("i"), 0.001);
  EXPECT_EQ(cc8.get<std::string>("steering_FL_position_controller/joint"), "steering_FL");
  EXPECT_EQ(cc8.get<std::vector<std::string>>("group/joints"), (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_EQ(cc8.get<std::vector<double>>("group/gains"), (std::vector<double>{1.0, 2.5, -0.03}));
}

TEST(Params, DefaultsOnlyWhenAbsent) {
  Params root = Params::from_yaml_string(kCc8);
  Params pid = root.child("cc8/steering_FL_position_controller/pid");
  EXPECT_DOUBLE_EQ(pid.get<double>("i_clamp", 0.0), 0.0);
  EXPECT_DOUBLE_EQ(pid.get<double>("p", 7.0), 1.0);
  EXPECT_TRUE(root.get<bool>("cc8/group/enabled"));
  EXPECT_FALSE(root.get<bool>("cc8/group/absent", false));
  EXPECT_TRUE(root.has("cc8/group/limits/a"));
  EXPECT_FALSE(root.has("cc8/group/limits/z"));
  auto limits = root.get<std::map<std::string, double>>("cc8/group/limits");
  EXPECT_DOUBLE_EQ(limits.at("b"), 2.0);
  // A quoted number is a string, as rosparam reads it.
  EXPECT_EQ(root.get<std::string>("cc8/group/quoted"), "12");
  EXPECT_THAT(error_of([&] { (void)root.get<double>("cc8/group/quoted"); }), HasSubstr("expected a number"));
}

TEST(Params, ErrorsNameTheFullPathAndLine) {
  Params root = Params::from_yaml_string(kCc8, "controller.yaml");
  std::string e = error_of([&] { (void)root.get<double>("cc8/steering_FL_position_controller/pid/x"); });
  EXPECT_THAT(e, HasSubstr("/cc8/steering_FL_position_controller/pid/x"));
  EXPECT_THAT(e, HasSubstr("not found"));
  e = error_of([&] { (void)root.get<double>("cc8/steering_FL_position_controller/joint"); });
  EXPECT_THAT(e, HasSubstr("parameter /cc8/steering_FL_position_controller/joint: expected a number"));
  EXPECT_THAT(e, HasSubstr("controller.yaml:7"));
  e = error_of([&] { (void)root.get<int>("cc8/group/gains"); });
  EXPECT_THAT(e, HasSubstr("/cc8/group/gains: expected an integer, got a list"));
  e = error_of([&] { (void)root.get<std::vector<int>>("cc8/group/gains"); });
  EXPECT_THAT(e, HasSubstr("/cc8/group/gains[1]: expected an integer"));
  try {
    (void)root.child("cc8/nothing/here");
    FAIL();
  } catch (const ParamsError& err) {
    EXPECT_EQ(err.path(), "/cc8/nothing/here");
  }
}

TEST(Params, MalformedYamlNamesFileAndLine) {
  const char* bad = "cc8:\n  a: 1\n  b: [1, 2\n  c: 3\n";
  std::string e = error_of([&] { (void)Params::from_yaml_string(bad, "bad.yaml"); });
  EXPECT_THAT(e, HasSubstr("bad.yaml:"));
  EXPECT_THAT(e, HasSubstr("malformed YAML"));
  e = error_of([&] { (void)Params::from_yaml_string("a: 1\na: 2\n", "dup.yaml"); });
  EXPECT_THAT(e, HasSubstr("dup.yaml:2"));
  EXPECT_THAT(e, HasSubstr("duplicate key"));
  e = error_of([&] { (void)Params::from_yaml_string("- 1\n- 2\n", "list.yaml"); });
  EXPECT_THAT(e, HasSubstr("top level"));
}

// An alias inside the node its anchor names makes yaml-cpp's graph a cycle; it was a stack
// overflow (found by controllers_fuzz). Now an error naming the file and the depth.
TEST(Params, AnAliasInsideItsOwnAnchorIsAnErrorNotACrash) {
  const std::string e = error_of([&] { (void)Params::from_yaml_string("a: &x\n  b: 1\n  c: *x\n", "cycle.yaml"); });
  EXPECT_THAT(e, HasSubstr("cycle.yaml:"));
  EXPECT_THAT(e, HasSubstr("nested more than 128 levels deep"));
}

// Stray bytes of an 8-bit file (Latin-1, a binary paste) passed through yaml-cpp into names that
// end in JSON (summary.json, a sweep's plan.json), where nlohmann::json refused them: `mechsim
// sweep` stopped with "[json.exception.type_error.316] invalid UTF-8 byte" naming neither file
// nor key (found by sweep_fuzz). Now the reader says where.
TEST(Params, TextThatIsNotUtf8IsAnErrorNamingTheLineAndTheParameter) {
  std::string e = error_of([&] { (void)Params::from_yaml_string("a: 1\nname: ev\xFFry\n", "latin.yaml"); });
  EXPECT_THAT(e, HasSubstr("latin.yaml:2:"));
  EXPECT_THAT(e, HasSubstr("parameter /name: the value is not UTF-8 text (byte 0xFF at offset 2)"));
  e = error_of([&] { (void)Params::from_yaml_string("pid:\n  caf\xE9: 1\n", "key.yaml"); });
  EXPECT_THAT(e, HasSubstr("key.yaml:2:"));
  EXPECT_THAT(e, HasSubstr("parameter /pid: the key is not UTF-8 text (byte 0xE9"));
  // Overlong forms, surrogates, code points past U+10FFFF and sequences cut short are refused too.
  for (const char* bad : {"v: \xC0\xAF\n", "v: \xED\xA0\x80\n", "v: \xF4\x90\x80\x80\n", "v: \xE2\x82\n"}) {
    EXPECT_THAT(error_of([&] { (void)Params::from_yaml_string(bad, "b.yaml"); }), HasSubstr("not UTF-8")) << bad;
  }
  // Well-formed UTF-8 of every length reads back unchanged.
  const Params ok = Params::from_yaml_string("name: \"\xC3\xA9t\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x9A\x80\"\n", "ok.yaml");
  EXPECT_EQ(ok.get<std::string>("name"), "\xC3\xA9t\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x9A\x80");
}

TEST(Params, LoadsFromFile) {
  auto path = std::filesystem::temp_directory_path() / ("mechsim_params_test_" + std::to_string(::getpid()) + ".yaml");
  {
    std::ofstream out(path);
    out << "x:\n  y: 3\n  z: [oops\n";
  }
  std::string e = error_of([&] { (void)Params::from_yaml_file(path.string()); });
  EXPECT_THAT(e, HasSubstr(path.string() + ":"));
  {
    std::ofstream out(path);
    out << "x:\n  y: 3\n";
  }
  EXPECT_EQ(Params::from_yaml_file(path.string()).get<int>("x/y"), 3);
  std::filesystem::remove(path);
  e = error_of([&] { (void)Params::from_yaml_file("/nonexistent/file.yaml"); });
  EXPECT_THAT(e, HasSubstr("/nonexistent/file.yaml: cannot open"));
}

TEST(Params, BuildsInCode) {
  Params root;
  root.set("cc8/c/type", "effort_controllers/JointPositionController")
      .set("cc8/c/pid/p", 2.0)
      .set("cc8/c/pid/antiwindup", true)
      .set("cc8/c/count", 3)
      .set("cc8/g/joints", std::vector<std::string>{"a", "b"});
  Params c = root.child("cc8/c");
  EXPECT_EQ(c.get<std::string>("type"), "effort_controllers/JointPositionController");
  EXPECT_DOUBLE_EQ(c.get<double>("pid/p"), 2.0);
  EXPECT_DOUBLE_EQ(c.get<double>("count"), 3.0);  // an int reads as a double
  EXPECT_THAT(error_of([&] { (void)c.get<int>("pid/p"); }), HasSubstr("/cc8/c/pid/p: expected an integer"));
  EXPECT_TRUE(c.get<bool>("pid/antiwindup"));
  EXPECT_EQ(root.get<std::vector<std::string>>("cc8/g/joints").size(), 2u);
  // Handles share the tree.
  Params pid = c.child_or_create("pid");
  pid.set("d", 0.5);
  EXPECT_DOUBLE_EQ(root.get<double>("cc8/c/pid/d"), 0.5);
  EXPECT_EQ(pid.location(), "");
  EXPECT_EQ(pid.name(), "pid");
}

}  // namespace
}  // namespace mechsim::control
