#pragma once
// The robot description as mechsim sees it: URDF links and joints plus what urdfdom ignores
// (transmissions, gazebo extensions). Immutable once built; plain data, no urdfdom types.

#include <array>
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "description/pose.hpp"

namespace mechsim::description {

struct SensorSpec;  // description/sensor_spec.hpp
struct Ros2ControlHardware;  // description/ros2_control.hpp

// A generic XML element, kept for the parts of a description whose meaning depends on a type
// (PR2 transmissions, gazebo plugins). `line` is the 1-based line in the expanded document.
struct XmlNode {
  std::string name;
  std::map<std::string, std::string> attributes;
  std::string text;  // trimmed character data
  std::vector<XmlNode> children;
  int line = 0;

  const XmlNode* child(const std::string& child_name) const;  // first child so named, or null
  std::vector<const XmlNode*> children_named(const std::string& child_name) const;
  std::optional<std::string> attribute(const std::string& key) const;
};

struct Inertial {
  Pose origin;  // X_LI: inertial frame I in link frame L
  double mass = 0.0;  // kg
  // Inertia about the centre of mass, in frame I (kg m^2).
  double ixx = 0.0, ixy = 0.0, ixz = 0.0, iyy = 0.0, iyz = 0.0, izz = 0.0;
};

enum class GeometryType { Box, Cylinder, Sphere, Mesh };

struct Geometry {
  GeometryType type = GeometryType::Box;
  Vec3 size;             // box edge lengths (m)
  double radius = 0.0;   // cylinder, sphere (m)
  double length = 0.0;   // cylinder, along its z axis (m)
  std::string mesh_uri;  // as written, e.g. package://pr2_description/meshes/base_v0/base.dae
  std::string mesh_path; // resolved file path, empty when it could not be resolved
  Vec3 mesh_scale{1.0, 1.0, 1.0};
};

struct Visual {
  std::string name;
  Pose origin;  // X_LV
  Geometry geometry;
  std::string material_name;
  std::optional<std::array<double, 4>> rgba;
};

struct Collision {
  std::string name;
  Pose origin;  // X_LG
  Geometry geometry;
  // What a laser reports as the intensity of a hit on this shape (SDF <collision><laser_retro>);
  // absent: the link's gazebo <laserRetro>, else 0.
  std::optional<double> laser_retro;
};

struct Link {
  std::string name;
  std::optional<Inertial> inertial;
  std::vector<Visual> visuals;
  std::vector<Collision> collisions;
  std::string parent_joint;               // empty for the root
  std::vector<std::string> child_joints;  // in document order
  int line = 0;
};

enum class JointType { Revolute, Continuous, Prismatic, Fixed, Floating, Planar };

struct JointLimits {
  double lower = 0.0, upper = 0.0;  // rad or m
  double effort = 0.0;              // N m or N
  double velocity = 0.0;            // rad/s or m/s
};

struct SafetyController {
  double soft_lower_limit = 0.0, soft_upper_limit = 0.0;  // rad or m
  double k_position = 0.0;  // 1/s
  double k_velocity = 0.0;  // N m s/rad or N s/m
};

struct Dynamics {
  double damping = 0.0;   // N m s/rad or N s/m
  double friction = 0.0;  // N m or N
};

struct Calibration {
  std::optional<double> rising, falling;
};

struct Mimic {
  std::string joint;  // the joint mimicked
  double multiplier = 1.0;
  double offset = 0.0;  // q = multiplier * q_joint + offset
};

struct Joint {
  std::string name;
  JointType type = JointType::Fixed;
  std::string parent_link, child_link;
  Pose origin;             // X_PJ: joint frame J in parent link frame P
  Vec3 axis{1.0, 0.0, 0.0};  // in J, unit length
  std::optional<JointLimits> limits;
  std::optional<SafetyController> safety;
  std::optional<Dynamics> dynamics;
  std::optional<Calibration> calibration;
  std::optional<Mimic> mimic;
  int line = 0;
};

// One joint or actuator named by a transmission. `role` tells which part it plays in the
// transmission's type: "" for ros_control-format and PR2 SimpleTransmission entries;
// "flex"/"roll" and "right"/"left" for the PR2 wrist; "gap" and "passive" for the PR2 gripper;
// "simulated_actuated" for PR2 simulated_actuated_joint entries.
struct TransmissionJoint {
  std::string name;
  std::string role;
  std::vector<std::string> hardware_interfaces;  // as written
  std::optional<double> mechanical_reduction;   // where given on the joint (PR2 wrist)
};

struct TransmissionActuator {
  std::string name;
  std::string role;
  std::optional<double> mechanical_reduction;
  std::vector<std::string> hardware_interfaces;
};

struct Transmission {
  std::string name;
  std::string type;  // e.g. transmission_interface/SimpleTransmission, pr2_mechanism_model/WristTransmission
  std::vector<TransmissionJoint> joints;
  std::vector<TransmissionActuator> actuators;
  std::optional<double> mechanical_reduction;  // a top-level <mechanicalReduction>, PR2 format
  XmlNode xml;  // the whole <transmission> element, for type-specific parameters
  int line = 0;
};

// <gazebo reference="link"> properties.
struct GazeboLinkProperties {
  std::optional<double> mu1, mu2, kp, kd, min_depth, max_vel;
  std::optional<bool> self_collide;
  std::optional<bool> gravity;  // also set (negated) by <turnGravityOff>
  // <laserRetro> (sdformat's URDF name; <laser_retro> is taken too): the intensity lasers report
  // for the link's collision shapes.
  std::optional<double> laser_retro;
  std::string material;         // <material>NAME</material> or <material value="NAME"/>
  int line = 0;                 // the first <gazebo reference> element naming the link
};

// <gazebo reference="joint"> properties (Gazebo's joint stops and ODE options).
struct GazeboJointProperties {
  std::optional<double> stop_kp, stop_kd;  // joint-limit stop stiffness (N m/rad) and damping
  std::optional<double> fudge_factor;
  std::optional<bool> provide_feedback, implicit_spring_damper;
  int line = 0;
};

struct GazeboPlugin {
  std::string name, filename;
  std::string reference;  // the gazebo element's reference, empty for the robot
  std::string sensor;     // the enclosing <sensor>'s name; empty for a model plugin
  std::map<std::string, std::string> parameters;  // simple child elements: name -> trimmed text
  XmlNode xml;
};

struct RobotModel {
  std::string name;
  std::string source;      // file the description came from, or "<string>"
  std::string root_link;
  std::vector<Link> links;    // document order
  std::vector<Joint> joints;  // document order
  std::vector<Transmission> transmissions;
  std::map<std::string, GazeboLinkProperties> gazebo_links;  // by link name
  std::vector<GazeboPlugin> plugins;  // document order; model and sensor plugins
  std::map<std::string, GazeboJointProperties> gazebo_joints;  // by joint name
  // Document order: <sensor> elements and sensor plugins (description/sensor_spec.hpp; include
  // it to use them: the special members below are out of line so that this header need not).
  std::vector<SensorSpec> sensors;
  // Document order: the <ros2_control> tags (description/ros2_control.hpp; include it to use them).
  std::vector<Ros2ControlHardware> ros2_control;

  RobotModel();
  ~RobotModel();
  RobotModel(const RobotModel&);
  RobotModel(RobotModel&&) noexcept;
  RobotModel& operator=(const RobotModel&);
  RobotModel& operator=(RobotModel&&) noexcept;

  const Link* link(const std::string& link_name) const;     // null when absent
  const Joint* joint(const std::string& joint_name) const;  // null when absent
  std::size_t dof() const;  // number of non-fixed, non-mimic 1-DOF joints
  double total_mass() const;  // kg
};

}  // namespace mechsim::description
