// Every reference URDF in ../shared/robots/reference parses and validates; the counts are
// checked against an independent count of the XML elements made here with tinyxml2.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <filesystem>
#include <map>
#include <set>

#include "description/urdf/urdf_parser.hpp"

namespace mechsim::description {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

const fs::path kReferenceDir = fs::path(MECHSIM_SHARED_DIR) / "robots" / "reference";

struct ElementCounts {
  std::size_t links = 0, joints = 0, transmissions = 0, model_plugins = 0, sensor_plugins = 0;
  double mass = 0.0;  // kg, sum over <link><inertial><mass value>
};

ElementCounts count_elements(const tinyxml2::XMLElement& robot) {
  ElementCounts c;
  for (const tinyxml2::XMLElement* e = robot.FirstChildElement(); e; e = e->NextSiblingElement()) {
    const std::string tag = e->Name();
    if (tag == "link") {
      ++c.links;
      if (const auto* in = e->FirstChildElement("inertial"))
        if (const auto* m = in->FirstChildElement("mass")) c.mass += m->DoubleAttribute("value");
    } else if (tag == "joint") {
      ++c.joints;
    } else if (tag == "transmission") {
      ++c.transmissions;
    } else if (tag == "gazebo") {
      for (const auto* p = e->FirstChildElement("plugin"); p; p = p->NextSiblingElement("plugin")) ++c.model_plugins;
      for (const auto* s = e->FirstChildElement("sensor"); s; s = s->NextSiblingElement("sensor"))
        for (const auto* p = s->FirstChildElement("plugin"); p; p = p->NextSiblingElement("plugin")) ++c.sensor_plugins;
    }
  }
  return c;
}

std::vector<std::string> reference_files() {
  std::vector<std::string> out;
  std::error_code ec;
  if (!fs::is_directory(kReferenceDir, ec)) return out;
  for (const auto& entry : fs::directory_iterator(kReferenceDir))
    if (entry.path().extension() == ".urdf") out.push_back(entry.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

UrdfOptions options(bool lenient) {
  UrdfOptions o;
  o.lenient = lenient;
  o.packages["pr2_description"] = (fs::path(MECHSIM_SHARED_DIR) / "robots" / "pr2_description").string();
  o.packages["cc8_description"] = (fs::path(MECHSIM_SHARED_DIR) / "robots" / "cc8_description").string();
  return o;
}

// Parses strictly when the file allows it; otherwise every strict error must be a physical-
// plausibility problem that --lenient accepts (the PR2's placeholder sensor inertias).
RobotModel parse_reference(const std::string& path, bool* needed_lenient) {
  try {
    *needed_lenient = false;
    return parse_urdf_file(path, options(false));
  } catch (const DescriptionError& e) {
    for (const std::string& p : e.problems()) EXPECT_THAT(p, HasSubstr("triangle inequality")) << path;
    *needed_lenient = true;
    return parse_urdf_file(path, options(true));
  }
}

TEST(UrdfReference, SharedDataIsPresent) {
  if (!fs::is_directory(kReferenceDir)) GTEST_SKIP() << "no shared data at " << kReferenceDir;
  EXPECT_GE(reference_files().size(), 2u);
}

class UrdfReferenceFile : public ::testing::TestWithParam<std::string> {};

TEST_P(UrdfReferenceFile, ParsesValidatesAndMatchesTheXml) {
  const std::string path = (kReferenceDir / GetParam()).string();
  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.LoadFile(path.c_str()), tinyxml2::XML_SUCCESS) << path;
  const ElementCounts expected = count_elements(*doc.RootElement());

  bool lenient = false;
  std::vector<std::string> warnings;
  const RobotModel m = parse_reference(path, &lenient);
  EXPECT_EQ(m.name, doc.RootElement()->Attribute("name"));
  EXPECT_EQ(m.links.size(), expected.links);
  EXPECT_EQ(m.joints.size(), expected.joints);
  EXPECT_EQ(m.transmissions.size(), expected.transmissions);
  std::size_t sensor_plugins = 0;
  for (const GazeboPlugin& p : m.plugins) sensor_plugins += p.sensor.empty() ? 0 : 1;
  EXPECT_EQ(m.plugins.size() - sensor_plugins, expected.model_plugins);
  EXPECT_EQ(sensor_plugins, expected.sensor_plugins);
  EXPECT_NEAR(m.total_mass(), expected.mass, 1e-9 * expected.mass);
  // A tree: links = joints + 1, one root.
  EXPECT_EQ(m.links.size(), m.joints.size() + 1);
  EXPECT_FALSE(m.root_link.empty());
  // Every mesh URI resolves; the shared pr2_description ships its meshes (cc8_description
  // does not), so there the files must exist too.
  const bool meshes_shipped = GetParam().starts_with("pr2");
  for (const Link& l : m.links) {
    for (const Visual& v : l.visuals) {
      if (v.geometry.type != GeometryType::Mesh) continue;
      EXPECT_FALSE(v.geometry.mesh_path.empty()) << v.geometry.mesh_uri;
      if (meshes_shipped) {
        EXPECT_TRUE(fs::exists(v.geometry.mesh_path)) << v.geometry.mesh_uri << " -> " << v.geometry.mesh_path;
      }
    }
  }
  RecordProperty("needs_lenient", lenient ? "yes" : "no");
  std::cout << GetParam() << ": " << m.links.size() << " links, " << m.joints.size() << " joints, "
            << m.transmissions.size() << " transmissions, " << m.total_mass() << " kg"
            << (lenient ? " (needs --lenient)" : "") << "\n";
}

INSTANTIATE_TEST_SUITE_P(Reference, UrdfReferenceFile, ::testing::ValuesIn(reference_files()),
                         [](const ::testing::TestParamInfo<std::string>& param_info) {
                           std::string n = param_info.param;
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(UrdfReferenceFile);

TEST(UrdfReference, Cc8IsValidStrictlyAndWeighsAbout64Kg) {
  const fs::path path = kReferenceDir / "cc8.urdf";
  if (!fs::exists(path)) GTEST_SKIP() << "no shared data at " << path;
  const RobotModel m = parse_urdf_file(path.string(), options(false));
  EXPECT_NEAR(m.total_mass(), 64.0, 1.0);
  // The rocker differential and ros_control plugins with their parameters.
  std::map<std::string, const GazeboPlugin*> plugins;
  for (const GazeboPlugin& p : m.plugins) plugins[p.name] = &p;
  ASSERT_TRUE(plugins.count("gazebo_ros_control"));
  EXPECT_EQ(plugins["gazebo_ros_control"]->parameters.at("robotNamespace"), "/cc8");
  ASSERT_TRUE(plugins.count("rocker_differential"));
  const GazeboPlugin& diff = *plugins["rocker_differential"];
  EXPECT_NE(m.joint(diff.parameters.at("jointA")), nullptr);
  EXPECT_NE(m.joint(diff.parameters.at("jointB")), nullptr);
  EXPECT_DOUBLE_EQ(std::stod(diff.parameters.at("forceConstant")), 1000.0);
  for (const Transmission& t : m.transmissions) {
    EXPECT_EQ(t.type, "transmission_interface/SimpleTransmission");
    ASSERT_EQ(t.joints.size(), 1u);
    EXPECT_FALSE(t.joints[0].hardware_interfaces.empty());
    ASSERT_EQ(t.actuators.size(), 1u);
    EXPECT_TRUE(t.actuators[0].mechanical_reduction.has_value());
  }
  ASSERT_TRUE(m.gazebo_links.count("base_link"));
  EXPECT_TRUE(m.gazebo_links.at("base_link").mu1.has_value());
}

// The PR2's wrist and gripper transmissions: compare the roles with the XML read here.
TEST(UrdfReference, Pr2WristAndGripperTransmissionsKeepTheirRoles) {
  const fs::path path = kReferenceDir / "pr2.urdf";
  if (!fs::exists(path)) GTEST_SKIP() << "no shared data at " << path;
  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.LoadFile(path.string().c_str()), tinyxml2::XML_SUCCESS);
  bool lenient = false;
  const RobotModel m = parse_reference(path.string(), &lenient);
  std::map<std::string, const Transmission*> by_name;
  for (const Transmission& t : m.transmissions) by_name[t.name] = &t;

  const std::map<std::string, std::string> joint_roles = {{"flexJoint", "flex"}, {"rollJoint", "roll"},
                                                          {"gap_joint", "gap"}, {"passive_joint", "passive"},
                                                          {"simulated_actuated_joint", "simulated_actuated"}};
  const std::map<std::string, std::string> actuator_roles = {{"rightActuator", "right"}, {"leftActuator", "left"}};
  int wrists = 0, grippers = 0;
  for (const auto* e = doc.RootElement()->FirstChildElement("transmission"); e;
       e = e->NextSiblingElement("transmission")) {
    const std::string type = e->Attribute("type") ? e->Attribute("type") : "";
    if (type != "pr2_mechanism_model/WristTransmission" && type != "pr2_mechanism_model/PR2GripperTransmission")
      continue;
    (type.find("Wrist") != std::string::npos ? wrists : grippers)++;
    ASSERT_TRUE(by_name.count(e->Attribute("name"))) << e->Attribute("name");
    const Transmission& t = *by_name.at(e->Attribute("name"));
    EXPECT_EQ(t.type, type);
    std::multiset<std::pair<std::string, std::string>> want_joints, got_joints, want_act, got_act;
    for (const auto* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
      if (auto it = joint_roles.find(c->Name()); it != joint_roles.end())
        want_joints.insert({c->Attribute("name"), it->second});
      if (auto it = actuator_roles.find(c->Name()); it != actuator_roles.end())
        want_act.insert({c->Attribute("name"), it->second});
      if (std::string(c->Name()) == "actuator") want_act.insert({c->Attribute("name"), ""});
    }
    for (const TransmissionJoint& j : t.joints) got_joints.insert({j.name, j.role});
    for (const TransmissionActuator& a : t.actuators) got_act.insert({a.name, a.role});
    EXPECT_EQ(got_joints, want_joints) << t.name;
    EXPECT_EQ(got_act, want_act) << t.name;
    for (const TransmissionJoint& j : t.joints) EXPECT_NE(m.joint(j.name), nullptr) << j.name;
  }
  EXPECT_EQ(wrists, 2);
  EXPECT_EQ(grippers, 2);
  const Transmission& wrist = *by_name.at("r_wrist_trans");
  EXPECT_DOUBLE_EQ(*wrist.actuators.at(0).mechanical_reduction, 60.17142857142857);
  EXPECT_NE(by_name.at("r_gripper_trans")->xml.child("gap_joint"), nullptr);
  EXPECT_EQ(by_name.at("r_gripper_trans")->xml.child("gap_joint")->attribute("gear_ratio"), "40.095");
  // The real PR2 carries two placeholder sensor inertias (0.001, 0.001, 0.01) that break the
  // triangle inequality; it loads only with --lenient.
  EXPECT_TRUE(lenient);
}

}  // namespace
}  // namespace mechsim::description
