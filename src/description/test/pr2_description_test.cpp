// mechsim's own PR2 description (robots/pr2/urdf) against the real robot: each variant, expanded
// with mechsim's xacro, must carry the facts of the matching reference expansion of
// pr2_description (../shared/robots/reference): the same links and joints (names, types, axes,
// parents, children, origins), limits, safety controllers, dynamics, calibration, mimics, masses,
// inertias, transmissions and Gazebo contact/joint properties. Collision geometry differs on
// purpose (primitives instead of meshes) and is checked for presence only.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "description/robot_loader.hpp"
#include "description/urdf/urdf_parser.hpp"

namespace mechsim::description {
namespace {

namespace fs = std::filesystem;

const fs::path kShared(MECHSIM_SHARED_DIR);
const fs::path kPackage = fs::path(MECHSIM_SOURCE_DIR) / "robots" / "pr2";

constexpr double kTol = 1e-6;

// Inertias mechsim deliberately changes: the real values (0.001, 0.001, 0.01) break the
// triangle inequality; mechsim's description gives these plates izz = ixx + iyy (a thin plate).
const std::map<std::string, std::string> kChangedInertias = {
    {"sensor_mount_link", "real izz 0.01 > ixx + iyy: not a rigid body; mechsim uses ixx + iyy"},
    {"double_stereo_link", "real izz 0.01 > ixx + iyy: not a rigid body; mechsim uses ixx + iyy"},
};

// Gazebo-only links (<gazebo><link>) of the real gripper's loop closure: they are not URDF links
// and mechsim closes the gripper through its transmission instead.
bool gazebo_only_link(const std::string& name) { return name.find("_parallel_link") != std::string::npos; }

struct Variant {
  std::string ours;       // robots/pr2/urdf/<ours>.urdf.xacro
  std::string reference;  // reference/<reference>.urdf
};

void PrintTo(const Variant& v, std::ostream* os) { *os << v.ours; }

LoadedRobot load_ours(const std::string& name) {
  LoadOptions options;
  options.packages["mechsim_pr2"] = kPackage.string();
  options.lenient = false;  // mechsim's PR2 must pass strict validation
  return load_robot((kPackage / "urdf" / (name + ".urdf.xacro")).string(), options);
}

RobotModel load_reference(const std::string& name) {
  UrdfOptions options;
  options.lenient = true;  // the two sensor mounts above
  options.packages["pr2_description"] = (kShared / "robots" / "pr2_description").string();
  return parse_urdf_file((kShared / "robots" / "reference" / (name + ".urdf")).string(), options);
}

bool near(double a, double b, double tol = kTol) { return std::abs(a - b) <= tol * std::max(1.0, std::abs(b)); }

bool near(const Vec3& a, const Vec3& b) { return near(a.x, b.x) && near(a.y, b.y) && near(a.z, b.z); }

bool near(const Quat& a, const Quat& b) {
  // q and -q are the same rotation.
  const double d = std::abs(a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z);
  return std::abs(1.0 - d) <= kTol * kTol;
}

std::string str(const Vec3& v) {
  std::ostringstream s;
  s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
  return s.str();
}

std::string str(const Quat& q) {
  std::ostringstream s;
  s << "(w " << q.w << ", " << q.x << ", " << q.y << ", " << q.z << ")";
  return s.str();
}

template <class T, class F>
std::set<std::string> names_of(const std::vector<T>& items, F name) {
  std::set<std::string> out;
  for (const T& item : items) out.insert(name(item));
  return out;
}

std::string missing(const std::set<std::string>& a, const std::set<std::string>& b) {
  std::string out;
  for (const std::string& n : a)
    if (!b.count(n)) out += " " + n;
  return out;
}

template <class T>
void expect_same_optional(const std::optional<T>& ours, const std::optional<T>& ref, const std::string& what) {
  ASSERT_EQ(ours.has_value(), ref.has_value()) << what;
  if (ours) {
    EXPECT_TRUE(near(*ours, *ref)) << what << ": ours " << *ours << ", real " << *ref;
  }
}

void expect_same_optional(const std::optional<bool>& ours, const std::optional<bool>& ref, const std::string& what) {
  EXPECT_EQ(ours, ref) << what;
}

void compare_joint(const Joint& o, const Joint& r) {
  const std::string j = "joint '" + r.name + "'";
  EXPECT_EQ(o.type, r.type) << j;
  EXPECT_EQ(o.parent_link, r.parent_link) << j;
  EXPECT_EQ(o.child_link, r.child_link) << j;
  EXPECT_TRUE(near(o.origin.position, r.origin.position))
      << j << " origin xyz: ours " << str(o.origin.position) << ", real " << str(r.origin.position);
  EXPECT_TRUE(near(o.origin.orientation, r.origin.orientation))
      << j << " origin rotation: ours " << str(o.origin.orientation) << ", real " << str(r.origin.orientation);
  EXPECT_TRUE(near(o.axis, r.axis)) << j << " axis: ours " << str(o.axis) << ", real " << str(r.axis);

  ASSERT_EQ(o.limits.has_value(), r.limits.has_value()) << j << " limit";
  if (r.limits) {
    EXPECT_TRUE(near(o.limits->lower, r.limits->lower)) << j << " lower " << o.limits->lower << " vs " << r.limits->lower;
    EXPECT_TRUE(near(o.limits->upper, r.limits->upper)) << j << " upper " << o.limits->upper << " vs " << r.limits->upper;
    EXPECT_TRUE(near(o.limits->effort, r.limits->effort)) << j << " effort";
    EXPECT_TRUE(near(o.limits->velocity, r.limits->velocity)) << j << " velocity";
  }
  ASSERT_EQ(o.safety.has_value(), r.safety.has_value()) << j << " safety_controller";
  if (r.safety) {
    EXPECT_TRUE(near(o.safety->soft_lower_limit, r.safety->soft_lower_limit))
        << j << " soft_lower_limit " << o.safety->soft_lower_limit << " vs " << r.safety->soft_lower_limit;
    EXPECT_TRUE(near(o.safety->soft_upper_limit, r.safety->soft_upper_limit))
        << j << " soft_upper_limit " << o.safety->soft_upper_limit << " vs " << r.safety->soft_upper_limit;
    EXPECT_TRUE(near(o.safety->k_position, r.safety->k_position)) << j << " k_position";
    EXPECT_TRUE(near(o.safety->k_velocity, r.safety->k_velocity)) << j << " k_velocity";
  }
  ASSERT_EQ(o.dynamics.has_value(), r.dynamics.has_value()) << j << " dynamics";
  if (r.dynamics) {
    EXPECT_TRUE(near(o.dynamics->damping, r.dynamics->damping)) << j << " damping";
    EXPECT_TRUE(near(o.dynamics->friction, r.dynamics->friction)) << j << " friction";
  }
  ASSERT_EQ(o.calibration.has_value(), r.calibration.has_value()) << j << " calibration";
  if (r.calibration) {
    expect_same_optional(o.calibration->rising, r.calibration->rising, j + " calibration rising");
    expect_same_optional(o.calibration->falling, r.calibration->falling, j + " calibration falling");
  }
  ASSERT_EQ(o.mimic.has_value(), r.mimic.has_value()) << j << " mimic";
  if (r.mimic) {
    EXPECT_EQ(o.mimic->joint, r.mimic->joint) << j;
    EXPECT_TRUE(near(o.mimic->multiplier, r.mimic->multiplier)) << j << " mimic multiplier";
    EXPECT_TRUE(near(o.mimic->offset, r.mimic->offset)) << j << " mimic offset";
  }
}

bool satisfies_triangle_inequality(const Inertial& in) {
  // The changed plates are diagonal: the moments are the diagonal.
  std::vector<double> m{in.ixx, in.iyy, in.izz};
  std::sort(m.begin(), m.end());
  return m[0] + m[1] >= m[2] * (1.0 - 1e-9);
}

void compare_link(const Link& o, const Link& r) {
  const std::string l = "link '" + r.name + "'";
  ASSERT_EQ(o.inertial.has_value(), r.inertial.has_value()) << l << " inertial";
  if (r.inertial) {
    const Inertial& a = *o.inertial;
    const Inertial& b = *r.inertial;
    EXPECT_TRUE(near(a.mass, b.mass)) << l << " mass " << a.mass << " vs " << b.mass;
    EXPECT_TRUE(near(a.origin.position, b.origin.position)) << l << " com " << str(a.origin.position) << " vs "
                                                           << str(b.origin.position);
    EXPECT_TRUE(near(a.origin.orientation, b.origin.orientation)) << l << " inertial frame rotation";
    EXPECT_TRUE(near(a.ixx, b.ixx)) << l << " ixx";
    EXPECT_TRUE(near(a.iyy, b.iyy)) << l << " iyy";
    EXPECT_TRUE(near(a.ixy, b.ixy)) << l << " ixy";
    EXPECT_TRUE(near(a.ixz, b.ixz)) << l << " ixz";
    EXPECT_TRUE(near(a.iyz, b.iyz)) << l << " iyz";
    if (kChangedInertias.count(r.name)) {
      EXPECT_FALSE(satisfies_triangle_inequality(b)) << l << ": listed as changed, but the real inertia is valid";
      EXPECT_TRUE(satisfies_triangle_inequality(a)) << l;
      EXPECT_TRUE(near(a.izz, a.ixx + a.iyy)) << l << ": izz " << a.izz;
    } else {
      EXPECT_TRUE(near(a.izz, b.izz)) << l << " izz";
    }
  }
  // Where the real link collides, mechsim's collides too (with primitives).
  if (!r.collisions.empty()) {
    EXPECT_FALSE(o.collisions.empty()) << l << " has no collision shape";
  }
  for (const Collision& c : o.collisions) EXPECT_NE(c.geometry.type, GeometryType::Mesh) << l << ": a mesh";
  for (const Visual& v : o.visuals) EXPECT_NE(v.geometry.type, GeometryType::Mesh) << l << ": a mesh visual";
}

// Numbers compare within kTol (relative), anything else as text.
bool same_value(const std::string& a, const std::string& b) {
  if (a == b) return true;
  char* end_a = nullptr;
  char* end_b = nullptr;
  const double x = std::strtod(a.c_str(), &end_a);
  const double y = std::strtod(b.c_str(), &end_b);
  if (a.empty() || b.empty() || *end_a != '\0' || *end_b != '\0') return false;
  return near(x, y);
}

// Every element of a transmission, its attributes and text: the same, in any order.
void compare_xml(const XmlNode& o, const XmlNode& r, const std::string& where) {
  EXPECT_EQ(o.name, r.name) << where;
  std::set<std::string> keys;
  for (const auto& [k, v] : o.attributes) keys.insert(k);
  for (const auto& [k, v] : r.attributes) keys.insert(k);
  for (const std::string& k : keys) {
    const auto a = o.attribute(k);
    const auto b = r.attribute(k);
    ASSERT_TRUE(a && b) << where << ": attribute '" << k << "' only in " << (a ? "ours" : "the real one");
    EXPECT_TRUE(same_value(*a, *b)) << where << " @" << k << ": ours '" << *a << "', real '" << *b << "'";
  }
  EXPECT_TRUE(same_value(o.text, r.text)) << where << " text: ours '" << o.text << "', real '" << r.text << "'";
  ASSERT_EQ(o.children.size(), r.children.size()) << where << ": number of elements";
  std::vector<bool> used(o.children.size(), false);
  for (const XmlNode& rc : r.children) {
    const std::string rname = rc.attribute("name").value_or("");
    bool found = false;
    for (std::size_t i = 0; i < o.children.size() && !found; ++i) {
      if (used[i] || o.children[i].name != rc.name || o.children[i].attribute("name").value_or("") != rname) continue;
      used[i] = found = true;
      compare_xml(o.children[i], rc, where + "/" + rc.name + (rname.empty() ? "" : "[" + rname + "]"));
    }
    EXPECT_TRUE(found) << where << ": no <" << rc.name << " name='" << rname << "'>";
  }
}

void compare_transmission(const Transmission& o, const Transmission& r) {
  const std::string t = "transmission '" + r.name + "'";
  EXPECT_EQ(o.type, r.type) << t;
  ASSERT_EQ(o.joints.size(), r.joints.size()) << t;
  for (std::size_t i = 0; i < r.joints.size(); ++i) {
    auto it = std::find_if(o.joints.begin(), o.joints.end(), [&](const TransmissionJoint& j) {
      return j.name == r.joints[i].name && j.role == r.joints[i].role;
    });
    ASSERT_NE(it, o.joints.end()) << t << ": no joint '" << r.joints[i].name << "' (" << r.joints[i].role << ")";
    expect_same_optional(it->mechanical_reduction, r.joints[i].mechanical_reduction, t + " joint " + it->name);
  }
  ASSERT_EQ(o.actuators.size(), r.actuators.size()) << t;
  for (std::size_t i = 0; i < r.actuators.size(); ++i) {
    auto it = std::find_if(o.actuators.begin(), o.actuators.end(), [&](const TransmissionActuator& a) {
      return a.name == r.actuators[i].name && a.role == r.actuators[i].role;
    });
    ASSERT_NE(it, o.actuators.end()) << t << ": no actuator '" << r.actuators[i].name << "'";
    expect_same_optional(it->mechanical_reduction, r.actuators[i].mechanical_reduction, t + " actuator " + it->name);
  }
  expect_same_optional(o.mechanical_reduction, r.mechanical_reduction, t + " mechanicalReduction");
  compare_xml(o.xml, r.xml, t);
}

class Pr2Description : public ::testing::TestWithParam<Variant> {
 protected:
  void SetUp() override {
    if (!fs::is_directory(kShared / "robots" / "reference"))
      GTEST_SKIP() << "shared data not found at " << kShared << " (MECHSIM_SHARED_DIR): no reference to compare with";
    loaded_ = load_ours(GetParam().ours);
    ref_ = load_reference(GetParam().reference);
  }
  LoadedRobot loaded_;
  RobotModel ref_;
};

TEST_P(Pr2Description, HasTheRealLinksAndJoints) {
  const RobotModel& ours = loaded_.model;
  const auto link_name = [](const Link& l) { return l.name; };
  const auto joint_name = [](const Joint& j) { return j.name; };
  const auto ol = names_of(ours.links, link_name), rl = names_of(ref_.links, link_name);
  const auto oj = names_of(ours.joints, joint_name), rj = names_of(ref_.joints, joint_name);
  EXPECT_EQ(ol, rl) << "links missing:" << missing(rl, ol) << "; extra:" << missing(ol, rl);
  EXPECT_EQ(oj, rj) << "joints missing:" << missing(rj, oj) << "; extra:" << missing(oj, rj);
  EXPECT_EQ(ours.root_link, ref_.root_link);
  EXPECT_EQ(ours.name, ref_.name);
  EXPECT_GT(ours.joints.size(), 40u);
}

TEST_P(Pr2Description, JointsMatchKinematicsLimitsAndDynamics) {
  std::size_t compared = 0;
  for (const Joint& r : ref_.joints) {
    const Joint* o = loaded_.model.joint(r.name);
    if (o == nullptr) continue;  // reported by HasTheRealLinksAndJoints
    SCOPED_TRACE(r.name);
    compare_joint(*o, r);
    ++compared;
  }
  EXPECT_EQ(compared, ref_.joints.size());
}

TEST_P(Pr2Description, LinksMatchMassesAndInertias) {
  std::size_t compared = 0;
  for (const Link& r : ref_.links) {
    const Link* o = loaded_.model.link(r.name);
    if (o == nullptr) continue;
    SCOPED_TRACE(r.name);
    compare_link(*o, r);
    ++compared;
  }
  EXPECT_EQ(compared, ref_.links.size());
  EXPECT_NEAR(loaded_.model.total_mass(), ref_.total_mass(), 1e-6);
}

TEST_P(Pr2Description, TransmissionsMatch) {
  const auto name = [](const Transmission& t) { return t.name; };
  const auto ot = names_of(loaded_.model.transmissions, name), rt = names_of(ref_.transmissions, name);
  EXPECT_EQ(ot, rt) << "missing:" << missing(rt, ot) << "; extra:" << missing(ot, rt);
  for (const Transmission& r : ref_.transmissions) {
    auto it = std::find_if(loaded_.model.transmissions.begin(), loaded_.model.transmissions.end(),
                           [&](const Transmission& t) { return t.name == r.name; });
    if (it == loaded_.model.transmissions.end()) continue;
    SCOPED_TRACE(r.name);
    compare_transmission(*it, r);
  }
}

TEST_P(Pr2Description, GazeboContactAndJointPropertiesMatch) {
  const RobotModel& ours = loaded_.model;
  std::set<std::string> links;
  for (const auto& [name, p] : ours.gazebo_links) links.insert(name);
  for (const auto& [name, p] : ref_.gazebo_links)
    if (!gazebo_only_link(name)) links.insert(name);
  const GazeboLinkProperties none;
  for (const std::string& name : links) {
    auto o = ours.gazebo_links.find(name);
    auto r = ref_.gazebo_links.find(name);
    const GazeboLinkProperties& a = o == ours.gazebo_links.end() ? none : o->second;
    const GazeboLinkProperties& b = r == ref_.gazebo_links.end() ? none : r->second;
    const std::string l = "gazebo link '" + name + "'";
    expect_same_optional(a.mu1, b.mu1, l + " mu1");
    expect_same_optional(a.mu2, b.mu2, l + " mu2");
    expect_same_optional(a.kp, b.kp, l + " kp");
    expect_same_optional(a.kd, b.kd, l + " kd");
    expect_same_optional(a.max_vel, b.max_vel, l + " maxVel");
    expect_same_optional(a.min_depth, b.min_depth, l + " minDepth");
    expect_same_optional(a.gravity, b.gravity, l + " gravity");
    expect_same_optional(a.self_collide, b.self_collide, l + " selfCollide");
  }
  std::set<std::string> joints;
  for (const auto& [name, p] : ours.gazebo_joints) joints.insert(name);
  for (const auto& [name, p] : ref_.gazebo_joints) joints.insert(name);
  const GazeboJointProperties no_joint;
  for (const std::string& name : joints) {
    auto o = ours.gazebo_joints.find(name);
    auto r = ref_.gazebo_joints.find(name);
    const GazeboJointProperties& a = o == ours.gazebo_joints.end() ? no_joint : o->second;
    const GazeboJointProperties& b = r == ref_.gazebo_joints.end() ? no_joint : r->second;
    const std::string j = "gazebo joint '" + name + "'";
    expect_same_optional(a.stop_kp, b.stop_kp, j + " stopKp");
    expect_same_optional(a.stop_kd, b.stop_kd, j + " stopKd");
    expect_same_optional(a.fudge_factor, b.fudge_factor, j + " fudgeFactor");
    expect_same_optional(a.provide_feedback, b.provide_feedback, j + " provideFeedback");
  }
  // The controller manager plugin marks the robot as a PR2 (pr2_controller_manager).
  EXPECT_TRUE(std::any_of(ours.plugins.begin(), ours.plugins.end(), [](const GazeboPlugin& p) {
    return p.filename == "libgazebo_ros_controller_manager.so";
  }));
}

INSTANTIATE_TEST_SUITE_P(Variants, Pr2Description,
                         ::testing::Values(Variant{"pr2", "pr2"}, Variant{"pr2_no_arms", "pr2_no_arms"},
                                           Variant{"pr2_no_kinect", "pr2_no_kinect"},
                                           Variant{"pr2_one_arm", "pr2_se"}),
                         [](const ::testing::TestParamInfo<Variant>& p) { return p.param.ours; });

// Independent of the shared data: every variant expands, passes strict validation without
// warnings and uses no mesh (the package ships none).
TEST(Pr2OwnDescription, EveryVariantIsStrictlyValidAndMeshFree) {
  for (const char* name : {"pr2", "pr2_no_arms", "pr2_no_kinect", "pr2_one_arm"}) {
    SCOPED_TRACE(name);
    const LoadedRobot robot = load_ours(name);
    EXPECT_TRUE(robot.warnings.empty()) << robot.warnings.front();
    EXPECT_EQ(robot.model.root_link, "base_footprint");
    std::size_t shapes = 0;
    for (const Link& l : robot.model.links)
      for (const Collision& c : l.collisions) {
        EXPECT_NE(c.geometry.type, GeometryType::Mesh) << l.name;
        ++shapes;
      }
    EXPECT_GT(shapes, 20u);
  }
}

TEST(Pr2OwnDescription, VariantsDifferAsThePr2sDo) {
  const RobotModel full = load_ours("pr2").model;
  const RobotModel no_arms = load_ours("pr2_no_arms").model;
  const RobotModel one_arm = load_ours("pr2_one_arm").model;
  EXPECT_NE(full.joint("l_shoulder_pan_joint"), nullptr);
  EXPECT_NE(full.joint("r_gripper_joint"), nullptr);
  EXPECT_EQ(no_arms.joint("r_shoulder_pan_joint"), nullptr);
  EXPECT_EQ(no_arms.joint("l_shoulder_pan_joint"), nullptr);
  EXPECT_NE(one_arm.joint("r_shoulder_pan_joint"), nullptr);
  EXPECT_EQ(one_arm.joint("l_shoulder_pan_joint"), nullptr);
  EXPECT_NE(one_arm.link("head_mount_kinect_rgb_optical_frame"), nullptr);
  EXPECT_EQ(one_arm.link("double_stereo_link"), nullptr);
  EXPECT_EQ(one_arm.link("projector_wg6802418_frame"), nullptr);
  // 7 arm joints, gripper gap, 4 passive finger joints, slider and screw per arm.
  EXPECT_EQ(full.dof() - one_arm.dof(), 11u);
  EXPECT_EQ(one_arm.dof() - no_arms.dof(), 11u);
}

TEST(Pr2OwnDescription, ABadVariantArgumentIsNamed) {
  const std::string doc = R"(<?xml version="1.0"?>
<robot name="pr2" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:include filename="$(find mechsim_pr2)/urdf/assembly.xacro"/>
  <xacro:pr2_robot arms="left"/>
</robot>
)";
  XacroOptions options;
  options.packages["mechsim_pr2"] = kPackage.string();
  try {
    expand_xacro_string(doc, "bad_variant.urdf.xacro", options);
    FAIL() << "expected an error";
  } catch (const XacroError& e) {
    EXPECT_NE(std::string(e.what()).find("arms must be 'both', 'right' or 'none', not 'left'"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace mechsim::description
